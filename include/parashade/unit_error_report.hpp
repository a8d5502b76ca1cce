#pragma once
// What `parashade unit-error` prints and writes for a set of unit-error studies (unit_error.hpp): the
// table of every unit and span length, a verdict per unit on our bound and the source's formula, the
// printed gain of the even/odd pair (Δδ) against the measured one, and all of it as JSON.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "parashade/unit_error.hpp"

namespace parashade {

struct UnitErrorReport {
  std::string text;     // the table, the verdicts and the Δδ table, as `unit-error` prints them
  nlohmann::json json;  // the same and more (per pixel offset), as `unit-error --json` writes it
};

// `studies` ran in arithmetic `a` with options `o` (each unit's study_unit_error).
UnitErrorReport unit_error_report(const std::vector<UnitErrorStudy>& studies, const Arithmetic& a,
                                  const UnitErrorOptions& o);

}  // namespace parashade
