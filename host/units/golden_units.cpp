// What the golden models share: the common span load and the entry point that runs a unit's model
// (each model is its unit's: host/units/<unit>.cpp, unit_table.hpp).
#include "parashade/golden_units.hpp"

#include <cmath>
#include <stdexcept>

#include "parashade/shift_add_division.hpp"
#include "parashade/unit_table.hpp"

namespace parashade {

SpanLoad load_span(const FixedPlanes& p, int c, int xl, int xr, int dy, const UnitConfig& unit, const Arithmetic& a,
                   const SierpinskiLeaf* leaf, const SpanDivision& division) {
  const UnitModel& model = *unit_row(unit.kind).model;
  if (model.load) return model.load(p, c, xl, xr, dy, a, leaf);
  const int f = a.frac_bits, w = a.width();
  SpanLoad s;
  s.start = load_register(plane_value(p.ref[c], p.ddx[c], p.ddy[c], xl, dy), f, w);
  s.end = load_register(plane_value(p.ref[c], p.ddx[c], p.ddy[c], xr, dy), f, w);
  s.step = load_register(p.ddx[c], f, w);
  s.own_step = load_register(std::int64_t(std::uint64_t(p.ddx[c]) * std::uint64_t(unit.lanes)), f, w);
  s.length = xr - xl + 1;
  const int k = xr - xl;
  if (division.mode != DIV_CONSTANT) {
    // A divider per span: the difference of the end registers over the k steps between them.
    const std::int64_t difference = std::int64_t(s.end) - std::int64_t(s.start);
    std::int64_t q = 0;
    if (k >= 1 && division.mode == DIV_EXACT) {
      q = std::int64_t(std::floor((2.0L * difference + k) / (2.0L * k)));
    } else if (k >= 1) {
      const auto rounding = division.nearest ? ReciprocalRounding::nearest : ReciprocalRounding::truncate;
      q = shift_add_divide(difference, shift_add_reciprocal(k, division.bits, rounding)).value;
    }
    s.step = saturate_register(q, w);
  }
  return s;
}

SpanTrace run_unit(const UnitConfig& unit, const Arithmetic& a, const SpanLoad& span) {
  if (!a.fixed) throw std::invalid_argument("golden unit models are fixed point");
  if (span.length < 1) throw std::invalid_argument("a span has at least one pixel");
  return unit_row(unit.kind).model->run(Adder{a.width()}, span, unit);
}

}  // namespace parashade
