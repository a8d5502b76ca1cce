#include "parashade/light_bounds.hpp"

#include <algorithm>
#include <cmath>

namespace parashade {
namespace {

// max of N.h over the great arc from unit a to unit b (shorter arc; a, b not opposite).
double max_on_arc(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& h) {
  double best = std::max(glm::dot(a, h), glm::dot(b, h));
  const glm::dvec3 axis = glm::cross(a, b);
  const double axis2 = glm::dot(axis, axis);
  if (axis2 < 1e-12) return glm::dot(a, b) > 0 ? best : 1.0;  // equal ends; nearly opposite: no bound
  const glm::dvec3 p = h - axis * (glm::dot(h, axis) / axis2);  // h projected on the arc's plane
  const double len = glm::length(p);
  if (len < 1e-300) return best;
  const glm::dvec3 q = p / len;
  // q lies on the arc when it is a non-negative combination of a and b.
  if (glm::dot(glm::cross(a, q), axis) >= 0 && glm::dot(glm::cross(q, b), axis) >= 0) best = std::max(best, len);
  return best;
}

glm::dvec3 unit(const glm::dvec3& v) { return v * (1.0 / glm::length(v)); }

double angle(double cosine) { return std::acos(std::clamp(cosine, -1.0, 1.0)); }

}  // namespace

double max_cosine_over_normals(const glm::dvec3& n0, const glm::dvec3& n1, const glm::dvec3& n2, const glm::dvec3& h) {
  // h inside the cone of the three normals: h = sum c_i n_i with all c_i >= 0 (Cramer's rule).
  const double det = glm::dot(n0, glm::cross(n1, n2));
  if (std::abs(det) > 1e-12) {
    const double c0 = glm::dot(h, glm::cross(n1, n2)) / det, c1 = glm::dot(n0, glm::cross(h, n2)) / det,
                 c2 = glm::dot(n0, glm::cross(n1, h)) / det;
    if (c0 >= 0 && c1 >= 0 && c2 >= 0) return 1.0;
  }
  return std::max({max_on_arc(n0, n1, h), max_on_arc(n1, n2, h), max_on_arc(n2, n0, h)});
}

namespace {

double sine_of(double cosine) { return std::sqrt(std::max(0.0, 1.0 - cosine * cosine)); }
// A chord c between unit vectors is the angle 2 asin(c/2).
double chord_angle(double chord) { return chord < 2.0 ? 2.0 * std::asin(0.5 * chord) : M_PI; }

// Largest N.D for N in the normals' cone and D within the angle beta (sin beta = sin_radius, beta < pi/2)
// of the unit d: cos(gap), gap = angle(c_N, d) - a_N - beta, when positive; else 1. By cosines: no acos.
double max_cosine_between_cones(const TriangleFrame& f, const glm::dvec3& d, double sin_radius) {
  if (!(f.normal_cos_half > 0.0) || !(sin_radius < 1.0)) return 1.0;
  const double cos_n = f.normal_cos_half, sin_n = f.normal_sin_half;
  const double cos_b = sin_radius > 0.0 ? std::sqrt(1.0 - sin_radius * sin_radius) : 1.0;
  const double cos_r = cos_n * cos_b - sin_n * sin_radius, sin_r = sin_n * cos_b + cos_n * sin_radius;  // a_N + beta
  const double cos_t = glm::dot(f.normal_centre, d);
  if (!(cos_t < cos_r)) return 1.0;  // the gap is not positive
  return cos_t * cos_r + sine_of(cos_t) * sin_r;
}

}  // namespace

double TriangleFrame::normal_spread() const { return angle(cos_normal_spread); }
double LightBounds::l_spread() const { return std::min(M_PI, 2.0 * chord_angle(light_chord)); }
double LightBounds::h_spread() const { return sin_h_radius < 1.0 ? 2.0 * std::asin(sin_h_radius) : M_PI; }

TriangleFrame triangle_frame(const Scene& s, const ScreenGeometry& g, std::size_t t) {
  TriangleFrame f;
  const bool distant_viewer = !s.viewer_is_local();
  const glm::uvec3 idx = g.triangles[t];
  const std::uint32_t vid[3] = {idx.x, idx.y, idx.z};
  f.usable = distant_viewer || g.world.size() == g.normal.size();
  for (int k = 0; k < 3; ++k) {
    glm::dvec3 n(g.normal[vid[k]]);
    const double len2 = glm::dot(n, n);
    // Scene vertices carry unit normals (to float precision); clip-made ones are interpolations.
    if (std::abs(len2 - 1.0) > 1e-6) n *= 1.0 / std::sqrt(len2);
    f.usable = f.usable && len2 > 1e-24 && std::isfinite(len2);
    f.n[k] = f.usable ? n : glm::dvec3(0.0);
    f.w[k] = vid[k] < g.world.size() ? glm::dvec3(g.world[vid[k]]) : glm::dvec3(0.0);
  }
  f.cos_normal_spread = std::min({glm::dot(f.n[0], f.n[1]), glm::dot(f.n[1], f.n[2]), glm::dot(f.n[2], f.n[0])});
  const glm::dvec3 sum = f.n[0] + f.n[1] + f.n[2];
  const double len = glm::length(sum);
  if (len > 1e-12) {
    f.normal_centre = sum * (1.0 / len);
    f.normal_cos_half = std::min({glm::dot(f.normal_centre, f.n[0]), glm::dot(f.normal_centre, f.n[1]),
                                  glm::dot(f.normal_centre, f.n[2])});
    f.normal_sin_half = sine_of(f.normal_cos_half);
  }
  f.centroid = (f.w[0] + f.w[1] + f.w[2]) / 3.0;
  f.radius = std::sqrt(std::max({glm::dot(f.w[0] - f.centroid, f.w[0] - f.centroid),
                                 glm::dot(f.w[1] - f.centroid, f.w[1] - f.centroid),
                                 glm::dot(f.w[2] - f.centroid, f.w[2] - f.centroid)}));
  if (distant_viewer) {
    f.view_centre = unit(glm::dvec3(s.camera.position - s.camera.target));
  } else {
    const glm::dvec3 d = glm::dvec3(s.camera.position) - f.centroid;
    const double dist = glm::length(d);
    const double inv = 1.0 / dist;
    f.view_centre = dist > 0.0 ? d * inv : glm::dvec3(0.0, 0.0, 1.0);
    f.view_chord = dist > 0.0 ? std::min(2.0, 2.0 * f.radius * inv) : 2.0;
  }
  return f;
}

LightBounds light_bounds(const TriangleFrame& f, const Light& l, double enough) {
  LightBounds b;
  if (!f.usable) return b;
  if (l.type == LightType::directional) {
    b.light_centre = -unit(glm::dvec3(l.direction));
    b.light_chord = 0.0;
  } else {
    const glm::dvec3 d = glm::dvec3(l.position) - f.centroid;
    const double dist = glm::length(d);
    if (!(dist > 2.0 * f.radius)) return b;  // the light within the triangle's reach: no useful bound
    const double inv = 1.0 / dist;
    b.light_centre = d * inv;
    b.light_chord = 2.0 * f.radius * inv;
    b.light_distance = dist;
  }
  // L is within the angle 2 asin(chord/2) of c_L, whose sine is chord sqrt(1 - chord^2/4).
  b.max_n_dot_l = max_cosine_between_cones(f, b.light_centre,
                                           b.light_chord * std::sqrt(std::max(0.0, 1.0 - 0.25 * b.light_chord * b.light_chord)));
  // |(L + V) - (c_L + c_V)| <= chord_L + chord_V, so H is within asin(that / |c_L + c_V|) of
  // H_c = normalize(c_L + c_V).
  const glm::dvec3 sum = b.light_centre + f.view_centre;
  const double sum_len = glm::length(sum);
  const double inv_sum = 1.0 / sum_len, ratio = (b.light_chord + f.view_chord) * inv_sum;
  if (!(ratio < 1.0)) return b;
  b.sin_h_radius = ratio;
  b.half_min = sum_len - (b.light_chord + f.view_chord);
  const glm::dvec3 hc = sum * inv_sum;
  // Cheap first: the normals' cone against H's cone.
  b.max_n_dot_h = max_cosine_between_cones(f, hc, ratio);
  if (b.max_n_dot_h <= enough || !(f.normal_cos_half > 0.0)) return b;
  const double distance = angle(max_cosine_over_normals(f.n[0], f.n[1], f.n[2], hc));
  const double spread = std::asin(ratio);
  b.max_n_dot_h = std::min(b.max_n_dot_h, distance > spread ? std::cos(distance - spread) : 1.0);
  return b;
}

}  // namespace parashade
