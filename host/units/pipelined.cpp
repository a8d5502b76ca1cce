// The pipelined:M unit (kernels/units/pipelined.h, hw/ps_pipelined.v): interleave:M with double-buffered
// span registers, so that the next span's load overlaps this span's clocks. Its code for the unit
// table: spec, golden model, cost; error bound and source formula classic's (its registers hold the
// same values).
#include "parashade/unit_table.hpp"
#include "parashade/kernels/constants.h"

namespace parashade {
namespace {

bool in_range(int m) { return m >= 1 && m <= MAX_INTERLEAVE_LANES; }

std::optional<UnitConfig> parse(const std::string& spec) {
  const auto m = match_lanes(spec, R"(pipelined:(\d{1,3}))", "M", in_range,
                            ("in 1.." + std::to_string(MAX_INTERLEAVE_LANES)).c_str());
  if (!m) return std::nullopt;
  return UnitConfig{UnitKind::pipelined, std::stoi((*m)[1]), false};
}

std::string name(const UnitConfig& u) { return "pipelined:" + std::to_string(u.lanes); }

// The active bank steps exactly as interleave:M's interpolators (M*dI a shifted and added copy of the
// rounded dI). Its ceil(L/M) output clocks include the one in which the next span's load fills the
// shadow bank: of them, only those beyond the SPAN_LOAD_CLOCKS every span is charged are the span's own.
SpanTrace run(const Adder& add, const SpanLoad& s, const UnitConfig& unit) {
  SpanTrace t = unit_row(UnitKind::interleave).model->run(add, s, {UnitKind::interleave, unit.lanes, false});
  t.clocks -= SPAN_LOAD_CLOCKS;
  return t;
}

const UnitModel& classic() { return *unit_row(UnitKind::classic).model; }
double error_bound(const UnitConfig& u, int length, int z, double h, double e) {
  return classic().error_bound(u, length, z, h, e);
}
double source_formula(const UnitConfig& u, int v, int length, int z) {
  return classic().source_formula(u, v, length, z);
}
std::string source_formula_name(const UnitConfig& u) { return classic().source_formula_name(u); }

}  // namespace

extern const UnitModel kPipelinedModel = {parse,   name,        pipelined_span_clocks, run,
                                          nullptr, error_bound, source_formula,        source_formula_name};

}  // namespace parashade
