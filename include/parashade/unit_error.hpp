#pragma once
// Accumulated fixed-point error of the shading units ([Malovanyi 2019, parallel Gouraud] ch. 3) as a function of span length and
// fraction bits: random exact spans go through setup's plane registers and a unit's golden model,
// and every pixel's register is compared with the exact value. Also the analytic bounds of our
// register model and the source's printed formulas (δ_K, δ_KH). Derivations: docs/unit-error.md.
#include <cstdint>
#include <string>
#include <vector>

#include "parashade/golden_units.hpp"
#include "parashade/units.hpp"

namespace parashade {

// A span with an exact start value and increment, in levels (the "ideal" a unit approximates).
struct ExactSpan {
  double start = 0;
  double step = 0;
  int length = 1;
};

// The units this study covers, those with an error bound: classic, counter, interleave:M[:own],
// segment:P (one span from its own registers; a unit that copies spans of other sub-triangles is not a
// span accumulator).
bool is_span_unit(const UnitConfig& unit);

// The span registers as setup and the line interpolators would hand them to the unit: a FixedPlanes
// with ref = start, ddx = step, ddy = 0 (to_plane_register), read by load_span over [0, length - 1].
SpanLoad load_exact_span(const ExactSpan& s, const UnitConfig& unit, const Arithmetic& a);

struct SpanError {
  std::vector<double> error;  // per pixel z: register / 2^F - (start + z * step), levels, reduced modulo 2^I
  bool wrapped = false;       // an adder wrapped: some raw register differs from the value by >= 2^(I-1) levels
};

// Runs the unit's golden model over the span and measures each pixel's error. The error is taken
// modulo the register range 2^I levels so that it is the accumulated rounding error; a span whose
// register wrapped around is flagged (its pixels would be off by 2^I levels).
SpanError measure_span_error(const UnitConfig& unit, const Arithmetic& a, const ExactSpan& s);

// Our register model's bound on |error| at pixel z of a span of `length` pixels, levels: the unit's own
// (UnitModel::error_bound, host/units/<unit>.cpp). With h = 2^-(F+1) (a register load's rounding) and
// e = 2^-33 (setup's 32-fraction-bit plane rounding):
//   classic, segment:P, interleave:M   (1 + z)(h + e)
//   counter                             (1 + z)(h + e) left of the middle, else
//                                       h + L e + (L - 1 - z)(h + e)   (from its own rounded end E)
//   interleave:M:own, z = kM + j        (1 + j)(h + e) + k (h + M e)
double unit_error_bound(const UnitConfig& unit, const Arithmetic& a, int length, int z);
// The same without setup's plane rounding (e = 0): the unit's own share.
double unit_error_bound_registers_only(const UnitConfig& unit, const Arithmetic& a, int length, int z);

// The source's printed formula for this unit with V fraction bits and δ0 = 2^-(V+1), or NaN where
// the source prints none (interleave:M with M > 2; the unit's UnitModel::source_formula). The study
// takes V = F unless told otherwise.
//   classic, segment:P, interleave:1   δ_K  = δ0 + z·2^-(V+1)
//   counter ("error split")            δ0 + min(z, L-1-z)·2^-(V+1)
//   interleave:2, interleave:2:own     δ_KH = δ0 + ⌊z/2⌋·2^-(V+2)
double source_formula(const UnitConfig& unit, int v, int length, int z);
// "δ_K", "δ_K split", "δ_KH" or "" (none printed).
std::string source_formula_name(const UnitConfig& unit);
// The printed gain of the even/odd pair over one interpolator, Δδ = δ_K - δ_KH = 3/4·z·2^-(V+1).
double source_delta_delta(int v, int z);

struct UnitErrorOptions {
  std::vector<int> lengths{1, 2, 3, 4, 8, 16, 64, 256, 1024, 4096};
  int trials = 2000;       // spans per length: even trials uniform random, odd ones adversarial
  std::uint64_t seed = 1;
  int formula_bits = 0;    // V of the source's formulas; 0: V = F
};

// The spans drawn for one length, the same for every unit (so units are compared on the same spans).
// Even indices are uniform: start and end value uniform in 0..255. Odd ones are adversarial, all with
// the start on a rounding tie of the F-bit register (or just below one) and, in turn, the increment on
// a tie, M·increment on a tie (M = 2..16 in turn: the own step of interleave:M:own), or the increment
// uniform. Exact ties round up and values just below round down, so start and step errors add up.
// Every span stays within 0..255 (an adversarial start may lie up to 2^-F outside).
std::vector<ExactSpan> draw_spans(int length, int trials, std::uint64_t seed, const Arithmetic& a);

struct UnitErrorAtLength {
  int length = 0;
  std::uint64_t spans = 0, random_spans = 0, wrapped_spans = 0;
  double max_abs = 0;          // over all spans and pixels, levels
  double max_abs_random = 0;   // over the uniform spans only
  double mean_abs = 0;         // over the uniform spans' pixels
  double mean_span_max = 0;    // over the uniform spans of each span's max |error|
  double bound = 0;            // max over z of unit_error_bound
  double formula = 0;          // max over z of source_formula (NaN when none)
  std::uint64_t pixels = 0;
  std::uint64_t bound_exceeded = 0;    // pixels with |error| > bound(z)
  std::uint64_t formula_exceeded = 0;  // pixels with |error| > formula(z) + setup's plane share of bound(z)
  double worst_over_formula = 0;       // max over pixels of |error| / formula(z)
  double max_jump = 0;                 // max over spans and z of |error(z+1) - error(z)|: a seam in the span
  std::vector<double> max_by_z;        // all spans
  std::vector<double> mean_by_z;       // uniform spans
};

struct UnitErrorStudy {
  UnitConfig unit;
  Arithmetic arith;
  int formula_bits = 0;  // the V the source's formulas were evaluated with
  std::vector<UnitErrorAtLength> lengths;
};

// Throws std::invalid_argument on a float arithmetic, a length < 1 or trials < 1.
UnitErrorStudy study_unit_error(const UnitConfig& unit, const Arithmetic& a, const UnitErrorOptions& o);

}  // namespace parashade
