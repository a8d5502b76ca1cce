#include "parashade/highlight.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>

#include "parashade/parallel.hpp"

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

// A cone (unit centre, half-angle) holding the conic hull of three unit directions: centre the
// normalized sum, half-angle the largest angle to a direction; half-angle > pi/2 means no useful cone.
struct Cone {
  glm::dvec3 centre;
  double half_angle;
};
Cone cone_of(const glm::dvec3 d[3]) {
  const glm::dvec3 sum = d[0] + d[1] + d[2];
  const double len = glm::length(sum);
  if (!(len > 1e-12)) return {glm::dvec3(0, 0, 1), M_PI};
  const glm::dvec3 c = sum / len;
  double a = 0.0;
  for (int k = 0; k < 3; ++k) a = std::max(a, std::acos(std::clamp(glm::dot(c, d[k]), -1.0, 1.0)));
  return {c, a};
}

glm::dvec3 unit(const glm::dvec3& v) { return v / glm::length(v); }

}  // namespace

HighlightMarks mark_highlights(const Scene& s, const ScreenGeometry& g, float* attributes, std::size_t stride, int slot,
                               double negligible_levels) {
  const bool distant_viewer = !(s.local_viewer && s.camera.projection == Projection::perspective);
  const glm::dvec3 eye(s.camera.position), view = unit(glm::dvec3(s.camera.position - s.camera.target));
  std::atomic<std::uint64_t> without{0}, skipped{0};
  parallel_for_ranges(g.triangles.size(), 2048, [&](std::size_t first, std::size_t last) {
  std::uint64_t range_without = 0, range_skipped = 0;
  for (std::size_t t = first; t < last; ++t) {
    const glm::uvec3 idx = g.triangles[t];
    const std::uint32_t vid[3] = {idx.x, idx.y, idx.z};
    bool usable = true;
    glm::dvec3 n[3], w[3];
    for (int k = 0; k < 3; ++k) {
      const glm::dvec3 raw(g.normal[vid[k]]);
      const double len = glm::length(raw);
      usable = usable && len > 1e-12 && std::isfinite(len);
      n[k] = usable ? raw / len : glm::dvec3(0.0);
      w[k] = vid[k] < g.world.size() ? glm::dvec3(g.world[vid[k]]) : glm::dvec3(0.0);
    }
    usable = usable && (distant_viewer || g.world.size() == g.normal.size());
    // The shaded points are convex combinations of the vertices, so V(p) and a point light's L(p) lie in
    // the conic hulls of their vertex values.
    glm::dvec3 vd[3];
    for (int k = 0; k < 3; ++k) vd[k] = distant_viewer ? view : unit(eye - w[k]);
    const Cone vc = cone_of(vd);
    const Material& m = s.materials[g.material[t]];
    unsigned mask = 0;
    for (std::size_t i = 0; i < s.lights.size(); ++i) {
      const Light& l = s.lights[i];
      bool needed = true;
      if (usable) {
        glm::dvec3 ld[3];
        for (int k = 0; k < 3; ++k)
          ld[k] = l.type == LightType::directional ? -unit(glm::dvec3(l.direction)) : unit(glm::dvec3(l.position) - w[k]);
        const Cone lc = cone_of(ld);
        // |(L + V) - (c_L + c_V)| <= 2 sin(a_L/2) + 2 sin(a_V/2), so H is within asin(that / |c_L + c_V|) of
        // H_c = normalize(c_L + c_V).
        const glm::dvec3 sum = lc.centre + vc.centre;
        const double ratio = (2 * std::sin(0.5 * lc.half_angle) + 2 * std::sin(0.5 * vc.half_angle)) / glm::length(sum);
        if (lc.half_angle < M_PI / 2 && vc.half_angle < M_PI / 2 && ratio < 1.0) {
          const double spread = std::asin(ratio);
          const double distance =
              std::acos(std::clamp(max_cosine_over_normals(n[0], n[1], n[2], unit(sum)), -1.0, 1.0));
          const double cosine = distance > spread ? std::cos(distance - spread) : 1.0;
          double peak = 0.0;
          for (int c = 0; c < 3; ++c) peak = std::max(peak, 255.0 * double(l.color[c]) * double(m.specular[c]));
          needed = cosine > 0.0 && peak * std::pow(cosine, double(m.shininess)) > negligible_levels;
        }
      }
      if (needed) mask |= 1u << i;
      else ++range_skipped;
    }
    attributes[t * stride + slot] = float(mask);
    range_without += mask == 0;
  }
  without += range_without;
  skipped += range_skipped;
  });
  return {g.triangles.size(), without.load(), skipped.load()};
}

}  // namespace parashade
