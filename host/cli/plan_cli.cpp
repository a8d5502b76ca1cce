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

void print_plan(const PlanReport& r, bool per_unit) {
  std::printf("plan %s, U = %d, tile %d%s: modeled frame clocks %llu (slowest unit), total %llu, imbalance %.3f\n",
              partition_name(r.partition).c_str(), r.units, r.tile_size,
              r.partition == Partition::dynamic ? (", batch " + std::to_string(r.batch)).c_str() : "",
              (unsigned long long)r.frame_clocks(), (unsigned long long)r.total_clocks(), r.imbalance());
  if (!per_unit) return;
  std::printf("  %5s %12s %12s %12s %14s\n", "unit", "triangles", "spans", "pixels", "clocks");
  for (std::size_t u = 0; u < r.load.size(); ++u) {
    const UnitLoad& l = r.load[u];
    std::printf("  %5zu %12llu %12llu %12llu %14llu\n", u, (unsigned long long)l.triangles, (unsigned long long)l.spans,
                (unsigned long long)l.pixels, (unsigned long long)l.clocks);
  }
}

void print_unit_mapping(const FrameStats& s, const FrameTimings& t) {
  if (!s.unit_pass_on_sub_devices) {
    if (!s.unit_pass.empty())
      std::printf("units as %d work-items (work-group size 1) of one kernel on %s\n", s.unit_pass[0].units,
                  s.unit_pass[0].device.c_str());
    return;
  }
  std::printf("units on %zu sub-devices (contiguous blocks; keys min-merged in %.3f ms):\n", s.unit_pass.size(),
              t.key_merge_ms);
  for (std::size_t k = 0; k < s.unit_pass.size(); ++k) {
    const UnitPassShare& u = s.unit_pass[k];
    const double ms = k < t.unit_pass_share_ms.size() ? t.unit_pass_share_ms[k] : 0.0;
    if (u.units == 0)
      std::printf("  %-48s %d CU: no units\n", u.device.c_str(), u.compute_units);
    else
      std::printf("  %-48s %d CU: units %d..%d, %d packet(s) from %d, pass %.3f ms\n", u.device.c_str(),
                  u.compute_units, u.first_unit, u.first_unit + u.units - 1, u.packets, u.first_packet, ms);
  }
}

}  // namespace parashade::cli
