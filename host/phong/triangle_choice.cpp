#include "parashade/triangle_choice.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstring>
#include <memory>
#include <mutex>

#include "parashade/errors.hpp"
#include "parashade/gouraud_fit_lanes.hpp"
#include "parashade/highlight.hpp"
#include "parashade/light_bounds.hpp"
#include "parashade/light_bounds_lanes.hpp"
#include "parashade/parallel.hpp"
#include "parashade/kernels/triangle_record.h"

namespace parashade {

double gouraud_term_bound(double phi, double n, bool crosses_zero) {
  if (!(phi > 0.0)) return 0.0;
  if (!(phi < 0.5 * M_PI)) return 1.0;
  const double chord = chord_error_bound(phi, n, crosses_zero);
  // Along an edge the ends are unit normals: only normalization's non-uniform angle adds. Along a span
  // the ends are interpolations of length >= cos(phi/2), so the chord parameter is off by delta too.
  const double root = std::sqrt(1.0 / std::cos(0.5 * phi));
  const double delta = (root - 1.0) / (root + 1.0);
  const double edge = chord + angle_shift_error(nonuniform_angle(phi), n);
  const double span = chord + angle_shift_error(2.0 * delta * std::tan(0.5 * phi) + nonuniform_angle(phi), n);
  return std::min(1.0, edge + span);
}

namespace {

// The listing's selectMetod(): true = Gouraud. Light 0's direction and the view direction are taken at
// the triangle's centroid (the listing's scene has a directional light and a distant viewer).
bool sources_choose_gouraud(const Scene& s, const TriangleFrame& f, const CombinedConfig& c) {
  if (!f.usable) return false;
  const double m[3] = {glm::dot(f.n[0], f.n[1]), glm::dot(f.n[0], f.n[2]), glm::dot(f.n[1], f.n[2])};
  for (double mij : m) {
    if (c.rule == TriangleRule::sources_literal ? std::abs(mij) > c.source_m : !(mij > c.source_m)) return false;
  }
  if (s.lights.empty()) return true;
  const Light& l = s.lights[0];
  const glm::dvec3 light = glm::normalize(l.type == LightType::directional ? -glm::dvec3(l.direction)
                                                                         : glm::dvec3(l.position) - f.centroid);
  const glm::dvec3& view = f.view_centre;
  const glm::dvec3 h = light + view;  // unnormalized, as in the listing
  const auto spread = [&](const glm::dvec3& d) {
    const double a = glm::dot(f.n[0], d), b = glm::dot(f.n[1], d), e = glm::dot(f.n[2], d);
    return std::max({std::abs(a - b), std::abs(a - e), std::abs(b - e)});
  };
  return spread(h) <= c.source_q && spread(light) <= c.source_p;
}

// An increasing function tabulated on [0, hi]: at() returns the value at the next grid point at or above x,
// never less than f(x) (the bounds stay bounds). The per-triangle pass calls pow and the chord bound for
// many triangles; a lookup is ~20x cheaper.
class IncreasingTable {
 public:
  IncreasingTable() = default;
  template <typename F>
  IncreasingTable(double hi, const F& f) : step_(hi / double(kSize - 1)) {
    for (int i = 0; i < kSize; ++i) value_[i] = f(step_ * double(i));
    // A multiply instead of a divide, rounded up by far more than its two roundings: x * inverse_ is
    // never below x / step_, so the grid point found is never below x.
    inverse_ = (1.0 / step_) * (1.0 + 1e-15);
  }
  double at(double x) const {
    if (!(x > 0.0)) return value_[0];
    const double i = std::ceil(x * inverse_);
    return i < double(kSize) ? value_[std::size_t(i)] : value_[kSize - 1];
  }

 private:
  static constexpr int kSize = 1024;
  double step_ = 1.0, inverse_ = 1.0;
  std::array<double, kSize> value_{};
};

// Distance from the origin to the triangle (a, b, c): the smallest |N'| of the interpolated normals
// (Ericson, Real-Time Collision Detection 5.1.5, with the point at the origin).
double distance_to_origin(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  const glm::dvec3 ab = b - a, ac = c - a, ap = -a;
  const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return glm::length(a);
  const glm::dvec3 bp = -b;
  const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return glm::length(b);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return glm::length(a + ab * (d1 / (d1 - d3)));
  const glm::dvec3 cp = -c;
  const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return glm::length(c);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return glm::length(a + ac * (d2 / (d2 - d6)));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) return glm::length(b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))));
  const double denom = 1.0 / (va + vb + vc);
  return glm::length(a + ab * (vb * denom) + ac * (vc * denom));
}

// One light's diffuse term over a triangle whose interpolated normals N' = sum b_i n_i and light vectors
// D' = sum b_i d_i (d_i = P - w_i, or L for a directional light) are screen-linear, as in the kernel.
struct DiffuseBound {
  enum { lit, dark, crosses } state;
  double levels_unit;  // bound on |Gouraud - Phong| of max(0, N.L) (lit: docs/triangle-choice.md §2)
  double distance = 0.0;  // lit or dark: N.L stays at least this far from 0 over the triangle
};
DiffuseBound diffuse_bound(const TriangleFrame& f, double normal_chord, double min_normal, const Light& l,
                           const LightBounds& b) {
  // N'.D' = sum b_i b_j n_i.d_j: positive (negative) where every pair is.
  bool all_positive = true, all_nonpositive = true;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double v = glm::dot(f.n[i], l.type == LightType::directional ? b.light_centre : glm::dvec3(l.position) - f.w[j]);
      all_positive &= v > 0.0;
      all_nonpositive &= v <= 0.0;
    }
  // N^.L^ >= min_ij n_i.L_j (N'.D' = sum b_i b_j n_i.d_j, |N'| <= 1, |D'| <= sum b_j |d_j|), and every L_j is
  // within the light's chord of its centre: how far the triangle keeps from the terminator.
  double lowest = 1.0, highest = -1.0;
  for (int i = 0; i < 3; ++i) {
    const double v = glm::dot(f.n[i], b.light_centre);
    lowest = std::min(lowest, v);
    highest = std::max(highest, v);
  }
  const double chord = l.type == LightType::directional ? 0.0 : b.light_chord;
  if (all_nonpositive) return {DiffuseBound::dark, 0.0, std::max(0.0, -highest - chord)};
  if (!all_positive) return {DiffuseBound::crosses, 1.0, 0.0};
  // Any two L within two chords of the centroid's; the distances to the light within [dist - r, dist + r].
  const double light_chord = std::min(2.0, 2.0 * b.light_chord);
  const double rho = b.light_distance > 0.0 ? (b.light_distance + f.radius) / (b.light_distance - f.radius) : 1.0;
  const double min_light = std::sqrt(std::max(1e-6, 1.0 - light_chord * light_chord / 3.0));
  // Gouraud - Phong = [sum b_i n_i.L_i - N'.L'] + [N'.L' - N^.L'] + [N^.L' - N^.L^], L' = sum b_i L_i:
  // the first is (1/2) sum b_i b_j (n_i - n_j).(L_i - L_j), the second (N^.L')(|N'| - 1) with
  // N^.L' <= |L'| max N.L over the cones, the third
  // at most (1 - |L'|) plus the turn from reweighting L' by the distances (ratio rho).
  const double bound = normal_chord * light_chord / 3.0 + (1.0 - min_normal) * std::clamp(b.max_n_dot_l, 0.0, 1.0) +
                       (1.0 - min_light) + (rho - 1.0) * light_chord / min_light;
  return {DiffuseBound::lit, std::min(1.0, bound), std::max(0.0, lowest - chord)};
}

// What the bound rule needs of one triangle and each light, from either the scalar double reference
// (light_bounds.cpp and diffuse_bound above) or the float lanes (light_bounds_lanes.cpp).
struct LightTerms {
  double max_n_dot_h = 1.0, sin_h_radius = 1.0, chord = 2.0;
  int state = 2;  // 0 lit, 1 dark, 2 the terminator may cross
  double diffuse = 1.0, distance = 0.0;
  double h_spread() const { return sin_h_radius < 1.0 ? 2.0 * std::asin(sin_h_radius) : M_PI; }
  double l_spread() const { return chord < 2.0 ? std::min(M_PI, 4.0 * std::asin(0.5 * chord)) : M_PI; }
};
struct TriangleTerms {
  bool usable = false;
  glm::dvec3 n[3];
  double cos_spread = 1.0, min_normal = 0.0;
  LightTerms light[24];
};

void reference_terms(const Scene& s, const TriangleFrame& f, TriangleTerms& out) {
  out.usable = f.usable;
  for (int k = 0; k < 3; ++k) out.n[k] = f.n[k];
  out.cos_spread = f.cos_normal_spread;
  out.min_normal = f.usable ? distance_to_origin(f.n[0], f.n[1], f.n[2]) : 0.0;
  const double normal_chord = std::sqrt(std::max(0.0, 2.0 - 2.0 * f.cos_normal_spread));
  for (std::size_t i = 0; i < s.lights.size(); ++i) {
    const LightBounds b = light_bounds(f, s.lights[i], 2.0);  // the cone test alone: the exact one costs more than it saves
    const DiffuseBound d = diffuse_bound(f, normal_chord, out.min_normal, s.lights[i], b);
    LightTerms& l = out.light[i];
    l.max_n_dot_h = b.max_n_dot_h;
    l.sin_h_radius = b.sin_h_radius;
    l.chord = b.light_chord;
    l.state = !f.usable || d.state == DiffuseBound::crosses ? 2 : d.state == DiffuseBound::dark ? 1 : 0;
    l.diffuse = d.levels_unit;
    l.distance = d.distance;
  }
}

void lane_terms(std::size_t lights, const FrameLanes& f, const LightLanes* light, int j, TriangleTerms& out) {
  out.usable = f.usable[j] > 0.0f;
  for (int k = 0; k < 3; ++k) out.n[k] = glm::dvec3(f.n[k][0][j], f.n[k][1][j], f.n[k][2][j]);
  out.cos_spread = f.cos_spread[j];
  out.min_normal = f.min_normal[j];
  for (std::size_t i = 0; i < lights; ++i) {
    const LightLanes& b = light[i];
    LightTerms& l = out.light[i];
    l.max_n_dot_h = b.max_n_dot_h[j];
    l.sin_h_radius = b.sin_h_radius[j];
    l.chord = b.chord[j];
    l.state = int(b.state[j]);
    l.diffuse = b.diffuse[j];
    l.distance = b.terminator_distance[j];
  }
}

// Everything the choice needs of the materials and lights, not of the geometry: built once and reused
// while the scene's shading and the budget stay the same (it costs ~0.2 ms per material, serially).
struct ChoiceTables {
  std::vector<double> key;
  std::vector<float> psi;  // psi limits per material and (terminator, specular) class
  std::vector<double> thresholds;  // negligible_cosines per (material, light)
  // Levels per unit of a light's diffuse and specular term, largest channel, per (material, light).
  std::vector<double> diffuse_levels, specular_levels;
  // Per material: x^n on [0, 1], and the chord bound of the specular term (n); beyond pi/2 the bound is 1.
  std::vector<IncreasingTable> power, specular_chord;
  // The same for the lanes (gouraud_fit_lanes.hpp): the chord bound by u = sin(phi / 2).
  std::vector<LaneTable> power_lanes, specular_chord_lanes;
};

std::shared_ptr<const ChoiceTables> choice_tables(const Scene& s, const CombinedConfig& c, double shading_budget) {
  const bool bound = c.rule == TriangleRule::bound;
  std::vector<double> key = {double(bound), double(c.automatic), shading_budget, c.negligible_specular,
                             double(uses_highlight_mask(c)), double(s.materials.size()), double(s.lights.size())};
  for (const Material& m : s.materials) key.insert(key.end(), {m.shininess, m.diffuse.r, m.diffuse.g, m.diffuse.b,
                                                              m.specular.r, m.specular.g, m.specular.b});
  for (const Light& l : s.lights) key.insert(key.end(), {l.color.r, l.color.g, l.color.b});
  static std::mutex mutex;
  static std::shared_ptr<const ChoiceTables> last;
  {
    std::lock_guard<std::mutex> lock(mutex);
    if (last && last->key == key) return last;
  }
  auto t = std::make_shared<ChoiceTables>();
  t->key = std::move(key);
  // Specular terms the mask drops add up to negligible_specular each.
  const double segment_budget =
      std::max(0.0, shading_budget - (uses_highlight_mask(c) ? c.negligible_specular * double(s.lights.size()) : 0.0));
  t->psi.assign(s.materials.size() * 4, 0.0f);
  if (c.automatic)
    for (std::size_t mi = 0; mi < s.materials.size(); ++mi)
      for (int cls = 0; cls < 4; ++cls)
        t->psi[4 * mi + cls] =
            bound || cls == 3 ? float(psi_limit(s, s.materials[mi], segment_budget, {bool(cls & 1), bool(cls & 2)})) : 0.0f;
  t->thresholds = negligible_cosines(s, c.negligible_specular);
  for (const Material& m : s.materials)
    for (const Light& l : s.lights) {
      double d = 0.0, sp = 0.0;
      for (int ch = 0; ch < 3; ++ch) {
        d = std::max(d, 255.0 * double(l.color[ch]) * double(m.diffuse[ch]));
        sp = std::max(sp, 255.0 * double(l.color[ch]) * double(m.specular[ch]));
      }
      t->diffuse_levels.push_back(d);
      t->specular_levels.push_back(sp);
    }
  t->power.resize(s.materials.size());
  t->specular_chord.resize(s.materials.size());
  if (bound)
    for (std::size_t mi = 0; mi < s.materials.size(); ++mi) {
      const double n = s.materials[mi].shininess;
      t->power[mi] = IncreasingTable(1.0, [n](double x) { return std::pow(x, n); });
      t->specular_chord[mi] = IncreasingTable(0.5 * M_PI, [n](double phi) { return gouraud_term_bound(phi, n, true); });
      t->power_lanes.push_back(make_lane_table(1.0, [n](double x) { return std::pow(x, n); }));
      t->specular_chord_lanes.push_back(
          make_lane_table(kChordTableEnd, [n](double u) { return gouraud_term_bound(2.0 * std::asin(u), n, true); }));
    }
  std::lock_guard<std::mutex> lock(mutex);
  last = t;
  return t;
}

}  // namespace

TriangleChoiceStats choose_triangle_methods(const Scene& s, const ScreenGeometry& g, const CombinedConfig& c,
                                            double shading_budget, std::vector<TriangleShading>& out,
                                            ChoiceArithmetic arithmetic) {
  // The masks travel as floats in the records: exact up to 24 bits.
  if (s.lights.size() > 24) throw InputError("the per-triangle choice handles at most 24 lights");
  const std::size_t count = g.triangles.size();
  out.resize(count);
  const bool bound = c.rule == TriangleRule::bound;
  const unsigned all_lights = (1u << s.lights.size()) - 1u;
  const bool masked = uses_highlight_mask(c);
  const std::size_t lights = s.lights.size();
  const std::shared_ptr<const ChoiceTables> tables = choice_tables(s, c, shading_budget);
  const std::vector<float>& psi = tables->psi;
  const std::vector<double>& thresholds = tables->thresholds;
  const std::vector<double>&diffuse_levels = tables->diffuse_levels, &specular_levels = tables->specular_levels;
  const std::vector<IncreasingTable>&power = tables->power, &specular_chord = tables->specular_chord;
  static const IncreasingTable diffuse_chord(0.5 * M_PI, [](double phi) { return gouraud_term_bound(phi, 1.0, true); });
  const auto chord_bound = [](const IncreasingTable& t, double phi) { return phi < 0.5 * M_PI ? t.at(phi) : 1.0; };
  const int fixed_walk_width = combined_min_width(c);
  std::atomic<std::uint64_t> gouraud{0}, segments{0}, without{0}, terminator{0}, skipped{0};
  std::atomic<std::uint64_t> largest_bits{0};  // largest expected error among Gouraud triangles (double bits)
  const bool lanes = bound && arithmetic == ChoiceArithmetic::float_lanes;
  static const LaneTable diffuse_chord_lanes =
      make_lane_table(kChordTableEnd, [](double u) { return gouraud_term_bound(2.0 * std::asin(u), 1.0, true); });
  GouraudFitConstants fit_constants;
  fit_constants.lights = lights;
  fit_constants.thresholds = thresholds.data();
  fit_constants.specular_levels = specular_levels.data();
  fit_constants.diffuse_levels = diffuse_levels.data();
  fit_constants.power = tables->power_lanes.data();
  fit_constants.specular_chord = tables->specular_chord_lanes.data();
  fit_constants.diffuse_chord = &diffuse_chord_lanes;
  fit_constants.negligible_specular = float(c.negligible_specular);
  fit_constants.budget = float(shading_budget);
  parallel_for_ranges(count, 1024, [&](std::size_t first, std::size_t last) {
    std::uint64_t n_gouraud = 0, n_segments = 0, n_without = 0, n_terminator = 0, n_skipped = 0;
    double largest = 0.0;
    FrameLanes frame;
    LightLanes light[24];
    GouraudFitLanes fit;
    TriangleTerms terms;
    for (std::size_t t = first; t < last; ++t) {
      const int lane = int((t - first) % kLanes);
      if (lanes && lane == 0) {  // the next kLanes triangles' bounds and Gouraud tests at once
        frame_lanes(s, g, t, int(std::min<std::size_t>(kLanes, last - t)), frame);
        for (std::size_t i = 0; i < lights; ++i) light_lanes(frame, s.lights[i], light[i]);
        gouraud_fit_lanes(frame, light, fit_constants, fit);
      }
      TriangleShading& o = out[t];
      o = TriangleShading{};  // the vector is reused frame to frame
      const std::size_t mat = g.material[t];
      const glm::uvec3 idx = g.triangles[t];
      const double px = 1.0 / double(kSubpixel);
      const glm::dvec2 p[3] = {glm::dvec2(g.xy[idx.x]) * px, glm::dvec2(g.xy[idx.y]) * px, glm::dvec2(g.xy[idx.z]) * px};
      const double width = std::max({p[0].x, p[1].x, p[2].x}) - std::min({p[0].x, p[1].x, p[2].x});
      const double* threshold = &thresholds[mat * lights];
      // Clip-made vertices carry interpolated colours and normals: no Gouraud bound for them.
      const bool clipped = idx.x >= g.clip.size() || idx.y >= g.clip.size() || idx.z >= g.clip.size();
      unsigned mask = all_lights;
      bool fits = false;
      double expected = 0.0;
      if (!bound) {
        // The sources' listing decides Gouraud; the mask only when --highlight-test asks for it.
        const TriangleFrame f = triangle_frame(s, g, t);
        terms.usable = f.usable;
        for (int k = 0; k < 3; ++k) terms.n[k] = f.n[k];
        terms.min_normal = f.usable ? distance_to_origin(f.n[0], f.n[1], f.n[2]) : 0.0;
        if (masked && f.usable) {
          mask = 0;
          for (std::size_t i = 0; i < lights; ++i)
            if (light_bounds(f, s.lights[i], 2.0).max_n_dot_h > threshold[i]) mask |= 1u << i;
        }
        fits = c.rule != TriangleRule::none && sources_choose_gouraud(s, f, c);
      } else if (lanes) {
        mask = fit.mask[lane];
        fits = fit.fits[lane] && !clipped;
        expected = fit.expected[lane];
        terms.usable = frame.usable[lane] > 0.0f;  // the rest of terms only if the segments need it, below
      } else {
        reference_terms(s, triangle_frame(s, g, t), terms);
        double spread = -1.0;  // the normals' spread, an acos computed only if a chord bound needs it
        const auto normal_spread = [&] {
          if (spread < 0.0) spread = std::acos(std::clamp(terms.cos_spread, -1.0, 1.0));
          return spread;
        };
        if (terms.usable) {
          mask = 0;
          for (std::size_t i = 0; i < lights; ++i)
            if (terms.light[i].max_n_dot_h > threshold[i]) mask |= 1u << i;
        }
        // Expected |Gouraud - Phong| in levels, summed term by term (largest channel each), cheapest and most
        // often decisive first; a light whose specular term the mask drops adds at most negligible_specular.
        expected = c.negligible_specular * double(lights - std::size_t(__builtin_popcount(mask)));
        fits = terms.usable && !clipped && expected <= shading_budget;
        for (std::size_t i = 0; i < lights && fits; ++i) {
          if (!(mask & (1u << i))) continue;
          // Both images lie in [0, peak]: the chord bound only when the peak alone does not fit.
          const double peak = specular_levels[mat * lights + i] * power[mat].at(terms.light[i].max_n_dot_h);
          expected += expected + peak <= shading_budget
                          ? peak
                          : std::min(peak, specular_levels[mat * lights + i] *
                                               chord_bound(specular_chord[mat], normal_spread() + terms.light[i].h_spread()));
          fits = expected <= shading_budget;
        }
        for (std::size_t i = 0; i < lights && fits; ++i) {
          const LightTerms& l = terms.light[i];
          expected += diffuse_levels[mat * lights + i] *
                      (l.state == 2 ? chord_bound(diffuse_chord, normal_spread() + l.l_spread()) : l.diffuse);
          fits = expected <= shading_budget;
        }
      }
      o.specular_mask = mask;
      n_without += mask == 0;
      n_skipped += lights - std::size_t(__builtin_popcount(mask));
      if (fits) {
        o.method = TriangleMethod::gouraud;
        largest = std::max(largest, expected);
      } else if (!c.automatic) {
        o.method = width + 1.0 >= double(fixed_walk_width) ? TriangleMethod::segments : TriangleMethod::phong;
      } else if (terms.usable && c.walk_min_k <= kCombinedMaxK && width + 1.0 >= std::ldexp(2.0, c.walk_min_k)) {
        if (lanes) lane_terms(lights, frame, light, lane, terms);
        // Which terms can show decides the segment limit psi (a terminator, a highlight).
        // The segments' normals reach beyond the triangle (the last one is extrapolated, docs/combined.md):
        // the kink-free bound holds only if the terminator stays farther than the normals can turn there.
        const double reach = std::asin(std::min(1.0, double(psi[4 * mat + (mask || !bound ? 2 : 0)]))) + 1e-3;
        bool crosses_any = !bound;
        for (std::size_t i = 0; i < lights && !crosses_any; ++i)
          crosses_any = terms.light[i].state == 2 || terms.light[i].distance <= reach;
        n_terminator += crosses_any;
        const int cls = (crosses_any ? 1 : 0) | (mask || !bound ? 2 : 0);
        o.psi_limit = psi[4 * mat + cls];
        // The segment length the kernel can use on this triangle: |dN/dx| 2^K <= psi min|N'|.
        const glm::dvec2 e1 = p[1] - p[0], e2 = p[2] - p[0];
        const double det = e1.x * e2.y - e2.x * e1.y;
        const glm::dvec3 ddx = ((terms.n[1] - terms.n[0]) * e2.y - (terms.n[2] - terms.n[0]) * e1.y) * (1.0 / det);
        const double allowed = double(o.psi_limit) * terms.min_normal, change = glm::length(ddx);
        int k = 0;
        while (k < kCombinedMaxK && change * double(2 << k) <= allowed) ++k;
        o.method = k >= c.walk_min_k && width + 1.0 >= double(2 << k) ? TriangleMethod::segments : TriangleMethod::phong;
      } else {
        o.method = TriangleMethod::phong;
      }
      n_gouraud += o.method == TriangleMethod::gouraud;
      n_segments += o.method == TriangleMethod::segments;
    }
    gouraud += n_gouraud;
    segments += n_segments;
    without += n_without;
    terminator += n_terminator;
    skipped += n_skipped;
    // A positive double's bits order like the double: an atomic max on the bits.
    std::uint64_t bits, seen = largest_bits.load();
    std::memcpy(&bits, &largest, sizeof bits);
    while (bits > seen && !largest_bits.compare_exchange_weak(seen, bits)) {
    }
  });
  TriangleChoiceStats st;
  st.triangles = count;
  st.gouraud = gouraud.load();
  st.segments = segments.load();
  st.without_highlight = without.load();
  st.terminator = terminator.load();
  st.light_terms_skipped = skipped.load();
  const std::uint64_t bits = largest_bits.load();
  std::memcpy(&st.largest_expected_levels, &bits, sizeof bits);
  return st;
}

void apply_triangle_choice(const std::vector<TriangleShading>& choice, float* attributes, std::size_t stride) {
  for (std::size_t t = 0; t < choice.size(); ++t) {
    float* a = attributes + t * stride;
    a[PHONG_HIGHLIGHT_SLOT] = float(choice[t].specular_mask);
    a[PHONG_METHOD_SLOT] = float(int(choice[t].method));
    a[PHONG_PSI_SLOT] = choice[t].psi_limit;
  }
}

}  // namespace parashade
