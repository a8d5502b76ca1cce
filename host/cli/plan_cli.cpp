#include "plan_cli.hpp"

#include <cstdio>

#include "cli_args.hpp"
#include "common_options.hpp"
#include "parashade/errors.hpp"
#include "parashade/kernels/constants.h"

namespace parashade::cli {
namespace {

int parse_units_count(const std::string& text) {
  try {
    std::size_t used = 0;
    const int u = std::stoi(text, &used);
    if (used == text.size() && u >= 1 && u <= MAX_MODELED_UNITS) return u;
  } catch (const std::exception&) {
  }
  throw UsageError("--cu '" + text + "' is not a number of modeled units (1.." + std::to_string(MAX_MODELED_UNITS) + ")");
}

}  // namespace

void add_plan_options(CLI::App& cmd, PlanArgs& a, bool lists) {
  cmd.add_option("--cu", a.units,
                 lists ? "Modeled shading units U, or a list (1,2,4,8); default 1"
                       : "Shade the frame by U modeled units from the planner's work lists (docs/planner.md); the image "
                         "is unchanged")
      ->check(count_list_validator(MAX_MODELED_UNITS, lists));
  cmd.add_option("--partition", a.partition,
                 std::string("Planner strategy: round-robin, lpt (cost-balanced), tiles (screen tiles by cost), dynamic "
                             "(batches from a shared counter)") +
                     (lists ? "; a list, or all" : "; default lpt"));
  cmd.add_option("--batch", a.batch, "dynamic: triangles per batch a unit pulls")->capture_default_str();
  cmd.add_option("--setup-clocks", a.setup_clocks, "Modeled clocks per triangle a unit starts (cost model)")
      ->capture_default_str();
}

std::optional<PlanOptions> plan_options(const PlanArgs& a) {
  if (!a.given()) return std::nullopt;
  PlanOptions o;
  if (!a.units.empty()) o.units = parse_units_count(a.units);
  if (!a.partition.empty()) o.partition = parse_partition(a.partition);
  o.batch = a.batch;
  o.setup_clocks = a.setup_clocks;
  return o;
}

std::vector<PlanOptions> plan_option_list(const PlanArgs& a) {
  std::vector<int> units{1};
  if (!a.units.empty()) {
    units.clear();
    for (const std::string& u : split_list(a.units, "--cu")) units.push_back(parse_units_count(u));
  }
  std::vector<Partition> parts{Partition::round_robin, Partition::lpt, Partition::tiles, Partition::dynamic};
  if (!a.partition.empty() && a.partition != "all") {
    parts.clear();
    for (const std::string& p : split_list(a.partition, "--partition")) parts.push_back(parse_partition(p));
  }
  std::vector<PlanOptions> out;
  for (Partition p : parts)
    for (int u : units) {
      PlanOptions o;
      o.partition = p;
      o.units = u;
      o.batch = a.batch;
      o.setup_clocks = a.setup_clocks;
      out.push_back(o);
    }
  return out;
}

}  // namespace parashade::cli
