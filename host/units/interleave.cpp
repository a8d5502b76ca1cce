// The interleave:M[:own] unit (kernels/units/interleave.h; interleave:2 is the even/odd unit): M code
// interpolators, M intensities per clock. Its code for the unit table: spec, golden model, cost, error
// bound and the source's δ_K (M = 1) and δ_KH (M = 2).
#include <cmath>
#include <limits>

#include "parashade/unit_table.hpp"
#include "parashade/kernels/constants.h"

namespace parashade {
namespace {

bool in_range(int m) { return m >= 1 && m <= MAX_INTERLEAVE_LANES; }

std::optional<UnitConfig> parse(const std::string& spec) {
  const auto m = match_lanes(spec, R"(interleave:(\d{1,3})(:own)?)", "M", in_range,
                            ("in 1.." + std::to_string(MAX_INTERLEAVE_LANES)).c_str());
  if (!m) return std::nullopt;
  return UnitConfig{UnitKind::interleave, std::stoi((*m)[1]), (*m)[2].matched};
}

std::string name(const UnitConfig& u) { return "interleave:" + std::to_string(u.lanes) + (u.own_step ? ":own" : ""); }

// Interpolator j starts at S + j*dI (a chain of adders at load) and steps by M*dI, which is M times the
// rounded dI (formed by adding dI M times: shifts and adds in hardware) or, with own_step, rounded on
// its own. An interpolator whose next pixel lies past the span is blocked.
SpanTrace run(const Adder& add, const SpanLoad& s, const UnitConfig& unit) {
  const int m = unit.lanes;
  SpanTrace t;
  t.values.assign(std::size_t(s.length), 0);
  t.clock.assign(std::size_t(s.length), 0);
  std::int32_t step = 0;
  for (int j = 0; j < m; ++j) step = add(step, s.step);
  if (unit.own_step) step = s.own_step;
  std::vector<std::int32_t> reg(static_cast<std::size_t>(m));
  reg[0] = s.start;
  for (int j = 1; j < m; ++j) reg[std::size_t(j)] = add(reg[std::size_t(j - 1)], s.step);
  for (int first = 0; first < s.length; first += m, ++t.clocks) {
    for (int j = 0; j < m && first + j < s.length; ++j) {
      t.values[std::size_t(first + j)] = reg[std::size_t(j)];
      t.clock[std::size_t(first + j)] = std::uint32_t(t.clocks);
      reg[std::size_t(j)] = add(reg[std::size_t(j)], step);
    }
  }
  return t;
}

// M times the rounded dI is what classic adds M times: classic's bound. With :own, pixel z = kM + j is
// j additions of dI and k of the own-rounded M*dI (plane rounding M e) from S.
double error_bound(const UnitConfig& unit, int length, int z, double h, double e) {
  if (!unit.own_step) return unit_row(UnitKind::classic).model->error_bound(unit, length, z, h, e);
  const int m = unit.lanes, k = z / m, j = z % m;
  return (1.0 + j) * (h + e) + k * (h + m * e);
}

// One interpolator is classic (δ_K); the even/odd pair's δ_KH = δ0 + ⌊z/2⌋·2^-(V+2); none printed for M > 2.
double source_formula(const UnitConfig& unit, int v, int length, int z) {
  if (unit.lanes == 1) return unit_row(UnitKind::classic).model->source_formula(unit, v, length, z);
  const double d0 = std::ldexp(1.0, -(v + 1)), per_step = d0;
  if (unit.lanes == 2) return d0 + (z / 2) * (per_step / 2);
  return std::numeric_limits<double>::quiet_NaN();
}

std::string source_formula_name(const UnitConfig& u) { return u.lanes == 1 ? "δ_K" : u.lanes == 2 ? "δ_KH" : ""; }

}  // namespace

extern const UnitModel kInterleaveModel = {parse,   name,        interleave_span_clocks, run,
                                           nullptr, error_bound, source_formula,         source_formula_name};

}  // namespace parashade
