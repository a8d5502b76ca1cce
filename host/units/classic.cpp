// The classic unit (kernels/units/classic.h): one code interpolator, one intensity per clock. Its code
// for the unit table: golden model, cost, error bound and the source's δ_K.
#include <cmath>

#include "parashade/unit_table.hpp"

namespace parashade {
namespace {

SpanTrace run(const Adder& add, const SpanLoad& s, const UnitConfig&) {
  SpanTrace t;
  std::int32_t reg = s.start;
  for (int x = 0; x < s.length; ++x, ++t.clocks) {
    t.values.push_back(reg);
    t.clock.push_back(std::uint32_t(t.clocks));
    reg = add(reg, s.step);
  }
  return t;
}

// S with one rounding, then z additions of the rounded dI, each off by one rounding.
double error_bound(const UnitConfig&, int, int z, double h, double e) { return (1.0 + z) * (h + e); }

// δ_K = δ0 + z·2^-(V+1), δ0 = 2^-(V+1).
double source_formula(const UnitConfig&, int v, int, int z) {
  const double d0 = std::ldexp(1.0, -(v + 1)), per_step = d0;
  return d0 + z * per_step;
}

std::string source_formula_name(const UnitConfig&) { return "δ_K"; }

}  // namespace

extern const UnitModel kClassicModel = {nullptr, nullptr, classic_span_clocks, run, nullptr,
                                        error_bound, source_formula, source_formula_name};

}  // namespace parashade
