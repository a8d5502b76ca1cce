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

/* render_tiles' parameters, the same in each kernel shape (render_tiles.cl, render_lanes.cl; the host sets them by
 * position, host/cl/tile_kernel_args.cpp), and the FrameArgs made of them. */
#if PLAN_PASS
#define PLAN_PASS_PARAMS                                                                                     \
  , __global ulong *keys, __global const uint *packet_first, __global const uint *vtile_tile,             \
      volatile __global int *packet_counter, int num_packets
#define PLAN_PASS_FIELDS , .keys = keys
#else
#define PLAN_PASS_PARAMS
#define PLAN_PASS_FIELDS
#endif
#define RENDER_TILES_PARAMS                                                                                  \
  __global const TriangleGeometry *tris, __global const float *attrs, __global const uint *tile_start,      \
      __global const uint *tile_tris, __constant float4 *lights, __constant float4 *materials, float4 viewer, \
      float4 background, int tiles_x, int num_tiles, int width, int height, __global uint *out_rgba,          \
      __global float *out_float, __global const FixedPlanes *fixed, __global ulong *tile_counters,            \
      __global const SierpinskiLeaf *leaves, __global const uint *dda_first,                                  \
      __global const int *dda_rows PLAN_PASS_PARAMS
#define FRAME_ARGS_OF_PARAMS                                                                                  \
  {.tris = tris, .attrs = attrs, .tile_tris = tile_tris, .lights = lights, .materials = materials,            \
   .viewer = viewer, .background = background, .tiles_x = tiles_x, .width = width, .height = height,        \
   .out_rgba = out_rgba, .out_float = out_float, .tile_counters = tile_counters, .fixed = fixed,              \
   .leaves = leaves, .dda_first = dda_first, .dda_rows = dda_rows PLAN_PASS_FIELDS}

#endif
