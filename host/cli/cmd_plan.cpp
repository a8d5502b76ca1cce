// `parashade plan SCENE`: the planner's per-unit load for a scene without rendering (host only: the frame
// prepared as render prepares it, then make_plan for each strategy and U asked for).
#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>

#include "cli_args.hpp"
#include "commands.hpp"
#include "common_options.hpp"
#include "parashade/errors.hpp"
#include "parashade/frame_pipeline.hpp"
#include "parashade/planner.hpp"
#include "parashade/report.hpp"
#include "parashade/unit_table.hpp"
#include "plan_cli.hpp"

namespace parashade::cli {
namespace {

struct PlanCommandArgs {
  std::string scene, size, units, report;
  int tile = TILE_DEFAULT;
  bool per_unit = false, quiet = false;
  PlanArgs plan;
};

int run_plan(const PlanCommandArgs& a) {
  const auto size = parse_size(a.size);
  // The frame as render prepares it for Gouraud (the planner costs the unit's spans); each plan below.
  FrameConfig config;
  config.tile_size = a.tile;
  if (!a.units.empty()) config.units = for_option("--units", [&] { return parse_units(a.units); });
  const UnitConfig unit = config.unit();
  const std::vector<PlanOptions> list = plan_option_list(a.plan);
  for (const PlanOptions& o : list) {
    config.plan = o;
    check_config_options(config);
  }
  config.plan.reset();
  if (!a.report.empty()) check_report_destination(a.report);
  const Scene scene = load_scene_at(a.scene, size, a.size);

  FramePipeline pipeline;
  const PreparedFrame& frame = pipeline.prepare_frame(scene, config);
  const std::size_t n = frame.records;
  std::printf("%s: %dx%d, %zu screen triangles, %zu bin entries, tile %d, unit %s\n", scene.name.c_str(), scene.width,
              scene.height, n, frame.bin_entries(), a.tile, unit_name(unit).c_str());
  nlohmann::json plans = nlohmann::json::array();
  for (const PlanOptions& o : list) {
    const Plan plan = make_plan(frame.arrays.triangles, n, frame.bins(), unit, o);
    print_plan(plan.report, a.per_unit);
    plans.push_back(to_json(plan.report));
  }
  if (!a.report.empty()) {
    const nlohmann::json report = {{"scene", scene.name}, {"scene_file", a.scene}, {"width", scene.width},
                                   {"height", scene.height}, {"screen_triangles", n}, {"bin_entries", frame.bin_entries()},
                                   {"unit", unit_name(unit)}, {"plans", plans}};
    write_report(a.report, report, "plan");
  }
  return 0;
}

}  // namespace

Command add_plan_command(CLI::App& app) {
  auto a = std::make_shared<PlanCommandArgs>();
  auto* cmd = app.add_subcommand("plan", "Print the planner's per-unit load for a scene (modeled clocks), without rendering");
  cmd->add_option("scene", a->scene, "Scene file (.json) or mesh (.obj .off .ply .stl)")->required();
  add_size_option(*cmd, a->size);
  cmd->add_option("--tile", a->tile, "Screen tile size: " + tile_sizes_text())
      ->capture_default_str()
      ->check(CLI::IsMember(tile_sizes()));
  cmd->add_option("--units", a->units,
                  "The modeled unit whose clocks are the cost, as render --units takes it: " + unit_specs_help() +
                      "; default classic");
  add_report_option(*cmd, a->report, "the plans");
  cmd->add_flag("--per-unit", a->per_unit, "Print every unit's load");
  add_plan_options(*cmd, a->plan, true);
  add_quiet_flag(*cmd, a->quiet);  // nothing to silence: plan prints results only
  return {cmd, [a]() { return run_plan(*a); }};
}

}  // namespace parashade::cli
