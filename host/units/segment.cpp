// The segment:P unit (kernels/units/segment.h): P intensities per clock from precomputed multiples of
// dI. Its code for the unit table: spec, golden model, adder count, cost; error bound and source
// formula classic's (its registers hold the same values).
#include <stdexcept>

#include "parashade/unit_table.hpp"
#include "parashade/kernels/constants.h"

namespace parashade {
namespace {

bool power_of_two_in_range(int p) { return p >= 2 && p <= MAX_SEGMENT_LANES && (p & (p - 1)) == 0; }

std::optional<UnitConfig> parse(const std::string& spec) {
  const auto m = match_lanes(spec, R"(segment:(\d{1,3}))", "P", power_of_two_in_range,
                            ("a power of two in 2.." + std::to_string(MAX_SEGMENT_LANES)).c_str());
  if (!m) return std::nullopt;
  return UnitConfig{UnitKind::segment, std::stoi((*m)[1]), false};
}

std::string name(const UnitConfig& u) { return "segment:" + std::to_string(u.lanes); }

// The multiples i*dI (i = 0..P): an even multiple is its half shifted one bit (wiring), an odd one the
// previous multiple plus dI (one adder). Counts the adders.
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

// Output adder i adds multiple i to the segment base (P - 1 adders; i = 0 is the base itself); the
// base steps by P*dI (one accumulating adder).
SpanTrace run(const Adder& add, const SpanLoad& s, const UnitConfig& unit) {
  const int p = unit.lanes;
  SpanTrace t;
  t.values.assign(std::size_t(s.length), 0);
  t.clock.assign(std::size_t(s.length), 0);
  int adders = 0;
  const std::vector<std::int32_t> multiple = segment_multiples(add, s.step, p, &adders);
  std::int32_t base = s.start;
  for (int first = 0; first < s.length; first += p, ++t.clocks) {
    for (int i = 0; i < p && first + i < s.length; ++i) {
      t.values[std::size_t(first + i)] = i == 0 ? base : add(base, multiple[std::size_t(i)]);
      t.clock[std::size_t(first + i)] = std::uint32_t(t.clocks);
    }
    base = add(base, multiple[std::size_t(p)]);
  }
  return t;
}

// The multiples are copies of the rounded dI: the registers, so the bound and the source's formula,
// are classic's.
const UnitModel& classic() { return *unit_row(UnitKind::classic).model; }
double error_bound(const UnitConfig& u, int length, int z, double h, double e) {
  return classic().error_bound(u, length, z, h, e);
}
double source_formula(const UnitConfig& u, int v, int length, int z) {
  return classic().source_formula(u, v, length, z);
}
std::string source_formula_name(const UnitConfig& u) { return classic().source_formula_name(u); }

}  // namespace

SegmentAdders segment_adders(int p) {
  if (p < 1) throw std::invalid_argument("a segment has at least one pixel");
  SegmentAdders a;
  segment_multiples(Adder{32}, 1, p, &a.multiples);
  a.outputs = p - 1;
  a.accumulator = 1;
  return a;
}

extern const UnitModel kSegmentModel = {parse,   name,        segment_span_clocks, run,
                                        nullptr, error_bound, source_formula,      source_formula_name};

}  // namespace parashade
