// `parashade tune SCENE`: searches a space of render configurations (tune_space.hpp: layout and shading
// parameters, `--param NAME=V1,V2,...`) by a strategy (tune_strategy.hpp: brute, random, anneal), measures
// each candidate's frame time, verifies its image and measures its error against the exact reference,
// and appends every result to the tune cache (tune_cache.hpp), which `render` then uses for this device,
// build and problem. The objective is the fastest candidate, within an error budget when one is given.
// With --mpi (under mpirun) the candidates are dealt across the ranks and rank 0 writes the merged
// report. docs/tuning.md.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <memory>

#include "cli_args.hpp"
#include "commands.hpp"
#include "common_options.hpp"
#include "device_option.hpp"
#include "progress.hpp"
#include "parashade/distributed.hpp"
#include "parashade/errors.hpp"
#include "parashade/geometry_stage.hpp"
#include "parashade/json_number.hpp"
#include "parashade/metrics.hpp"
#include "parashade/reference.hpp"
#include "parashade/renderer.hpp"
#include "parashade/report.hpp"
#include "parashade/report_header.hpp"
#include "parashade/statistics.hpp"
#include "parashade/tile_choice.hpp"
#include "tune_cache.hpp"
#include "tune_export.hpp"
#include "tune_space.hpp"
#include "tune_strategy.hpp"

namespace parashade::cli {
namespace {

struct TuneArgs {
  std::string scene, size, device, method = "gouraud", cache, strategy = "brute", objective = "fastest", report, export_kt;
  std::vector<std::string> params;  // --param NAME=V1,V2,...
  std::string device_origin = "--device";  // or PARASHADE_DEVICE (device_option.hpp)
  int budget_runs = 12, frames = 5;
  double budget_seconds = 0, max_error = 0, max_nmse = 0;  // budgets: 0 = none
  std::uint64_t seed = 2026;
  bool mpi = false, quiet = false;
};

// One evaluated candidate.
struct Result {
  std::size_t sequence = 0;  // its place in the strategy's order
  std::size_t point = 0;     // index into the valid points
  nlohmann::json params;     // point_params
  TuneMeasurement m;
  bool cached = false, within_budget = true;
  double compile_ms = 0, verify_ms = 0;
  std::string timestamp;
};

nlohmann::json result_json(const Result& r) {
  return {{"sequence", r.sequence},
          {"params", r.params},
          {"cached", r.cached},
          {"verified", r.m.verified},
          {"max_error", r.m.max_error},
          {"nmse", number_or_null(r.m.nmse)},
          {"within_budget", r.within_budget},
          {"frame_ms", r.m.objective},
          {"frame_ms_samples", r.m.times},
          {"timing", timing_json(r.m.times, 1)},
          {"compile_ms", r.compile_ms},
          {"verify_ms", r.verify_ms},
          {"timestamp", r.timestamp}};
}

Result result_from_json(const nlohmann::json& j, std::size_t point) {
  Result r;
  r.sequence = j.at("sequence");
  r.point = point;
  r.params = j.at("params");
  r.cached = j.at("cached");
  r.m.verified = j.at("verified");
  r.m.max_error = j.at("max_error");
  r.m.nmse = j.at("nmse").is_null() ? std::numeric_limits<double>::infinity() : j.at("nmse").get<double>();
  r.within_budget = j.at("within_budget");
  r.m.objective = j.at("frame_ms");
  r.m.times = j.at("frame_ms_samples").get<std::vector<double>>();
  r.compile_ms = j.at("compile_ms");
  r.verify_ms = j.at("verify_ms");
  r.timestamp = j.at("timestamp");
  return r;
}

bool eligible(const Result& r) { return r.m.verified && r.within_budget; }

// The render options that give `o` on the command line (the shading and the layout).
std::string render_flags(const RenderOptions& o) {
  std::string s = std::string("--method ") + (o.method == Method::combined ? combined_name(o.combined) : method_name(o.method));
  if (o.units) s += " --units " + unit_name(*o.units);
  if (o.normalize.kind != NormalizeKind::exact) s += " --normalize " + normalize_name(o.normalize);
  if (o.specular.kind != SpecularKind::exact) s += " --specular " + specular_name(o.specular);
  s += " --tile " + std::to_string(o.tile_size) + " --work-items " + std::to_string(o.work_items);
  if (o.plan) {
    s += " --cu " + std::to_string(o.plan->units) + " --partition " + partition_name(o.plan->partition);
    if (o.plan->partition == Partition::dynamic) s += " --batch " + std::to_string(o.plan->batch);
  }
  return s;
}

// The tune report (--report): one function, so that the report's header and schema live in one place.
nlohmann::json tune_report(const TuneArgs& a, const Scene& scene, const DeviceInfo& dev, const TuneSpace& space,
                           const TunePoints& points, const std::vector<Result>& results, const Result* best,
                           const nlohmann::json& confirmation) {
  nlohmann::json space_json = nlohmann::json::object();
  for (std::size_t i = 0; i < space.names.size(); ++i) space_json[space.names[i]] = space.values[i];
  nlohmann::json candidates = nlohmann::json::array();
  for (const Result& r : results) candidates.push_back(result_json(r));
  return {{"scene", scene.name},
          {"scene_file", a.scene},
          {"width", scene.width},
          {"height", scene.height},
          {"device", to_json(dev)},
          {"frames", a.frames},
          {"strategy", a.strategy},
          {"seed", a.seed},
          {"objective",
           {{"kind", a.objective},
            {"max_error", a.max_error > 0 ? nlohmann::json(a.max_error) : nlohmann::json()},
            {"max_nmse", a.max_nmse > 0 ? nlohmann::json(a.max_nmse) : nlohmann::json()},
            {"error_against", "exact Phong (double-precision reference), 8-bit levels"}}},
          {"space", space_json},
          {"points", {{"valid", points.valid.size()}, {"refused", points.refused}, {"not_applicable", points.not_applicable}}},
          {"candidates", candidates},
          {"best", best ? result_json(*best) : nlohmann::json()},
          {"confirmation", confirmation}};
}

void write_tune_report(const std::string& path, const nlohmann::json& report) {
  if (!path.empty()) write_report(path, report, "tune");
}

int run_tune(const TuneArgs& a) {
  // The command line first (usage errors), then the scene, then the device.
  if (a.budget_runs < 1) throw UsageError("--budget-runs must be at least 1");
  if (a.budget_seconds < 0) throw UsageError("--budget-seconds must not be negative");
  if (a.frames < 1 || a.frames > kMaxFrames) throw UsageError("--frames must be 1.." + std::to_string(kMaxFrames));
  if (a.objective != "fastest")
    throw UsageError("--objective: unknown objective '" + a.objective +
                     "' (valid: fastest; with --max-error or --max-nmse, fastest within that error budget)");
  if (a.max_error < 0 || a.max_error > 255) throw UsageError("--max-error must be in (0, 255] levels");
  if (a.max_nmse < 0 || !std::isfinite(a.max_nmse)) throw UsageError("--max-nmse must be a positive number");
  const TuneStrategy strategy = parse_tune_strategy(a.strategy);
  if (a.mpi && strategy == TuneStrategy::anneal)
    throw UsageError("--mpi deals a known list of candidates across the ranks; anneal chooses each candidate from the "
                     "last one's time (use --strategy brute or random with --mpi)");
  const auto size = parse_size(a.size);
  RenderOptions base;
  base.method = parse_method(a.method);
  if (base.method == Method::combined) base.combined = parse_combined(a.method);
  // The space needs the device's compute units for its defaults; the explicit values are checked now.
  {
    TuneSpace probe = default_tune_space(a.method, 1);
    for (const std::string& p : a.params) set_tune_param(probe, p);
  }

  std::unique_ptr<RankGroup> group;
  if (a.mpi) group = RankGroup::join();
  const int rank = group ? group->rank() : 0, ranks = group ? group->size() : 1;
  const auto step = [&](const std::function<void()>& f) { step_in(group.get(), f); };
  Scene scene;
  std::unique_ptr<Device> device;
  std::unique_ptr<TuneCache> cache;
  TuneSpace space;
  TunePoints points;
  step([&] {
    scene = load_scene_at(a.scene, size, a.size);
    // The default configuration is the layout `render` takes without --tile (tile_choice.hpp).
    base.tile_size = default_tile_size(scene, base, base.band_record_bytes);
    if (rank == 0) {
      if (!a.report.empty()) check_report_destination(a.report);
      if (!a.export_kt.empty()) check_report_destination(a.export_kt);
    }
    cache = std::make_unique<TuneCache>(a.cache.empty() ? default_tune_cache() : std::filesystem::path(a.cache));
    device = for_device(a.device_origin, [&] { return open_device(a.device); });
    space = default_tune_space(a.method, device->info().compute_units);
    for (const std::string& p : a.params) set_tune_param(space, p);
    points = enumerate_points(space, base);
    if (points.valid.empty()) throw UsageError("--param: the space has no point the table of combinations models");
  });
  const DeviceInfo& dev = device->info();
  if (rank == 0) {
    std::printf("tuning %s (%dx%d) on %s (driver %s, %d compute units)%s; cache %s\n", scene.name.c_str(), scene.width,
                scene.height, dev.name.c_str(), dev.driver.c_str(), dev.compute_units,
                group ? (" over " + std::to_string(ranks) + " ranks").c_str() : "", cache->path().string().c_str());
    std::printf("space: %zu points: %zu valid, %zu refused by the table of combinations, %zu vary units or batch "
                "where nothing reads them; strategy %s, seed %llu\n",
                space_size(space), points.valid.size(), points.refused, points.not_applicable, a.strategy.c_str(),
                (unsigned long long)a.seed);
    if (!points.refusal_example.empty() && !a.quiet) std::cerr << "parashade: note: refused, e.g. " << points.refusal_example << "\n";
    if (const std::string stale = cache->stale_entries(dev); !stale.empty() && !a.quiet)
      std::cerr << "parashade: note: " << stale << "\n";
  }

  const auto started = std::chrono::steady_clock::now();
  const auto elapsed_s = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(); };
  const auto out_of_time = [&] { return a.budget_seconds > 0 && elapsed_s() >= a.budget_seconds; };
  std::map<std::string, std::vector<std::uint8_t>> verified_bytes;  // per shading: the default layout's image
  std::map<std::string, ReferenceImage> references;                  // per method: the exact reference
  const auto problem_of = [&](const RenderOptions& o) {
    const std::optional<TuneProblem> p = tune_problem(scene, o);
    if (!p) throw std::logic_error("tune: a candidate the cache cannot key");
    return *p;
  };
  const auto within_budget = [&](const TuneMeasurement& m) {
    return (a.max_error <= 0 || m.max_error <= a.max_error) && (a.max_nmse <= 0 || m.nmse <= a.max_nmse);
  };
  const auto cached_result = [&](std::size_t i) -> std::optional<Result> {
    const RenderOptions o = options_at(space, points.valid[i], base);
    const auto e = cache->find(dev, problem_of(o), tuned_params(o));
    if (!e || !e->contains("max_error")) return std::nullopt;
    Result r;
    r.point = i;
    r.params = point_params(space, points.valid[i]);
    r.cached = true;
    r.m.times = e->value("times_ms", std::vector<double>{});
    r.m.objective = e->value("objective", 0.0);
    r.m.verified = e->value("verified", false);
    r.m.max_error = e->value("max_error", 0.0);
    r.m.nmse = (*e)["nmse"].is_number() ? (*e)["nmse"].get<double>() : std::numeric_limits<double>::infinity();
    r.within_budget = within_budget(r.m);
    return r;
  };
  // Measures point i: warm-up (program build), the timed frames, the image against its shading's
  // default layout (the layout never changes the image) and against the exact reference.
  const auto measure = [&](std::size_t i) {
    const RenderOptions o = options_at(space, points.valid[i], base);
    Result r;
    r.point = i;
    r.params = point_params(space, points.valid[i]);
    r.timestamp = utc_now_iso8601();
    Renderer renderer(*device, o);
    auto t0 = std::chrono::steady_clock::now();
    renderer.render(scene);
    r.compile_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    const Frame* f = nullptr;
    for (int k = 0; k < a.frames; ++k) {
      f = &renderer.render(scene);
      r.m.times.push_back(f->timings.total_ms);
    }
    r.m.objective = median(r.m.times);
    t0 = std::chrono::steady_clock::now();
    const TuneProblem problem = problem_of(o);
    const std::string shading = problem.to_json().dump();
    const std::vector<std::uint8_t> bytes(f->image.rgba.begin(), f->image.rgba.end());
    if (!verified_bytes.count(shading)) {
      RenderOptions plain = o;
      plain.tile_size = base.tile_size;
      plain.work_items = base.work_items;
      plain.plan.reset();
      if (plain.tile_size == o.tile_size && plain.work_items == o.work_items && !o.plan) {
        verified_bytes[shading] = bytes;
      } else {
        Renderer reference(*device, plain);
        const Frame& g = reference.render(scene);
        verified_bytes[shading].assign(g.image.rgba.begin(), g.image.rgba.end());
      }
    }
    r.m.verified = verified_bytes[shading] == bytes;
    const std::string method = problem.method;
    if (!references.count(method)) {
      ScreenGeometry g;
      build_screen_geometry(scene, {o.method, true}, g);
      references[method] = render_reference(scene, g, o.method);
    }
    const ReferenceImage& ref = references[method];
    const ErrorMetrics e = compare_to_reference(f->image, ref.covered, ref.exact, "exact phong");
    r.m.max_error = e.max_abs;
    r.m.nmse = e.nmse;
    r.within_budget = within_budget(r.m);
    r.verify_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    return r;
  };
  // A candidate as the parameters the space varies ("tile=32 work_items=8"), or "default" for none.
  const auto varied = [&](const nlohmann::json& params) {
    std::string s;
    for (std::size_t i = 0; i < space.names.size(); ++i)
      if (space.values[i].size() > 1 && params[space.names[i]] != "-") {
        const nlohmann::json& v = params[space.names[i]];
        s += (s.empty() ? "" : " ") + space.names[i] + "=" + (v.is_string() ? v.get<std::string>() : v.dump());
      }
    return s.empty() ? std::string("the one point") : s;
  };
  const auto print_result = [&](const Result& r) {
    std::string flags;
    if (!r.m.verified) flags += "  IMAGE DIFFERS from its shading's default layout: not eligible";
    if (!r.within_budget) flags += "  over the error budget";
    if (r.cached) flags += "  (cached)";
    std::printf("%-60s %9.3f ms  max %6.2f  NMSE %.3g%s\n", varied(r.params).c_str(), r.m.objective, r.m.max_error,
                r.m.nmse, flags.c_str());
    std::fflush(stdout);
  };
  const auto record = [&](const Result& r, bool write_now) {
    if (r.cached) return;
    const RenderOptions o = options_at(space, points.valid[r.point], base);
    cache->add(dev, problem_of(o), tuned_params(o), r.m);
    if (write_now) cache->write();
  };

  std::vector<Result> results;
  std::size_t skipped = 0;
  step([&] {
    if (strategy == TuneStrategy::anneal) {
      FrameProgress progress(a.budget_runs, a.quiet);
      std::vector<int> counts;
      for (const auto& v : space.values) counts.push_back(int(v.size()));
      const auto cost = [&](std::size_t i) {
        std::optional<Result> r = cached_result(i);
        if (!r) r = measure(i);
        r->sequence = results.size();
        record(*r, true);
        print_result(*r);
        results.push_back(*r);
        progress.step(int(results.size()));
        return eligible(*r) ? r->m.objective : std::numeric_limits<double>::infinity();
      };
      anneal(points.valid, counts, cost, std::size_t(a.budget_runs), a.seed, out_of_time);
      return;
    }
    std::vector<bool> planned;
    for (const TunePoint& p : points.valid) planned.push_back(point_params(space, p)["partition"] != "none");
    const TunePoint first = default_point(space, base);
    long first_index = -1;
    for (std::size_t i = 0; i < points.valid.size() && !first.empty(); ++i)
      if (points.valid[i] == first) first_index = long(i);
    // The candidates to measure: the strategy's order without what the cache holds, up to the budget;
    // the same list on every rank, candidate k measured by rank k mod N.
    std::vector<std::size_t> todo;
    for (std::size_t i : visit_order(strategy, points.valid.size(), first_index, planned, a.seed)) {
      if (todo.size() >= std::size_t(a.budget_runs)) break;
      if (cached_result(i)) ++skipped;
      else todo.push_back(i);
    }
    std::size_t mine = 0;
    for (std::size_t k = 0; k < todo.size(); ++k) mine += int(k % std::size_t(ranks)) == rank;
    FrameProgress progress(int(mine), a.quiet || rank != 0);
    int done = 0;
    for (std::size_t k = 0; k < todo.size(); ++k) {
      if (int(k % std::size_t(ranks)) != rank) continue;
      if (out_of_time()) break;
      Result r = measure(todo[k]);
      r.sequence = k;
      if (!group) {  // with --mpi rank 0 records and prints the merged results
        record(r, true);
        print_result(r);
      }
      results.push_back(r);
      progress.step(++done);
    }
  });

  if (group) {
    // Every rank's results to rank 0, which merges them in the strategy's order and writes the cache.
    nlohmann::json sent = nlohmann::json::array();
    for (const Result& r : results) {
      nlohmann::json j = result_json(r);
      j["point"] = r.point;
      sent.push_back(j);
    }
    const std::vector<std::string> got = group->gather(sent.dump());
    if (rank != 0) {
      step([] {});  // rank 0's report
      return 0;
    }
    for (std::size_t q = 1; q < got.size(); ++q)
      for (const auto& j : nlohmann::json::parse(got[q])) results.push_back(result_from_json(j, j.at("point")));
    std::sort(results.begin(), results.end(), [](const Result& x, const Result& y) { return x.sequence < y.sequence; });
    for (const Result& r : results) {
      print_result(r);
      if (r.point < points.valid.size()) record(r, false);
    }
  }

  // Rank 0 alone from here (the others wait in the step for its outcome).
  step([&] {
  // The best: this run's candidates and whatever the cache holds for the space's points.
  std::vector<Result> known = results;
  for (std::size_t i = 0; i < points.valid.size(); ++i)
    if (std::none_of(results.begin(), results.end(), [&](const Result& r) { return r.point == i; }))
      if (auto r = cached_result(i)) known.push_back(*r);
  const Result* best = nullptr;
  for (const Result& r : known)
    if (eligible(r) && (!best || r.m.objective < best->m.objective)) best = &r;
  std::size_t over_budget = 0, unverified = 0;
  for (const Result& r : results) {
    over_budget += !r.within_budget;
    unverified += !r.m.verified;
  }
  std::printf("measured %zu configuration(s) (%zu over the error budget, %zu with a different image), %zu already in "
              "the cache\n",
              std::count_if(results.begin(), results.end(), [](const Result& r) { return !r.cached; }), over_budget,
              unverified, skipped);

  nlohmann::json confirmation;
  if (best) {
    const RenderOptions tuned = options_at(space, points.valid[best->point], base);
    std::printf("best%s: %s at %.3f ms when it was tried (max error %.2f levels, NMSE %.3g)\n",
                a.max_error > 0 || a.max_nmse > 0 ? " within the error budget" : "", varied(best->params).c_str(),
                best->m.objective, best->m.max_error, best->m.nmse);
    std::printf("render with: %s\n", render_flags(tuned).c_str());
    // The speed-up, measured now: default and best alternately (the machine's load drifts), medians.
    Renderer plain(*device, base), fast(*device, tuned);
    plain.render(scene);
    fast.render(scene);
    std::vector<double> t_plain, t_fast;
    for (int i = 0; i < std::max(5, a.frames); ++i) {
      t_plain.push_back(plain.render(scene).timings.total_ms);
      t_fast.push_back(fast.render(scene).timings.total_ms);
    }
    confirmation = {{"frames", t_plain.size()},        {"default_ms", median(t_plain)},
                    {"tuned_ms", median(t_fast)},        {"speedup", median(t_plain) / median(t_fast)},
                    {"default", timing_json(t_plain, 1)}, {"tuned", timing_json(t_fast, 1)}};
    std::printf("confirmation (%zu alternating frames each): default %.3f ms, tuned %.3f ms: speed-up %.2fx\n",
                t_plain.size(), median(t_plain), median(t_fast), median(t_plain) / median(t_fast));
  } else {
    std::printf("no candidate is eligible (verified%s)\n", a.max_error > 0 || a.max_nmse > 0 ? " and within the error budget" : "");
  }
  const nlohmann::json report = tune_report(a, scene, dev, space, points, results, best, confirmation);
    if (group) cache->write();
    write_tune_report(a.report, report);
    if (!a.export_kt.empty())
      write_text_atomically(a.export_kt,
                            kernel_tuner_cache(space, dev.name, "parashade:" + scene.name, scene.width, scene.height,
                                               report["candidates"])
                                    .dump(1) +
                                "\n");
  if (!a.report.empty()) std::printf("wrote %s\n", a.report.c_str());
  if (!a.export_kt.empty()) std::printf("wrote %s (Kernel Tuner cache format)\n", a.export_kt.c_str());
  });
  return 0;
}

}  // namespace

Command add_tune_command(CLI::App& app) {
  auto a = std::make_shared<TuneArgs>();
  auto* cmd = app.add_subcommand(
      "tune", "Search render configurations (layout, method, unit, normalization, specular model) for a scene: the "
              "fastest, within an error budget when given; cache the results (docs/tuning.md)");
  cmd->add_option("scene", a->scene, "Scene file (.json) or mesh")->required();
  add_size_option(*cmd, a->size);
  add_device_option(*cmd, a->device, "OpenCL device: index or name substring");
  cmd->add_option("--method", a->method, "Shading method when --param method is not given: flat, gouraud, phong, combined:K|auto")
      ->capture_default_str();
  cmd->add_option("--param", a->params,
                  "NAME=V1,V2,... (repeatable): the values of one parameter of the space: tile, work_items, partition, "
                  "units (U, modeled units), batch, method, unit (as --units), normalize, specular");
  cmd->add_option("--strategy", a->strategy, "brute, random or anneal (simulated annealing)")->capture_default_str();
  cmd->add_option("--seed", a->seed, "Seed of the strategy's random choices (the same seed, the same sequence)")
      ->capture_default_str();
  cmd->add_option("--objective", a->objective, "fastest (within --max-error / --max-nmse when given)")
      ->capture_default_str();
  cmd->add_option("--max-error", a->max_error,
                  "Error budget: the largest error against the exact reference, in 8-bit levels, a candidate may have");
  cmd->add_option("--max-nmse", a->max_nmse, "Error budget: the largest NMSE against the exact reference");
  cmd->add_option("--budget-runs", a->budget_runs,
                  "Configurations to measure in this run (brute, random: cached ones are skipped; anneal: every "
                  "distinct point it evaluates)")
      ->capture_default_str();
  cmd->add_option("--budget-seconds", a->budget_seconds, "Stop starting new configurations after this many seconds (0: no limit)");
  cmd->add_option("--frames", a->frames, "Timed frames per configuration (median)")->capture_default_str();
  cmd->add_option("--cache", a->cache, "Tune cache file (default $PARASHADE_TUNE_CACHE or ~/.cache/parashade/tune.json)");
  add_report_option(*cmd, a->report, "the space, every candidate with its frame samples, the best, the confirmation");
  cmd->add_option("--export-kt", a->export_kt, "Write the candidates as a Kernel Tuner cache file (docs/tuning.md)");
  cmd->add_flag("--mpi", a->mpi,
                "Under mpirun: deal the candidates across the ranks (brute, random); rank 0 writes the merged report "
                "and the cache");
  add_quiet_flag(*cmd, a->quiet);
  return {cmd, [a]() {
            a->device_origin = device_from_environment(a->device);
            return run_tune(*a);
          }};
}

}  // namespace parashade::cli
