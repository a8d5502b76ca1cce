#pragma once
// Four float lanes per GCC generic vector (one SSE register; wider generic vectors have their selects
// lowered lane by lane), for the per-triangle choice's lanes (light_bounds_lanes.hpp): arithmetic,
// comparisons giving lane masks and selects on them compile to vector instructions without branches.
// Internal to the files that include it: the vectors never cross a library interface.
#include <cmath>
#include <cstdint>
#include <cstring>

#include "parashade/light_bounds_lanes.hpp"

namespace parashade::lanes {

constexpr int kWidth = 4;
static_assert(kLanes % kWidth == 0, "whole vectors");
typedef float vf __attribute__((vector_size(4 * kWidth)));
typedef std::int32_t vi __attribute__((vector_size(4 * kWidth)));

#define PARASHADE_LANE inline __attribute__((always_inline))
PARASHADE_LANE vf load(const float (&a)[kLanes], int at) {
  vf v;
  std::memcpy(&v, a + at, sizeof v);
  return v;
}
PARASHADE_LANE void store(float (&a)[kLanes], int at, vf v) { std::memcpy(a + at, &v, sizeof v); }
PARASHADE_LANE vf vmin(vf a, vf b) { return a < b ? a : b; }  // b where a is NaN
PARASHADE_LANE vf vmax(vf a, vf b) { return a > b ? a : b; }  // b where a is NaN
PARASHADE_LANE vf splat(float x) { return vf{} + x; }
PARASHADE_LANE vf vsqrt(vf x) {
  vf r;
  for (int j = 0; j < kWidth; ++j) r[j] = std::sqrt(x[j]);
  return r;
}
PARASHADE_LANE vf vsqrt0(vf x) { return vsqrt(vmax(x, splat(0.0f))); }  // sqrt(max(0, x)); a NaN x gives 0
PARASHADE_LANE vf weight(vi m) { return m ? splat(1.0f) : splat(0.0f); }  // 1 where the mask is set
#undef PARASHADE_LANE

}  // namespace parashade::lanes
