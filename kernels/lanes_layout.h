/* The lanes shape's layout of a tile (render_lanes.cl): a work-group of WORK_GROUP_SIZE work-items per tile, each
 * owning a block of LANE_PIXELS = BLOCK_W x BLOCK_H of its pixels (as square as a power of two allows), the blocks
 * numbered in Morton order. A work-item whose block misses a triangle's box skips it with one test; neighbouring
 * work-items, which an implicit vectorizer or a GPU's wavefront makes the lanes of one vector, own a square of
 * blocks, so a small triangle concerns few such vectors (and the others skip it whole). A work-item owning a
 * column of pixels across the tile (the first layout) had to test every triangle of the tile at every pixel:
 * 100-1000x slower than the vector shape on PoCL and on Intel's runtime (bench/README.md). */
#ifndef PARASHADE_LANES_LAYOUT_H
#define PARASHADE_LANES_LAYOUT_H

#if PLAN_PASS || UNIT_PATH || SHADE_SPAN
#error "the lanes shape: the plain frame and the float image only (the combinations table refuses the rest)"
#endif
#ifndef WORK_GROUP_SIZE
#error "the lanes shape needs WORK_GROUP_SIZE (the host passes it)"
#endif
#if (TILE * TILE) % WORK_GROUP_SIZE != 0
#error "WORK_GROUP_SIZE must divide the tile's pixels"
#endif
#define LANE_PIXELS ((TILE * TILE) / WORK_GROUP_SIZE)

/* Triangle records a work-group holds in local memory at once (lanes_batch.h). */
#ifndef LANES_BATCH
#define LANES_BATCH 32
#endif

/* LOG2(n) of a power of two up to 4096, for the preprocessor. */
#define LOG2_4096(n)                                                                                           \
  ((n) >= 4096 ? 12 : (n) >= 2048 ? 11 : (n) >= 1024 ? 10 : (n) >= 512 ? 9 : (n) >= 256 ? 8 : (n) >= 128 ? 7    \
   : (n) >= 64 ? 6 : (n) >= 32 ? 5 : (n) >= 16 ? 4 : (n) >= 8 ? 3 : (n) >= 4 ? 2 : (n) >= 2 ? 1 : 0)
/* The block: BLOCK_W = 2^ceil(log2(P) / 2) columns, BLOCK_H the rest (P = 8: 4 x 2). */
#define BLOCK_W (1 << ((LOG2_4096(LANE_PIXELS) + 1) / 2))
#define BLOCK_H (LANE_PIXELS / BLOCK_W)
/* Blocks across a tile as bits: no more than down it (BLOCK_W >= BLOCK_H). */
#define BLOCK_BITS_X LOG2_4096(TILE / BLOCK_W)

/* Work-item lid's block: its top-left pixel's column (lane_block_x) and row (lane_block_y) in the tile. Morton order:
 * the index's bits alternate x and y, those past the x bits are y's. Plain ints, no int2: PoCL's vectorizer of the
 * work-item loops leaves a loop with any vector-typed instruction scalar. */
INLINE int lane_block_x(int lid) {
  int x = 0;
  for (int b = 0; b < BLOCK_BITS_X; ++b) x |= ((lid >> (2 * b)) & 1) << b;
  return x * BLOCK_W;
}
INLINE int lane_block_y(int lid) {
  int y = 0;
  for (int b = 0; b < BLOCK_BITS_X; ++b) y |= ((lid >> (2 * b + 1)) & 1) << b;
  return (y | (lid >> (2 * BLOCK_BITS_X)) << BLOCK_BITS_X) * BLOCK_H;
}

/* Pixel p of the block: its column and row in the block. */
#define BLOCK_X(p) ((p) % BLOCK_W)
#define BLOCK_Y(p) ((p) / BLOCK_W)

#endif
