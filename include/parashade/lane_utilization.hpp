#pragma once
// Lane utilization of the frame kernel (kernels/render_tiles.cl): of the pixel lanes it evaluates
// (coverage, depth test and, where any lane passes, shading), how many a triangle covers. Counted on the
// host from a prepared frame's records and bins by walking each tile's triangles as the kernel's plain
// path does, once with 1x16 row segments and once with 4x4 stamps. Device-free.
#include <cstdint>

#include "parashade/frame_pipeline.hpp"

namespace parashade {

struct LaneUtilization {
  std::uint64_t covered = 0;         // (triangle, pixel) pairs with the pixel covered, over all tiles
  std::uint64_t row_lanes = 0;       // lanes the row-segment walk evaluates (16 per segment)
  std::uint64_t stamp_lanes = 0;     // lanes the stamp walk evaluates (16 per stamp)
  double rows() const { return row_lanes ? double(covered) / double(row_lanes) : 0.0; }
  double stamps() const { return stamp_lanes ? double(covered) / double(stamp_lanes) : 0.0; }
};

// The plain path's walk (no unit, combined method or span normalization) over the frame's bins.
LaneUtilization lane_utilization(const PreparedFrame& frame);

}  // namespace parashade
