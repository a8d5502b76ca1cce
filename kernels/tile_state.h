/* A tile's private state while its triangles are walked: depth and colour per pixel as TILE_VECTORS vectors
 * (row segments, or stamps: stamp_layout.h), a deferred tile's winners, and the tile's counters. It stays in
 * private memory and is written once, so there is no read-modify-write of the frame and the result is
 * deterministic. */
#ifndef PARASHADE_TILE_STATE_H
#define PARASHADE_TILE_STATE_H

#define TILE_VECTORS (TILE * SEGMENTS)
/* The tile arrays' length: one vector more than the tile's, so that at TILE 32 and 64 (4 and 16 KiB an array)
 * they are not a multiple of 4 KiB apart; a load of cr[i] right after a store to depth[i] at such a distance waits
 * on the store (4K aliasing). 0.7-2.6 % off the kernel time of Gouraud and Phong on the bunny and the teapot
 * (1920x1080, PoCL pthread on a 2-core AVX-512 VM, bench_kernel_ab). */
#define TILE_ARRAY (TILE_VECTORS + 1)

#if REGISTER_COLOUR
typedef intV colourV;
#else
typedef floatV colourV;
#endif

#if UNIT_PATH
/* A unit's spans counted in this tile (those whose left pixel it holds), their pixels and modeled clocks. */
typedef struct { ulong spans, span_pixels, clocks; } TileCounts;
#else
/* Per-span normalization's setups, their fallbacks and a sequential unit's steps (SHADE_SPAN; unused, and
 * compiled away, otherwise). */
typedef struct { ulong span_setups, span_fallbacks, span_steps; } TileCounts;
#endif

#if DEFER_STAMPS
/* Deferred stamps (Phong, deferred_shade.h): in a tile of at least DEFER_MIN_TRIANGLES triangles (deferred) the
 * walk only keeps, per pixel, the record of the triangle that passed its depth test last (winner, -1: none). */
#define DEFER_DECL , intV* winner, int deferred
#define DEFER_ARGS , winner, deferred
#else
#define DEFER_DECL
#define DEFER_ARGS
#endif

/* The stamps' tiles (not the combined method's, nor the units' register colour) keep no background in their
 * colour arrays: write_tile takes the background wherever the depth is still infinite, and every pixel of
 * finite depth has had its colour kept by the walk, the tile fill or the deferred shading. Their clear writes
 * the depth (and a deferred tile's winners) only: three of a pixel's four or five stores fewer.
 * -D CLEAR_COLOUR clears the colour as before (bench_kernel_ab's A/B). */
#if STAMPS && !COMBINED && !REGISTER_COLOUR && !defined(CLEAR_COLOUR)
#define CLEARS_DEPTH_ONLY 1
#else
#define CLEARS_DEPTH_ONLY 0
#endif

/* Every pixel uncovered (depth infinite), of the background colour (CLEARS_DEPTH_ONLY: left to write_tile) and,
 * in a deferred tile, without a winner. */
INLINE void clear_tile(floatV* depth, colourV* cr, colourV* cg, colourV* cb, float4 background DEFER_DECL) {
  for (int i = 0; i < TILE_VECTORS; ++i) {
    depth[i] = (floatV)INFINITY;
#if DEFER_STAMPS
    winner[i] = (intV)(-1);
#endif
#if REGISTER_COLOUR
    /* Colour holds span registers: the background as a register value. */
    cr[i] = (intV)(int)(background.x * (1 << FRAC_BITS));
    cg[i] = (intV)(int)(background.y * (1 << FRAC_BITS));
    cb[i] = (intV)(int)(background.z * (1 << FRAC_BITS));
#elif !CLEARS_DEPTH_ONLY
    cr[i] = (floatV)background.x;
    cg[i] = (floatV)background.y;
    cb[i] = (floatV)background.z;
#endif
  }
}

#endif
