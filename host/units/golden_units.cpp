#include "parashade/golden_units.hpp"

#include <cmath>
#include <stdexcept>

#include "parashade/shift_add_division.hpp"

namespace parashade {
namespace {

// One W-bit adder: the carry out of the register is lost.
struct Adder {
  int width;
  std::int32_t operator()(std::int32_t a, std::int32_t b) const {
    return wrap_register(std::uint32_t(a) + std::uint32_t(b), width);
  }
};

SpanTrace classic(const Adder& add, const SpanLoad& s) {
  SpanTrace t;
  std::int32_t reg = s.start;
  for (int x = 0; x < s.length; ++x, ++t.clocks) {
    t.values.push_back(reg);
    reg = add(reg, s.step);
  }
  return t;
}

// Two code interpolators from the span's ends toward each other; on an odd length the left one
// shades the middle pixel while the right one is blocked.
SpanTrace counter(const Adder& add, const SpanLoad& s) {
  SpanTrace t;
  t.values.assign(std::size_t(s.length), 0);
  std::int32_t left = s.start, right = s.end;
  const std::int32_t minus_step = add(~s.step, 1);  // two's complement: the right interpolator subtracts
  for (int a = 0, b = s.length - 1; a <= b; ++t.clocks) {
    t.values[std::size_t(a++)] = left;
    left = add(left, s.step);
    if (a <= b) {
      t.values[std::size_t(b--)] = right;
      right = add(right, minus_step);
    }
  }
  return t;
}

// M interpolators: interpolator j starts at S + j*dI (a chain of adders at load) and steps by M*dI,
// which is M times the rounded dI (formed by adding dI M times: shifts and adds in hardware) or,
// with own_step, rounded on its own. An interpolator whose next pixel lies past the span is blocked.
SpanTrace interleave(const Adder& add, const SpanLoad& s, int m, bool own_step) {
  SpanTrace t;
  t.values.assign(std::size_t(s.length), 0);
  std::int32_t step = 0;
  for (int j = 0; j < m; ++j) step = add(step, s.step);
  if (own_step) step = s.own_step;
  std::vector<std::int32_t> reg(static_cast<std::size_t>(m));
  reg[0] = s.start;
  for (int j = 1; j < m; ++j) reg[std::size_t(j)] = add(reg[std::size_t(j - 1)], s.step);
  for (int first = 0; first < s.length; first += m, ++t.clocks) {
    for (int j = 0; j < m && first + j < s.length; ++j) {
      t.values[std::size_t(first + j)] = reg[std::size_t(j)];
      reg[std::size_t(j)] = add(reg[std::size_t(j)], step);
    }
  }
  return t;
}

// The multiples i*dI (i = 0..P) of the segment unit: an even multiple is its half shifted one bit
// (wiring), an odd one the previous multiple plus dI (one adder). Counts the adders.
std::vector<std::int32_t> segment_multiples(const Adder& add, std::int32_t step, int p, int* adders) {
  std::vector<std::int32_t> m(std::size_t(p) + 1, 0);
  if (p >= 1) m[1] = step;
  for (int i = 2; i <= p; ++i) {
    if (i % 2 == 0) {
      m[std::size_t(i)] = wrap_register(std::uint32_t(m[std::size_t(i / 2)]) << 1, add.width);
    } else {
      m[std::size_t(i)] = add(m[std::size_t(i - 1)], step);
      ++*adders;
    }
  }
  return m;
}

// P intensities per clock: output adder i adds multiple i to the segment base (P - 1 adders; i = 0 is
// the base itself); the base steps by P*dI (one accumulating adder).
SpanTrace segment(const Adder& add, const SpanLoad& s, int p) {
  SpanTrace t;
  t.values.assign(std::size_t(s.length), 0);
  int adders = 0;
  const std::vector<std::int32_t> multiple = segment_multiples(add, s.step, p, &adders);
  std::int32_t base = s.start;
  for (int first = 0; first < s.length; first += p, ++t.clocks) {
    for (int i = 0; i < p && first + i < s.length; ++i)
      t.values[std::size_t(first + i)] = i == 0 ? base : add(base, multiple[std::size_t(i)]);
    base = add(base, multiple[std::size_t(p)]);
  }
  return t;
}

// Extra triangulation: the classic code interpolator steps the shaded sub-triangle's span; in the same
// clock the copy's adder turns each value into the copy's (offset + I, or offset - I for a reflected
// copy, whose pixels run the other way).
SpanTrace sierpinski(const Adder& add, const SpanLoad& s) {
  SpanTrace shaded = classic(add, s);
  SpanTrace t;
  t.clocks = shaded.clocks;
  t.values.assign(std::size_t(s.length), 0);
  const std::int32_t offset = s.offset;
  for (int x = 0; x < s.length; ++x) {
    const std::int32_t v = shaded.values[std::size_t(x)];
    if (s.sign > 0) t.values[std::size_t(x)] = add(offset, v);
    else t.values[std::size_t(s.length - 1 - x)] = add(offset, add(~v, 1));
  }
  return t;
}

}  // namespace

SpanLoad load_span(const FixedPlanes& p, int c, int xl, int xr, int dy, const UnitConfig& unit, const Arithmetic& a,
                   const SierpinskiLeaf* leaf, const SpanDivision& division) {
  const int f = a.frac_bits, w = a.width();
  SpanLoad s;
  if (unit.kind == UnitKind::sierpinski) {
    if (!leaf) throw std::invalid_argument("the sierpinski unit needs the sub-triangle's record");
    // The shaded sub-triangle's span starts at this copy's left pixel, or at its right one when reflected.
    s.sign = leaf->sign;
    s.start = load_register(plane_value(p.ref[c], p.ddx[c], p.ddy[c], s.sign > 0 ? xl : xr, dy), f, w);
    s.step = load_register(s.sign > 0 ? p.ddx[c] : std::int64_t(0 - std::uint64_t(p.ddx[c])), f, w);
    s.offset = load_register(leaf->offset[c], f, w);
    s.length = xr - xl + 1;
    return s;
  }
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
  const Adder add{a.width()};
  switch (unit.kind) {
    case UnitKind::classic: return classic(add, span);
    case UnitKind::counter: return counter(add, span);
    case UnitKind::interleave: return interleave(add, span, unit.lanes, unit.own_step);
    case UnitKind::segment: return segment(add, span, unit.lanes);
    case UnitKind::sierpinski: return sierpinski(add, span);
  }
  throw std::invalid_argument("unknown unit");
}

SegmentAdders segment_adders(int p) {
  if (p < 1) throw std::invalid_argument("a segment has at least one pixel");
  SegmentAdders a;
  segment_multiples(Adder{32}, 1, p, &a.multiples);
  a.outputs = p - 1;
  a.accumulator = 1;
  return a;
}

}  // namespace parashade
