#pragma once
// Bounds of the lighting terms over one screen triangle (docs/combined.md §5, docs/triangle-choice.md).
// The shaded normals are normalize(b0 n0 + b1 n1 + b2 n2), b >= 0: they fill the spherical triangle of
// the unit vertex normals, inside the cone around their normalized sum. With a point light or a local
// viewer L and V vary too: every shaded point p lies within `radius` of the triangle's centroid c, and
// |unit(E - p) - unit(E - c)| <= 2 |p - c| / |E - c| for any eye or light position E, so L and V stay
// within a chord of their directions at the centroid. Kept cheap on purpose: the per-triangle method
// choice (triangle_choice.hpp) runs this for every triangle of every frame.
// Used by the highlight-presence test (highlight.hpp) and the per-triangle method choice.
#include <cstddef>

#include <glm/glm.hpp>

#include "parashade/scene.hpp"
#include "parashade/screen_geometry.hpp"

namespace parashade {

// One triangle's unit vertex normals and world positions, the cone of its normals (centre, cosine of the
// half-angle) and the viewer's direction over it (centre, chord).
struct TriangleFrame {
  glm::dvec3 n[3], w[3];
  bool usable = false;  // false: a zero or non-finite vertex normal, or no world positions for a local viewer
  glm::dvec3 normal_centre{0.0, 0.0, 1.0};
  double normal_cos_half = -1.0;    // every shaded normal N has N.normal_centre >= this (<= 0: no useful cone)
  double normal_sin_half = 1.0;
  double cos_normal_spread = 1.0;   // cosine of the largest angle between two vertex normals
  glm::dvec3 centroid{0.0};
  double radius = 0.0;              // every point of the triangle is within this of the centroid (world)
  glm::dvec3 view_centre{0.0, 0.0, 1.0};
  double view_chord = 0.0;          // |V(p) - view_centre| <= this (0 for a distant viewer)
  double normal_spread() const;     // largest angle between two vertex normals (radians)
};
TriangleFrame triangle_frame(const Scene& s, const ScreenGeometry& g, std::size_t t);

// One light over one triangle: every shaded point's N.H is at most max_n_dot_h; |L(p) - light_centre| <=
// light_chord; H stays within asin(sin_h_radius) of one direction. When the triangle is not usable, or the
// chords are too wide, the bounds are the trivial ones (1, chord 2, radius pi/2).
struct LightBounds {
  double max_n_dot_h = 1.0;
  double max_n_dot_l = 1.0;     // every shaded point's N.L is at most this (the normals' cone against L's)
  glm::dvec3 light_centre{0.0, 0.0, 1.0};
  double light_chord = 2.0;
  double light_distance = 0.0;  // point light: from the centroid (0 for a directional light)
  double sin_h_radius = 1.0;
  double half_min = 0.0;        // |L + V| >= this over the triangle (0: no bound)
  double l_spread() const;  // largest angle between two L over the triangle
  double h_spread() const;  // largest angle between two H over the triangle
};
// `enough`: the caller only needs to know whether max N.H <= enough; the cheap cone-against-cone bound is
// returned when it already shows that, else the tighter bound over the spherical triangle of normals.
LightBounds light_bounds(const TriangleFrame& f, const Light& l, double enough = 1.0);

// max over N = normalize(b0 n0 + b1 n1 + b2 n2), b >= 0, of N.h (n0..n2 and h unit vectors). The maximum
// is at a vertex, on an edge's great arc (where h's projection on the arc's plane falls between its
// ends), or 1 when h itself lies in the spherical triangle.
double max_cosine_over_normals(const glm::dvec3& n0, const glm::dvec3& n1, const glm::dvec3& n2, const glm::dvec3& h);

}  // namespace parashade
