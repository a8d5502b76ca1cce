// `parashade tune SCENE`: searches a space of render configurations (tune_space.hpp: layout and shading
// parameters, `--param NAME=V1,V2,...`) by a strategy (tune_strategy.hpp: brute, random, anneal), measures
// each candidate's frame time, verifies its image and measures its error against the exact reference,
// and appends every result to the tune cache (tune_cache.hpp), which `render` then uses for this device,
// build and problem. The objective is the fastest candidate, within an error budget when one is given;
// `--objective pareto` adds the speed-vs-error front (tune_pareto.hpp). `--restrict EXPR` excludes points
// (tune_restrict.hpp); `--export-kt` and `--export-t4` write the space for Kernel Tuner (tune_export.hpp).
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
#include "suggest.hpp"
#include "parashade/distributed.hpp"
#include "parashade/errors.hpp"
#include "parashade/json_number.hpp"
#include "parashade/metrics.hpp"
#include "parashade/notes.hpp"
#include "parashade/reference.hpp"
#include "parashade/command_files.hpp"
#include "parashade/render_step.hpp"
#include "parashade/renderer.hpp"
#include "parashade/report.hpp"
#include "parashade/report_header.hpp"
#include "parashade/statistics.hpp"
#include "parashade/tile_choice.hpp"
#include "../render/tune_cache.hpp"
#include "tune_export.hpp"
#include "tune_pareto.hpp"
#include "tune_restrict.hpp"
#include "tune_space.hpp"
#include "tune_strategy.hpp"

namespace parashade::cli {
namespace {

struct TuneArgs {
  std::string scene, size, device, method = "gouraud", cache, strategy = "brute", objective = "fastest", report, export_kt,
      export_t4;
  std::vector<std::string> params;          // --param NAME=V1,V2,...
  std::vector<std::string> restrict_exprs;  // --restrict EXPR
  int budget_runs = 12, frames = 5;
  double budget_seconds = 0, max_error = 0, max_nmse = 0;  // budgets: 0 = none
  std::uint64_t seed = 2026;
  bool mpi = false, quiet = false;
  double rank_timeout = 0;  // --mpi: the rank watchdog (off: a rank's whole search is one wait)
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

// A candidate's frames as their range, "(min..max)" in ms.
std::string spread(const std::vector<double>& times) {
  if (times.empty()) return "(no samples)";
  char text[64];
  std::snprintf(text, sizeof text, "(%.3f..%.3f)", *std::min_element(times.begin(), times.end()),
                *std::max_element(times.begin(), times.end()));
  return text;
}

nlohmann::json result_json(const Result& r) {
  return {{"sequence", r.sequence},
          {"params", r.params},
          {"cached", r.cached},
          {"verified", r.m.verified},
          {"max_abs", r.m.max_error},
          {"nmse", number_or_null(r.m.nmse)},
          {"within_budget", r.within_budget},
          {"frame_ms", r.m.objective},
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
  r.m.max_error = j.at("max_abs");
  r.m.nmse = j.at("nmse").is_null() ? std::numeric_limits<double>::infinity() : j.at("nmse").get<double>();
  r.within_budget = j.at("within_budget");
  r.m.objective = j.at("frame_ms");
  r.m.times = j.at("timing").at("samples_ms").get<std::vector<double>>();
  r.compile_ms = j.at("compile_ms");
  r.verify_ms = j.at("verify_ms");
  r.timestamp = j.at("timestamp");
  return r;
}

bool eligible(const Result& r) { return r.m.verified && r.within_budget; }

// The tune report (--report): one function, so that the report's header and schema live in one place.
nlohmann::json tune_report(const TuneArgs& a, const Scene& scene, const DeviceInfo& dev, const TuneSpace& space,
                           const TunePoints& points, std::size_t restricted, const std::vector<Result>& results,
                           const Result* best, const nlohmann::json& confirmation) {
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
            {"error_against", "exact Phong (double-precision reference), 8-bit levels"},
            {"restrictions", a.restrict_exprs}}},
          {"space", space_json},
          {"points",
           {{"valid", points.valid.size()},
            {"refused", points.refused},
            {"not_applicable", points.not_applicable},
            {"restricted", restricted}}},
          {"candidates", candidates},
          {"best", best ? result_json(*best) : nlohmann::json()},
          {"confirmation", confirmation}};
}

void write_tune_report(const std::string& path, const nlohmann::json& report) {
  if (!path.empty()) write_report(path, report, "tune");
}

// The command line's values (usage errors, before any file is read).
// Returns the --restrict expressions, parsed (once: the run evaluates these).
std::vector<TuneRestriction> check_tune_args(const TuneArgs& a, TuneStrategy strategy) {
  if (a.budget_runs < 1) throw UsageError("--budget-runs must be at least 1");
  if (a.budget_seconds < 0) throw UsageError("--budget-seconds must not be negative");
  if (a.frames < 1 || a.frames > kMaxFrames) throw UsageError("--frames must be 1.." + std::to_string(kMaxFrames));
  if (a.objective != "fastest" && a.objective != "pareto")
    throw UsageError("--objective: unknown objective '" + a.objective +
                     "' (valid: fastest, within --max-error or --max-nmse when given; pareto, the speed-vs-error front)" +
                     did_you_mean(a.objective, {"fastest", "pareto"}));
  if (!(a.max_error >= 0 && a.max_error <= 255)) throw UsageError("--max-error must be in (0, 255] levels");  // NaN too
  if (a.max_nmse < 0 || !std::isfinite(a.max_nmse)) throw UsageError("--max-nmse must be a positive number");
  if (a.mpi && strategy == TuneStrategy::anneal)
    throw UsageError("--mpi deals a known list of candidates across the ranks; anneal chooses each candidate from the "
                     "last one's time (use --strategy brute or random with --mpi)");
  // The space needs the device's compute units for its defaults; the explicit values are checked now.
  TuneSpace probe = default_tune_space(a.method, 1);
  for (const std::string& p : a.params) set_tune_param(probe, p);
  std::vector<TuneRestriction> restrictions = parse_restrictions(a.restrict_exprs);
  // Kernel Tuner reads them as Python: one that does not translate stops the run now, not after the search.
  if (!a.export_kt.empty())
    for (const TuneRestriction& r : restrictions) r.python();
  return restrictions;
}

// One tuning run: the scene on the device (the render step's base), the space, the cache, and what the
// candidates measured.
class TuneRun {
 public:
  TuneRun(const TuneArgs& a, std::vector<TuneRestriction> restrictions)
      : a_(a), strategy_(parse_tune_strategy(a.strategy)), restrictions_(std::move(restrictions)) {
    request_.scene_file = a.scene;
    request_.size = checked_size(a.size);
    request_.device = a.device;
    request_.options.tile_size = 0;  // render's choice for the scene (tile_choice.hpp): the default point's
    request_.options.method = parse_method(a.method);
    if (request_.options.method == Method::combined) request_.options.combined = parse_combined(a.method);
    request_.use_tuned = false;  // the default configuration: the layout `render` takes without --tile (tile_choice.hpp)
    request_.device_kernel_shape = true;  // and without --kernel-shape (device_layout.hpp)
    request_.quiet = a.quiet;
  }

  // `group`: the ranks of tune --mpi, or none.
  int run(RankGroup* group) {
    group_ = group;
    step([&] { prepare(); });
    if (rank() == 0) print_start();
    step([&] { search(); });
    if (group_ && !merge_ranks()) return 0;
    // Rank 0 alone from here (the others wait in the step for its outcome).
    step([&] { conclude(); });
    return 0;
  }

 private:
  int rank() const { return group_ ? group_->rank() : 0; }
  int ranks() const { return group_ ? group_->size() : 1; }
  void step(const std::function<void()>& f) { step_in(group_, f); }

  void prepare() {
    CommandFiles files;
    if (rank() == 0) {
      files.output("--report", a_.report);
      files.output("--export-kt", a_.export_kt);
      files.output("--export-t4", a_.export_t4);
    }
    const std::filesystem::path cache = a_.cache.empty() ? default_tune_cache() : std::filesystem::path(a_.cache);
    // The default cache's folder (~/.cache/parashade) is parashade's to make: on a fresh machine the check
    // of the outputs' folders refused it. A folder --cache or PARASHADE_TUNE_CACHE names must exist.
    const std::string origin = tune_cache_origin(a_.cache, "--cache");
    std::error_code ec;
    if (origin.empty() && cache.has_parent_path() && rank() == 0) std::filesystem::create_directories(cache.parent_path(), ec);
    files.input_output(origin.empty() ? "the tune cache" : origin, cache);
    base_ = std::make_unique<ResolvedRender>(resolve_with_option_names(request_, files));
    cache_ = std::make_unique<TuneCache>(cache);
    space_ = default_tune_space(a_.method, device().compute_units);
    for (const std::string& p : a_.params) set_tune_param(space_, p);
    points_ = enumerate_points(space_, base_->options);
    if (points_.valid.empty()) throw UsageError("--param: the space has no point the table of combinations models");
    restrict_points();
  }

  // --restrict: the points an expression excludes leave the search (the export still names them).
  void restrict_points() {
    std::vector<TunePoint> kept;
    for (const TunePoint& p : points_.valid) (allowed(restrictions_, space_, p) ? kept : restricted_).push_back(p);
    if (kept.empty())
      throw UsageError("--restrict: the restrictions exclude every one of the space's " +
                       std::to_string(points_.valid.size()) + " valid points");
    points_.valid = kept;
  }

  const DeviceInfo& device() const { return base_->devices.front()->info(); }
  RenderOptions options(std::size_t i) const { return options_at(space_, points_.valid[i], base_->options); }

  void print_start() const {
    const Scene& scene = base_->scene;
    const DeviceInfo& dev = device();
    std::printf("tuning %s (%dx%d) on %s (driver %s, %d compute units)%s; cache %s\n", scene.name.c_str(), scene.width,
                scene.height, dev.name.c_str(), dev.driver.c_str(), dev.compute_units,
                group_ ? (" over " + std::to_string(ranks()) + " ranks").c_str() : "", cache_->path().string().c_str());
    const std::string restricted =
        restrictions_.empty() ? "" : ", " + std::to_string(restricted_.size()) + " excluded by --restrict";
    std::printf("space: %zu points: %zu valid, %zu refused by the table of combinations, %zu vary cu or batch "
                "where nothing reads them%s; strategy %s, seed %llu\n",
                space_size(space_), points_.valid.size(), points_.refused, points_.not_applicable, restricted.c_str(),
                a_.strategy.c_str(), (unsigned long long)a_.seed);
    print_resolved(*base_);
    if (!points_.refusal_example.empty() && !a_.quiet)
      print_note("refused, e.g. " + points_.refusal_example);
    if (const std::string stale = cache_->stale_entries(dev); !stale.empty() && !a_.quiet)
      print_note(stale);
    if (const std::string aside = cache_->set_aside(); !aside.empty()) std::cerr << "parashade: warning: " << aside << "\n";
  }

  TuneProblem problem_of(const RenderOptions& o) const {
    const std::optional<TuneProblem> p = tune_problem(base_->scene, o);
    if (!p) throw std::logic_error("tune: a candidate the cache cannot key");
    return *p;
  }

  bool within_budget(const TuneMeasurement& m) const {
    return (a_.max_error <= 0 || m.max_error <= a_.max_error) && (a_.max_nmse <= 0 || m.nmse <= a_.max_nmse);
  }

  std::optional<Result> cached_result(std::size_t i) const {
    const RenderOptions o = options(i);
    const auto e = cache_->find(device(), problem_of(o), tuned_params(o));
    if (!e || !e->contains("max_error")) return std::nullopt;
    Result r;
    r.point = i;
    r.params = point_params(space_, points_.valid[i]);
    r.cached = true;
    r.m.times = e->value("times_ms", std::vector<double>{});
    r.m.objective = e->value("objective", 0.0);
    r.m.verified = e->value("verified", false);
    r.m.max_error = e->value("max_error", 0.0);
    r.m.nmse = (*e)["nmse"].is_number() ? (*e)["nmse"].get<double>() : std::numeric_limits<double>::infinity();
    r.within_budget = within_budget(r.m);
    return r;
  }

  // The bytes of the candidate's shading in the default layout (the layout never changes the image).
  const std::vector<std::uint8_t>& verified_bytes(const RenderOptions& o, const std::vector<std::uint8_t>& bytes) {
    const std::string shading = problem_of(o).to_json().dump();
    auto it = verified_bytes_.find(shading);
    if (it != verified_bytes_.end()) return it->second;
    RenderOptions plain = o;
    plain.tile_size = base_->options.tile_size;
    plain.work_items = base_->options.work_items;
    plain.kernel_shape = base_->options.kernel_shape;
    plain.work_group_size = base_->options.work_group_size;
    plain.plan.reset();
    if (tuned_params(plain) == tuned_params(o)) return verified_bytes_[shading] = bytes;  // o is the default layout
    const ResolvedRender reference = with_options(*base_, plain);
    RenderSession session(reference);
    const Frame& g = session.frame();
    return verified_bytes_[shading] = std::vector<std::uint8_t>(g.image.rgba.begin(), g.image.rgba.end());
  }

  // Measures point i: warm-up (program build), the timed frames, the image against its shading's
  // default layout and against the exact reference.
  Result measure(std::size_t i) {
    const RenderOptions o = options(i);
    Result r;
    r.point = i;
    r.params = point_params(space_, points_.valid[i]);
    r.timestamp = utc_now_iso8601();
    const ResolvedRender candidate = with_options(*base_, o);
    RenderSession session(candidate);
    auto t0 = std::chrono::steady_clock::now();
    session.frame();
    r.compile_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    const Frame* f = nullptr;
    for (int k = 0; k < a_.frames; ++k) {
      f = &session.frame();
      r.m.times.push_back(f->timings.total_ms);
    }
    r.m.objective = median(r.m.times);
    t0 = std::chrono::steady_clock::now();
    const std::vector<std::uint8_t> bytes(f->image.rgba.begin(), f->image.rgba.end());
    r.m.verified = verified_bytes(o, bytes) == bytes;
    const std::string method = problem_of(o).method;
    if (!references_.count(method)) references_[method] = exact_reference(base_->scene, o.method);
    const ErrorFigures e = error_against(references_[method], o.method, f->image);
    r.m.max_error = e.method.max_abs;
    r.m.nmse = e.method.nmse;
    r.within_budget = within_budget(r.m);
    r.verify_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    return r;
  }

  // A candidate as the parameters the space varies ("tile=32 work_items=8"), or "the one point".
  std::string varied(const nlohmann::json& params) const {
    std::string s;
    for (std::size_t i = 0; i < space_.names.size(); ++i)
      if (space_.values[i].size() > 1 && params[space_.names[i]] != "-") {
        const nlohmann::json& v = params[space_.names[i]];
        s += (s.empty() ? "" : " ") + space_.names[i] + "=" + (v.is_string() ? v.get<std::string>() : v.dump());
      }
    return s.empty() ? std::string("the one point") : s;
  }

  // The median frame and the spread of the candidate's frames (min..max), so that two candidates whose
  // ranges overlap are not read as one faster than the other.
  void print_result(const Result& r) const {
    std::string flags;
    if (!r.m.verified) flags += "  IMAGE DIFFERS from its shading's default layout: not eligible";
    if (!r.within_budget) flags += "  over the error budget";
    if (r.cached) flags += "  (cached)";
    std::printf("%-60s %9.3f ms %-19s  max %6.2f  NMSE %.3g%s\n", varied(r.params).c_str(), r.m.objective,
                spread(r.m.times).c_str(), r.m.max_error, r.m.nmse, flags.c_str());
    std::fflush(stdout);
  }

  void record(const Result& r, bool write_now) {
    if (r.cached) return;
    const RenderOptions o = options(r.point);
    cache_->add(device(), problem_of(o), tuned_params(o), r.m);
    if (write_now) cache_->write();
  }

  void search() {
    if (strategy_ == TuneStrategy::anneal) return search_anneal();
    search_list();
  }

  void search_anneal() {
    FrameProgress progress(a_.budget_runs, a_.quiet);
    std::vector<int> counts;
    for (const auto& v : space_.values) counts.push_back(int(v.size()));
    const auto cost = [&](std::size_t i) {
      std::optional<Result> r = cached_result(i);
      if (!r) r = measure(i);
      r->sequence = results_.size();
      record(*r, true);
      print_result(*r);
      results_.push_back(*r);
      progress.step(int(results_.size()));
      return eligible(*r) ? r->m.objective : std::numeric_limits<double>::infinity();
    };
    anneal(points_.valid, counts, cost, std::size_t(a_.budget_runs), a_.seed, [&] { return out_of_time(); });
  }

  bool out_of_time() const {
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
    return a_.budget_seconds > 0 && s >= a_.budget_seconds;
  }

  // The candidates to measure: the strategy's order without what the cache holds, up to the budget; the
  // same list on every rank, candidate k measured by rank k mod N.
  std::vector<std::size_t> candidates() {
    std::vector<bool> planned;
    for (const TunePoint& p : points_.valid) planned.push_back(point_params(space_, p)["partition"] != "none");
    const TunePoint first = default_point(space_, base_->options);
    long first_index = -1;
    for (std::size_t i = 0; i < points_.valid.size() && !first.empty(); ++i)
      if (points_.valid[i] == first) first_index = long(i);
    std::vector<std::size_t> todo;
    for (std::size_t i : visit_order(strategy_, points_.valid.size(), first_index, planned, a_.seed)) {
      if (todo.size() >= std::size_t(a_.budget_runs)) break;
      if (cached_result(i)) ++skipped_;
      else todo.push_back(i);
    }
    return todo;
  }

  void search_list() {
    const std::vector<std::size_t> todo = candidates();
    std::size_t mine = 0;
    for (std::size_t k = 0; k < todo.size(); ++k) mine += int(k % std::size_t(ranks())) == rank();
    FrameProgress progress(int(mine), a_.quiet || rank() != 0);
    int done = 0;
    for (std::size_t k = 0; k < todo.size(); ++k) {
      if (int(k % std::size_t(ranks())) != rank()) continue;
      if (out_of_time()) break;
      Result r = measure(todo[k]);
      r.sequence = k;
      if (!group_) {  // with --mpi rank 0 records and prints the merged results
        record(r, true);
        print_result(r);
      }
      results_.push_back(r);
      progress.step(++done);
    }
  }

  // Every rank's results to rank 0, which merges them in the strategy's order; false on the other ranks
  // (done, after waiting in rank 0's last step).
  bool merge_ranks() {
    nlohmann::json sent = nlohmann::json::array();
    for (const Result& r : results_) {
      nlohmann::json j = result_json(r);
      j["point"] = r.point;
      sent.push_back(j);
    }
    const std::vector<std::string> got = group_->gather(sent.dump());
    if (rank() != 0) {
      step([] {});  // rank 0's report
      return false;
    }
    for (std::size_t q = 1; q < got.size(); ++q)
      for (const auto& j : nlohmann::json::parse(got[q])) results_.push_back(result_from_json(j, j.at("point")));
    std::sort(results_.begin(), results_.end(), [](const Result& x, const Result& y) { return x.sequence < y.sequence; });
    for (const Result& r : results_) {
      print_result(r);
      if (r.point < points_.valid.size()) record(r, false);
    }
    return true;
  }

  // The speed-up, measured now: default and best alternately (the machine's load drifts), medians.
  nlohmann::json confirm(const RenderOptions& tuned) {
    const ResolvedRender plain_render = with_options(*base_, base_->options), fast_render = with_options(*base_, tuned);
    RenderSession plain(plain_render), fast(fast_render);
    plain.frame();
    fast.frame();
    std::vector<double> t_plain, t_fast;
    for (int i = 0; i < std::max(5, a_.frames); ++i) {
      t_plain.push_back(plain.frame().timings.total_ms);
      t_fast.push_back(fast.frame().timings.total_ms);
    }
    // The speed-up is the median of the pairs' ratios (each pair run back to back, so a drift of the
    // machine's speed cancels), given only with its interval: a distribution-free one for that median.
    std::vector<double> ratios;
    for (std::size_t i = 0; i < t_plain.size(); ++i) ratios.push_back(t_plain[i] / t_fast[i]);
    const double speedup = median(ratios);
    const MedianInterval ci = median_interval(ratios);
    std::printf("confirmation (%zu alternating frames each): default %.3f ms, tuned %.3f ms: speed-up %.2fx, "
                "%.0f %% interval %.2fx..%.2fx (median of the %zu pairs' ratios)%s\n",
                t_plain.size(), median(t_plain), median(t_fast), speedup, 100 * ci.confidence, ci.low, ci.high,
                ratios.size(), ci.low <= 1 && 1 <= ci.high ? "; it holds 1: no difference measured" : "");
    return {{"frames", t_plain.size()},
            {"default_ms", median(t_plain)},
            {"tuned_ms", median(t_fast)},
            {"speedup", speedup},
            {"speedup_interval", {{"low", ci.low}, {"high", ci.high}, {"confidence", ci.confidence}}},
            {"default", timing_json(t_plain, 1)},
            {"tuned", timing_json(t_fast, 1)}};
  }

  // The best of this run's candidates and whatever the cache holds for the space's points, confirmed; the
  // report, the cache and the Kernel Tuner export.
  void conclude() {
    known_ = results_;
    for (std::size_t i = 0; i < points_.valid.size(); ++i)
      if (std::none_of(results_.begin(), results_.end(), [&](const Result& r) { return r.point == i; }))
        if (auto r = cached_result(i)) known_.push_back(*r);
    const std::vector<Result>& known = known_;
    const Result* best = nullptr;
    for (const Result& r : known)
      if (eligible(r) && (!best || r.m.objective < best->m.objective)) best = &r;
    std::size_t over_budget = 0, unverified = 0;
    for (const Result& r : results_) over_budget += !r.within_budget, unverified += !r.m.verified;
    std::printf("measured %zu configuration(s) (%zu over the error budget, %zu with a different image), %zu already in "
                "the cache\n",
                std::count_if(results_.begin(), results_.end(), [](const Result& r) { return !r.cached; }), over_budget,
                unverified, skipped_);
    nlohmann::json confirmation;
    if (best) {
      const RenderOptions tuned = options(best->point);
      std::printf("best%s: %s at %.3f ms %s when it was tried (max error %.2f levels, NMSE %.3g)\n",
                  a_.max_error > 0 || a_.max_nmse > 0 ? " within the error budget" : "", varied(best->params).c_str(),
                  best->m.objective, spread(best->m.times).c_str(), best->m.max_error, best->m.nmse);
      std::printf("render with: %s\n", render_flags(best->params).c_str());
      confirmation = confirm(tuned);
    } else {
      std::printf("no candidate is eligible (verified%s)\n",
                  a_.max_error > 0 || a_.max_nmse > 0 ? " and within the error budget" : "");
    }
    nlohmann::json report =
        tune_report(a_, base_->scene, device(), space_, points_, restricted_.size(), results_, best, confirmation);
    if (a_.objective == "pareto") report["pareto_front"] = pareto();
    write_outputs(report);
  }

  // --objective pareto: the front of the verified candidates (this run's and the cache's), the error budget
  // aside: the front shows what each level of error costs, the budget then picks the best. Printed fastest
  // first, in the report's candidate form.
  nlohmann::json pareto() const {
    std::vector<const Result*> verified;
    std::vector<SpeedError> points;
    for (const Result& r : known_)
      if (r.m.verified) verified.push_back(&r), points.push_back({r.m.objective, r.m.max_error});
    const std::vector<std::size_t> front = pareto_front(points);
    std::printf("speed-vs-error Pareto front (median frame time against max error; %zu of %zu verified candidates):\n",
                front.size(), points.size());
    nlohmann::json out = nlohmann::json::array();
    for (std::size_t i : front) {
      const Result& r = *verified[i];
      std::printf("  %-58s %9.3f ms %-19s  max %6.2f  NMSE %.3g%s\n", varied(r.params).c_str(), r.m.objective,
                  spread(r.m.times).c_str(), r.m.max_error, r.m.nmse, r.within_budget ? "" : "  over the error budget");
      out.push_back(result_json(r));
    }
    return out;
  }

  // The space's points for the exports: every valid one with what is known of it, and the restricted ones.
  std::vector<ExportPoint> export_points() const {
    std::vector<ExportPoint> out;
    for (std::size_t i = 0; i < points_.valid.size(); ++i) {
      ExportPoint p;
      p.params = point_params(space_, points_.valid[i]);
      for (const Result& r : known_)
        if (r.point == i) p.candidate = result_json(r);
      out.push_back(p);
    }
    for (const TunePoint& t : restricted_) {
      ExportPoint p;
      p.params = point_params(space_, t);
      p.restricted = true;
      out.push_back(p);
    }
    return out;
  }

  void write_exports() const {
    if (a_.export_kt.empty() && a_.export_t4.empty()) return;
    const std::vector<ExportPoint> points = export_points();
    ExportHeader header{device().name, "parashade:" + base_->scene.name, base_->scene.width, base_->scene.height, {}};
    for (const TuneRestriction& r : restrictions_) header.restrictions.push_back(r.python());
    if (!a_.export_kt.empty())
      write_text_atomically(a_.export_kt, kernel_tuner_cache(space_, header, points).dump(1) + "\n");
    if (!a_.export_t4.empty()) write_text_atomically(a_.export_t4, t4_results(points).dump(1) + "\n");
  }

  void write_outputs(const nlohmann::json& report) {
    if (group_) cache_->write();
    write_tune_report(a_.report, report);
    write_exports();
    // The cache was written when a candidate was measured (record) or the ranks' results merged.
    const bool cache_written = group_ || std::any_of(results_.begin(), results_.end(), [](const Result& r) { return !r.cached; });
    print_wrote({a_.report, a_.export_kt.empty() ? "" : a_.export_kt + " (Kernel Tuner cache format)",
                 a_.export_t4.empty() ? "" : a_.export_t4 + " (T4 results format)",
                 cache_written ? cache_->path().string() + " (the tune cache)" : ""});
  }

  const TuneArgs& a_;
  RankGroup* group_ = nullptr;
  TuneStrategy strategy_;
  RenderRequest request_;
  std::unique_ptr<ResolvedRender> base_;
  std::unique_ptr<TuneCache> cache_;
  TuneSpace space_;
  TunePoints points_;
  std::map<std::string, std::vector<std::uint8_t>> verified_bytes_;  // per shading: the default layout's image
  std::map<std::string, ReferenceImage> references_;                  // per method: the exact reference
  std::vector<Result> results_;
  std::vector<Result> known_;  // results_ and the cache's results of the space's points (conclude)
  std::vector<TuneRestriction> restrictions_;
  std::vector<TunePoint> restricted_;  // valid points --restrict excludes
  std::size_t skipped_ = 0;
  const std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now();
};

int run_tune(const TuneArgs& a) {
  // The command line first (usage errors), then the scene, then the device.
  TuneRun tune(a, check_tune_args(a, parse_tune_strategy(a.strategy)));
  std::unique_ptr<RankGroup> group;
  if (a.mpi) group = RankGroup::join(a.rank_timeout);
  return tune.run(group.get());
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
                  "NAME=V1,V2,... (repeatable): the values of one parameter of the space, each named as the render "
                  "option it sets: tile, work_items, kernel_shape, work_group_size, partition, cu (U, modeled units), batch, "
                  "method, units, normalize, "
                  "specular");
  cmd->add_option("--strategy", a->strategy, "brute, random or anneal (simulated annealing)")->capture_default_str();
  cmd->add_option("--seed", a->seed, "Seed of the strategy's random choices (the same seed, the same sequence)")
      ->capture_default_str();
  cmd->add_option("--objective", a->objective,
                  "fastest (within --max-error / --max-nmse when given), or pareto: also the speed-vs-error front")
      ->capture_default_str();
  cmd->add_option("--restrict", a->restrict_exprs,
                  "EXPR (repeatable): search only the points where it is true, e.g. \"tile*work_items<=4096\" "
                  "(muParser; names: tile, work_items, work_group_size, cu, batch)");
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
  cmd->add_option("--export-kt", a->export_kt,
                  "Write the searched space as a Kernel Tuner cache file its simulation mode replays (docs/tuning.md)");
  cmd->add_option("--export-t4", a->export_t4, "Write the measured candidates in the T4 results format (docs/tuning.md)");
  cmd->add_flag("--mpi", a->mpi,
                "Under mpirun: deal the candidates across the ranks (brute, random); rank 0 writes the merged report "
                "and the cache");
  add_rank_timeout_option(*cmd, a->rank_timeout, "--mpi",
                          " (0, the default here: the others wait for the slowest rank's whole share in one call)");
  add_quiet_flag(*cmd, a->quiet);
  return {cmd, [a]() {
            return run_tune(*a);
          }};
}

}  // namespace parashade::cli
