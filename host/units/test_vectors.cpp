// Test vectors from the golden models (test_vectors.hpp; the format is docs/hardware.md's).
#include "parashade/test_vectors.hpp"

#include <algorithm>
#include <random>
#include <sstream>

#include "parashade/errors.hpp"
#include "parashade/unit_table.hpp"

namespace parashade {
namespace {

constexpr int kMaxLength = 4096;  // 12-bit screen addresses: a span has at most 4096 pixels

struct Format {
  int w, f;
  std::int32_t one() const { return std::int32_t(1) << f; }  // one level
  std::int32_t max() const { return std::int32_t((std::int64_t(1) << (w - 1)) - 1); }
  std::int32_t min() const { return -max() - 1; }
  std::int32_t sat(std::int64_t v) const { return saturate_register(v, w); }
  std::int32_t wrap(std::int64_t v) const { return wrap_register(std::uint32_t(std::uint64_t(v)), w); }
};

// A span as the load would give it: E the right pixel's value rounded on its own (here S + (L-1) dI
// off by `e_off`), M*dI the own-rounded step (here M dI + 1, so that a unit using it shows).
SpanLoad span(const Format& fm, const UnitConfig& u, std::int64_t start, std::int64_t step, int length,
              std::int64_t e_off = 3) {
  SpanLoad s;
  s.start = fm.sat(start);
  s.step = fm.wrap(step);
  s.end = fm.sat(std::int64_t(s.start) + std::int64_t(s.step) * (length - 1) + e_off);
  s.own_step = fm.wrap(std::int64_t(s.step) * u.lanes + 1);
  s.length = length;
  return s;
}

std::vector<SpanLoad> hand_spans(const UnitConfig& u, const Format& fm) {
  std::vector<SpanLoad> out;
  // tests/core/golden_units_test.cpp's spans (register values, 12.4 there; any format holds them).
  const int golden[][4] = {{100, 7, 5, 3}, {100, 7, 4, 10}, {100, 7, 1, 0}, {10, 5, 7, 0}, {1, 3, 10, 0},
                           {1, 3, 3, 0},    {509, 1, 4, 0}, {0, 3, 2, -514}};
  for (const auto& g : golden) out.push_back(span(fm, u, g[0], g[1], g[2], g[3]));
  // Every short length, from a rounding tie (S = 100.5 levels) stepping half a level: ties all along.
  const std::int32_t one = fm.one(), half = one / 2;
  for (int length = 1; length <= 2 * u.lanes + 3 || length <= 9; ++length)
    out.push_back(span(fm, u, 100 * std::int64_t(one) + half, half, length));
  // Saturation: below 0 up through 255 and above, and down again; a start beyond the register.
  out.push_back(span(fm, u, -20 * std::int64_t(one), half + 1, 600));
  out.push_back(span(fm, u, 280 * std::int64_t(one), -(half + 1), 600));
  out.push_back(span(fm, u, std::int64_t(fm.max()) + 1000, 0, 3));
  // Adders wrapping: from the largest register past it, and from the smallest down past it.
  const std::int64_t third = one / 3 + 1;
  out.push_back(span(fm, u, fm.max() - 2 * third, third, 9));
  out.push_back(span(fm, u, fm.min() + 2 * third, -third, 9));
  out.push_back(span(fm, u, 0, fm.max(), 33));  // the largest step: wraps every clock
  out.push_back(span(fm, u, 0, fm.min(), 17));
  // The longest spans: across the levels, and one that wraps many times.
  out.push_back(span(fm, u, 10 * std::int64_t(one) + 3, 250 * std::int64_t(one) / (kMaxLength - 1), kMaxLength));
  out.push_back(span(fm, u, -5 * std::int64_t(one), one * 3 + 1, kMaxLength, -7));
  return out;
}

// A random plane (levels -64..320 at the corner, up to +-64 levels per pixel, with fractions finer than
// any register) and a random span on it, loaded as the unit loads it.
SpanLoad random_span(const UnitConfig& u, const Arithmetic& a, std::mt19937_64& rng) {
  auto below = [&rng](std::uint64_t n) { return rng() % n; };
  const std::int64_t unit = std::int64_t(1) << PLANE_FRAC;
  FixedPlanes p{};
  p.ref[0] = (std::int64_t(below(384)) - 64) * unit + std::int64_t(below(std::uint64_t(unit)));
  auto slope = [&]() {
    const int e = int(below(21)) - 14;  // 2^-14 .. 2^6 levels per pixel
    const std::int64_t m = std::int64_t(below(std::uint64_t(1) << 31)) + (std::int64_t(1) << 31);
    const std::int64_t v = e >= 0 ? m << e : m >> -e;
    return below(2) ? v : -v;
  };
  p.ddx[0] = slope();
  p.ddy[0] = slope() / 8;
  int length;
  const std::uint64_t kind = below(20);
  if (kind < 10) length = 1 + int(below(64));
  else if (kind < 18) length = 65 + int(below(std::uint64_t(64) << below(7)));  // 65..4160, log-spread
  else length = kMaxLength - int(below(2));
  if (length > kMaxLength) length = kMaxLength;
  const int xl = int(below(std::uint64_t(kMaxLength - length + 1))), dy = int(below(kMaxLength));
  return load_span(p, 0, xl, xl + length - 1, dy, u, a);
}

}  // namespace

bool has_test_vectors(const UnitConfig& unit) {
  return unit.kind != UnitKind::sierpinski;
}

std::vector<SpanLoad> test_vector_spans(const UnitConfig& unit, const Arithmetic& a, int random_spans,
                                        std::uint64_t seed) {
  const Format fm{a.width(), a.frac_bits};
  std::vector<SpanLoad> out = hand_spans(unit, fm);
  std::mt19937_64 rng(seed);
  for (int k = 0; k < random_spans; ++k) out.push_back(random_span(unit, a, rng));
  return out;
}

std::string test_vectors_text(const UnitConfig& unit, const Arithmetic& a, const std::vector<SpanLoad>& spans,
                              std::uint64_t seed) {
  if (!has_test_vectors(unit))
    throw UsageError("--unit '" + unit_name(unit) + "': only the span units have hardware (" +
                     unit_specs_help(true) + ")");
  if (!a.fixed) throw UsageError("--arith: test vectors are for fixed:I.F registers");
  std::ostringstream o;
  o << "# parashade test vectors: the golden model of " << unit_name(unit) << " in " << arith_name(a)
    << " (docs/hardware.md)\n"
    << "format parashade-vectors 1\n"
    << "unit " << unit_name(unit) << "\nlanes " << unit.lanes << "\narith " << arith_name(a) << "\nint_bits "
    << a.int_bits << "\nfrac_bits " << a.frac_bits << "\nload_clocks " << SPAN_LOAD_CLOCKS << "\nseed " << seed
    << "\nspans " << spans.size() << "\n";
  for (const SpanLoad& s : spans) {
    const SpanTrace t = run_unit(unit, a, s);
    o << "span " << s.length << " " << s.start << " " << s.end << " " << s.step << " " << s.own_step << " "
      << SPAN_LOAD_CLOCKS + span_clocks(unit, s.length) << "\n";
    std::vector<int> order(std::size_t(s.length));  // pixels by clock; a clock's in ascending x (= lane order)
    for (int i = 0; i < s.length; ++i) order[std::size_t(i)] = i;
    std::stable_sort(order.begin(), order.end(),
                     [&t](int p, int q) { return t.clock[std::size_t(p)] < t.clock[std::size_t(q)]; });
    std::size_t k = 0;
    for (std::uint32_t clock = 0; k < order.size(); ++clock) {
      o << "clock";
      for (; k < order.size() && t.clock[std::size_t(order[k])] == clock; ++k) {
        const std::int32_t v = t.values[std::size_t(order[k])];
        o << " " << order[k] << " " << v << " " << register_level(v, a.frac_bits);
      }
      o << "\n";
    }
  }
  o << "end\n";
  return o.str();
}

}  // namespace parashade
