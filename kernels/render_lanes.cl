/* Shades one frame in the lanes shape (KERNEL_SHAPE_LANES, docs/pipeline.md): a work-group per tile, a work-item
 * per pixel lane (a block of LANE_PIXELS of the tile's pixels each, lanes_layout.h), written so that an implicit vectorizer
 * or a GPU makes vector lanes of the work-items, where the vector shape (render_tiles.cl) has each work-item walk
 * whole tiles with explicit 16-lane vectors. The work-group reads its tile's triangle records into local memory a
 * batch at a time (lanes_batch.h); each work-item walks them in primitive order over its own pixels, keeping
 * each pixel's depth and winner in private memory (lanes_walk.h), then shades each pixel once by its winner and
 * writes it (lanes_shade.h). The same coverage, depth test and shading operations per pixel as the vector shape,
 * so the same image. Takes render_tiles' parameters (frame_args.h): the host sets either shape's alike. */
#include "common.h"
#include "triangle_record.h"
#include "span.h"
#include "fixed_point.h"
#include "sierpinski_leaf.h"
#include "tile_paths.h"
#include "frame_args.h"
/* A barrier after every triangle instead of every batch: PoCL's work-item loops then wrap one triangle's walk, the
 * innermost loop its vectorizer needs; measured (bench_kernel_ab -D LANES_TRIANGLE_BARRIER=1, teapot Gouraud, tile 32):
 * PoCL 0.91x, Intel's runtime 1.05-1.23x. Off: PoCL still left the loops scalar (bench/README.md "Run KS"). */
#ifndef LANES_TRIANGLE_BARRIER
#define LANES_TRIANGLE_BARRIER 0
#endif
#include "lanes_layout.h"
#include "lanes_batch.h"
#include "lanes_walk.h"
#include "lanes_shade.h"

/* Tile `tile`, its list tile_tris[begin .. end), by work-item lid of the tile's work-group. The batch loop's bounds
 * are the same for every work-item, so each reaches every barrier. */
INLINE void render_lanes_tile(const FrameArgs* f, int tile, uint begin, uint end, int lid,
                              __local TriangleGeometry* batch, __local int* ids) {
  const int tile_x = (tile % f->tiles_x) * TILE, tile_y = (tile / f->tiles_x) * TILE;
  const int block_x = tile_x + lane_block_x(lid), block_y = tile_y + lane_block_y(lid); /* its pixels, in the frame */
  float depth[LANE_PIXELS];
  int winner[LANE_PIXELS];
#pragma unroll
  for (int p = 0; p < LANE_PIXELS; ++p) {
    depth[p] = INFINITY;
    winner[p] = -1;
  }
  for (uint first = begin; first < end; first += LANES_BATCH) {
    const int n = (int)min((uint)LANES_BATCH, end - first);
    load_batch(f, first, n, lid, batch, ids);
    barrier(CLK_LOCAL_MEM_FENCE);
#if LANES_TRIANGLE_BARRIER
    for (int j = 0; j < n; ++j) {
      walk_lane_triangle(&batch[j], ids[j], tile_x, tile_y, block_x, block_y, depth, winner);
      barrier(CLK_LOCAL_MEM_FENCE);
    }
#else
    for (int j = 0; j < n; ++j) walk_lane_triangle(&batch[j], ids[j], tile_x, tile_y, block_x, block_y, depth, winner);
    barrier(CLK_LOCAL_MEM_FENCE); /* every work-item is done with the batch before the next one overwrites it */
#endif
  }
  write_lane_pixels(f, block_x, block_y, winner);
}

/* One work-group per tile: the host launches tiles x WORK_GROUP_SIZE work-items, a band's from its first tile on
 * (the global offset, a multiple of WORK_GROUP_SIZE). */
__kernel __attribute__((reqd_work_group_size(WORK_GROUP_SIZE, 1, 1)))
void render_tiles(RENDER_TILES_PARAMS) {
  const FrameArgs f = FRAME_ARGS_OF_PARAMS;
  __local TriangleGeometry batch[LANES_BATCH];
  __local int ids[LANES_BATCH];
  /* The group's id and offset, not the global id: a compiler sees that they are the same for the whole group (Intel's
   * runtime, which took get_global_id(0) / WORK_GROUP_SIZE as varying, read the batch by gathers: 10x slower). */
  const int tile = (int)(get_group_id(0) + get_global_offset(0) / WORK_GROUP_SIZE);
  if (tile >= num_tiles) return; /* the whole work-group: no barrier is left waiting */
  render_lanes_tile(&f, tile, tile_start[tile], tile_start[tile + 1], (int)get_local_id(0), batch, ids);
}
