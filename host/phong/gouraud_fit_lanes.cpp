#include "parashade/gouraud_fit_lanes.hpp"

#include <algorithm>
#include <cmath>

#include "parashade/lane_vectors.hpp"

namespace parashade {

LaneTable make_lane_table(double hi, const std::function<double(double)>& f) {
  constexpr int kSize = 1024;
  const double step = hi / double(kSize - 1);
  LaneTable t;
  t.value.resize(kSize);
  for (int i = 0; i < kSize; ++i) {
    const double v = f(step * double(i));
    float rounded = float(v);
    if (double(rounded) < v) rounded = std::nextafter(rounded, INFINITY);
    t.value[std::size_t(i)] = rounded;
  }
  // Rounded up by far more than the float roundings of x * inverse_step.
  t.inverse_step = float((1.0 / step) * (1.0 + 1e-5));
  return t;
}

namespace {

// W lanes a vector (lane_vectors.hpp).
template <int W>
struct GouraudFitOf : lanes::Lanes<W> {
  PARASHADE_USING_LANES(W);

  // The grid index of each lane's x (ceil, clamped to the table; NaN reads the last point).
  static PARASHADE_LANE vi table_index(vf x, float inverse_step, float last) {
    const vf t = vmax(vmin(x * inverse_step, splat(last)), splat(0.0f));
    const vi i = __builtin_convertvector(t, vi);  // truncates: t >= 0
    return i + (__builtin_convertvector(i, vf) < t ? vi{} + 1 : vi{});
  }

  static PARASHADE_LANE vf gather(const LaneTable* const* table, vi index) {
    vf r;
    for (int j = 0; j < kWidth; ++j) r[j] = table[j]->value[std::size_t(index[j])];
    return r;
  }

  static PARASHADE_LANE vf lookup(const LaneTable* const* table, vf x) {
    return gather(table, table_index(x, table[0]->inverse_step, float(table[0]->value.size() - 1)));
  }

  // u = sin(phi / 2) for phi = a + b, from a's half-angle cosine and sine and b's (each half-angle in
  // [0, pi/2]); phi >= pi / 2 (or any input NaN) gives kChordTableEnd, where the bounds are 1.
  static PARASHADE_LANE vf half_sine_of_sum(vf sa, vf ca, vf sb, vf cb) {
    const vf s = sa * cb + ca * sb, c = ca * cb - sa * sb;
    const vf u = s * (1.0f + 1e-6f) + 1e-7f;  // rounded up
    return (c > s) & (cb >= 0.0f) ? vmin(u, splat(float(kChordTableEnd))) : splat(float(kChordTableEnd));
  }

  // Gouraud's error of the specular term (in units of the term) where H moves over the triangle, from the
  // lanes' chords (docs/triangle-choice.md §2): (1/6)(w^2 P(n) + a S(n)) with the turning rates of N (the
  // normals' chord over min|N'|), of L and V (a chord 2r/d gives a longest edge over the nearest distance
  // <= 2r / (d - r) = 2 chord / (2 - chord)) and of H (over |L + V| >= half_min). Rounded up; 1 without a bound.
  static PARASHADE_LANE vf moving_specular(vf c_n, vf min_normal, vf light_chord, vf view_chord, vf half_min, vf curvature, vf slope) {
    const vf rate_n = c_n / vmax(min_normal, splat(1e-30f));
    const vf rate_l = 2.0f * light_chord / vmax(2.0f - light_chord, splat(1e-30f));
    const vf rate_v = 2.0f * view_chord / vmax(2.0f - view_chord, splat(1e-30f));
    const vf moving = rate_l + rate_v, inv_half = 1.0f / vmax(half_min, splat(1e-30f));
    const vf rate_h = moving * inv_half;
    const vf accel_h = (2.2360680f * (rate_l * rate_l + rate_v * rate_v) + 2.0f * rate_h * moving) * inv_half;
    const vf w = rate_n + rate_h, a = 2.0f * rate_n * rate_n + accel_h;
    const vf bound = (w * w * curvature + a * slope) * (1.0f / 6.0f) * 1.0001f + 1e-6f;
    const vi ok = (min_normal > 0.0f) & (half_min > 0.0f) & (light_chord < 2.0f) & (view_chord < 2.0f) & (curvature > 0.0f);
    return ok ? vmin(bound, splat(1.0f)) : splat(1.0f);
  }

  static PARASHADE_LANE void run(const FrameLanes& f, const LightLanes* light, const GouraudFitConstants& k,
                                 GouraudFitLanes& out) {
    const std::size_t lights = k.lights;
    const std::uint32_t* material = f.material;
    for (int at = 0; at < kLanes; at += kWidth) {
      const LaneTable* power[kWidth];
      const LaneTable* specular_chord[kWidth];
      const LaneTable* diffuse_chord[kWidth];
      for (int j = 0; j < kWidth; ++j) {
        power[j] = &k.power[material[at + j]];
        specular_chord[j] = &k.specular_chord[material[at + j]];
        diffuse_chord[j] = k.diffuse_chord;
      }
      const auto per_material = [&](const double* table) {
        vf r;
        for (int j = 0; j < kWidth; ++j) r[j] = float(table[material[at + j]]) * 1.0001f;
        return r;
      };
      const auto per_light = [&](const double* table, std::size_t i) {
        vf r;
        for (int j = 0; j < kWidth; ++j) r[j] = float(table[material[at + j] * lights + i]);
        return r;
      };
      const vi usable = load(f.usable, at) > 0.0f;
      const vf curvature = per_material(k.curvature), slope = per_material(k.slope);
      const vf c_n = vsqrt0(2.0f - 2.0f * load(f.cos_spread, at)), min_normal = load(f.min_normal, at);
      // Half-angle sine and cosine of the normals' spread a (cos a = cos_spread).
      const vf cos_spread = vmax(vmin(load(f.cos_spread, at), splat(1.0f)), splat(-1.0f));
      const vf sa = vsqrt0(0.5f - 0.5f * cos_spread), ca = vsqrt0(0.5f + 0.5f * cos_spread);
      vi mask{};
      vi on[24];
      vf expected{};
      for (std::size_t i = 0; i < lights; ++i) {
        // Where the bounds do not apply every light's specular term shows.
        on[i] = usable ? (load(light[i].max_n_dot_h, at) > per_light(k.thresholds, i)) : vi{} - 1;
        mask |= on[i] & (1 << i);
        expected += on[i] ? splat(0.0f) : splat(k.negligible_specular);
      }
      // Specular terms: both images lie in [0, peak], so the chord bound only where the peak alone does not fit.
      for (std::size_t i = 0; i < lights; ++i) {
        const vf levels = per_light(k.specular_levels, i);
        const vf peak = levels * lookup(power, load(light[i].max_n_dot_h, at));
        // H spreads by b = 2 asin(sin_h_radius): b / 2 has sine sin_h_radius.
        const vf sb = vmin(load(light[i].sin_h_radius, at), splat(1.0f));
        const vf chord = levels * lookup(specular_chord, half_sine_of_sum(sa, ca, sb, vsqrt0(1.0f - sb * sb)));
        // The chord bound takes H constant over the triangle; where H moves (a point light, a local viewer:
        // sin_h_radius > 0) the second-order bound of docs/triangle-choice.md §2 instead.
        const vf moving = levels * moving_specular(c_n, min_normal, load(light[i].chord, at), load(f.view_chord, at),
                                                   load(light[i].half_min, at), curvature, slope);
        const vf term = expected + peak <= k.budget ? peak : vmin(peak, sb > 0.0f ? moving : chord);
        expected += on[i] ? term : splat(0.0f);
      }
      // Diffuse terms: the lit bound, or the chord bound where the terminator may cross.
      for (std::size_t i = 0; i < lights; ++i) {
        // L spreads by b = 4 asin(chord / 2): b / 2 = 2 asin(chord / 2).
        const vf c = vmin(load(light[i].chord, at), splat(2.0f));
        const vf sb = c * vsqrt0(1.0f - 0.25f * c * c), cb = 1.0f - 0.5f * c * c;
        // Across the terminator the chord bound takes L constant; a point light's L moves: no bound but 1.
        const vf crossing = c > 0.0f ? splat(1.0f) : lookup(diffuse_chord, half_sine_of_sum(sa, ca, sb, cb));
        expected += per_light(k.diffuse_levels, i) * (load(light[i].state, at) == 2.0f ? crossing : load(light[i].diffuse, at));
      }
      const vi fits = usable & (expected * (1.0f + 1e-5f) <= k.budget);
      for (int j = 0; j < kWidth; ++j) {
        out.mask[at + j] = std::uint32_t(mask[j]);
        out.expected[at + j] = expected[j];
        out.fits[at + j] = fits[j] != 0;
      }
    }
  }
};

__attribute__((target("avx2"))) void gouraud_fit_avx2(const FrameLanes& f, const LightLanes* light,
                                                       const GouraudFitConstants& k, GouraudFitLanes& out) {
  GouraudFitOf<8>::run(f, light, k, out);
}

void gouraud_fit_sse(const FrameLanes& f, const LightLanes* light, const GouraudFitConstants& k, GouraudFitLanes& out) {
  GouraudFitOf<4>::run(f, light, k, out);
}

}  // namespace

void gouraud_fit_lanes(const FrameLanes& f, const LightLanes* light, const GouraudFitConstants& k, GouraudFitLanes& out) {
  if (lanes::avx2_lanes()) gouraud_fit_avx2(f, light, k, out);
  else gouraud_fit_sse(f, light, k, out);
}

}  // namespace parashade
