#pragma once
// The bound rule's Gouraud test (triangle_choice.cpp) for kLanes triangles at once: each light's
// specular mask bit and the expected |Gouraud - Phong| in levels, summed over the lights in the same order
// and by the same rule as the scalar test, in float. The chord bounds are looked up by u = sin(phi / 2),
// which the lanes get from the cosines and sines they hold without acos or asin.
#include <cstdint>
#include <functional>
#include <vector>

#include "parashade/light_bounds_lanes.hpp"

namespace parashade {

// An increasing function tabulated in float on [0, hi]: the value at the first grid point at or above x,
// rounded up, so a lookup never returns less than f(x); x beyond hi (or NaN) reads the last point.
struct LaneTable {
  std::vector<float> value;
  float inverse_step = 1.0f;  // grid index of x: ceil(x * inverse_step), never below x / step
};
LaneTable make_lane_table(double hi, const std::function<double(double)>& f);
// sin(pi / 4): u = sin(phi / 2) at phi = pi / 2, where every chord bound reaches 1.
constexpr double kChordTableEnd = 0.70710678118654752;

// What the test needs of the materials and lights, per (material, light) as [material * lights + light].
struct GouraudFitConstants {
  std::size_t lights = 0;
  const double* thresholds = nullptr;       // a light's specular term is dropped where max N.H <= this
  const double* specular_levels = nullptr;  // levels per unit of a light's specular term (largest channel)
  const double* diffuse_levels = nullptr;
  const LaneTable* power = nullptr;           // per material: x^n on [0, 1]
  const LaneTable* specular_chord = nullptr;  // per material: the specular chord bound by u on [0, kChordTableEnd]
  const LaneTable* diffuse_chord = nullptr;   // the diffuse chord bound (n = 1, crossing zero) by u
  // Per material: curvature_factor(n) and term_slope_bound(n) (moving_direction_bound.hpp), for the
  // specular term where H moves over the triangle (0 curvature: n < 2, no bound).
  const double* curvature = nullptr;
  const double* slope = nullptr;
  float negligible_specular = 0.0f;           // what a dropped specular term may still add, in levels
  float budget = 0.0f;                        // the shading budget in levels
};

struct GouraudFitLanes {
  std::uint32_t mask[kLanes];  // lights whose specular term can show (all lights where the bounds do not apply)
  float expected[kLanes];      // expected |Gouraud - Phong| in levels, every term summed
  bool fits[kLanes];           // the bounds apply and expected fits the budget
};
void gouraud_fit_lanes(const FrameLanes& f, const LightLanes* light, const GouraudFitConstants& k,
                       GouraudFitLanes& out);

}  // namespace parashade
