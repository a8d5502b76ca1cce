#pragma once
// render_tiles.cl's arguments by name. The kernel's signature is written out once, here (the enum's
// order); the plain pass, the units' depth pass and the resolve set them through these two calls.
#include <CL/opencl.hpp>

namespace parashade {

struct TileKernelArgs {
  const cl::Buffer* triangles;
  const cl::Buffer* attributes;
  const cl::Buffer* tile_start;  // per tile (plan pass 1: per virtual tile) the first entry of tile_list
  const cl::Buffer* tile_list;
  const cl::Buffer* lights;
  const cl::Buffer* materials;
  cl_float4 viewer;  // the camera position (local viewer) or the direction towards it
  cl_float4 background;
  cl_int tiles_x, num_tiles, width, height;
  const cl::Buffer* out_rgba;
  const cl::Buffer* out_float;
  const cl::Buffer* fixed;        // fixed point: the records' planes
  const cl::Buffer* tile_counters;  // per tile: modeled spans, pixels, clocks (or normalization counts)
  const cl::Buffer* leaves;       // sierpinski: the records' leaves
  const cl::Buffer* dda_first;    // dda coverage: the row table
  const cl::Buffer* dda_rows;
};

// Planned frames (PLAN_PASS 1 and 2): the depth keys and the plan's packets.
struct PlanPassArgs {
  const cl::Buffer* keys;
  const cl::Buffer* packet_first;
  const cl::Buffer* vtile_tile;
  const cl::Buffer* packet_counter;  // dynamic: the next packet
  cl_int num_packets;                // packets up to this one
};

void set_tile_kernel_args(cl::Kernel& k, const TileKernelArgs& a);
void set_plan_pass_args(cl::Kernel& k, const PlanPassArgs& a);

}  // namespace parashade
