#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <regex>
#include <tuple>
#include <utility>

#include <nlohmann/json.hpp>

#include "cli_args.hpp"
#include "common_options.hpp"
#include "commands.hpp"
#include "device_option.hpp"
#include "error_pictures.hpp"
#include "frame_medians.hpp"
#include "against_frames.hpp"
#include "plan_cli.hpp"
#include "progress.hpp"
#include "register_events_cli.hpp"
#include "vanishing_warnings.hpp"
#include "tune_cache.hpp"
#include "split_render_cli.hpp"
#include "parashade/split_renderer.hpp"
#include "parashade/sub_devices.hpp"
#include "parashade/choice_pixels.hpp"
#include "parashade/combined.hpp"
#include "parashade/distributed.hpp"
#include "parashade/errors.hpp"
#include "parashade/geometry_stage.hpp"
#include "parashade/image.hpp"
#include "parashade/metrics.hpp"
#include "parashade/output_file.hpp"
#include "parashade/reference.hpp"
#include "parashade/renderer.hpp"
#include "parashade/report.hpp"
#include "parashade/report_header.hpp"
#include "parashade/scene.hpp"
#include "parashade/statistics.hpp"
#include "parashade/tile_choice.hpp"
#include "parashade/unit_table.hpp"

namespace parashade::cli {
namespace {

struct RenderArgs {
  std::string scene, output, method = "gouraud", device, size, report, units, arith = "float", division = "constant",
              coverage = "centre", specular = "exact", normalize = "exact", triangle_choice;
  std::string against;  // --against: a plain method whose frames alternate with this one's
  int frames = 5, warmup = 1, tile = TILE_DEFAULT, work_items = 0;
  int defer_min_triangles = -1;  // -1: RenderOptions' default (RenderOptions::deferral_threshold)
  // Triangle records a frame may hold at once before it streams in bands of as many (MiB); 0: never
  // streams; -1 (not given): by the frame (default_band_mib, bands of 16).
  int band_mib = -1;
  double max_error = 0;  // 0: not given
  int combined_min_width = -1;
  bool float_output = false, no_error = false, quiet = false, highlight_test = false;
  PlanArgs plan;
  std::string tune_cache;
  std::string reference_image, error_map, error_reference = "ideal";  // the pictures of the error
  std::string triangle_map;  // the reference's visible triangle per pixel
  std::string distribute, rank_partition, read_scene;  // --distribute: MPI ranks (docs/distributed.md)
  std::string device_origin = "--device";  // or PARASHADE_DEVICE (device_option.hpp)
  bool no_tuned = false, explicit_config = false, keep_going = false;  // explicit: --tile, --work-items, --cu or --partition given
  bool tile_given = false;  // --tile given: else default_tile_size (tile_choice.hpp) on one device
};

// The geometry the exact reference renders: the frame's triangles in the same order, with every attribute
// the reference needs, and the vertex intensities too where a per-triangle choice is made on it.
ScreenGeometry reference_geometry(const Scene& scene, Method method, bool chooses_per_triangle = false) {
  ScreenGeometry g;
  build_screen_geometry(scene, {method, true, chooses_per_triangle}, g);
  return g;
}

// The exact reference of the scene's frame: the method's own ideal and exact Phong.
ReferenceImage reference_of(const Scene& scene, Method method) {
  return render_reference(scene, reference_geometry(scene, method), method);
}

// The per-triangle choice's visible pixels per method: the choice made again on the reference's geometry `g`,
// counted on the reference's visibility.
ChoicePixels choice_pixels_of(const Scene& scene, const RenderOptions& options, const ScreenGeometry& g,
                              const ReferenceImage& ref) {
  std::vector<TriangleShading> choice;
  choose_triangle_methods(scene, g, options.combined, combined_shading_budget(options.combined), choice);
  return visible_pixels_by_method(ref.triangle, choice);
}

// The name of the method's own ideal; combined's is Phong's (segment ends are exact Phong).
std::string ideal_name(Method method) {
  return method == Method::combined ? "ideal phong" : std::string("ideal ") + method_name(method);
}

// The image's error against the exact reference: the method's own ideal and exact Phong.
nlohmann::json error_figures(const ReferenceImage& ref, Method method, const RenderedImage& image,
                             std::vector<std::string>& lines) {
  nlohmann::json errors = nlohmann::json::object();
  const ErrorMetrics ideal = compare_to_reference(image, ref.covered, ref.ideal, ideal_name(method));
  const ErrorMetrics exact = compare_to_reference(image, ref.covered, ref.exact, "exact phong");
  errors["implementation"] = to_json(ideal);
  errors["method"] = to_json(exact);
  lines.push_back("error vs " + ideal.reference + ": " + describe_error(ideal));
  lines.push_back("error vs " + exact.reference + ": " + describe_error(exact));
  return errors;
}

// --reference-image, --error-map or --triangle-map was given.
bool wants_pictures(const RenderArgs& a) {
  return !a.reference_image.empty() || !a.error_map.empty() || !a.triangle_map.empty();
}

// The first picture option given, for messages.
std::string picture_option(const RenderArgs& a) {
  return !a.error_map.empty() ? "--error-map" : !a.reference_image.empty() ? "--reference-image" : "--triangle-map";
}

// Every output destination is writable and none overwrites an input or another output (before any work).
void check_destinations(const RenderArgs& a, const std::vector<std::filesystem::path>& inputs) {
  check_distinct_files({{"-o", a.output}, {"--report", a.report}, {"--reference-image", a.reference_image},
                        {"--error-map", a.error_map}, {"--triangle-map", a.triangle_map}},
                       inputs);
  check_image_destination(a.output);
  if (!a.report.empty()) check_report_destination(a.report);
  if (!a.reference_image.empty()) check_image_destination(a.reference_image);
  if (!a.error_map.empty()) check_image_destination(a.error_map);
  if (!a.triangle_map.empty()) check_triangle_map_destination(a.triangle_map);
}

// The pictures' options make sense together with the rest of the command line (before any work).
void check_picture_options(const RenderArgs& a) {
  if (a.error_reference != "ideal" && a.error_reference != "exact")
    throw UsageError("--error-reference must be ideal (the method's own ideal) or exact (exact Phong), not '" +
                     a.error_reference + "'");
  if (wants_pictures(a) && a.no_error)
    throw UsageError(picture_option(a) + " needs the exact reference, which --no-error skips");
}

// --reference-image and --error-map against the reference --error-reference names, and --triangle-map, staged:
// the caller commits them with its other outputs.
std::vector<StagedFile> stage_error_pictures(const RenderArgs& a, Method method, const ReferenceImage& ref,
                                             const RenderedImage& image, std::vector<std::string>& lines) {
  const bool exact = a.error_reference == "exact";
  const std::vector<glm::dvec3>& values = exact ? ref.exact : ref.ideal;
  const std::string name = exact ? "exact phong" : ideal_name(method);
  std::vector<StagedFile> files;
  if (!a.reference_image.empty()) {
    files.push_back(stage_image(a.reference_image, levels_image(values, ref.width, ref.height)));
    lines.push_back("reference image " + a.reference_image + ": " + name);
  }
  if (!a.error_map.empty()) {
    files.push_back(stage_error_map(a.error_map, image, ref.covered, values, lines));
    lines.back() += ", against " + name;
  }
  if (!a.triangle_map.empty()) {
    files.push_back(stage_image(a.triangle_map, triangle_map_image(ref.triangle, ref.width, ref.height)));
    lines.push_back("triangle map " + a.triangle_map + ": the reference's visible triangle + 1 per pixel (R high byte)");
  }
  return files;
}

// render --distribute: the frame across MPI ranks (docs/distributed.md); every rank runs this.
int run_distributed_checked(const RenderArgs& a, RenderOptions options, const std::optional<std::pair<int, int>>& size);

// Every rank checks the command line before MPI starts; only rank 0 (or a run without mpirun) says what
// is wrong, the others leave with the same code and no message (main prints none for an empty one).
int run_distributed(const RenderArgs& a, RenderOptions options, const std::optional<std::pair<int, int>>& size) {
  try {
    return run_distributed_checked(a, options, size);
  } catch (const UsageError& e) {
    const char* rank = std::getenv("OMPI_COMM_WORLD_RANK");
    if (rank && std::string(rank) != "0" && *e.what()) throw UsageError("");
    throw;
  }
}

int run_distributed_checked(const RenderArgs& a, RenderOptions options, const std::optional<std::pair<int, int>>& size) {
  DistributedRender job;
  job.mode = parse_distribute(a.distribute);
  if (a.keep_going) throw UsageError("--keep-going does not combine with --distribute: a failing rank stops every rank");
  if (is_device_list(a.device) || is_sub_device_selector(a.device))
    throw UsageError("--distribute: each rank opens one device; '" + a.device + "' names several");
  if (!a.rank_partition.empty()) {
    if (job.mode != Distribute::sort_last)
      throw UsageError("--rank-partition assigns triangles to sort-last ranks; sort-first ranks take bands");
    job.rank_partition = parse_partition(a.rank_partition);
    if (job.rank_partition == Partition::tiles)
      throw UsageError("--rank-partition tiles: sort-last ranks take shares of the triangles, not screen tiles "
                       "(round-robin, lpt or dynamic; --distribute sort-first takes bands of tiles)");
  }
  if (!a.read_scene.empty()) {
    if (a.read_scene != "every-rank" && a.read_scene != "rank-0")
      throw UsageError("unknown --read-scene '" + a.read_scene + "' (valid: every-rank, rank-0)");
    job.scatter_scene = a.read_scene == "rank-0";
  }
  check_config_options(options, distribute_device_mode(job.mode));
  if (!options.units && options.unit_path() && !a.quiet)
    std::cerr << "parashade: note: " << (options.arith.fixed ? "--arith " + a.arith : std::string("--coverage dda"))
              << " runs on the classic unit (--units chooses another)\n";
  job.options = options;
  job.rank_batch = a.plan.batch;
  job.setup_clocks = a.plan.setup_clocks;
  job.device = a.device;
  job.output = a.output;
  job.report = a.report;
  job.scene_file = a.scene;
  job.frames = a.frames;
  job.warmup = a.warmup;
  job.quiet = a.quiet;
  job.no_error = a.no_error;
  job.load_scene = [&] {
    Scene scene = load_scene_at(a.scene, size, a.size);
    for (const std::string& w : scene.warnings) std::cerr << "parashade: warning: " << w << "\n";
    return scene;
  };
  job.check_destinations = [&] {
    check_destinations(a, {a.scene});
  };
  const Method method = options.method;
  // Rank 0 holds the whole image and scene here; the pictures are written at once, before the image.
  job.error_figures = [method, &a](const Scene& scene, const RenderedImage& image, std::vector<std::string>& lines) {
    const ReferenceImage ref = reference_of(scene, method);
    nlohmann::json errors = error_figures(ref, method, image, lines);
    std::vector<StagedFile> pictures = stage_error_pictures(a, method, ref, image, lines);
    for (StagedFile& f : pictures) f.commit();
    return errors;
  };
  return run_distributed_render(job);
}

// The scene's meshes as the memory budget counts them (bench/README.md "Peak memory"): positions and
// normals (2 x 12 bytes per vertex) and index triples (12 bytes per triangle).
nlohmann::json mesh_json(const Scene& scene) {
  std::uint64_t vertices = 0, triangles = 0;
  for (const Object& o : scene.objects) {
    vertices += o.mesh->positions.size();
    triangles += o.mesh->triangles.size();
  }
  return {{"vertices", vertices}, {"triangles", triangles}, {"bytes", 24 * vertices + 12 * triangles}};
}

int run_render(const RenderArgs& a) {
  const Method method = parse_method(a.method);
  RenderOptions options;
  options.method = method;
  options.float_output = a.float_output;
  options.tile_size = a.tile;
  options.work_items = a.work_items;
  options.defer_min_triangles = a.defer_min_triangles;
  options.band_record_bytes = a.band_mib < 0    ? kBandBytesByFrame
                              : a.band_mib == 0 ? SIZE_MAX
                                                : std::size_t(a.band_mib) << 20;
  if (method == Method::combined) options.combined = parse_combined(a.method);
  options.combined.highlight_test = a.highlight_test;
  if (a.combined_min_width != -1) {
    if (method != Method::combined) throw UsageError("--combined-min-width needs --method combined:K or combined:auto");
    if (a.combined_min_width < 0 || a.combined_min_width > kMaxResolution)
      throw UsageError("--combined-min-width must be 0.." + std::to_string(kMaxResolution) + " pixels");
    options.combined.min_width = a.combined_min_width;
  }
  if (!a.triangle_choice.empty())
    for_option("--triangle-choice", [&] { parse_triangle_rule(a.triangle_choice, options.combined); });
  if (a.max_error != 0) {
    if (method != Method::combined || !(options.combined.automatic || options.combined.rule == TriangleRule::bound))
      throw UsageError("--max-error is the error budget of --method combined:auto or --triangle-choice bound; method '" +
                       a.method + "' with triangle choice '" + triangle_rule_name(options.combined) + "' has none");
    if (!(a.max_error > 0 && a.max_error <= 255)) throw UsageError("--max-error must be in (0, 255] levels");
    options.combined.max_error = a.max_error;
  }
  if (!a.units.empty()) options.units = for_option("--units", [&] { return parse_units(a.units); });
  options.arith = for_option("--arith", [&] { return parse_arith(a.arith); });
  options.division = for_option("--div", [&] { return parse_division(a.division); });
  if (a.coverage != "centre" && a.coverage != "dda")
    throw UsageError("unknown coverage '" + a.coverage + "' (valid: centre, dda)");
  options.dda_coverage = a.coverage == "dda";
  options.plan = plan_options(a.plan);
  options.specular = for_option("--specular", [&] { return parse_specular(a.specular); });
  options.normalize = for_option("--normalize", [&] { return parse_normalize(a.normalize); });
  const auto size = parse_size(a.size);
  if (a.frames < 1 || a.frames > kMaxFrames)
    throw UsageError("--frames must be 1.." + std::to_string(kMaxFrames) + " (got " + std::to_string(a.frames) + ")");
  if (a.warmup < 0 || a.warmup > kMaxFrames)
    throw UsageError("--warmup must be 0.." + std::to_string(kMaxFrames) + " (got " + std::to_string(a.warmup) + ")");
  if (a.work_items < 0) throw UsageError("--work-items must not be negative");
  if (a.defer_min_triangles < -1 || a.defer_min_triangles > kMaxDeferMinTriangles)
    throw UsageError("--defer-min-triangles must be 0.." + std::to_string(kMaxDeferMinTriangles) + " (or -1, the default)");
  check_picture_options(a);
  if (!a.against.empty()) {
    AgainstFrames::check_method(a.against);
    if (!a.distribute.empty() || is_device_list(a.device))
      throw UsageError("--against pairs frames of two renderers on one device in one process; not with --distribute "
                       "or a device list ('" + (a.distribute.empty() ? a.device : "--distribute " + a.distribute) + "')");
  }
  if (!a.distribute.empty()) return run_distributed(a, options, size);
  if (!a.rank_partition.empty()) throw UsageError("--rank-partition needs --distribute sort-last");
  if (!a.read_scene.empty()) throw UsageError("--read-scene needs --distribute (how MPI ranks get the scene)");
  // --cu with sub:NAME:N: the units' depth pass spread over the sub-devices; without --cu a device list
  // or sub-devices take bands of the frame (docs/planner.md).
  const bool units_on_sub_devices = options.plan && is_sub_device_selector(a.device);
  check_config_options(options, units_on_sub_devices   ? DeviceMode::unit_sub_devices
                                : is_device_list(a.device) ? DeviceMode::bands
                                                         : DeviceMode::one);
  if (!options.units && options.unit_path() && !a.quiet)
    std::cerr << "parashade: note: " << (options.arith.fixed ? "--arith " + a.arith : std::string("--coverage dda"))
              << " runs on the classic unit (--units chooses another)\n";
  std::vector<std::filesystem::path> inputs;  // the scene file and its meshes
  Scene scene = load_scene_at(a.scene, size, a.size, &inputs);
  for (const std::string& w : scene.warnings) std::cerr << "parashade: warning: " << w << "\n";
  // Fail on an unwritable output before the work, not after it.
  check_destinations(a, inputs);
  const std::filesystem::path out_path(a.output);
  if (wants_pictures(a) && is_device_list(a.device) && !units_on_sub_devices)
    throw UsageError(picture_option(a) + " needs the error figures, which a frame split across devices ('" +
                     a.device + "') does not compute; render on one device");

  if (a.keep_going && units_on_sub_devices)
    throw UsageError("--keep-going drops devices of a split frame; the units of --cu on sub-devices ('" + a.device +
                     "') have no fallback: a failing sub-device ends the run");
  if (a.keep_going && !is_device_list(a.device))
    throw UsageError("--keep-going drops failing devices of a list (--device all, A,B or sub:NAME:N); " +
                     (a.device.empty() ? std::string("the default device") : "'" + a.device + "'") + " is one device");
  if (is_device_list(a.device) && !units_on_sub_devices)
    return run_split_render(scene, options, {a.device, a.device_origin, a.output, a.report, a.scene, a.frames, a.warmup, a.keep_going, a.quiet});
  SubDevices sub;  // with units_on_sub_devices: the parent (renders) and the sub-devices (run the units)
  std::vector<Device*> unit_devices;
  if (units_on_sub_devices) {
    sub = for_device(a.device_origin, [&] { return open_sub_devices(a.device, SubDeviceContext::shared); });
    for (const auto& d : sub.subs) unit_devices.push_back(d.get());
  }
  auto device = units_on_sub_devices ? std::move(sub.parent) : for_device(a.device_origin, [&] { return open_device(a.device); });
  const DeviceInfo& dev = device->info();
  nlohmann::json tuned = nullptr;
  const std::optional<TuneProblem> problem = tune_problem(scene, options);
  if (!a.no_tuned && !a.explicit_config && problem) {
    const std::filesystem::path path = a.tune_cache.empty() ? default_tune_cache() : std::filesystem::path(a.tune_cache);
    try {
      const TuneCache cache(path);
      if (const std::string stale = cache.stale_entries(dev, &*problem); !stale.empty() && !a.quiet)
        std::cerr << "parashade: note: " << stale << "\n";
      if (const auto best = cache.best(dev, *problem)) {
        apply_tuned_params(best->at("params"), options);
        tuned = {{"cache", path.string()}, {"params", best->at("params")}, {"objective_ms", best->at("objective")}};
        std::cerr << "using the tuned configuration " << best->at("params").dump() << " from " << path.string()
                  << " (--no-tuned to disable)\n";
      }
    } catch (const InputError& e) {
      std::cerr << "parashade: warning: tune cache not used: " << e.what() << "\n";
    }
  }
  if (!a.tile_given && tuned.is_null()) options.tile_size = default_tile_size(scene, options, options.band_record_bytes);
  Renderer renderer(*device, options, unit_devices);
  std::optional<AgainstFrames> against;
  if (!a.against.empty()) against.emplace(*device, scene, a.against, options.band_record_bytes);
  if (!a.quiet)
    std::cerr << "rendering " << scene.name << " (" << scene.width << "x" << scene.height << ", "
              << scene.triangle_count() << " triangles, " << method_name(method) << ") on " << dev.name << " ...\n";
  FrameProgress progress(a.warmup + a.frames, a.quiet);
  for (int i = 0; i < a.warmup; ++i) {
    renderer.render(scene);  // builds programs, compiles work-group functions
    if (against) against->warm_up(scene);
    progress.step(i + 1);
  }
  std::vector<FrameTimings> timings;
  std::vector<double> frame_samples_ms;
  const Frame* last = nullptr;
  for (int i = 0; i < a.frames; ++i) {
    if (against && AgainstFrames::first_in_pair(i)) against->frame(scene);
    last = &renderer.render(scene);
    if (against && !AgainstFrames::first_in_pair(i)) against->frame(scene);
    timings.push_back(last->timings);
    frame_samples_ms.push_back(last->timings.total_ms);
    progress.step(a.warmup + i + 1);
  }
  const Frame& frame = *last;
  const FrameTimings med = median_timings(timings);

  warn_vanishing(frame.stats, frame.image, std::cerr);
  nlohmann::json errors = nlohmann::json::object();
  std::vector<std::string> error_lines;
  std::optional<ReferenceImage> ref;
  std::optional<ChoicePixels> choice_pixels;
  if (!a.no_error) {
    const ScreenGeometry g = reference_geometry(scene, method, options.chooses_per_triangle());
    ref = render_reference(scene, g, method);
    errors = error_figures(*ref, method, frame.image, error_lines);
    if (options.chooses_per_triangle()) choice_pixels = choice_pixels_of(scene, options, g, *ref);
  }
  // Fixed point: the registers' wraps and saturations, from the golden models (the kernels count none).
  std::optional<RegisterEvents> registers;
  if (options.arith.fixed) {
    registers = count_register_events(scene, options);
    warn_register_events(*registers, options.arith, std::cerr);
  }

  // Every output is written to a temporary file first and replaces its destination only when all were
  // written: a failed report leaves the previous image (and pictures) in place.
  StagedFile staged_image = stage_image(out_path, frame.image);
  std::vector<StagedFile> pictures;
  if (ref) pictures = stage_error_pictures(a, method, *ref, frame.image, error_lines);
  const double pixels = double(scene.width) * scene.height;
  const std::optional<int> deferral = renderer.deferral_threshold(scene);
  nlohmann::json report = {
      {"scene", scene.name},
      {"scene_file", a.scene},
      {"image", a.output},
      {"device", to_json(dev)},
      {"method", method_name(method)},
      {"specular", specular_name(options.specular)},
      {"normalize", {{"method", normalize_name(options.normalize)},
                     {"span_setups", frame.stats.normalize_span_setups},
                     {"fallback_spans", frame.stats.normalize_fallback_spans},
                     {"sequential_steps", frame.stats.normalize_sequential_steps}}},
      {"width", scene.width},
      {"height", scene.height},
      {"tile_size", options.tile_size},
      {"band_mib", a.band_mib < 0 ? default_band_mib(scene.width, scene.height) : a.band_mib},
      {"tuned", tuned},
      {"work_items", renderer.work_items(frame.stats.tiles)},
      {"defer_min_triangles", deferral.has_value() ? nlohmann::json(*deferral) : nlohmann::json(nullptr)},
      {"triangles", {{"in", frame.stats.geometry.triangles_in},
                     {"after_culling", frame.stats.geometry.triangles_out}}},
      {"mesh", mesh_json(scene)},
      {"frame_ms", med.total_ms},
      {"frame_ms_note", "median of " + std::to_string(a.frames) + " frames after " + std::to_string(a.warmup) +
                            " warm-up frame(s); whole frame: geometry, setup, binning, kernel, read-back"},
      {"stages_ms", to_json(med)},
      {"timing", timing_json(frame_samples_ms, a.warmup)},
      {"mpixel_per_s", pixels / (med.total_ms * 1e3)},
      {"mtriangle_per_s", double(frame.stats.geometry.triangles_in) / (med.total_ms * 1e3)},
      {"stats", to_json(frame.stats)},
      {"error", errors}};
  if (against) report["against"] = against->summary(timings);
  if (method == Method::combined) {
    report["method"] = combined_name(options.combined);
    if (options.combined.automatic) report["max_error_levels"] = options.combined.max_error;
    report["combined_min_width"] = combined_min_width(options.combined);
    report["highlight_test"] = uses_highlight_mask(options.combined);
    report["triangle_choice_rule"] = triangle_rule_name(options.combined);
    if (choice_pixels)
      report["stats"]["triangle_choice"]["visible_pixels"] = {
          {"gouraud", choice_pixels->gouraud}, {"segments", choice_pixels->segments}, {"phong", choice_pixels->phong}};
  }
  if (options.unit_path()) {
    report["units"] = unit_name(options.unit());
    report["arith"] = arith_name(options.arith);
    report["span_division"] = division_name(options.division);
    report["coverage"] = a.coverage;
    report["modeled_clocks"] = to_json(frame.stats.clocks);
    if (registers) report["registers"] = register_events_json(*registers);
  }
  if (frame.stats.plan) {
    report["plan"] = to_json(*frame.stats.plan);
    report["plan"]["measured_frame_ms"] = med.total_ms;
    report["plan"]["mapping"] = unit_mapping_json(frame.stats, med);
  }
  std::optional<StagedFile> staged_report;
  if (!a.report.empty()) staged_report.emplace(stage_text(a.report, report_text(report, "render")));
  staged_image.commit();
  for (StagedFile& f : pictures) f.commit();
  if (staged_report) staged_report->commit();

  std::printf("%s: %dx%d, %llu triangles (%llu after culling and clipping), method %s\n", scene.name.c_str(),
              scene.width, scene.height, (unsigned long long)frame.stats.geometry.triangles_in,
              (unsigned long long)frame.stats.geometry.triangles_out,
              method == Method::combined ? combined_name(options.combined).c_str() : method_name(method));
  std::printf("device: %s (%s), %d compute units\n", dev.name.c_str(), dev.platform.c_str(), dev.compute_units);
  std::printf("frame: %.3f ms (median of %d after %d warm-up; geometry %.3f, setup %.3f, binning %.3f, kernel %.3f, "
              "read-back %.3f) = %.1f fps, %.1f Mpixel/s, %.2f Mtriangle/s\n",
              med.total_ms, a.frames, a.warmup, med.geometry_ms, med.setup_ms, med.binning_ms, med.kernel_ms,
              med.readback_ms, 1e3 / med.total_ms, pixels / (med.total_ms * 1e3),
              double(frame.stats.geometry.triangles_in) / (med.total_ms * 1e3));
  if (med.choice_ms > 0.0) std::printf("setup includes the per-triangle method choice: %.3f ms\n", med.choice_ms);
  if (against) std::printf("%s\n", AgainstFrames::line(report["against"]).c_str());
  if (options.unit_path()) {
    const ModeledClocks& c = frame.stats.clocks;
    std::printf("unit %s, %s arithmetic, span increment %s: %llu modeled clocks (%llu spans, %llu span pixels, %.3f pixels per clock)\n",
                unit_name(options.unit()).c_str(), arith_name(options.arith).c_str(),
                division_name(options.division).c_str(), (unsigned long long)c.clocks,
                (unsigned long long)c.spans, (unsigned long long)c.pixels, c.clocks ? double(c.pixels) / double(c.clocks) : 0.0);
    if (registers)
      std::printf("registers: %llu of %llu span pixels wrapped around, %llu span register loads saturated\n",
                  (unsigned long long)registers->wrapped_pixels, (unsigned long long)registers->span_pixels,
                  (unsigned long long)registers->saturated_loads);
  }
  if (frame.stats.plan) {
    print_plan(*frame.stats.plan, !a.quiet);
    std::printf("planned frame: planning %.3f ms, units' depth pass %.3f ms, resolve kernel %.3f ms (medians)\n",
                med.planning_ms, med.unit_pass_ms, med.kernel_ms);
    print_unit_mapping(frame.stats, med);
  }
  if (options.span_normalize() || options.specular.kind != SpecularKind::exact) {
    const std::string steps = frame.stats.normalize_sequential_steps
                                  ? ", " + std::to_string(frame.stats.normalize_sequential_steps) + " sequential steps"
                                  : "";
    std::printf("phong: normals %s (%llu span setups, %llu fell back to the exact normal%s), specular %s\n",
                normalize_name(options.normalize).c_str(), (unsigned long long)frame.stats.normalize_span_setups,
                (unsigned long long)frame.stats.normalize_fallback_spans, steps.c_str(),
                specular_name(options.specular).c_str());
  }
  if (const auto& c = frame.stats.choice)
    std::printf("triangle choice %s: of %llu triangles %llu by Gouraud (largest expected error %.2f levels), %llu by "
                "segments, %llu by Phong per pixel; %llu where a terminator may cross\n",
                triangle_rule_name(options.combined).c_str(), (unsigned long long)c->triangles,
                (unsigned long long)c->gouraud, c->largest_expected_levels, (unsigned long long)c->segments,
                (unsigned long long)(c->triangles - c->gouraud - c->segments), (unsigned long long)c->terminator);
  if (choice_pixels) {
    const ChoicePixels& p = *choice_pixels;
    const double all = std::max(1.0, double(p.gouraud + p.segments + p.phong));
    std::printf("visible pixels by the choice (exact reference's visibility): %.1f %% Gouraud, %.1f %% segments, "
                "%.1f %% Phong per pixel, of %llu\n",
                100.0 * double(p.gouraud) / all, 100.0 * double(p.segments) / all, 100.0 * double(p.phong) / all,
                (unsigned long long)(p.gouraud + p.segments + p.phong));
  }
  if (method == Method::combined && uses_highlight_mask(options.combined))
    std::printf("highlight test: %llu of %llu triangles without a highlight, %llu (triangle, light) specular terms skipped\n",
                (unsigned long long)frame.stats.highlight.without_highlight,
                (unsigned long long)frame.stats.highlight.triangles,
                (unsigned long long)frame.stats.highlight.light_terms_skipped);
  for (const auto& l : error_lines) std::printf("%s\n", l.c_str());
  std::printf("wrote %s%s%s\n", a.output.c_str(), a.report.empty() ? "" : " and ", a.report.c_str());
  return 0;
}

}  // namespace

Command add_render_command(CLI::App& app) {
  auto a = std::make_shared<RenderArgs>();
  auto* cmd = app.add_subcommand("render", "Render a scene (JSON) or a bare mesh file; print frame time and error");
  cmd->add_option("scene", a->scene, "Scene file (.json) or mesh (.obj .off .ply .stl)")->required();
  cmd->add_option("-o,--output", a->output, "Image to write; format from the extension (png, jpg, tif, ppm, exr ...)")
      ->required();
  cmd->add_option("--method", a->method,
                  "Shading method: flat, gouraud, phong, combined:K (Phong at the ends of 2^K-pixel segments, K = 0.." +
                      std::to_string(kCombinedMaxK) + "), "
                  "combined:auto (K per span from --max-error); which options combine: parashade combinations")
      ->capture_default_str();
  cmd->add_option("--max-error", a->max_error,
                  "combined:auto or --triangle-choice bound: error budget in 8-bit levels against Phong (default 1; 0.5 "
                  "of it is the image's rounding); chooses Gouraud per triangle (and combined:auto's K per span) to meet it");
  cmd->add_option("--specular", a->specular,
                  "Phong specular model: exact, cosk:taylor:2|4, cosk:lobe:2|4, quadratic, 7n16[:P] (docs/phong-methods.md)")
      ->capture_default_str();
  cmd->add_option("--normalize", a->normalize,
                  "Phong unit normals: exact, slerp, quadratic:exact|quad|cubic|cubic-fit, "
                  "dichotomy:exact|linear|quadratic|linear-fit|quadratic-fit[:K][:extrapolate] (segments of 2^K, K = 1..6, "
                  "default 4), recurrence[-diff][:exact|table|table-fixed][:R] (a sequential unit per span, re-anchored "
                  "every R pixels) (docs/phong-methods.md)")
      ->capture_default_str();
  add_device_option(*cmd, a->device,
                    "OpenCL device: index or name substring (see 'parashade devices'); 'all' or a comma list splits the "
                    "frame across devices by measured speed; sub:NAME:N or sub:NAME:N1+N2 uses NAME's sub-devices (bands "
                    "of the frame; with --cu, the units' depth pass on them)");
  cmd->add_option("--distribute", a->distribute,
                  "Under mpirun: the frame across the MPI ranks, sort-last (shares of the triangles by modeled cost, "
                  "depth keys composited) or sort-first (bands by measured speed); the image is the one-process "
                  "render's (docs/distributed.md)");
  cmd->add_option("--rank-partition", a->rank_partition,
                  "--distribute sort-last: the planner's strategy for triangles to ranks: lpt (default), round-robin, "
                  "dynamic (batches of --batch)");
  cmd->add_option("--read-scene", a->read_scene,
                  "--distribute: every-rank (default: each rank reads the scene file) or rank-0 (rank 0 reads it and "
                  "scatters each sort-last rank its share of the triangles, or broadcasts the scene to sort-first ranks)");
  cmd->add_flag("--keep-going", a->keep_going,
                "With a device list (bands): drop a failing device (named) and go on with the others");
  add_size_option(*cmd, a->size);
  add_report_option(*cmd, a->report, "timings, stages, error figures");
  cmd->add_option("--frames", a->frames,
                  "Timed frames (at most " + std::to_string(kMaxFrames) + "); the median is reported; on a terminal "
                  "a progress line [i/N] shows the time left")
      ->capture_default_str();
  cmd->add_option("--warmup", a->warmup, "Untimed frames first (program build, work-group compilation; at most " +
                                             std::to_string(kMaxFrames) + ")")
      ->capture_default_str();
  cmd->add_option("--tile", a->tile,
                  "Screen tile size: " + tile_sizes_text() + " (default: " + std::to_string(TILE_MAX) +
                      " for a Gouraud or flat frame on one device that is not streamed in bands, else " +
                      std::to_string(TILE_DEFAULT) + "; a tuned entry's when there is one)")
      ->check(CLI::IsMember(tile_sizes()));
  cmd->add_option("--work-items", a->work_items,
                  "Kernel work-items, each rendering every N-th tile (0: " + std::to_string(WORK_ITEMS_PER_COMPUTE_UNIT) +
                      " per compute unit)")
      ->capture_default_str();
  cmd->add_option("--defer-min-triangles", a->defer_min_triangles,
                  "Phong and the combined method on the stamps: a tile of at least N triangles shades each pixel once, "
                  "after its depth test (-1: the default, every tile for Phong, tile x tile / 16 for combined; 0: every "
                  "tile). "
                  "Same image; docs/pipeline.md")
      ->capture_default_str();
  cmd->add_option("--band-mib", a->band_mib,
                  "A frame whose triangle records would exceed this many MiB is set up, binned and shaded in bands "
                  "of tile rows of at most as many, which bounds its memory (0: never; the image is the same "
                  "either way). Default: 16 plus the frame's colour and depth (8 bytes a pixel), 32 at 1920x1080 "
                  "and 80 at 3840x2160, with bands of 16")
      ->check(CLI::Range(0, 1 << 20));
  cmd->add_option("--units", a->units,
                  "Shade the spans through a modeled shading unit (Gouraud's intensities, or Phong's normal "
                  "components with --method phong): " + unit_specs_help() + "; reports modeled clocks");
  cmd->add_option("--arith", a->arith, "Span register arithmetic: float, fixed (= fixed:12.12) or fixed:I.F (I >= 9, I + F <= 32)")
      ->capture_default_str();
  cmd->add_option("--div", a->division,
                  "Span increment: constant (dI_G once per triangle), or a division per span: exact, shiftadd:N "
                  "(n digits of 1/k, rounded as the sources' Table 1), shiftadd:N:trunc; needs --arith fixed")
      ->capture_default_str();
  cmd->add_option("--coverage", a->coverage,
                  "Coverage: centre (pixel centres, top-left rule) or dda (the sources' edge walk; Gouraud units; "
                  "differences show as coverage mismatches against the reference)")
      ->capture_default_str();
  add_plan_options(*cmd, a->plan, false);
  cmd->add_option("--tune-cache", a->tune_cache, "Tune cache to take the best configuration from (default: as 'tune')");
  cmd->add_flag("--no-tuned", a->no_tuned, "Ignore the tune cache: the default configuration");
  cmd->add_option("--combined-min-width", a->combined_min_width,
                  "combined:*: triangles with a narrower box (pixels) go by Phong per pixel (default 2^(K+1), auto 8; 0: none)");
  cmd->add_option("--triangle-choice", a->triangle_choice,
                  "combined:*: per triangle Gouraud or the segments: bound (combined:auto's default: Gouraud where its "
                  "expected error meets --max-error), sources[:M,Q,P] (the thesis's thresholds 0.9,0.004,0.008), "
                  "sources-literal[:M,Q,P] (its listing as printed), list:FILE (Phong for the screen triangles FILE names, "
                  "Gouraud for the rest: a choice made elsewhere, e.g. scripts/mix_oracle.py's), none (combined:K's "
                  "default); docs/triangle-choice.md");
  cmd->add_flag("--highlight-test", a->highlight_test,
                "combined:*: skip the specular term per triangle and light where no highlight can fall ([Dembitsky 2025, software/hardware rendering] ch. 3)");
  cmd->add_option("--against", a->against,
                  "Also render METHOD (flat, gouraud or phong, its defaults) in the same process, its frames "
                  "alternating with this method's, and report the median of the pairs' frame ratios: a comparison "
                  "that a host whose speed drifts between processes cannot bias (bench/README.md)")
      ->type_name("METHOD");
  cmd->add_flag("--float", a->float_output, "Also read back unclamped float colour (EXR output; error of the float values)");
  cmd->add_flag("--no-error", a->no_error, "Skip the exact reference and the error figures");
  cmd->add_option("--reference-image", a->reference_image,
                  "Also write the exact reference (double precision, --error-reference) as an image; any format -o "
                  "takes (EXR keeps the unrounded values)");
  cmd->add_option("--error-map", a->error_map,
                  "Also write the per-pixel error (levels, largest channel difference, as the report's max) as a "
                  "viridis colour map with its scale; white: not compared (docs/pictures.md)");
  cmd->add_option("--triangle-map", a->triangle_map,
                  "Also write the exact reference's visible triangle per pixel (its index + 1 in 24 bits, R the high "
                  "byte, B the low; 0 where none) as a png, tif or ppm: an ID buffer for studies (docs/pictures.md)");
  cmd->add_option("--error-reference", a->error_reference,
                  "Reference of --reference-image and --error-map: ideal (the method's own ideal, the report's "
                  "'implementation' error) or exact (exact Phong, the report's 'method' error)")
      ->capture_default_str();
  add_quiet_flag(*cmd, a->quiet);
  return {cmd, [a, cmd]() {
            a->explicit_config = cmd->count("--tile") + cmd->count("--work-items") + cmd->count("--cu") +
                                     cmd->count("--partition") > 0;
            a->tile_given = cmd->count("--tile") > 0;
            a->device_origin = device_from_environment(a->device);
            return run_render(*a);
          }};
}

}  // namespace parashade::cli
