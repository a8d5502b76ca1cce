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
#include "parashade/moving_direction_bound.hpp"
#include "parashade/parallel.hpp"
#include "parashade/kernels/triangle_record.h"

namespace parashade {

// The lights' masks travel as floats in the records: exact up to 24 bits, so at most 24 lights (the
// per-triangle arrays below are sized by it).
constexpr std::size_t kChoiceMaxLights = 24;

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
  double max_n_dot_h = 1.0, sin_h_radius = 1.0, chord = 2.0, half_min = 0.0;
  int state = 2;  // 0 lit, 1 dark, 2 the terminator may cross
  double diffuse = 1.0, distance = 0.0;
  double h_spread() const { return sin_h_radius < 1.0 ? 2.0 * std::asin(sin_h_radius) : M_PI; }
  double l_spread() const { return chord < 2.0 ? std::min(M_PI, 4.0 * std::asin(0.5 * chord)) : M_PI; }
};
struct TriangleTerms {
  bool usable = false;
  glm::dvec3 n[3];
  double cos_spread = 1.0, min_normal = 0.0, view_chord = 0.0;
  LightTerms light[kChoiceMaxLights];
};

void reference_terms(const Scene& s, const TriangleFrame& f, TriangleTerms& out) {
  out.usable = f.usable;
  for (int k = 0; k < 3; ++k) out.n[k] = f.n[k];
  out.cos_spread = f.cos_normal_spread;
  out.view_chord = f.view_chord;
  out.min_normal = f.usable ? distance_to_origin(f.n[0], f.n[1], f.n[2]) : 0.0;
  const double normal_chord = std::sqrt(std::max(0.0, 2.0 - 2.0 * f.cos_normal_spread));
  for (std::size_t i = 0; i < s.lights.size(); ++i) {
    const LightBounds b = light_bounds(f, s.lights[i], 2.0);  // the cone test alone: the exact one costs more than it saves
    const DiffuseBound d = diffuse_bound(f, normal_chord, out.min_normal, s.lights[i], b);
    LightTerms& l = out.light[i];
    l.max_n_dot_h = b.max_n_dot_h;
    l.sin_h_radius = b.sin_h_radius;
    l.chord = b.light_chord;
    l.half_min = b.half_min;
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
  out.view_chord = f.view_chord[j];
  for (std::size_t i = 0; i < lights; ++i) {
    const LightLanes& b = light[i];
    LightTerms& l = out.light[i];
    l.max_n_dot_h = b.max_n_dot_h[j];
    l.sin_h_radius = b.sin_h_radius[j];
    l.chord = b.chord[j];
    l.half_min = b.half_min[j];
    l.state = int(b.state[j]);
    l.diffuse = b.diffuse[j];
    l.distance = b.terminator_distance[j];
  }
}

// Gouraud's error of one specular term where H moves over the triangle (docs/triangle-choice.md §2): at a
// point b, Gouraud - Phong = sum_i b_i (g(x_i) - g(b) - g'(b).(x_i - b)), each at most half the largest g''
// along the line from b to vertex i, whose rates are moving_term_bound's with the change |x_i - b|;
// sum_i b_i |x_i - b|^2 <= (longest edge)^2 / 3, so the error is at most (1/6)(w^2 P(n) + a S(n)) with the
// rates of a change as long as the longest edge: the normals' chord over min|N'|, and 2r / (d - r) for L
// and V (r the triangle's radius, d the distance from its centroid). 1 where no bound applies.
double gouraud_moving_specular(const TriangleTerms& terms, const LightTerms& l, double curvature, double slope) {
  if (!(curvature > 0.0) || !(terms.min_normal > 0.0) || !(l.half_min > 0.0) || !(l.chord < 2.0) || !(terms.view_chord < 2.0))
    return 1.0;
  const double c_n = std::sqrt(std::max(0.0, 2.0 - 2.0 * terms.cos_spread));
  const double rate_n = c_n / terms.min_normal;
  const double rate_l = 2.0 * l.chord / (2.0 - l.chord), rate_v = 2.0 * terms.view_chord / (2.0 - terms.view_chord);
  const double rate_h = (rate_l + rate_v) / l.half_min;
  const double accel_h = (std::sqrt(5.0) * (rate_l * rate_l + rate_v * rate_v) + 2.0 * rate_h * (rate_l + rate_v)) / l.half_min;
  const double w = rate_n + rate_h, a = 2.0 * rate_n * rate_n + accel_h;
  return std::min(1.0, (w * w * curvature + a * slope) / 6.0);
}

// combined:auto with a point light or a local viewer (L or H moves along a segment, docs/combined.md §2b):
// the largest psi for which moving_term_bound, summed over the lights' terms, fits `budget` levels for any
// K the kernel takes with it. The kernel's K keeps |dN'/dx| 2^K <= psi min|N'| (so the normal turns at most
// psi per segment) and 2^K <= 64, and min|N'| <= |N'(xl)| <= 1, so a segment moves the shaded point by at
// most |dp/dx| psi / |dN'/dx|: every rate is psi times a rate per unit of psi, and the bound is
// psi^2 quad + psi lin (lin: the kink of a diffuse term whose terminator the segments may reach).
// The points reach up to 64 pixels past the triangle (the extrapolated last segment): distances to the
// light and the eye are taken from there. 0 when no psi fits (no bound: Phong per pixel).
struct MovingLimit {
  double psi = 0.0;
  bool terminator = false;  // a light's terminator is within the segments' reach
};
MovingLimit moving_psi_limit(const Scene& s, const ScreenGeometry& g, std::size_t t, const TriangleTerms& terms,
                             unsigned mask, double budget, const double* diffuse_levels, const double* specular_levels,
                             double curvature, double slope, double normal_rate, const glm::dvec3& position_rate) {
  MovingLimit out;
  const glm::uvec3 idx = g.triangles[t];
  if (g.world.size() != g.normal.size() || !(budget > 0.0)) return out;
  const glm::dvec3 w[3] = {glm::dvec3(g.world[idx.x]), glm::dvec3(g.world[idx.y]), glm::dvec3(g.world[idx.z])};
  const glm::dvec3 centroid = (w[0] + w[1] + w[2]) / 3.0;
  double radius = 0.0;
  for (const glm::dvec3& p : w) radius = std::max(radius, glm::length(p - centroid));
  const double step = glm::length(position_rate);  // world distance per pixel along a row
  const double reach = (radius + double(1 << kCombinedMaxK) * step) * (1.0 + 1e-6) + 1e-9;
  // World distance a segment spans per unit of psi (the normal plane constant along rows: any K, so 64 px).
  const bool flat_rows = !(normal_rate > 1e-9);
  const double per_psi = flat_rows ? 0.0 : step / normal_rate;
  const double fixed_move = flat_rows ? double(1 << kCombinedMaxK) * step : 0.0;
  const bool distant_viewer = !s.viewer_is_local();
  glm::dvec3 view_centre;
  double view_chord = 0.0, view_distance = INFINITY;
  if (distant_viewer) {
    view_centre = glm::normalize(glm::dvec3(s.camera.position - s.camera.target));
  } else {
    const glm::dvec3 d = glm::dvec3(s.camera.position) - centroid;
    const double dist = glm::length(d);
    if (!(dist > 2.0 * reach)) return out;
    view_centre = d / dist;
    view_chord = 2.0 * reach / dist;
    view_distance = dist - reach;
  }
  const std::size_t lights = s.lights.size();
  struct Term {
    SegmentRates per_psi, fixed;  // rates per unit of psi, and the part that does not shrink with psi
    double diffuse_levels, specular_levels, distance;
    int state;
    bool specular;
  };
  Term term[kChoiceMaxLights];
  for (std::size_t i = 0; i < lights; ++i) {
    const Light& l = s.lights[i];
    glm::dvec3 light_centre;
    double light_chord = 0.0, light_distance = INFINITY;
    if (l.type == LightType::directional) {
      light_centre = -glm::normalize(glm::dvec3(l.direction));
    } else {
      const glm::dvec3 d = glm::dvec3(l.position) - centroid;
      const double dist = glm::length(d);
      if (!(dist > 2.0 * reach)) return out;
      light_centre = d / dist;
      light_chord = 2.0 * reach / dist;
      light_distance = dist - reach;
    }
    Term& k = term[i];
    k.per_psi.normal = 1.0;
    k.per_psi.light = per_psi / light_distance;
    k.per_psi.view = per_psi / view_distance;
    k.fixed.light = fixed_move / light_distance;
    k.fixed.view = fixed_move / view_distance;
    k.per_psi.half_min = k.fixed.half_min = glm::length(light_centre + view_centre) - light_chord - view_chord;
    k.diffuse_levels = diffuse_levels[i];
    k.specular_levels = specular_levels[i];
    k.state = terms.light[i].state;
    k.distance = terms.light[i].distance;
    k.specular = (mask >> i) & 1u;
  }
  // The bound at psi (every rate scaled, plus the fixed part of flat rows): a quadratic in psi.
  const auto scaled = [](const SegmentRates& a, const SegmentRates& b, double psi) {
    SegmentRates r;
    r.normal = a.normal * psi + b.normal;
    r.light = a.light * psi + b.light;
    r.view = a.view * psi + b.view;
    r.half_min = a.half_min;
    return r;
  };
  const auto error_at = [&](double psi, bool crossing_every_lit) {
    double e = 0.0;
    for (std::size_t i = 0; i < lights; ++i) {
      const Term& k = term[i];
      const SegmentRates r = scaled(k.per_psi, k.fixed, psi);
      const bool cross = k.state == 2 || crossing_every_lit;
      if (k.state != 1 || cross) e += k.diffuse_levels * moving_term_bound_uncapped(r, 1.0, 1.0, false, cross);
      if (k.specular) e += k.specular_levels * moving_term_bound_uncapped(r, curvature, slope, true, false);
    }
    return e;
  };
  // The largest psi in [0, 1] with error_at(psi) <= budget: the quadratic's coefficients from three values
  // (rounding is covered by the margin on the result), then its positive root.
  const auto solve = [&](bool crossing_every_lit) {
    const double e0 = error_at(0.0, crossing_every_lit), e1 = error_at(0.5, crossing_every_lit),
                 e2 = error_at(1.0, crossing_every_lit);
    if (!(e0 <= budget) || !std::isfinite(e2)) return 0.0;
    if (e2 <= budget) return 1.0;
    const double quad = std::max(0.0, 2.0 * (e2 - 2.0 * e1 + e0)), lin = std::max(0.0, e2 - e0 - quad);
    const double room = budget - e0;
    const double psi = 2.0 * room / (lin + std::sqrt(lin * lin + 4.0 * quad * room));
    return std::min(1.0, psi * (1.0 - 1e-6));
  };
  // Without the kink term the lit and dark lights' terminators must stay out of the segments' reach:
  // along one segment N.L changes by at most the rate sum normal + light (per segment), and the
  // extrapolated end is within one segment of a pixel of the triangle. Either psi is kept that small, or
  // the kink term is added: whichever allows the longer segments.
  const double unlimited = solve(false);
  double kink_free = unlimited;
  for (std::size_t i = 0; i < lights; ++i) {
    const Term& k = term[i];
    out.terminator = out.terminator || k.state == 2;
    if (k.state == 2) continue;
    const double room = k.distance - 1e-4 - k.fixed.light, per = k.per_psi.normal + k.per_psi.light;
    kink_free = room > 0.0 ? std::min(kink_free, room / per) : 0.0;
  }
  // The kink terms only add: they can allow more only where the terminators' reach cut kink_free.
  const double with_kink = kink_free < unlimited ? solve(true) : 0.0;
  out.terminator = out.terminator || with_kink > kink_free;
  const double psi = std::max(kink_free, with_kink);
  out.psi = psi * (1.0 - 1e-4);  // float rounding of the kernel's |D| and min|N'|
  return out;
}

// Everything the choice needs of the materials and lights, not of the geometry: built once and reused
// while the scene's shading and the budget stay the same (it costs ~0.2 ms per material, serially).
struct ChoiceTables {
  std::vector<double> key;
  std::vector<float> psi;  // psi limits per material and (terminator, specular) class
  double dropped = 0.0;  // what a specular term the mask drops may add (dropped_specular_levels)
  std::vector<double> thresholds;  // negligible_cosines of `dropped` per (material, light)
  // Levels per unit of a light's diffuse and specular term, largest channel, per (material, light).
  std::vector<double> diffuse_levels, specular_levels;
  // Per material: x^n on [0, 1], and the chord bound of the specular term (n); beyond pi/2 the bound is 1.
  std::vector<IncreasingTable> power, specular_chord;
  // The same for the lanes (gouraud_fit_lanes.hpp): the chord bound by u = sin(phi / 2).
  std::vector<LaneTable> power_lanes, specular_chord_lanes;
  // Per material: curvature_factor and term_slope_bound of its n (0, 0 for n < 2: no moving-H bound).
  std::vector<double> curvature, slope;
};

std::shared_ptr<const ChoiceTables> choice_tables(const Scene& s, const CombinedConfig& c, double shading_budget) {
  const bool bound = c.rule == TriangleRule::bound;
  const double dropped = dropped_specular_levels(c, shading_budget, s.lights.size());
  std::vector<double> key = {double(bound), double(c.automatic), shading_budget, dropped,
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
  // Specular terms the mask drops add up to `dropped` each.
  const double segment_budget =
      std::max(0.0, shading_budget - (uses_highlight_mask(c) ? dropped * double(s.lights.size()) : 0.0));
  t->psi.assign(s.materials.size() * 4, 0.0f);
  if (c.automatic)
    for (std::size_t mi = 0; mi < s.materials.size(); ++mi)
      for (int cls = 0; cls < 4; ++cls)
        t->psi[4 * mi + cls] =
            bound || cls == 3 ? float(psi_limit(s, s.materials[mi], segment_budget, {bool(cls & 1), bool(cls & 2)})) : 0.0f;
  t->dropped = dropped;
  t->thresholds = negligible_cosines(s, dropped);
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
  for (const Material& m : s.materials) {
    const bool smooth = m.shininess >= 2.0f;
    t->curvature.push_back(smooth ? curvature_factor(m.shininess) : 0.0);
    t->slope.push_back(smooth ? term_slope_bound(m.shininess) : 0.0);
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

// What every range of one frame's choice reads: the scene, the config, the tables built for them and
// the output (TriangleChooser::Shared adds the counters).
struct FrameChoice {
  FrameChoice(const Scene& scene, const ScreenGeometry& geometry, const CombinedConfig& combined, double budget,
              std::vector<TriangleShading>& shading)
      : s(scene), g(geometry), c(combined), shading_budget(budget), out(shading) {}
  const Scene& s;
  const ScreenGeometry& g;
  const CombinedConfig& c;
  double shading_budget;
  std::vector<TriangleShading>& out;
  // What the scene and the config do not say by themselves: the arithmetic, and whether L or H moves.
  bool lanes = false, moving = false;
  std::shared_ptr<const ChoiceTables> tables;
  GouraudFitConstants fit_constants;
  std::vector<std::uint8_t> listed;  // list:FILE: 1 for each triangle the list gives to Phong
};

// The chord bound of a table, which ends at pi/2: beyond it the bound is 1.
double chord_bound(const IncreasingTable& t, double phi) { return phi < 0.5 * M_PI ? t.at(phi) : 1.0; }

// One range's counts, added to the frame's once at the range's end (no atomics per triangle).
struct ChoiceCounts {
  std::uint64_t gouraud = 0, segments = 0, without = 0, terminator = 0, skipped = 0;
  double largest = 0.0;  // largest expected error among the Gouraud triangles
};

// A triangle's Gouraud test: which lights' specular terms can show, whether Gouraud fits the budget, and
// the error in levels it is expected to make.
struct GouraudTest {
  unsigned mask;
  bool fits = false;
  double expected = 0.0;
};

// What the tests read of a screen triangle: its vertices in pixels and its width.
struct ScreenTriangle {
  std::size_t t, mat;
  glm::uvec3 idx;
  glm::dvec2 p[3];
  double width;
  bool clipped;  // clip-made vertices carry interpolated colours and normals: no Gouraud bound for them
};

// The choice of one range of triangles, in order. The lanes, and the terms of the last triangle, stay from
// one triangle to the next: the lanes are filled kLanes triangles at a time, the terms only as needed.
class RangeChooser {
 public:
  explicit RangeChooser(const FrameChoice& f)
      : f_(f),
        tables_(*f.tables),
        bound_(f.c.rule == TriangleRule::bound),
        masked_(uses_highlight_mask(f.c)),
        lights_(f.s.lights.size()),
        all_lights_((1u << lights_) - 1u),
        fixed_walk_width_(combined_min_width(f.c)) {}

  void choose(std::size_t t, std::size_t first, std::size_t last) {
    const int lane = int((t - first) % kLanes);
    if (f_.lanes && lane == 0) fill_lanes(t, last);
    TriangleShading& o = f_.out[t];
    o = TriangleShading{};  // the vector is reused frame to frame
    const ScreenTriangle tri = screen_triangle(t);
    const GouraudTest test = gouraud_test(tri, lane);
    o.specular_mask = test.mask;
    counts_.without += test.mask == 0;
    counts_.skipped += lights_ - std::size_t(__builtin_popcount(test.mask));
    const CombinedConfig& c = f_.c;
    if (test.fits) {
      o.method = TriangleMethod::gouraud;
      counts_.largest = std::max(counts_.largest, test.expected);
    } else if (!c.automatic) {
      o.method = tri.width + 1.0 >= double(fixed_walk_width_) ? TriangleMethod::segments : TriangleMethod::phong;
    } else if (terms_.usable && c.walk_min_k <= kCombinedMaxK && tri.width + 1.0 >= std::ldexp(2.0, c.walk_min_k)) {
      o.method = segments_or_phong(tri, test.mask, lane, o.psi_limit);
    } else {
      o.method = TriangleMethod::phong;
    }
    counts_.gouraud += o.method == TriangleMethod::gouraud;
    counts_.segments += o.method == TriangleMethod::segments;
  }

  const ChoiceCounts& counts() const { return counts_; }

 private:
  // The next kLanes triangles' bounds and Gouraud tests at once.
  void fill_lanes(std::size_t t, std::size_t last) {
    frame_lanes(f_.s, f_.g, t, int(std::min<std::size_t>(kLanes, last - t)), frame_);
    for (std::size_t i = 0; i < lights_; ++i) light_lanes(frame_, f_.s.lights[i], light_[i]);
    gouraud_fit_lanes(frame_, light_, f_.fit_constants, fit_);
  }

  ScreenTriangle screen_triangle(std::size_t t) const {
    const ScreenGeometry& g = f_.g;
    ScreenTriangle tri;
    tri.t = t;
    tri.mat = g.material[t];
    tri.idx = g.triangles[t];
    const glm::uvec3 idx = tri.idx;
    const double px = 1.0 / double(kSubpixel);
    tri.p[0] = glm::dvec2(g.xy[idx.x]) * px;
    tri.p[1] = glm::dvec2(g.xy[idx.y]) * px;
    tri.p[2] = glm::dvec2(g.xy[idx.z]) * px;
    const glm::dvec2* p = tri.p;
    tri.width = std::max({p[0].x, p[1].x, p[2].x}) - std::min({p[0].x, p[1].x, p[2].x});
    tri.clipped = idx.x >= g.outcode.size() || idx.y >= g.outcode.size() || idx.z >= g.outcode.size();
    return tri;
  }

  GouraudTest gouraud_test(const ScreenTriangle& tri, int lane) {
    const CombinedConfig& c = f_.c;
    if (c.rule == TriangleRule::list && !masked_ && !c.automatic) {
      // A list alone decides, and nothing below needs the triangle's frame: the choice costs next to nothing.
      return {all_lights_, !tri.clipped && !f_.listed[tri.t], 0.0};
    }
    if (!bound_) return sources_test(tri);
    if (f_.lanes) {
      terms_.usable = frame_.usable[lane] > 0.0f;  // the rest of terms only if the segments need it
      return {fit_.mask[lane], fit_.fits[lane] && !tri.clipped, fit_.expected[lane]};
    }
    return reference_test(tri);
  }

  // The sources' listing or a list decides Gouraud; the mask only when --highlight-test asks for it.
  GouraudTest sources_test(const ScreenTriangle& tri) {
    const CombinedConfig& c = f_.c;
    const TriangleFrame f = triangle_frame(f_.s, f_.g, tri.t);
    terms_.usable = f.usable;
    for (int k = 0; k < 3; ++k) terms_.n[k] = f.n[k];
    terms_.min_normal = f.usable ? distance_to_origin(f.n[0], f.n[1], f.n[2]) : 0.0;
    GouraudTest test{all_lights_};
    if (masked_ && f.usable) {
      const double* threshold = &tables_.thresholds[tri.mat * lights_];
      test.mask = 0;
      for (std::size_t i = 0; i < lights_; ++i)
        if (light_bounds(f, f_.s.lights[i], 2.0).max_n_dot_h > threshold[i]) test.mask |= 1u << i;
    }
    if (c.rule == TriangleRule::list) {
      test.fits = !tri.clipped && !f_.listed[tri.t];
    } else {
      test.fits = c.rule != TriangleRule::none && sources_choose_gouraud(f_.s, f, c);
    }
    return test;
  }

  // The bound rule in double (ChoiceArithmetic::double_reference): the expected |Gouraud - Phong| in
  // levels, summed term by term (largest channel each), cheapest and most often decisive first.
  GouraudTest reference_test(const ScreenTriangle& tri) {
    static const IncreasingTable diffuse_chord(0.5 * M_PI,
                                               [](double phi) { return gouraud_term_bound(phi, 1.0, true); });
    const std::size_t mat = tri.mat, lights = lights_;
    const double shading_budget = f_.shading_budget;
    const double* threshold = &tables_.thresholds[mat * lights];
    reference_terms(f_.s, triangle_frame(f_.s, f_.g, tri.t), terms_);
    const TriangleTerms& terms = terms_;
    double spread = -1.0;  // the normals' spread, an acos computed only if a chord bound needs it
    const auto normal_spread = [&] {
      if (spread < 0.0) spread = std::acos(std::clamp(terms.cos_spread, -1.0, 1.0));
      return spread;
    };
    unsigned mask = all_lights_;
    if (terms.usable) {
      mask = 0;
      for (std::size_t i = 0; i < lights; ++i)
        if (terms.light[i].max_n_dot_h > threshold[i]) mask |= 1u << i;
    }
    // A light whose specular term the mask drops adds at most tables_.dropped.
    double expected = tables_.dropped * double(lights - std::size_t(__builtin_popcount(mask)));
    bool fits = terms.usable && !tri.clipped && expected <= shading_budget;
    for (std::size_t i = 0; i < lights && fits; ++i) {
      if (!(mask & (1u << i))) continue;
      // Both images lie in [0, peak]: the chord bound only when the peak alone does not fit.
      const LightTerms& l = terms.light[i];
      const double peak = tables_.specular_levels[mat * lights + i] * tables_.power[mat].at(l.max_n_dot_h);
      // The chord bound takes H constant; where it moves (sin_h_radius > 0) the second-order bound.
      const double levels = tables_.specular_levels[mat * lights + i];
      expected += expected + peak <= shading_budget
                      ? peak
                      : std::min(peak, l.sin_h_radius > 0.0
                                           ? levels * gouraud_moving_specular(terms, l, tables_.curvature[mat],
                                                                              tables_.slope[mat])
                                           : levels * chord_bound(tables_.specular_chord[mat],
                                                                  normal_spread() + l.h_spread()));
      fits = expected <= shading_budget;
    }
    for (std::size_t i = 0; i < lights && fits; ++i) {
      const LightTerms& l = terms.light[i];
      expected += tables_.diffuse_levels[mat * lights + i] *
                  (l.state != 2    ? l.diffuse
                   : l.chord > 0.0 ? 1.0
                                   : chord_bound(diffuse_chord, normal_spread() + l.l_spread()));
      fits = expected <= shading_budget;
    }
    return {mask, fits, expected};
  }

  // combined:auto on a triangle Gouraud does not fit: segments of 2^K pixels where K >= walk_min_k fits
  // the segment limit psi (written to psi_limit) and the triangle is that wide; else Phong per pixel.
  TriangleMethod segments_or_phong(const ScreenTriangle& tri, unsigned mask, int lane, float& psi_limit) {
    if (f_.lanes) lane_terms(lights_, frame_, light_, lane, terms_);
    const std::vector<float>& psi = tables_.psi;
    const std::size_t mat = tri.mat;
    // Which terms can show decides the segment limit psi (a terminator, a highlight).
    const bool crosses_any = terminator_in_reach(psi[4 * mat + (mask || !bound_ ? 2 : 0)]);
    const int cls = (crosses_any ? 1 : 0) | (mask || !bound_ ? 2 : 0);
    psi_limit = psi[4 * mat + cls];
    // The segment length the kernel can use on this triangle: |dN/dx| 2^K <= psi min|N'|.
    const glm::dvec2 e1 = tri.p[1] - tri.p[0], e2 = tri.p[2] - tri.p[0];
    const double det = e1.x * e2.y - e2.x * e1.y;
    const glm::dvec3 ddx = ((terms_.n[1] - terms_.n[0]) * e2.y - (terms_.n[2] - terms_.n[0]) * e1.y) * (1.0 / det);
    const double change = glm::length(ddx);
    bool bounded = true, terminator = crosses_any;
    if (f_.moving) {
      // L or H moves along a segment: the old limit assumed them constant; the second-order bound replaces it.
      const MovingLimit m = moving_limit(tri, mask, e1, e2, det);
      psi_limit = float(m.psi);
      terminator = m.terminator;
      bounded = m.psi > 0.0;
    }
    counts_.terminator += terminator;
    const double allowed = double(psi_limit) * terms_.min_normal;
    int k = 0;
    while (k < kCombinedMaxK && change * double(2 << k) <= allowed) ++k;
    return bounded && k >= f_.c.walk_min_k && tri.width + 1.0 >= double(2 << k) ? TriangleMethod::segments
                                                                                 : TriangleMethod::phong;
  }

  // The segments' normals reach beyond the triangle (the last one is extrapolated, docs/combined.md): the
  // kink-free bound holds only if every terminator stays farther than the normals can turn there.
  bool terminator_in_reach(float specular_class_psi) const {
    const double reach = std::asin(std::min(1.0, double(specular_class_psi))) + 1e-3;
    bool crosses_any = !bound_;
    for (std::size_t i = 0; i < lights_ && !crosses_any; ++i)
      crosses_any = terms_.light[i].state == 2 || terms_.light[i].distance <= reach;
    return crosses_any;
  }

  // moving_psi_limit for the triangle whose screen edges are e1, e2 (det: their cross product).
  MovingLimit moving_limit(const ScreenTriangle& tri, unsigned mask, glm::dvec2 e1, glm::dvec2 e2, double det) const {
    const ScreenGeometry& g = f_.g;
    const glm::uvec3 idx = tri.idx;
    const std::size_t mat = tri.mat, lights = lights_;
    const glm::dvec3 w0(g.world[idx.x]), w1(g.world[idx.y]), w2(g.world[idx.z]);
    const glm::dvec3 dpdx = ((w1 - w0) * e2.y - (w2 - w0) * e1.y) * (1.0 / det);
    // The kernel's normal plane is made of the vertex normals as they are (clip-made ones unnormalized).
    const glm::dvec3 n0(g.normal[idx.x]), n1(g.normal[idx.y]), n2(g.normal[idx.z]);
    const double kernel_change = glm::length(((n1 - n0) * e2.y - (n2 - n0) * e1.y) * (1.0 / det));
    const double budget =
        f_.shading_budget - tables_.dropped * double(lights - std::size_t(__builtin_popcount(mask)));
    return moving_psi_limit(f_.s, g, tri.t, terms_, mask, budget, &tables_.diffuse_levels[mat * lights],
                            &tables_.specular_levels[mat * lights], tables_.curvature[mat], tables_.slope[mat],
                            kernel_change, dpdx);
  }

  const FrameChoice& f_;
  const ChoiceTables& tables_;
  const bool bound_, masked_;
  const std::size_t lights_;
  const unsigned all_lights_;
  const int fixed_walk_width_;  // combined:K's narrowest triangle walked by segments
  FrameLanes frame_;
  LightLanes light_[kChoiceMaxLights];
  GouraudFitLanes fit_;
  TriangleTerms terms_;
  ChoiceCounts counts_;
};

}  // namespace

// What every range of one frame's choice shares: the frame's inputs and tables, and the counters.
struct TriangleChooser::Shared : FrameChoice {
  using FrameChoice::FrameChoice;
  std::atomic<std::uint64_t> gouraud{0}, segments{0}, without{0}, terminator{0}, skipped{0};
  std::atomic<std::uint64_t> largest_bits{0};  // largest expected error among Gouraud triangles (double bits)
};

TriangleChooser::TriangleChooser(const Scene& s, const ScreenGeometry& g, const CombinedConfig& c, double shading_budget,
                                 std::vector<TriangleShading>& out, ChoiceArithmetic arithmetic) {
  if (s.lights.size() > kChoiceMaxLights)
    throw InputError("the per-triangle choice handles at most " + std::to_string(kChoiceMaxLights) + " lights");
  if (c.rule == TriangleRule::list && !c.phong_list->empty() && c.phong_list->back() >= g.triangles.size())
    throw InputError("--triangle-choice list: '" + c.list_file + "' names triangle " +
                     std::to_string(c.phong_list->back()) + ", the frame has " + std::to_string(g.triangles.size()));
  out.resize(g.triangles.size());
  shared_ = std::make_unique<Shared>(s, g, c, shading_budget, out);
  Shared& sh = *shared_;
  if (c.rule == TriangleRule::list) {
    sh.listed.assign(g.triangles.size(), 0);
    for (const std::uint32_t t : *c.phong_list) sh.listed[t] = 1;
  }
  const bool bound = c.rule == TriangleRule::bound;
  sh.tables = choice_tables(s, c, shading_budget);
  sh.lanes = bound && arithmetic == ChoiceArithmetic::float_lanes;
  // combined:auto's segments under a point light or a local viewer: L or H moves along them.
  const bool point_light = std::any_of(s.lights.begin(), s.lights.end(),
                                       [](const Light& l) { return l.type != LightType::directional; });
  sh.moving = bound && c.automatic && ((s.viewer_is_local() && !s.lights.empty()) || point_light);
  static const LaneTable diffuse_chord_lanes =
      make_lane_table(kChordTableEnd, [](double u) { return gouraud_term_bound(2.0 * std::asin(u), 1.0, true); });
  const ChoiceTables& tables = *sh.tables;
  GouraudFitConstants& fit_constants = sh.fit_constants;
  fit_constants.lights = s.lights.size();
  fit_constants.thresholds = tables.thresholds.data();
  fit_constants.specular_levels = tables.specular_levels.data();
  fit_constants.diffuse_levels = tables.diffuse_levels.data();
  fit_constants.power = tables.power_lanes.data();
  fit_constants.specular_chord = tables.specular_chord_lanes.data();
  fit_constants.diffuse_chord = &diffuse_chord_lanes;
  fit_constants.curvature = tables.curvature.data();
  fit_constants.slope = tables.slope.data();
  fit_constants.negligible_specular = float(tables.dropped);
  fit_constants.budget = float(shading_budget);
}

TriangleChooser::~TriangleChooser() = default;

void TriangleChooser::choose(std::size_t first, std::size_t last) {
  Shared& sh = *shared_;
  RangeChooser range(sh);
  for (std::size_t t = first; t < last; ++t) range.choose(t, first, last);
  const ChoiceCounts& n = range.counts();
  sh.gouraud += n.gouraud;
  sh.segments += n.segments;
  sh.without += n.without;
  sh.terminator += n.terminator;
  sh.skipped += n.skipped;
  // A positive double's bits order like the double: an atomic max on the bits.
  std::uint64_t bits, seen = sh.largest_bits.load();
  std::memcpy(&bits, &n.largest, sizeof bits);
  while (bits > seen && !sh.largest_bits.compare_exchange_weak(seen, bits)) {
  }
}

TriangleChoiceStats TriangleChooser::stats() const {
  const Shared& sh = *shared_;
  TriangleChoiceStats st;
  st.triangles = sh.g.triangles.size();
  st.gouraud = sh.gouraud.load();
  st.segments = sh.segments.load();
  st.without_highlight = sh.without.load();
  st.terminator = sh.terminator.load();
  st.light_terms_skipped = sh.skipped.load();
  const std::uint64_t bits = sh.largest_bits.load();
  std::memcpy(&st.largest_expected_levels, &bits, sizeof bits);
  return st;
}

TriangleChoiceStats choose_triangle_methods(const Scene& s, const ScreenGeometry& g, const CombinedConfig& c,
                                            double shading_budget, std::vector<TriangleShading>& out,
                                            ChoiceArithmetic arithmetic) {
  TriangleChooser chooser(s, g, c, shading_budget, out, arithmetic);
  parallel_for_ranges(g.triangles.size(), 1024, [&](std::size_t first, std::size_t last) { chooser.choose(first, last); });
  return chooser.stats();
}

void apply_triangle_choice(const std::vector<TriangleShading>& choice, float* attributes, std::size_t stride,
                           std::size_t first, std::size_t last) {
  for (std::size_t t = first; t < last; ++t) {
    float* a = attributes + t * stride;
    a[PHONG_HIGHLIGHT_SLOT] = float(choice[t].specular_mask);
    a[PHONG_METHOD_SLOT] = float(int(choice[t].method));
    a[PHONG_PSI_SLOT] = choice[t].psi_limit;
  }
}

}  // namespace parashade
