#pragma once
// The modeled shading units, one row each (host/units/unit_table.cpp): what `--units` accepts, each
// unit's code, and the configurations the tests and studies run. A unit is a pair of files,
// kernels/units/<unit>.h (id, clocks, register closed form) and host/units/<unit>.cpp (its UnitModel);
// adding one is docs/units.md, "Adding a unit". parse_units, unit_name, load_span, run_unit, the
// planner's costs, the unit-error study, `scaling` and the golden tests all go through this table.
#include <optional>
#include <regex>
#include <string>
#include <vector>

#include "parashade/golden_units.hpp"
#include "parashade/units.hpp"

namespace parashade {

// A unit's code (host/units/<unit>.cpp), as plain function pointers so that each unit's constant is
// initialized before any code runs.
struct UnitModel {
  // A unit with parameters parses its spec (nullopt for another unit's; it sets lanes; UsageError naming
  // a bad parameter) and names a UnitConfig so that parsing the name gives it back. nullptr: the unit's
  // spec is its word alone (UnitRow::spec).
  std::optional<UnitConfig> (*parse)(const std::string& spec);
  std::string (*name)(const UnitConfig& unit);
  // Cost model: clocks for the pixels of a span of `length` >= 1 pixels, without the load clock (its
  // header in kernels/units/, which the kernels count with).
  ps_int (*span_clocks)(int lanes, ps_int length);
  // Golden model: the unit's registers stepped clock by clock over one span.
  SpanTrace (*run)(const Adder& add, const SpanLoad& span, const UnitConfig& unit);
  // Its own load of a span's registers; nullptr: load_span's (S, E, dI, M*dI from setup's plane).
  SpanLoad (*load)(const FixedPlanes& p, int c, int xl, int xr, int dy, const Arithmetic& a,
                   const SierpinskiLeaf* leaf);
  // A span accumulator's error bound at pixel z of a span of `length` pixels, levels, given one register
  // load's rounding h and setup's plane rounding e (unit_error.hpp); the source's printed formula with V
  // fraction bits (NaN where it prints none) and its name ("δ_K", "" for none). nullptr: no span
  // accumulator, the unit-error study leaves it out.
  double (*error_bound)(const UnitConfig& unit, int length, int z, double h, double e);
  double (*source_formula)(const UnitConfig& unit, int v, int length, int z);
  std::string (*source_formula_name)(const UnitConfig& unit);
};

struct UnitRow {
  UnitKind kind;
  // `--units`: the unit's word ("classic") or the form of its spec ("interleave:M[:own] with M = 1..16"),
  // as the help and the errors list it.
  std::string spec;
  // Its values on the unit axis of the table of what combines (combinations.hpp): its word, and where
  // the table tells the own-step variant apart (UnitConfig::own_step) a second value for it.
  std::vector<std::string> combination_values;
  // The lanes (intensities per clock) of a unit without parameters, 0 where its parser sets them.
  int lanes;
  const UnitModel* model;
  // The configurations run by the golden-model tests (kernel against golden model), by default in
  // `scaling`'s sweep and in `unit-error`'s study.
  std::vector<std::string> golden_tests, scaling_sweep, error_study;
};

// Every unit, in the order the lists and the help show them.
const std::vector<UnitRow>& unit_table();
const UnitRow& unit_row(UnitKind kind);

// For a unit's parser: the match of a spec whose first group is its lane count N (`pattern`, e.g.
// "interleave:(\d{1,3})(:own)?"), nullopt for a spec it does not match; throws UsageError
// "unit 'SPEC': LETTER = N is not RULE" when `valid` refuses N.
std::optional<std::smatch> match_lanes(const std::string& spec, const char* pattern, const char* letter,
                                       bool (*valid)(int lanes), const char* rule);

// The unit axis of the table of what combines, after its "none": every row's combination_values in
// table order; and a unit's index among them.
std::vector<std::string> unit_combination_values();
std::size_t unit_combination_value(const UnitConfig& unit);

// The unit's span clocks (UnitModel::span_clocks), without the load clock.
ps_int span_clocks(const UnitConfig& unit, ps_int length);

// The units' spec forms, comma-separated: every unit's, or only the span accumulators' (error_bound).
std::string unit_specs_help(bool span_units_only = false);
// One list of the table's configurations (e.g. &UnitRow::scaling_sweep), all units', comma-separated.
std::string unit_specs(std::vector<std::string> UnitRow::*list);

}  // namespace parashade
