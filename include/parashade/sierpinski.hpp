#pragma once
// Setup for the extra-triangulation unit (kernels/sierpinski_leaf.h): vertex parity normalization
// (the sources' remedy (a) for midpoints off the pixel grid) and the split of every triangle's setup
// records into its 4^D sub-triangle records.
#include <cstddef>
#include <cstdint>

#include "parashade/screen_geometry.hpp"
#include "fixed_point.h"
#include "sierpinski_leaf.h"
#include "triangle_record.h"

namespace parashade {

// Moves every vertex to the nearest pixel corner whose pixel coordinates are 0 (or, with `odd`, 1)
// modulo 2^depth, so that all midpoints down to depth D fall on pixel corners; intensities unchanged.
// A vertex moves at most 2^(depth-1) pixels each way. Triangles that this makes degenerate or flips
// are dropped from g.triangles (with their material and flat colour); returns how many.
std::uint64_t normalize_vertex_parity(ScreenGeometry& g, int depth, bool odd);

// Splits screen triangle records (setup_triangles on the normalized geometry) into 4^depth sub-triangle
// records each, in primitive order, the shaded one first: out[t * 4^depth + k]. fixed_in/fixed_out may
// be null (float arithmetic); attributes are Gouraud's. A copy covers exactly the mapped pixels of the
// shaded sub-triangle; with `seal`, a reflected copy decides pixel centres on its edges by its own
// top-left rule (the mirror image of the rule is the bottom-right rule, which leaves the midlines it
// shares with translated copies covered twice or not at all). Throws std::logic_error if the geometry
// is not normalized for `depth`.
void split_sierpinski(const ScreenGeometry& g, int depth, bool seal, const TriangleGeometry* in, const float* attr_in,
                      const FixedPlanes* fixed_in, TriangleGeometry* out, float* attr_out, FixedPlanes* fixed_out,
                      SierpinskiLeaf* leaf_out);

}  // namespace parashade
