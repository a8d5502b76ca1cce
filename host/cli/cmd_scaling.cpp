// parashade scaling: Gouraud through each modeled shading unit in turn (unit_table.hpp), per unit and span
// arithmetic the modeled clocks of a frame and the measured frame time on the device, each against the
// classic one-intensity-per-clock unit in the same arithmetic, and the error against the ideal Gouraud.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <iterator>
#include <memory>
#include <limits>
#include <optional>
#include <regex>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_args.hpp"
#include "commands.hpp"
#include "device_option.hpp"
#include "common_options.hpp"
#include "progress.hpp"
#include "parashade/distributed.hpp"
#include "parashade/errors.hpp"
#include "parashade/metrics.hpp"
#include "parashade/reference.hpp"
#include "parashade/command_files.hpp"
#include "parashade/render_step.hpp"
#include "parashade/renderer.hpp"
#include "parashade/report.hpp"
#include "parashade/report_header.hpp"
#include "parashade/scene.hpp"
#include "parashade/statistics.hpp"
#include "parashade/unit_table.hpp"
#include "parashade/units.hpp"

namespace parashade::cli {
namespace {

const char* const kDefaultArith = "fixed:12.12";

// Every unit's sweep (unit_table.hpp).
std::string default_units() { return unit_specs(&UnitRow::scaling_sweep); }

struct ScalingArgs {
  std::string scene, units = default_units(), arith = kDefaultArith, method = "gouraud", size, device, report;
  int frames = 5, warmup = 1;
  bool float_output = false, markdown = false, quiet = false;
  double rank_timeout = 0;  // --mpi: the rank watchdog (off: a rank's whole share is one wait)
  bool mpi = false;  // under mpirun: configurations dealt across the ranks, rank 0 merges (docs/distributed.md)
};

// One configuration: its renderer (kept for the whole run, so that programs and buffers are warm when
// the timed frames go round), what the warm-up frame showed, and the timed frames.
struct Config {
  UnitConfig unit;
  Arithmetic arith;
  std::unique_ptr<ResolvedRender> resolved;  // the base render with this unit and arithmetic
  std::unique_ptr<RenderSession> session;    // its renderer (declared after: destroyed first)
  ModeledClocks clocks;
  GeometryStats geometry;
  ErrorMetrics ideal, exact;
  nlohmann::json ideal_json, exact_json;  // as the report has them (from another rank with --mpi)
  std::vector<double> total_ms, kernel_ms;
  double frame_ms = 0, kernel_med_ms = 0, kernel_min_ms = 0;
  const Config* classic = nullptr;  // classic in the same arithmetic, when it is in the list
  std::string name() const { return unit_name(unit); }
};

// A configuration's render options: the method through the unit in the arithmetic, the default tile.
RenderOptions options_of(const ScalingArgs& a, Method method, const Config& c) {
  RenderOptions o;
  o.method = method;
  o.float_output = a.float_output;
  o.units = c.unit;
  o.arith = c.arith;
  o.tile_size = TILE_DEFAULT;
  return o;
}

double ratio(double baseline, double value) { return value > 0 ? baseline / value : 0.0; }

double pixels_per_clock(const ModeledClocks& c) { return c.clocks ? double(c.pixels) / double(c.clocks) : 0.0; }

std::optional<double> modeled_speedup(const Config& c) {
  if (!c.classic) return std::nullopt;
  return ratio(double(c.classic->clocks.clocks), double(c.clocks.clocks));
}
std::optional<double> measured_speedup(const Config& c) {
  if (!c.classic) return std::nullopt;
  return ratio(c.classic->frame_ms, c.frame_ms);
}
std::optional<double> kernel_speedup(const Config& c) {
  if (!c.classic) return std::nullopt;
  return ratio(c.classic->kernel_med_ms, c.kernel_med_ms);
}

nlohmann::json optional_number(const std::optional<double>& v) { return v ? number_or_null(*v) : nlohmann::json(); }

std::string fixed_or_dash(const std::optional<double>& v, const char* format) {
  if (!v) return "-";
  char buf[64];
  std::snprintf(buf, sizeof buf, format, *v);
  return buf;
}

// 1234567 -> "1 234 567"
std::string grouped(std::uint64_t v) {
  std::string digits = std::to_string(v), out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i && (digits.size() - i) % 3 == 0) out += ' ';
    out += digits[i];
  }
  return out;
}

void print_table(const std::vector<Config>& configs, bool markdown) {
  const char* head[] = {"unit", "arith", "clocks/frame", "modeled x", "px/clock", "frame ms", "measured x",
                        "kernel ms", "kernel min", "max abs", "NMSE"};
  std::vector<std::vector<std::string>> rows;
  for (const Config& c : configs) {
    char ppc[32], frame[32], kernel[32], kernel_min[32];
    std::snprintf(ppc, sizeof ppc, "%.3f", pixels_per_clock(c.clocks));
    std::snprintf(frame, sizeof frame, "%.2f", c.frame_ms);
    std::snprintf(kernel, sizeof kernel, "%.2f", c.kernel_med_ms);
    std::snprintf(kernel_min, sizeof kernel_min, "%.2f", c.kernel_min_ms);
    // Undefined figures (no pixel compared: metrics.hpp) as "-", never "nan".
    const auto figure = [](double v) { return std::isfinite(v) ? std::optional<double>(v) : std::nullopt; };
    const std::string max_abs = fixed_or_dash(figure(c.ideal.max_abs), "%.3g"), nmse = fixed_or_dash(figure(c.ideal.nmse), "%.3g");
    rows.push_back({c.name(), arith_name(c.arith), grouped(c.clocks.clocks), fixed_or_dash(modeled_speedup(c), "%.2f"),
                    ppc, frame, fixed_or_dash(measured_speedup(c), "%.2f"), kernel, kernel_min, max_abs, nmse});
  }
  const std::size_t n = std::size(head);
  if (markdown) {
    std::string line = "|", rule = "|";
    for (std::size_t i = 0; i < n; ++i) {
      line += std::string(" ") + head[i] + " |";
      rule += i < 2 ? "---|" : "---:|";
    }
    std::printf("%s\n%s\n", line.c_str(), rule.c_str());
    for (const auto& r : rows) {
      std::string l = "|";
      for (const auto& cell : r) l += " " + cell + " |";
      std::printf("%s\n", l.c_str());
    }
    return;
  }
  std::vector<std::size_t> width(n);
  for (std::size_t i = 0; i < n; ++i) {
    width[i] = std::string(head[i]).size();
    for (const auto& r : rows) width[i] = std::max(width[i], r[i].size());
  }
  const auto print_row = [&](const std::vector<std::string>& r) {
    std::string l;
    for (std::size_t i = 0; i < n; ++i) {
      const std::string pad(width[i] - r[i].size(), ' ');
      l += (i ? "  " : "") + (i < 2 ? r[i] + pad : pad + r[i]);  // names left, numbers right
    }
    while (!l.empty() && l.back() == ' ') l.pop_back();
    std::printf("%s\n", l.c_str());
  };
  print_row(std::vector<std::string>(head, head + n));
  for (const auto& r : rows) print_row(r);
}

// The units and arithmetics of the sweep, each checked against the table (usage errors, before any file
// is read). Units the table refuses with this method (phong: the extra triangulation) are left out of the
// default list, and refused when asked for.
std::vector<Config> sweep_configs(const ScalingArgs& a, Method method) {
  std::vector<UnitConfig> units = parse_unique_list(a.units, "--units", parse_units, unit_name);
  const std::vector<Arithmetic> ariths = parse_unique_list(a.arith, "--arith", parse_arith, arith_name);
  const auto refused = [&](const UnitConfig& u) {
    FrameConfig c;
    c.method = method;
    c.units = u;
    return find_refusal(combination_of(c)) != nullptr;
  };
  if (a.units == default_units() && !std::all_of(units.begin(), units.end(), refused))  // flat refuses them all
    units.erase(std::remove_if(units.begin(), units.end(), refused), units.end());
  std::vector<Config> configs;
  for (const Arithmetic& ar : ariths)
    for (const UnitConfig& u : units) {
      Config c;
      c.unit = u;
      c.arith = ar;
      const RenderOptions o = options_of(a, method, c);
      with_option_names(o, DeviceMode::one, [&] { check_render_options(o, DeviceMode::one); });
      configs.push_back(std::move(c));
    }
  for (Config& c : configs)
    for (const Config& other : configs)
      if (other.unit.kind == UnitKind::classic && arith_name(other.arith) == arith_name(c.arith)) c.classic = &other;
  return configs;
}

// This rank's configurations: warm-up (programs built, buffers allocated; the last warm-up frame gives the
// modeled clocks and the error: the units are deterministic), then the timed frames round-robin, each round
// starting one configuration later: on a noisy shared machine a slow spell then falls on every
// configuration alike instead of on whichever ran during it.
void measure_configs(const ScalingArgs& a, const ResolvedRender& base, const ReferenceImage& ref,
                     std::vector<Config>& configs, const std::function<bool(std::size_t)>& mine, FrameProgress& progress) {
  const Method method = base.options.method;
  int done = 0;
  for (std::size_t i = 0; i < configs.size(); ++i) {
    if (!mine(i)) continue;
    Config& c = configs[i];
    c.resolved = std::make_unique<ResolvedRender>(with_options(base, options_of(a, method, c)));
    c.session = std::make_unique<RenderSession>(*c.resolved);
    const Frame* f = nullptr;
    for (int w = 0; w < a.warmup; ++w) {
      f = &c.session->frame();
      progress.step(++done);
    }
    c.clocks = f->stats.clocks;
    c.geometry = f->stats.geometry;
    const ErrorFigures e = error_against(ref, method, f->image);
    c.ideal = e.implementation;
    c.exact = e.method;
    c.ideal_json = to_json(c.ideal);
    c.exact_json = to_json(c.exact);
  }
  const std::size_t total = configs.size();
  for (int round = 0; round < a.frames; ++round)
    for (std::size_t k = 0; k < total; ++k) {
      if (!mine((k + std::size_t(round)) % total)) continue;
      Config& c = configs[(k + std::size_t(round)) % total];
      const Frame& f = c.session->frame();
      c.total_ms.push_back(f.timings.total_ms);
      c.kernel_ms.push_back(f.timings.kernel_ms);
      progress.step(++done);
    }
}

// --mpi: every rank's configurations to rank 0, which fills them in.
void merge_from_ranks(RankGroup& group, std::vector<Config>& configs, const std::function<bool(std::size_t)>& mine) {
  nlohmann::json sent = nlohmann::json::array();
  for (std::size_t i = 0; i < configs.size(); ++i) {
    if (!mine(i) || group.rank() == 0) continue;
    const Config& c = configs[i];
    sent.push_back({{"i", i}, {"clocks", to_json(c.clocks)}, {"in", c.geometry.triangles_in},
                    {"out", c.geometry.triangles_out}, {"ideal", c.ideal_json}, {"exact", c.exact_json},
                    {"total_ms", c.total_ms}, {"kernel_ms", c.kernel_ms}});
  }
  const std::vector<std::string> got = group.gather(sent.dump());
  for (std::size_t r = 1; r < got.size(); ++r)
    for (const auto& j : nlohmann::json::parse(got[r])) {
      Config& c = configs[j["i"].get<std::size_t>()];
      c.clocks.spans = j["clocks"]["spans"];
      c.clocks.pixels = j["clocks"]["span_pixels"];
      c.clocks.clocks = j["clocks"]["clocks"];
      c.geometry.triangles_in = j["in"];
      c.geometry.triangles_out = j["out"];
      c.ideal_json = j["ideal"];
      c.exact_json = j["exact"];
      // null: undefined (nothing compared), printed "-", not 0
      const double undefined = std::numeric_limits<double>::quiet_NaN();
      c.ideal.max_abs = c.ideal_json["max_abs"].is_null() ? undefined : c.ideal_json["max_abs"].get<double>();
      c.ideal.nmse = c.ideal_json["nmse"].is_null() ? undefined : c.ideal_json["nmse"].get<double>();
      c.total_ms = j["total_ms"].get<std::vector<double>>();
      c.kernel_ms = j["kernel_ms"].get<std::vector<double>>();
    }
}

nlohmann::json scaling_report(const ScalingArgs& a, const ResolvedRender& base, const std::vector<Config>& configs) {
  nlohmann::json rows = nlohmann::json::array();
  for (const Config& c : configs) {
    rows.push_back({{"unit", c.name()},
                    {"arith", arith_name(c.arith)},
                    {"modeled_clocks", to_json(c.clocks)},
                    {"pixels_per_clock", pixels_per_clock(c.clocks)},
                    {"modeled_speedup", optional_number(modeled_speedup(c))},
                    {"frame_ms", c.frame_ms},
                    {"timing", timing_json(c.total_ms, a.warmup)},
                    {"measured_speedup", optional_number(measured_speedup(c))},
                    {"kernel_ms", c.kernel_med_ms},
                    {"kernel_ms_min", c.kernel_min_ms},
                    {"kernel_ms_samples", c.kernel_ms},
                    {"kernel_speedup", optional_number(kernel_speedup(c))},
                    {"error", {{"implementation", c.ideal_json}, {"method", c.exact_json}}}});
  }
  const GeometryStats& geo = configs.front().geometry;
  const Scene& scene = base.scene;
  return {{"scene", scene.name},
          {"scene_file", a.scene},
          {"device", to_json(base.devices.front()->info())},
          {"method", method_name(base.options.method)},
          {"width", scene.width},
          {"height", scene.height},
          {"triangles", {{"in", geo.triangles_in}, {"after_culling", geo.triangles_out}}},
          {"frames", a.frames},
          {"warmup", a.warmup},
          {"float_output", a.float_output},
          {"frame_ms_note", frame_ms_note(a.frames, a.warmup, "frames per configuration",
                                          std::string(" each, round-robin across configurations; ") + kWholeFrame)},
          {"speedup_note", "classic in the same arithmetic divided by the configuration (modeled clocks, frame_ms, "
                           "kernel_ms); null when classic is not in the list"},
          {"rows", rows}};
}

void print_scaling(const ScalingArgs& a, const ResolvedRender& base, const std::vector<Config>& configs) {
  const Scene& scene = base.scene;
  const DeviceInfo& dev = base.devices.front()->info();
  const Method method = base.options.method;
  const GeometryStats& geo = configs.front().geometry;
  std::printf("%s: %dx%d, %llu triangles (%llu after culling and clipping), %s through modeled shading units\n",
              scene.name.c_str(), scene.width, scene.height, (unsigned long long)geo.triangles_in,
              (unsigned long long)geo.triangles_out, method == Method::phong ? "Phong (normal components)" : "Gouraud");
  std::printf("device: %s (%s), %d compute units\n", dev.name.c_str(), dev.platform.c_str(), dev.compute_units);
  bool same_spans = true;
  for (const Config& c : configs)
    same_spans = same_spans && c.clocks.spans == configs.front().clocks.spans &&
                 c.clocks.pixels == configs.front().clocks.pixels;
  if (same_spans)
    std::printf("modeled: %llu spans, %llu span pixels per frame; clocks = spans x %d + the unit's clocks per span\n",
                (unsigned long long)configs.front().clocks.spans, (unsigned long long)configs.front().clocks.pixels,
                SPAN_LOAD_CLOCKS);
  else
    std::printf("modeled: spans and span pixels differ between the units (the report has them per row)\n");
  std::printf("measured: median of %d frame(s) per configuration after %d warm-up, round-robin; whole frame "
              "(geometry, setup, binning, kernel, read-back); x = classic (same arith) / this; kernel min = fastest "
              "kernel of the %d\n",
              a.frames, a.warmup, a.frames);
  std::printf("error: against the ideal %s (exact reference, double precision), %s, in levels\n", method_name(method),
              a.float_output ? "unclamped float output" : "8-bit output");
  print_table(configs, a.markdown);
  print_wrote({a.report});
}

int run_scaling(const ScalingArgs& a) {
  // The command line first (usage errors, exit 2), then the scene and the destination (exit 3), then the device.
  const Method method = parse_method(a.method);
  std::vector<Config> configs = sweep_configs(a, method);
  RenderRequest request;
  request.scene_file = a.scene;
  request.size = checked_size(a.size);
  request.device = a.device;
  request.options = options_of(a, method, configs.front());
  request.use_tuned = false;
  request.quiet = a.quiet;
  if (a.frames < 1 || a.frames > kMaxFrames) throw UsageError("--frames must be 1.." + std::to_string(kMaxFrames));
  if (a.warmup < 1 || a.warmup > kMaxFrames)
    throw UsageError("--warmup must be 1.." + std::to_string(kMaxFrames) + " (the warm-up frame gives the error figures)");

  // --mpi: configuration i runs on rank i mod N; every step agrees across the ranks (a failure on any
  // rank stops them all), rank 0 merges the rows and writes the one report.
  std::unique_ptr<RankGroup> group;
  if (a.mpi) group = RankGroup::join(a.rank_timeout);
  const int rank = group ? group->rank() : 0, ranks = group ? group->size() : 1;
  const auto step = [&](const std::function<void()>& f) { step_in(group.get(), f); };
  std::unique_ptr<ResolvedRender> base;
  ReferenceImage ref;
  step([&] {
    CommandFiles files;
    if (rank == 0) files.output("--report", a.report);
    base = std::make_unique<ResolvedRender>(resolve_with_option_names(request, files));
    if (rank == 0) print_resolved(*base);
    // The exact reference, once for the scene: every configuration shades the same screen triangles.
    if (!a.quiet && rank == 0)
      std::cerr << "scaling " << base->scene.name << " (" << base->scene.width << "x" << base->scene.height << ", "
                << base->scene.triangle_count() << " triangles) on " << base->devices.front()->info().name
                << (group ? " over " + std::to_string(ranks) + " ranks" : std::string()) << ": exact reference ...\n";
    ref = exact_reference(base->scene, method);
  });
  const auto mine = [&](std::size_t i) { return int(i % std::size_t(ranks)) == rank; };
  std::size_t my_configs = 0;
  for (std::size_t i = 0; i < configs.size(); ++i) my_configs += mine(i);
  // [i/N] over this rank's frames, warm-up and timed; rank 0's only (the ranks share a terminal).
  FrameProgress progress(int(my_configs) * (a.warmup + a.frames), a.quiet || rank != 0);
  step([&] { measure_configs(a, *base, ref, configs, mine, progress); });
  if (group) {
    merge_from_ranks(*group, configs, mine);
    if (rank != 0) {
      step([] {});  // rank 0's report
      return 0;
    }
  }
  for (Config& c : configs) {
    c.frame_ms = median(c.total_ms);
    c.kernel_med_ms = median(c.kernel_ms);
    c.kernel_min_ms = *std::min_element(c.kernel_ms.begin(), c.kernel_ms.end());
  }
  const nlohmann::json report = scaling_report(a, *base, configs);
  step([&] {
    if (!a.report.empty()) write_report(a.report, report, "scaling");
  });
  print_scaling(a, *base, configs);
  return 0;
}

}  // namespace

Command add_scaling_command(CLI::App& app) {
  auto a = std::make_shared<ScalingArgs>();
  auto* cmd = app.add_subcommand(
      "scaling",
      "Sweep the modeled shading units (Gouraud intensities, or Phong's normal components with --method phong): "
      "per unit and arithmetic the modeled clocks per frame, the measured frame and kernel time, both as speed-up "
      "over classic in the same arithmetic, and the error against the method's ideal");
  cmd->add_option("scene", a->scene, "Scene file (.json) or mesh (.obj .off .ply .stl)")->required();
  cmd->add_option("--units", a->units,
                  "Comma-separated units, each as render --units takes it: " + unit_specs_help() +
                      "; include classic for the speed-ups")
      ->capture_default_str();
  cmd->add_option("--method", a->method, "gouraud (intensities through the units) or phong (normal components)")
      ->capture_default_str();
  cmd->add_option("--arith", a->arith,
                  "Comma-separated span arithmetics: float, fixed (= fixed:12.12), fixed:I.F (I >= 9, I + F <= 32)")
      ->capture_default_str();
  add_size_option(*cmd, a->size);
  cmd->add_option("--frames", a->frames, "Timed frames per configuration (round-robin); the median is reported")
      ->capture_default_str();
  cmd->add_option("--warmup", a->warmup,
                  "Untimed frames per configuration first (program build; the last gives clocks and error)")
      ->capture_default_str();
  add_device_option(*cmd, a->device, "OpenCL device: index or name substring (see 'parashade devices')");
  add_report_option(*cmd, a->report, "every row with its frame samples, the device");
  cmd->add_flag("--float", a->float_output, "Error of the unclamped float values instead of the 8-bit image");
  cmd->add_flag("--markdown", a->markdown, "Print the table as Markdown");
  cmd->add_flag("--mpi", a->mpi,
                "Under mpirun: deal the configurations across the ranks (configuration i on rank i mod N); rank 0 "
                "writes the merged report and table (docs/distributed.md)");
  add_rank_timeout_option(*cmd, a->rank_timeout, "--mpi",
                          " (0, the default here: the others wait for the slowest rank's whole share in one call)");
  add_quiet_flag(*cmd, a->quiet);
  return {cmd, [a]() {
            return run_scaling(*a);
          }};
}

}  // namespace parashade::cli
