// The unit table, one row per unit, and what enumerates it: the --units parser and namer, the cost
// model, the lists of specs. Each unit's code is its own file (host/units/<unit>.cpp).
#include "parashade/unit_table.hpp"

#include <stdexcept>

#include "parashade/errors.hpp"
#include "parashade/kernels/constants.h"

namespace parashade {

extern const UnitModel kClassicModel, kCounterModel, kInterleaveModel, kSegmentModel, kSierpinskiModel,
    kPipelinedModel;

const std::vector<UnitRow>& unit_table() {
  static const std::vector<UnitRow> table = {
      {UnitKind::classic, "classic", {"classic"}, 1, &kClassicModel, {"classic"}, {"classic"}, {"classic"}},
      {UnitKind::counter, "counter", {"counter"}, 2, &kCounterModel, {"counter"}, {"counter"}, {"counter"}},
      {UnitKind::interleave, "interleave:M[:own] with M = 1.." + std::to_string(MAX_INTERLEAVE_LANES),
       {"interleave", "interleave:own"}, 0, &kInterleaveModel,
       {"interleave:1", "interleave:2", "interleave:3", "interleave:4", "interleave:7", "interleave:16",
        "interleave:2:own", "interleave:3:own", "interleave:16:own"},
       {"interleave:1", "interleave:2", "interleave:3", "interleave:4", "interleave:8", "interleave:16",
        "interleave:2:own", "interleave:4:own"},
       {"interleave:2", "interleave:2:own", "interleave:4:own"}},
      {UnitKind::segment, "segment:P with P = 2, 4, ..., " + std::to_string(MAX_SEGMENT_LANES), {"segment"}, 0,
       &kSegmentModel,
       {"segment:2", "segment:4", "segment:16", "segment:64"},
       {"segment:2", "segment:4", "segment:8", "segment:16", "segment:32", "segment:64"},
       {"segment:8"}},
      {UnitKind::sierpinski,
       "sierpinski[:D][:even|:odd|:touch|:overlap][:seal] with D = 1.." + std::to_string(MAX_SIERPINSKI_DEPTH),
       {"sierpinski"}, 0, &kSierpinskiModel,
       {"sierpinski:1", "sierpinski:2:odd", "sierpinski:3", "sierpinski:2:seal", "sierpinski:1:overlap",
        "sierpinski:2:touch:seal"},
       {"sierpinski:1:seal", "sierpinski:2:seal"},
       {}},
      {UnitKind::pipelined, "pipelined:M with M = 1.." + std::to_string(MAX_INTERLEAVE_LANES), {"pipelined"}, 0,
       &kPipelinedModel, {"pipelined:1", "pipelined:4"}, {"pipelined:1", "pipelined:4", "pipelined:16"}, {}},
  };
  return table;
}

const UnitRow& unit_row(UnitKind kind) {
  for (const UnitRow& row : unit_table())
    if (row.kind == kind) return row;
  throw std::invalid_argument("unknown unit");
}

UnitConfig parse_units(const std::string& spec) {
  for (const UnitRow& row : unit_table()) {
    if (!row.model->parse && spec == row.spec) return UnitConfig{row.kind, row.lanes, false};
    if (row.model->parse)
      if (const std::optional<UnitConfig> unit = row.model->parse(spec)) return *unit;
  }
  throw UsageError("unknown unit '" + spec + "' (valid: " + unit_specs_help() + ")");
}

std::string unit_name(const UnitConfig& u) {
  const UnitRow& row = unit_row(u.kind);
  return row.model->name ? row.model->name(u) : row.spec;
}

std::optional<std::smatch> match_lanes(const std::string& spec, const char* pattern, const char* letter,
                                       bool (*valid)(int lanes), const char* rule) {
  std::smatch m;
  if (!std::regex_match(spec, m, std::regex(pattern))) return std::nullopt;
  if (!valid(std::stoi(m[1])))
    throw UsageError("unit '" + spec + "': " + letter + " = " + m[1].str() + " is not " + rule);
  return m;
}

std::vector<std::string> unit_combination_values() {
  std::vector<std::string> out;
  for (const UnitRow& row : unit_table()) out.insert(out.end(), row.combination_values.begin(), row.combination_values.end());
  return out;
}

std::size_t unit_combination_value(const UnitConfig& unit) {
  std::size_t index = 0;
  for (const UnitRow& row : unit_table()) {
    if (row.kind == unit.kind) return index + (unit.own_step && row.combination_values.size() > 1 ? 1 : 0);
    index += row.combination_values.size();
  }
  throw std::invalid_argument("unknown unit");
}

ps_int span_clocks(const UnitConfig& unit, ps_int length) {
  return unit_row(unit.kind).model->span_clocks(unit.lanes, length);
}

std::string unit_specs_help(bool span_units_only) {
  std::string out;
  for (const UnitRow& row : unit_table())
    if (!span_units_only || row.model->error_bound) out += (out.empty() ? "" : ", ") + row.spec;
  return out;
}

std::string unit_specs(std::vector<std::string> UnitRow::*list) {
  std::string out;
  for (const UnitRow& row : unit_table())
    for (const std::string& spec : row.*list) out += (out.empty() ? "" : ",") + spec;
  return out;
}

}  // namespace parashade
