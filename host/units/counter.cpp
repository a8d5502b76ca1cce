// The counter unit (kernels/units/counter.h): two code interpolators from the span's ends toward each
// other, two intensities per clock. Its code for the unit table: golden model, cost, error bound and
// the source's "error split".
#include <algorithm>
#include <cmath>

#include "parashade/unit_table.hpp"

namespace parashade {
namespace {

// On an odd length the left interpolator shades the middle pixel while the right one is blocked.
SpanTrace run(const Adder& add, const SpanLoad& s, const UnitConfig&) {
  SpanTrace t;
  t.values.assign(std::size_t(s.length), 0);
  t.clock.assign(std::size_t(s.length), 0);
  std::int32_t left = s.start, right = s.end;
  const std::int32_t minus_step = add(~s.step, 1);  // two's complement: the right interpolator subtracts
  for (int a = 0, b = s.length - 1; a <= b; ++t.clocks) {
    t.clock[std::size_t(a)] = std::uint32_t(t.clocks);
    t.values[std::size_t(a++)] = left;
    left = add(left, s.step);
    if (a <= b) {
      t.clock[std::size_t(b)] = std::uint32_t(t.clocks);
      t.values[std::size_t(b--)] = right;
      right = add(right, minus_step);
    }
  }
  return t;
}

// Left of the middle classic's; right of it from E, rounded on its own from a plane value L steps away
// (L e), walking back L - 1 - z roundings.
double error_bound(const UnitConfig& unit, int length, int z, double h, double e) {
  const int left = (length + 1) / 2;  // the left interpolator shades pixels 0 .. ceil(L/2) - 1
  if (z < left) return unit_row(UnitKind::classic).model->error_bound(unit, length, z, h, e);
  return h + length * e + (length - 1.0 - z) * (h + e);
}

// The source's "error split": δ0 + min(z, L-1-z)·2^-(V+1).
double source_formula(const UnitConfig&, int v, int length, int z) {
  const double d0 = std::ldexp(1.0, -(v + 1)), per_step = d0;
  return d0 + std::min(z, length - 1 - z) * per_step;
}

std::string source_formula_name(const UnitConfig&) { return "δ_K split"; }

}  // namespace

extern const UnitModel kCounterModel = {nullptr, nullptr, counter_span_clocks, run, nullptr,
                                        error_bound, source_formula, source_formula_name};

}  // namespace parashade
