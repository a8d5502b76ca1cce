// `parashade tune SCENE`: measures render configurations (tile size, work-items, planner strategy, U,
// batch) within a budget, checks each image against the default configuration's bytes, and appends
// every result to the tune cache (tune_cache.hpp), which `render` then uses for this device and problem.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <random>

#include "cli_args.hpp"
#include "commands.hpp"
#include "device_option.hpp"
#include "common_options.hpp"
#include "progress.hpp"
#include "parashade/errors.hpp"
#include "parashade/renderer.hpp"
#include "parashade/report.hpp"
#include "parashade/report_header.hpp"
#include "parashade/statistics.hpp"
#include "tune_cache.hpp"

namespace parashade::cli {
namespace {

struct TuneArgs {
  std::string scene, size, device, method = "gouraud", cache, report;
  std::string device_origin = "--device";  // or PARASHADE_DEVICE (device_option.hpp)
  bool quiet = false;
  int budget_runs = 12, frames = 5;
  double budget_seconds = 0;
};

// The default configuration first, then the search space in a fixed order (so a resumed run continues
// with the same sequence).
std::vector<RenderOptions> candidates(const RenderOptions& base, int cus) {
  std::vector<RenderOptions> out;
  out.push_back(base);
  std::vector<RenderOptions> rest;
  const std::vector<int> tiles = tile_sizes();
  for (int tile : tiles)
    for (int wi : {0, cus, 4 * cus, 64 * cus}) {
      RenderOptions o = base;
      o.tile_size = tile;
      o.work_items = wi;
      if (tile != base.tile_size || wi != base.work_items) rest.push_back(o);
    }
  for (Partition p : {Partition::round_robin, Partition::lpt, Partition::tiles, Partition::dynamic})
    for (int u : {cus, 2 * cus, 4 * cus, 16})
      for (int tile : std::vector<int>(tiles.begin(), tiles.end() - 1))  // not the largest
        for (int batch : p == Partition::dynamic ? std::vector<int>{16, 64, 256} : std::vector<int>{64}) {
          RenderOptions o = base;
          o.tile_size = tile;
          PlanOptions plan;
          plan.partition = p;
          plan.units = u;
          plan.batch = batch;
          o.plan = plan;
          rest.push_back(o);
        }
  // The plain configurations first (the planned frame runs two passes: docs/planner.md), each group
  // in a fixed shuffled order.
  const auto planned = std::stable_partition(rest.begin(), rest.end(), [](const RenderOptions& o) { return !o.plan; });
  std::mt19937 rng(2026);
  std::shuffle(rest.begin(), planned, rng);
  std::shuffle(planned, rest.end(), rng);
  out.insert(out.end(), rest.begin(), rest.end());
  return out;
}

int run_tune(const TuneArgs& a) {
  if (a.budget_runs < 1) throw UsageError("--budget-runs must be at least 1");
  if (a.budget_seconds < 0) throw UsageError("--budget-seconds must not be negative");
  if (a.frames < 1) throw UsageError("--frames must be at least 1");
  const auto size = parse_size(a.size);
  RenderOptions base;
  base.method = parse_method(a.method);
  if (!a.report.empty()) check_report_destination(a.report);
  const Scene scene = load_scene_at(a.scene, size, a.size);
  TuneCache cache(a.cache.empty() ? default_tune_cache() : std::filesystem::path(a.cache));
  auto device = for_device(a.device_origin, [&] { return open_device(a.device); });
  const DeviceInfo& dev = device->info();
  const TuneProblem problem{scene.name, scene.width, scene.height, method_name(base.method), "float"};
  std::printf("tuning %s (%dx%d, %s) on %s (driver %s); cache %s\n", scene.name.c_str(), scene.width, scene.height,
              method_name(base.method), dev.name.c_str(), dev.driver.c_str(), cache.path().string().c_str());

  const auto started = std::chrono::steady_clock::now();
  const auto elapsed_s = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(); };
  std::vector<std::uint8_t> reference;
  double default_ms = 0;
  int measured = 0, skipped = 0;
  nlohmann::json tried = nlohmann::json::array();  // the report's rows
  const std::vector<RenderOptions> space = candidates(base, std::max(1, dev.compute_units));
  FrameProgress progress(int(std::min<std::size_t>(space.size(), std::size_t(a.budget_runs))), a.quiet);
  for (const RenderOptions& o : space) {
    const bool is_default = reference.empty();
    const nlohmann::json params = tuned_params(o);
    if (!is_default && cache.has(dev, problem, params)) {
      ++skipped;
      continue;
    }
    if (!is_default && (measured >= a.budget_runs || (a.budget_seconds > 0 && elapsed_s() >= a.budget_seconds))) break;
    Renderer r(*device, o);
    r.render(scene);  // warm-up: program build
    std::vector<double> times;
    const Frame* f = nullptr;
    for (int i = 0; i < a.frames; ++i) {
      f = &r.render(scene);
      times.push_back(f->timings.total_ms);
    }
    const double ms = median(times);
    bool verified = true;
    if (is_default) {
      reference.assign(f->image.rgba.begin(), f->image.rgba.end());
      default_ms = ms;
    } else {
      verified = std::equal(reference.begin(), reference.end(), f->image.rgba.begin(), f->image.rgba.end());
    }
    ++measured;
    progress.step(measured);
    tried.push_back({{"params", params}, {"timing", timing_json(times, 1)}, {"verified", verified}, {"default", is_default}});
    if (!is_default || !cache.has(dev, problem, params)) cache.add(dev, problem, params, times, ms, verified);
    std::printf("%-80s %9.3f ms%s\n", params.dump().c_str(), ms,
                verified ? "" : "  IMAGE DIFFERS from the default's: not eligible");
  }
  const auto best = cache.best(dev, problem);
  nlohmann::json report = {{"scene", scene.name},   {"scene_file", a.scene}, {"width", scene.width},
                           {"height", scene.height}, {"method", method_name(base.method)},
                           {"device", to_json(dev)}, {"cache", cache.path().string()},
                           {"measured", tried},      {"skipped_cached", skipped},
                           {"best", best ? nlohmann::json{{"params", (*best)["params"]}, {"objective_ms", (*best)["objective"]}}
                                         : nlohmann::json(nullptr)},
                           {"confirmation", nullptr}};
  const auto write = [&] {
    if (!a.report.empty()) write_report(a.report, report, "tune");
  };
  std::printf("measured %d configuration(s), %d already in the cache; default %.3f ms (this run)\n", measured, skipped,
              default_ms);
  if (!best) {
    write();
    return 0;
  }
  std::printf("best in cache: %s at %.3f ms when it was tried\n", (*best)["params"].dump().c_str(),
              (*best)["objective"].get<double>());
  // The speed-up, measured now: default and best alternately (the machine's load drifts), medians.
  RenderOptions tuned = base;
  apply_tuned_params((*best)["params"], tuned);
  Renderer plain(*device, base), fast(*device, tuned);
  plain.render(scene);
  fast.render(scene);
  std::vector<double> t_plain, t_fast;
  for (int i = 0; i < std::max(5, a.frames); ++i) {
    t_plain.push_back(plain.render(scene).timings.total_ms);
    t_fast.push_back(fast.render(scene).timings.total_ms);
  }
  std::printf("confirmation (%zu alternating frames each): default %.3f ms, tuned %.3f ms: speed-up %.2fx\n",
              t_plain.size(), median(t_plain), median(t_fast), median(t_plain) / median(t_fast));
  report["confirmation"] = {{"default", timing_json(t_plain, 1)}, {"tuned", timing_json(t_fast, 1)},
                            {"speedup", median(t_plain) / median(t_fast)}};
  write();
  return 0;
}

}  // namespace

Command add_tune_command(CLI::App& app) {
  auto a = std::make_shared<TuneArgs>();
  auto* cmd = app.add_subcommand("tune", "Search tile size, work-items, planner strategy and U for a scene; cache the best");
  cmd->add_option("scene", a->scene, "Scene file (.json) or mesh")->required();
  add_size_option(*cmd, a->size);
  add_device_option(*cmd, a->device, "OpenCL device: index or name substring");
  cmd->add_option("--method", a->method, "Shading method: flat, gouraud, phong")->capture_default_str();
  cmd->add_option("--budget-runs", a->budget_runs, "Configurations to measure in this run, the default included (cached ones are skipped)")
      ->capture_default_str();
  cmd->add_option("--budget-seconds", a->budget_seconds, "Stop starting new configurations after this many seconds (0: no limit)");
  cmd->add_option("--frames", a->frames, "Timed frames per configuration (median)")->capture_default_str();
  cmd->add_option("--cache", a->cache, "Tune cache file (default $PARASHADE_TUNE_CACHE or ~/.cache/parashade/tune.json)");
  add_report_option(*cmd, a->report, "every configuration measured in this run with its frame samples, the best, "
                                     "the confirmation");
  add_quiet_flag(*cmd, a->quiet);
  return {cmd, [a]() {
            a->device_origin = device_from_environment(a->device);
            return run_tune(*a);
          }};
}

}  // namespace parashade::cli
