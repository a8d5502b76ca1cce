#pragma once
// x^n for the vertex stage's specular term (vertex_lighting.cpp), for one vertex or for kLanes at once with
// the same bits: 2^(n log2 x) in double precision with polynomials, so the lanes need no libm call per lane
// (powf was 4-6 % of the Gouraud host stages' samples, bench/README.md "Run AA"). Before the rounding to
// float its relative error is below 1e-10, so the float is the correctly rounded x^n except within 1e-10 of a
// rounding boundary; tests/core/vertex_power_test.cpp checks it against std::pow in double.
// Domain: x > 0 and n >= 0, both finite. Values below 2^-160 come out as 0 (float's least subnormal is
// 2^-149); lanes outside the domain give unspecified values, for the caller to mask.
#include <cstdint>
#include <cstring>

#include "parashade/vertex_lanes.hpp"

namespace parashade::vertex_lanes {

// Half the lanes in double precision: four doubles, one AVX2 register. (On eight, GCC 12 splits the arithmetic
// into halves but turns comparisons into per-lane scalar code.)
typedef double Doubles4 __attribute__((vector_size(32)));
typedef unsigned long long Words4 __attribute__((vector_size(32)));  // their bits
typedef float Floats4 __attribute__((vector_size(16)));

namespace power_detail {

template <class D>
struct Types;
template <>
struct Types<double> {
  using Bits = std::uint64_t;
  static __attribute__((always_inline)) double constant(double v) { return v; }
  static __attribute__((always_inline)) Bits bits(Bits v) { return v; }
  static __attribute__((always_inline)) double clamp(double y, double lo, double hi) { return y < lo ? lo : y > hi ? hi : y; }
};
template <>
struct Types<Doubles4> {
  using Bits = Words4;
  static __attribute__((always_inline)) Doubles4 constant(double v) { return Doubles4{} + v; }
  static __attribute__((always_inline)) Bits bits(std::uint64_t v) { return Words4{} + v; }
  static __attribute__((always_inline)) Doubles4 clamp(Doubles4 y, double lo, double hi) {
    y = y < constant(lo) ? constant(lo) : y;
    return y > constant(hi) ? constant(hi) : y;
  }
};

// ln 2; the series' coefficients below are constant expressions of it, folded at compile time alike in every
// build and in both instantiations.
constexpr double kLn2 = 0.69314718055994530942;

template <class D>
inline __attribute__((always_inline)) D power(D x, D n) {
  using T = Types<D>;
  using Bits = typename T::Bits;
  // log2 x = k + log2 m with m in [sqrt(1/2), sqrt(2)): k from the bits offset by sqrt(1/2)'s, shifted
  // unsigned (AVX2 has no 64-bit arithmetic shift) with a bias of 1024.
  const Bits ix = __builtin_bit_cast(Bits, x);
  const Bits biased = ix - T::bits(0x3FE6A09E667F3BCDull) + T::bits(std::uint64_t(1024) << 52);
  const Bits k_biased = biased >> 52;  // k + 1024, in [0, 2048)
  const D m = __builtin_bit_cast(D, ix - ((k_biased - T::bits(1024)) << 52));
  // k as a double without an int64 conversion (none in AVX2): 2^52 + (k + 1024) exactly, less 2^52 + 1024.
  const D k = __builtin_bit_cast(D, k_biased | T::bits(0x4330000000000000ull)) - T::constant(4503599627370496.0 + 1024.0);
  // log2 m = (2 / ln 2) atanh(t), t = (m - 1) / (m + 1), |t| <= 0.1716: seven odd terms leave < 2e-12 relative.
  // The polynomials by Estrin's scheme, not Horner's: the vertex lighting is one long dependent chain, so
  // the chain's length is what costs.
  const D t = (m - T::constant(1.0)) / (m + T::constant(1.0));
  const D w = t * t, w2 = w * w;
  const auto c = [](int i) { return T::constant(2.0 / (double(2 * i + 1) * kLn2)); };
  const D s = (c(0) + c(1) * w) + (c(2) + c(3) * w) * w2 + ((c(4) + c(5) * w) + c(6) * w2) * (w2 * w2);
  D y = n * (k + t * s);
  // 2^y = 2^j 2^f, j the nearest integer (the 1.5 * 2^52 shifter rounds), |f| <= 1/2.
  y = T::clamp(y, -160.0, 128.0);
  const D shifter = T::constant(6755399441055744.0);
  const D shifted = y + shifter;
  const D f = y - (shifted - shifter);
  const Bits j = __builtin_bit_cast(Bits, shifted) - __builtin_bit_cast(Bits, shifter);  // two's complement
  // 2^f = e^(f ln 2) by its Taylor series to degree 10: |f ln 2| <= 0.347, remainder < 3e-13 relative.
  const D u = f * T::constant(kLn2), u2 = u * u, u4 = u2 * u2;
  constexpr double inv[11] = {1.0, 1.0, 1.0 / 2, 1.0 / 6, 1.0 / 24, 1.0 / 120, 1.0 / 720, 1.0 / 5040, 1.0 / 40320,
                              1.0 / 362880, 1.0 / 3628800};  // 1 / i!
  const auto e = [&](int i) { return T::constant(inv[i]); };
  const D p = ((e(0) + e(1) * u) + (e(2) + e(3) * u) * u2) + ((e(4) + e(5) * u) + (e(6) + e(7) * u) * u2) * u4 +
              ((e(8) + e(9) * u) + e(10) * u2) * (u4 * u4);
  // p is in [2^-1/2, 2^1/2] and j in [-160, 128]: adding j to the exponent stays normal.
  return __builtin_bit_cast(D, __builtin_bit_cast(Bits, p) + (j << 52));
}

}  // namespace power_detail

// One vertex: x > 0 and n >= 0.
inline float power(float x, float n) { return float(power_detail::power<double>(double(x), double(n))); }

// kLanes vertices, lane k the same bits as power(x[k], n).
inline __attribute__((always_inline)) Floats power(Floats x, float n) {
  const Doubles4 nd = power_detail::Types<Doubles4>::constant(double(n));
  Floats4 half[2];
  std::memcpy(half, &x, sizeof half);
  for (Floats4& h : half)
    h = __builtin_convertvector(power_detail::power<Doubles4>(__builtin_convertvector(h, Doubles4), nd), Floats4);
  std::memcpy(&x, half, sizeof half);
  return x;
}

}  // namespace parashade::vertex_lanes
