#include "tile_kernel_args.hpp"

namespace parashade {
namespace {

// render_tiles' parameters in signature order (kernels/render_tiles.cl).
enum TileArg : cl_uint {
  kTriangles, kAttributes, kTileStart, kTileList, kLights, kMaterials, kViewer, kBackground, kTilesX, kNumTiles,
  kWidth, kHeight, kOutRgba, kOutFloat, kFixed, kTileCounters, kLeaves, kDdaFirst, kDdaRows,
  // PLAN_PASS only
  kKeys, kPacketFirst, kVtileTile, kPacketCounter, kNumPackets,
};

}  // namespace

void set_tile_kernel_args(cl::Kernel& k, const TileKernelArgs& a) {
  k.setArg(kTriangles, *a.triangles);
  k.setArg(kAttributes, *a.attributes);
  k.setArg(kTileStart, *a.tile_start);
  k.setArg(kTileList, *a.tile_list);
  k.setArg(kLights, *a.lights);
  k.setArg(kMaterials, *a.materials);
  k.setArg(kViewer, a.viewer);
  k.setArg(kBackground, a.background);
  k.setArg(kTilesX, a.tiles_x);
  k.setArg(kNumTiles, a.num_tiles);
  k.setArg(kWidth, a.width);
  k.setArg(kHeight, a.height);
  k.setArg(kOutRgba, *a.out_rgba);
  k.setArg(kOutFloat, *a.out_float);
  k.setArg(kFixed, *a.fixed);
  k.setArg(kTileCounters, *a.tile_counters);
  k.setArg(kLeaves, *a.leaves);
  k.setArg(kDdaFirst, *a.dda_first);
  k.setArg(kDdaRows, *a.dda_rows);
}

void set_plan_pass_args(cl::Kernel& k, const PlanPassArgs& a) {
  k.setArg(kKeys, *a.keys);
  k.setArg(kPacketFirst, *a.packet_first);
  k.setArg(kVtileTile, *a.vtile_tile);
  k.setArg(kPacketCounter, *a.packet_counter);
  k.setArg(kNumPackets, a.num_packets);
}

}  // namespace parashade
