#pragma once
// Setup for the extra-triangulation unit (host/units/sierpinski_setup.cpp; its records:
// kernels/sierpinski_leaf.h; the unit: kernels/units/sierpinski.h, host/units/sierpinski.cpp): vertex
// parity normalization (the sources' remedy (a) for midpoints off the pixel grid) and the split of every
// triangle's setup records into its 4^D sub-triangle records.
#include <cstddef>
#include <cstdint>

#include "parashade/screen_geometry.hpp"
#include "parashade/units.hpp"
#include "parashade/kernels/fixed_point.h"
#include "parashade/kernels/sierpinski_leaf.h"
#include "parashade/kernels/triangle_record.h"

namespace parashade {

// Moves every vertex to the nearest pixel corner whose pixel coordinates are 0 (or, with `odd`, 1)
// modulo 2^depth, so that all midpoints down to depth D fall on pixel corners; intensities unchanged.
// A vertex moves at most 2^(depth-1) pixels each way. Triangles that this makes degenerate or flips
// are dropped from g.triangles (with their material and flat colour); returns how many.
std::uint64_t normalize_vertex_parity(ScreenGeometry& g, int depth, bool odd);

// The vertex move of the unit's grid (UnitConfig::grid): remedy (a) normalize_vertex_parity; remedy (b)
// the nearest pixel corner (depth 0). Returns the triangles dropped.
std::uint64_t snap_sierpinski_vertices(ScreenGeometry& g, const UnitConfig& unit);

// Splits screen triangle records (setup_triangles on the snapped geometry) into 4^D sub-triangle records
// each, in primitive order, the shaded one first: out[t * 4^D + k]. fixed_in/fixed_out may be null (float
// arithmetic); attributes are Gouraud's. Every record is the shaded sub-triangle translated by whole
// pixels or point-reflected, so a copy covers exactly the mapped pixels of the shaded one.
// The sub-triangle's shape halves the triangle's level by level, relative to its top vertex: exactly
// (remedy (a); throws std::logic_error if a half is not whole pixels), or, remedy (b), rounded toward the
// top vertex (touch: corner copies start at the rounded midpoints, so an odd edge comes out one pixel
// short) or away from it (overlap: corner copies end at the vertices, and meet their neighbours
// one pixel deep). With `seal`, a reflected copy decides pixel centres on its edges by its own top-left
// rule (the mirror image of the rule is the bottom-right rule, which leaves the midlines it shares with
// translated copies covered twice or not at all). A triangle whose rounded sub-triangle is degenerate is
// shaded whole (its first record is its own, the others empty); returns how many were.
std::uint64_t split_sierpinski(const ScreenGeometry& g, const UnitConfig& unit, const TriangleGeometry* in,
                               const float* attr_in, const FixedPlanes* fixed_in, TriangleGeometry* out,
                               float* attr_out, FixedPlanes* fixed_out, SierpinskiLeaf* leaf_out);

}  // namespace parashade
