// `parashade plan SCENE`: the planner's per-unit load for a scene without rendering (host only:
// scene_plans.hpp).
#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>

#include "cli_args.hpp"
#include "commands.hpp"
#include "common_options.hpp"
#include "parashade/command_files.hpp"
#include "parashade/errors.hpp"
#include "parashade/scene_plans.hpp"
#include "parashade/planner.hpp"
#include "parashade/report.hpp"
#include "parashade/unit_table.hpp"
#include "plan_cli.hpp"
#include "../render/plan_summary.hpp"

namespace parashade::cli {
namespace {

struct PlanCommandArgs {
  std::string scene, size, units, report;
  int tile = TILE_DEFAULT;
  bool per_unit = false, quiet = false;
  PlanArgs plan;
};

int run_plan(const PlanCommandArgs& a) {
  const auto size = checked_size(a.size);
  // The frame as render prepares it for Gouraud (the planner costs the unit's spans); each plan below.
  FrameConfig config;
  config.tile_size = a.tile;
  if (!a.units.empty()) config.units = for_option("--units", [&] { return parse_units(a.units); });
  const UnitConfig unit = config.unit();
  const std::vector<PlanOptions> list = plan_option_list(a.plan);
  for (const PlanOptions& o : list) {
    config.plan = o;
    RenderOptions checked;
    static_cast<FrameConfig&>(checked) = config;
    with_option_names(config, DeviceMode::one, [&] { check_render_options(checked, DeviceMode::one); });
  }
  config.plan.reset();
  CommandFiles files;
  files.output("--report", a.report);
  files.check_folders();
  std::vector<std::filesystem::path> inputs;
  const Scene scene = load_scene_at(a.scene, size, &inputs);
  files.scene(inputs);
  files.check();

  const ScenePlans plans = plan_scene(scene, config, list);
  std::printf("%s: %dx%d, %zu screen triangles, %zu bin entries, tile %d, unit %s\n", scene.name.c_str(), scene.width,
              scene.height, plans.screen_triangles, plans.bin_entries, a.tile, unit_name(unit).c_str());
  nlohmann::json reports = nlohmann::json::array();
  for (const PlanReport& r : plans.reports) {
    print_plan(r, a.per_unit);
    reports.push_back(to_json(r));
  }
  if (!a.report.empty()) {
    const nlohmann::json report = {{"scene", scene.name}, {"scene_file", a.scene}, {"width", scene.width},
                                   {"height", scene.height}, {"screen_triangles", plans.screen_triangles},
                                   {"bin_entries", plans.bin_entries}, {"unit", unit_name(unit)}, {"plans", reports}};
    write_report(a.report, report, "plan");
  }
  print_wrote({a.report});
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
      ->check(tile_validator());
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
