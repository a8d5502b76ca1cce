#pragma once
// The light bounds of light_bounds.hpp for kLanes triangles at once, in float, as structures of arrays:
// the per-triangle choice's hot path (triangle_choice.cpp) and the highlight test (highlight.cpp). The
// per-triangle part is a branch-free loop the compiler vectorizes, the per-light part is written on
// vector types (lane_vectors.hpp); the scalar double version in light_bounds.cpp stays the readable
// reference (tests compare the two). Float rounding is covered by small margins that only ever make a
// bound more conservative.
#include <cstddef>
#include <cstdint>

#include "parashade/scene.hpp"
#include "parashade/screen_geometry.hpp"

namespace parashade {

constexpr int kLanes = 8;

// Triangles first .. first + count - 1 of a frame (count <= kLanes; unused lanes hold a harmless copy).
struct FrameLanes {
  int count = 0;
  float n[3][3][kLanes];        // unit vertex normals [vertex][component][lane]
  float w[3][3][kLanes];        // world positions
  std::uint32_t material[kLanes];  // the triangles' material indices
  float usable[kLanes];         // 1: bounds apply (as TriangleFrame::usable), 0: not
  float cos_spread[kLanes];     // at most the cosine of the largest angle between two vertex normals
  float normal_centre[3][kLanes], cos_half[kLanes], sin_half[kLanes];  // the normals' cone (cos_half <= 0: none)
  float centroid[3][kLanes], radius[kLanes];
  float view[3][kLanes], view_chord[kLanes];
  float min_normal[kLanes];     // distance from the origin to the triangle of normal tips (min |N'|)
};
void frame_lanes(const Scene& s, const ScreenGeometry& g, std::size_t first, int count, FrameLanes& f);

// One light over the lanes' triangles (light_bounds and the choice's diffuse bound, docs/triangle-choice.md §2).
struct LightLanes {
  float chord[kLanes];          // |L(p) - L at the centroid| <= chord
  float max_n_dot_h[kLanes];
  float sin_h_radius[kLanes];   // H within asin(this) of one direction (1: no bound)
  float half_min[kLanes];       // |L + V| >= this over the triangle (0: no bound)
  float state[kLanes];          // 0 lit everywhere, 1 dark everywhere, 2 the terminator may cross
  float diffuse[kLanes];        // lit: bound on |Gouraud - Phong| of the diffuse term (0 dark, 1 crosses)
  float terminator_distance[kLanes];  // lit or dark: N.L stays at least this far from 0
};
void light_lanes(const FrameLanes& f, const Light& l, LightLanes& out);

// light_lanes and gouraud_fit_lanes run on eight-float vectors where the CPU has AVX2, else on four
// (lane_vectors.hpp); both give the same bits. true: four everywhere, so that a test can compare the two
// (not while a choice runs).
void four_float_lanes_only(bool only);

}  // namespace parashade
