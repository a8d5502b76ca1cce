#pragma once
// W float lanes per GCC generic vector, for the per-triangle choice's lanes (light_bounds_lanes.hpp):
// arithmetic, comparisons giving lane masks and selects on them compile to vector instructions without
// branches. Four lanes (one SSE register) by default; eight (one AVX register) in the versions compiled for
// AVX2, where they take up to a quarter off the choice (bench_triangle_choice). Without AVX, GCC lowers the selects
// of eight-lane vectors lane by lane (2.5x slower), hence two widths.
// Internal to the files that include it: the vectors never cross a library interface.
#include <cmath>
#include <cstdint>
#include <cstring>

#include "parashade/light_bounds_lanes.hpp"

// Every lane helper is inlined into its caller, so that the AVX2 version compiles it for AVX2.
#define PARASHADE_LANE inline __attribute__((always_inline))

namespace parashade::lanes {

// The vector types of W lanes (spelled out per width: GCC takes a vector_size that depends on a template
// parameter as the plain element type inside the template).
template <int W>
struct VectorsOf;
template <>
struct VectorsOf<4> {
  typedef float vf __attribute__((vector_size(16)));
  typedef std::int32_t vi __attribute__((vector_size(16)));
};
template <>
struct VectorsOf<8> {
  typedef float vf __attribute__((vector_size(32)));
  typedef std::int32_t vi __attribute__((vector_size(32)));
};

template <int W>
struct Lanes {
  static constexpr int kWidth = W;
  static_assert(kLanes % W == 0, "whole vectors");
  using vf = typename VectorsOf<W>::vf;
  using vi = typename VectorsOf<W>::vi;

  static PARASHADE_LANE vf load(const float (&a)[kLanes], int at) {
    vf v;
    std::memcpy(&v, a + at, sizeof v);
    return v;
  }
  static PARASHADE_LANE void store(float (&a)[kLanes], int at, vf v) { std::memcpy(a + at, &v, sizeof v); }
  static PARASHADE_LANE vf vmin(vf a, vf b) { return a < b ? a : b; }  // b where a is NaN
  static PARASHADE_LANE vf vmax(vf a, vf b) { return a > b ? a : b; }  // b where a is NaN
  static PARASHADE_LANE vf splat(float x) { return vf{} + x; }
  static PARASHADE_LANE vf vsqrt(vf x) {
    vf r;
    for (int j = 0; j < W; ++j) r[j] = std::sqrt(x[j]);
    return r;
  }
  static PARASHADE_LANE vf vsqrt0(vf x) { return vsqrt(vmax(x, splat(0.0f))); }  // sqrt(max(0, x)); NaN gives 0
  static PARASHADE_LANE vf weight(vi m) { return m ? splat(1.0f) : splat(0.0f); }  // 1 where the mask is set
};

// Whether the AVX2 versions run: where the CPU has AVX2, unless four_float_lanes_only(true) said otherwise.
bool avx2_lanes();

}  // namespace parashade::lanes

// In a struct deriving from lanes::Lanes<W>: its names, which a dependent base does not lend by itself.
#define PARASHADE_USING_LANES(W)                                                                           \
  using Base = lanes::Lanes<W>;                                                                              \
  using typename Base::vf;                                                                                   \
  using typename Base::vi;                                                                                   \
  using Base::kWidth, Base::load, Base::store, Base::vmin, Base::vmax, Base::splat, Base::vsqrt, Base::vsqrt0, \
      Base::weight
