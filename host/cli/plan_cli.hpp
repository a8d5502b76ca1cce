#pragma once
// The planner's command-line options (render and plan share them) and its load table.
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "parashade/planner.hpp"
#include "parashade/renderer.hpp"

namespace parashade::cli {

struct PlanArgs {
  std::string units;      // --cu: U, or a list for `plan`
  std::string partition;  // --partition
  int batch = 64;
  int setup_clocks = 1;
  bool given() const { return !units.empty() || !partition.empty(); }
};

// Registers --cu, --partition, --batch and --setup-clocks; `lists` lets --cu and --partition take lists ("all").
void add_plan_options(CLI::App& cmd, PlanArgs& a, bool lists);

// The options of one planned frame (render): nullopt when neither --cu nor --partition is given.
std::optional<PlanOptions> plan_options(const PlanArgs& a);

// Every combination the lists name (plan): U from --cu (default 1), strategies from --partition.
std::vector<PlanOptions> plan_option_list(const PlanArgs& a);

}  // namespace parashade::cli
