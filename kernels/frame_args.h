/* render_tiles' arguments that every pass of a tile reads, as one value: the passes take a pointer to it
 * instead of twenty parameters each. They are always inlined, so the struct compiles away. */
#ifndef PARASHADE_FRAME_ARGS_H
#define PARASHADE_FRAME_ARGS_H

typedef struct {
  __global const TriangleGeometry* tris;
  __global const float* attrs; /* ATTR_FLOATS a triangle */
  __global const uint* tile_tris; /* the tiles' (or the plan's virtual tiles') lists, primitive order */
  __constant float4* lights;
  __constant float4* materials;
  float4 viewer;
  float4 background;
  int tiles_x, width, height;
  __global uint* out_rgba; /* width x height exactly (no padding), so the host can use it without a copy */
  __global float* out_float; /* OUTPUT_FLOAT: three planes of width x height */
  __global ulong* tile_counters; /* COUNTS_TILE: three a tile */
  __global const FixedPlanes* fixed; /* the unit path's fixed-point planes, */
  __global const SierpinskiLeaf* leaves; /* its records' leaves */
  __global const uint* dda_first; /* and DDA_COVERAGE's row table */
  __global const int* dda_rows;
#if PLAN_PASS
  __global ulong* keys; /* a pixel's least (depth, primitive index) */
#endif
} FrameArgs;

#endif
