#pragma once
// `--coverage dda`: the sources' edge-walking rasterization instead of pixel-centre sampling. Every vertex
// goes to the pixel that holds it (a 12-bit pixel address), each edge is walked by the line interpolator
// (include/parashade/edge_dda.hpp), and each row is filled between its leftmost and rightmost edge pixel.
// Records keep their planes (re-anchored at the new box corner); their spans come from a row table the
// kernels read instead of evaluating edge functions (which are zeroed, so binning takes the whole box).
#include <cstdint>
#include <vector>

#include "parashade/screen_geometry.hpp"
#include "parashade/kernels/fixed_point.h"
#include "parashade/kernels/triangle_record.h"

namespace parashade {

struct DdaRowTable {
  std::vector<std::uint32_t> first;  // per record: index of its first row in `rows`
  std::vector<std::int32_t> rows;    // per row from the record's y0 to y1: xl, xr relative to its x0 (xl > xr: empty)
};

// Rewrites Gouraud records made by setup_triangles (fixed may be null) for DDA coverage. Triangles that
// cover no pixel centre have no planes from setup and stay empty. Returns the row table.
DdaRowTable apply_dda_coverage(const ScreenGeometry& g, TriangleGeometry* records, float* attrs, FixedPlanes* fixed);

}  // namespace parashade
