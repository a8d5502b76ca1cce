// `parashade render SCENE -o IMAGE`: parse the command line into a render request, resolve it, render it
// (render_step.hpp), write the outputs and print the summary. --distribute runs the frame across MPI ranks
// (distributed.hpp) from the same request.
#include <algorithm>
#include <cstdlib>
#include <iostream>

#include "cli_args.hpp"
#include "common_options.hpp"
#include "commands.hpp"
#include "device_option.hpp"
#include "parse_errors.hpp"
#include "plan_cli.hpp"
#include "progress.hpp"
#include "render_call.hpp"
#include "../render/error_pictures.hpp"
#include "parashade/combined.hpp"
#include "parashade/device_layout.hpp"
#include "parashade/distributed.hpp"
#include "parashade/errors.hpp"
#include "parashade/notes.hpp"
#include "parashade/render_outputs.hpp"
#include "parashade/render_report.hpp"
#include "parashade/render_step.hpp"
#include "parashade/split_renderer.hpp"
#include "parashade/sub_devices.hpp"
#include "parashade/unit_table.hpp"

namespace parashade::cli {
namespace {

struct RenderArgs {
  std::string scene, output, method = "gouraud", device, size, report, units, arith = "float", division = "constant",
              coverage = "centre", specular = "exact", normalize = "exact", triangle_choice, kernel_shape = "vector";
  std::string against;  // --against: a plain method whose frames alternate with this one's
  std::string against_device;  // --against-device: a device whose frames of this request alternate with these
  int frames = 5, warmup = 1;
  // The knobs that are plain values bind straight to the options the renderer and its kernel read (one
  // name from --NAME to the kernel's macro): --tile (0 here: chosen for the scene, tile_choice.hpp),
  // --work-items, --work-group-size, --defer-min-triangles, --float; --kernel-shape is parsed into kernel_shape.
  RenderOptions options = [] {
    RenderOptions o;
    o.tile_size = 0;
    return o;
  }();
  // Triangle records a frame may hold at once before it streams in bands of as many (MiB); 0: never
  // streams; -1 (not given): by the frame (default_band_mib, bands of 16).
  int band_mib = -1;
  double max_error = 0;  // 0: not given
  int combined_min_width = -1;
  bool no_error = false, quiet = false, highlight_test = false;
  PlanArgs plan;
  std::string tune_cache;
  std::string reference_image, error_map, error_reference = "ideal";  // the pictures of the error
  std::string error_scale = "gamma", error_legend, flip_map;         // docs/pictures.md
  bool flip = false;                                                 // LDR-FLIP in the figures
  std::string triangle_map;  // the reference's visible triangle per pixel
  std::string distribute, rank_partition, read_scene;  // --distribute: MPI ranks (docs/distributed.md)
  double rank_timeout = kDefaultRankTimeoutSeconds;     // --distribute: the rank watchdog
  bool no_tuned = false, explicit_config = false, keep_going = false;  // explicit: --tile, --work-items, --cu or --partition given
  bool shape_given = false;                                            // --kernel-shape given (else the device's)
};

// The combined method's options (--method combined:*, --combined-min-width, --triangle-choice, --max-error).
void combined_options(const RenderArgs& a, RenderOptions& o) {
  if (o.method == Method::combined) o.combined = parse_combined(a.method);
  o.combined.highlight_test = a.highlight_test;
  if (a.combined_min_width != -1) {
    if (o.method != Method::combined) throw UsageError("--combined-min-width needs --method combined:K or combined:auto");
    if (a.combined_min_width < 0 || a.combined_min_width > kMaxResolution)
      throw UsageError("--combined-min-width must be 0.." + std::to_string(kMaxResolution) + " pixels");
    o.combined.min_width = a.combined_min_width;
  }
  if (!a.triangle_choice.empty())
    for_option("--triangle-choice", [&] { parse_triangle_rule(a.triangle_choice, o.combined); });
  if (a.max_error != 0) {
    if (o.method != Method::combined || !(o.combined.automatic || o.combined.rule == TriangleRule::bound))
      throw UsageError("--max-error is the error budget of --method combined:auto or --triangle-choice bound; method '" +
                       a.method + "' with triangle choice '" + triangle_rule_name(o.combined) + "' has none");
    if (!(a.max_error > 0 && a.max_error <= 255)) throw UsageError("--max-error must be in (0, 255] levels");
    o.combined.max_error = a.max_error;
  }
}

// Every option that reaches the frame, parsed (usage errors name the option).
RenderOptions render_options(const RenderArgs& a) {
  RenderOptions o = a.options;
  o.method = parse_method(a.method);
  o.kernel_shape = for_option("--kernel-shape", [&] { return parse_kernel_shape(a.kernel_shape); });
  if (o.work_items < 0) throw UsageError("--work-items must not be negative");
  if (o.defer_min_triangles < -1 || o.defer_min_triangles > kMaxDeferMinTriangles)
    throw UsageError("--defer-min-triangles must be 0.." + std::to_string(kMaxDeferMinTriangles) + " (or -1, the default)");
  o.band_record_bytes = a.band_mib < 0 ? kBandBytesByFrame : a.band_mib == 0 ? SIZE_MAX : std::size_t(a.band_mib) << 20;
  combined_options(a, o);
  if (!a.units.empty()) o.units = for_option("--units", [&] { return parse_units(a.units); });
  o.arith = for_option("--arith", [&] { return parse_arith(a.arith); });
  o.division = for_option("--div", [&] { return parse_division(a.division); });
  if (a.coverage != "centre" && a.coverage != "dda")
    throw UsageError("unknown coverage '" + a.coverage + "' (valid: centre, dda)");
  o.dda_coverage = a.coverage == "dda";
  o.plan = plan_options(a.plan);
  o.specular = for_option("--specular", [&] { return parse_specular(a.specular); });
  o.normalize = for_option("--normalize", [&] { return parse_normalize(a.normalize); });
  return o;
}

// The first picture option given (or --flip), for messages.
std::string picture_option(const RenderOutputs& o) {
  return !o.error_map.empty()         ? "--error-map"
         : !o.reference_image.empty() ? "--reference-image"
         : !o.triangle_map.empty()    ? "--triangle-map"
         : !o.flip_map.empty()        ? "--flip-map"
                                      : "--flip";
}

RenderOutputs render_outputs(const RenderArgs& a) {
  if (a.error_reference != "ideal" && a.error_reference != "exact")
    throw UsageError("--error-reference must be ideal (the method's own ideal) or exact (exact Phong), not '" +
                     a.error_reference + "'");
  RenderOutputs o;
  o.image = a.output;
  o.report = a.report;
  o.reference_image = a.reference_image;
  o.error_map = a.error_map;
  o.triangle_map = a.triangle_map;
  o.against_exact = a.error_reference == "exact";
  o.error_scale = parse_error_scale(a.error_scale);
  o.error_legend = a.error_legend;
  o.flip_map = a.flip_map;
  check_error_picture_options({o.error_map, o.error_legend, o.error_scale}, "--error-map");
  if ((o.pictures() || a.flip) && a.no_error)
    throw UsageError(picture_option(o) + " needs the exact reference, which --no-error skips");
  return o;
}

// The request the command line makes (usage errors first: before any file is read).
RenderRequest render_request(const RenderArgs& a, const RenderOutputs& outputs) {
  RenderRequest r;
  r.scene_file = a.scene;
  r.size = checked_size(a.size);
  r.options = render_options(a);
  r.device = a.device;
  r.keep_going = a.keep_going;
  if (a.frames < 1 || a.frames > kMaxFrames)
    throw UsageError("--frames must be 1.." + std::to_string(kMaxFrames) + " (got " + std::to_string(a.frames) + ")");
  if (a.warmup < 0 || a.warmup > kMaxFrames)
    throw UsageError("--warmup must be 0.." + std::to_string(kMaxFrames) + " (got " + std::to_string(a.warmup) + ")");
  r.frames = a.frames;
  r.warmup = a.warmup;
  r.error_figures = !a.no_error;
  r.keep_reference = outputs.needs_reference();
  r.pictures = outputs.picture_options();
  r.flip = {a.flip || !outputs.flip_map.empty(), outputs.against_exact, !outputs.flip_map.empty()};
  r.use_tuned = !a.no_tuned && !a.explicit_config;
  r.tune_cache = a.tune_cache;
  r.device_kernel_shape = !a.shape_given;
  if (!a.against.empty()) {
    r.against = for_option("--against", [&] { return parse_method(a.against); });
    // A combined configuration would need options of its own; the baselines are the plain methods.
    if (*r.against == Method::combined)
      throw UsageError("--against takes flat, gouraud or phong with render's defaults (got '" + a.against + "')");
    if (!a.distribute.empty() || is_device_list(a.device))
      throw UsageError("--against pairs frames of two renderers on one device in one process; not with --distribute "
                       "or a device list ('" + (a.distribute.empty() ? a.device : "--distribute " + a.distribute) + "')");
  }
  if (!a.against_device.empty() && !a.distribute.empty())
    throw UsageError("--against-device pairs frames of two devices in one process; not with --distribute " +
                     a.distribute);
  r.against_device = a.against_device;
  r.quiet = a.quiet;
  return r;
}

// The image and the report, as "wrote ..." names them.
std::vector<std::string> written_files(const RenderOutputs& o) {
  std::vector<std::string> files = {o.image.string()};
  if (!o.report.empty()) files.push_back(o.report.string());
  return files;
}

// What resolving decided that the user should hear before the frames.
void print_notes(const RenderArgs& a, const ResolvedRender& r) {
  print_resolved(r);
  if (!r.options.units && r.options.unit_path() && !a.quiet)
    print_note((r.options.arith.fixed ? "--arith " + a.arith : std::string("--coverage dda")) +
               " runs on the classic unit (--units chooses another)");
}

// What the devices the request resolved to allow (after resolve: the selector may come from the environment).
void check_device_use(const RenderArgs& a, const ResolvedRender& r, const RenderOutputs& outputs) {
  const std::string selector = a.device.empty() ? std::string("the default device") : "'" + a.device + "'";
  if ((outputs.pictures() || a.flip) && r.mode == DeviceMode::bands)
    throw UsageError(picture_option(outputs) + " needs the error figures, which a frame split across devices (" +
                     selector + ") does not compute; render on one device");
  if (a.keep_going && r.mode == DeviceMode::unit_sub_devices)
    throw UsageError("--keep-going drops devices of a split frame; the units of --cu on sub-devices (" + selector +
                     ") have no fallback: a failing sub-device ends the run");
  if (a.keep_going && r.mode != DeviceMode::bands)
    throw UsageError("--keep-going drops failing devices of a list (--device all, A,B or sub:NAME:N); " + selector +
                     " is one device");
}

// render --distribute: the frame across MPI ranks (docs/distributed.md); every rank runs this.
int run_distributed(const RenderArgs& a, const RenderRequest& request, const RenderOutputs& outputs) {
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
  if (!a.read_scene.empty() && a.read_scene != "every-rank" && a.read_scene != "rank-0")
    throw UsageError("unknown --read-scene '" + a.read_scene + "' (valid: every-rank, rank-0)");
  job.scatter_scene = a.read_scene == "rank-0";
  job.rank_timeout = a.rank_timeout;
  job.request = request;
  if (job.request.options.tile_size == 0) job.request.options.tile_size = TILE_DEFAULT;
  with_option_names(job.request.options, distribute_device_mode(job.mode),
                    [&] { check_render_options(job.request.options, distribute_device_mode(job.mode)); });
  job.outputs = outputs;
  job.rank_batch = a.plan.batch;
  job.setup_clocks = a.plan.setup_clocks;
  job.quiet = a.quiet;
  RenderResult result;
  std::vector<std::string> lines;
  const int code = run_distributed_render(job, &result, &lines);
  if (code == 0 && result.distributed) {  // rank 0
    print_render_warnings(result, std::cerr);
    print_render_summary(result, lines, written_files(outputs), !a.quiet);
  }
  return code;
}

// Every rank checks the command line before MPI starts; only rank 0 (or a run without mpirun) says what
// is wrong, the others leave with the same code and no message (main prints none for an empty one).
int run_distributed_quietly(const RenderArgs& a, const RenderRequest& request, const RenderOutputs& outputs) {
  try {
    return run_distributed(a, request, outputs);
  } catch (const UsageError& e) {
    const char* rank = std::getenv("OMPI_COMM_WORLD_RANK");
    if (rank && std::string(rank) != "0" && *e.what()) throw UsageError("");
    throw;
  }
}

int run_render(const RenderArgs& a) {
  const RenderOutputs outputs = render_outputs(a);
  const RenderRequest request = render_request(a, outputs);
  if (!a.distribute.empty()) return run_distributed_quietly(a, request, outputs);
  if (!a.rank_partition.empty()) throw UsageError("--rank-partition needs --distribute sort-last");
  if (!a.read_scene.empty()) throw UsageError("--read-scene needs --distribute (how MPI ranks get the scene)");
  CommandFiles files;
  outputs.declare(files);
  const ResolvedRender r = resolve_with_option_names(request, files);
  check_device_use(a, r, outputs);
  print_notes(a, r);
  if (!a.quiet)
    std::cerr << "rendering " << r.scene.name << " (" << r.scene.width << "x" << r.scene.height << ", "
              << r.scene.triangle_count() << " triangles, " << method_name(r.options.method) << ") on "
              << r.devices.front()->info().name << " ...\n";
  FrameProgress progress(a.warmup + a.frames, a.quiet);
  const RenderResult result = render(r, [&](int done, int) { progress.step(done); });
  print_render_warnings(result, std::cerr);
  const std::vector<std::string> lines = outputs.write(result);
  print_render_summary(result, lines, written_files(outputs), !a.quiet);
  return 0;
}

// What the frame computes: the method and its Phong and combined options.
void add_shading_options(CLI::App* cmd, const std::shared_ptr<RenderArgs>& a) {
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
}

// Where it renders: the device(s), MPI ranks, and the tune cache's entry for them.
void add_device_options(CLI::App* cmd, const std::shared_ptr<RenderArgs>& a) {
  add_device_option(*cmd, a->device,
                    "OpenCL device: index or name substring (see 'parashade devices'); 'all' (the real devices: not a "
                    "simulator, nor PoCL's basic beside pthread) or a comma list splits the frame across devices by "
                    "measured speed; sub:NAME:N or sub:NAME:N1+N2 uses NAME's sub-devices (bands "
                    "of the frame; with --cu, the units' depth pass on them)");
  cmd->add_option("--distribute", a->distribute,
                  "Under mpirun: the frame across the MPI ranks, sort-last (shares of the triangles by modeled cost, "
                  "depth keys composited) or sort-first (bands by measured speed); the image is the one-process "
                  "render's (docs/distributed.md)");
  cmd->add_option("--rank-partition", a->rank_partition,
                  "--distribute sort-last: the planner's strategy for triangles to ranks: lpt (default), round-robin, "
                  "dynamic (batches of --batch)");
  add_rank_timeout_option(*cmd, a->rank_timeout, "--distribute");
  cmd->add_option("--read-scene", a->read_scene,
                  "--distribute: every-rank (default: each rank reads the scene file) or rank-0 (rank 0 reads it and "
                  "scatters each sort-last rank its share of the triangles, or broadcasts the scene to sort-first ranks)");
  cmd->add_flag("--keep-going", a->keep_going,
                "With a device list (bands): drop a failing device (named) and go on with the others");
  cmd->add_option("--tune-cache", a->tune_cache, "Tune cache to take the best configuration from (default: as 'tune')");
  cmd->add_flag("--no-tuned", a->no_tuned, "Ignore the tune cache: the default configuration");
}

// How the modeled hardware computes it (unit, arithmetic, coverage, plan) and the kernel's layout.
void add_layout_options(CLI::App* cmd, const std::shared_ptr<RenderArgs>& a) {
  add_size_option(*cmd, a->size);
  cmd->add_option("--tile", a->options.tile_size,
                  "Screen tile size: " + tile_sizes_text() + " (default: " + std::to_string(TILE_MAX) +
                      " for a Gouraud or flat frame on one device that is not streamed in bands, else " +
                      std::to_string(TILE_DEFAULT) + "; a tuned entry's when there is one)")
      ->check(tile_validator());
  cmd->add_option("--work-items", a->options.work_items,
                  "Kernel work-items, each rendering every N-th tile (0: the device's: on a CPU one a tile up to " +
                      std::to_string(kCpuWorkItemsPerComputeUnit) + " per compute unit; docs/pipeline.md)")
      ->capture_default_str();
  cmd->add_option("--kernel-shape", a->kernel_shape,
                  "The frame kernel's shape: vector (a work-item walks whole tiles with explicit 16-lane vectors) or "
                  "lanes (a work-group per tile, a work-item per pixel lane, for implicit vectorizers and GPUs; the "
                  "plain frame and --float only). Default: a tuned entry's, else the device's (vector on a CPU or "
                  "simulator, lanes on a GPU). Same image; docs/pipeline.md");
  cmd->add_option("--work-group-size", a->options.work_group_size,
                  "Work-items per work-group, a power of two (0: the shape's default, 1 for vector, " +
                      std::to_string(LANES_WORK_GROUP_DEFAULT) + " or the tile's pixels or the device's largest for "
                      "lanes, each owning tile x tile / N of them)")
      ->capture_default_str();
  cmd->add_option("--defer-min-triangles", a->options.defer_min_triangles,
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
}

// What is timed and what is written: frames, the report, the error figures and their pictures.
void add_output_options(CLI::App* cmd, const std::shared_ptr<RenderArgs>& a) {
  add_report_option(*cmd, a->report, "timings, stages, error figures");
  cmd->add_option("--frames", a->frames,
                  "Timed frames (at most " + std::to_string(kMaxFrames) + "); the median is reported; on a terminal "
                  "a progress line [i/N] shows the time left")
      ->capture_default_str();
  cmd->add_option("--warmup", a->warmup, "Untimed frames first (program build, work-group compilation; at most " +
                                             std::to_string(kMaxFrames) + ")")
      ->capture_default_str();
  cmd->add_option("--against", a->against,
                  "Also render METHOD (flat, gouraud or phong, its defaults) in the same process, its frames "
                  "alternating with this method's, and report the median of the pairs' frame ratios: a comparison "
                  "that a host whose speed drifts between processes cannot bias (bench/README.md)")
      ->type_name("METHOD");
  cmd->add_option("--against-device", a->against_device,
                  "Also render this request on DEVICE (an index or a name, as --device; with its own tuned entry, "
                  "kernel shape and layout) in the same process, its frames alternating with these, and report the "
                  "median of the pairs' frame and kernel ratios: two devices compared on one host (docs/reports.md)")
      ->type_name("DEVICE");
  cmd->add_flag("--float", a->options.float_output, "Also read back unclamped float colour (EXR output; error of the float values)");
  cmd->add_flag("--no-error", a->no_error, "Skip the exact reference and the error figures");
  cmd->add_option("--reference-image", a->reference_image,
                  "Also write the exact reference (double precision, --error-reference) as an image; any format -o "
                  "takes (EXR keeps the unrounded values)");
  cmd->add_option("--error-map", a->error_map,
                  "Also write the per-pixel error (levels, largest channel difference, as the report's max): a viridis "
                  "colour map of the image's size (white: not compared; scale: --error-scale, --error-legend), or to "
                  ".exr the values in levels, one float channel (docs/pictures.md)");
  cmd->add_option("--triangle-map", a->triangle_map,
                  "Also write the exact reference's visible triangle per pixel (its index + 1 in 24 bits, R the high "
                  "byte, B the low; 0 where none) as a png, tif or ppm: an ID buffer for studies (docs/pictures.md)");
  cmd->add_option("--error-reference", a->error_reference,
                  "Reference of --reference-image, --error-map and --flip: ideal (the method's own ideal, the report's "
                  "'implementation' error) or exact (exact Phong, the report's 'method' error)")
      ->capture_default_str();
  add_error_picture_options(*cmd, a->error_scale, a->error_legend, a->flip, a->flip_map);
}

// render's subcommand and every option of it, bound to `a`.
CLI::App* add_render_options(CLI::App& app, const std::shared_ptr<RenderArgs>& a) {
  auto* cmd = app.add_subcommand("render", "Render a scene (JSON) or a bare mesh file; print frame time and error");
  cmd->add_option("scene", a->scene, "Scene file (.json) or mesh (.obj .off .ply .stl)")->required();
  cmd->add_option("-o,--output", a->output, "Image to write; format from the extension (png, jpg, tif, ppm, exr ...)")
      ->required();
  add_shading_options(cmd, a);
  add_device_options(cmd, a);
  add_layout_options(cmd, a);
  add_output_options(cmd, a);
  add_quiet_flag(*cmd, a->quiet);
  return cmd;
}

// What only the count of options given says: an explicit configuration, an explicit kernel shape.
void note_options_given(RenderArgs& a, const CLI::App& cmd) {
  a.explicit_config = cmd.count("--tile") + cmd.count("--work-items") + cmd.count("--cu") + cmd.count("--partition") +
                          cmd.count("--kernel-shape") + cmd.count("--work-group-size") > 0;
  a.shape_given = cmd.count("--kernel-shape") > 0;
}

// render's arguments through its own definition, -o optional; a parse error as render's message.
std::shared_ptr<RenderArgs> parsed_render_args(const std::vector<std::string>& words) {
  CLI::App app;
  auto a = std::make_shared<RenderArgs>();
  CLI::App* cmd = add_render_options(app, a);
  cmd->get_option("--output")->required(false);
  std::vector<std::string> args = {"render"};
  args.insert(args.end(), words.begin(), words.end());
  std::reverse(args.begin(), args.end());  // CLI11 takes a vector last word first
  try {
    app.parse(args);
  } catch (const CLI::ParseError& e) {
    throw UsageError(parse_error_message(app, e));
  }
  note_options_given(*a, *cmd);
  return a;
}

}  // namespace

RenderCall parse_render_call(const std::vector<std::string>& words) {
  const std::shared_ptr<RenderArgs> a = parsed_render_args(words);
  if (!a->distribute.empty() || !a->rank_partition.empty() || !a->read_scene.empty())
    throw UsageError("--distribute, --rank-partition and --read-scene run a frame across MPI ranks: parashade render "
                     "under mpirun (docs/distributed.md), not in one process");
  RenderCall c;
  c.outputs = render_outputs(*a);
  if (c.outputs.image.empty() && (!c.outputs.report.empty() || c.outputs.pictures() || !c.outputs.error_legend.empty()))
    throw UsageError("--report and the pictures are written with the image: give -o IMAGE too");
  c.request = render_request(*a, c.outputs);
  c.check_resolved = [a, outputs = c.outputs](const ResolvedRender& r) {
    check_device_use(*a, r, outputs);
    print_notes(*a, r);
  };
  return c;
}

Command add_render_command(CLI::App& app) {
  auto a = std::make_shared<RenderArgs>();
  CLI::App* cmd = add_render_options(app, a);
  return {cmd, [a, cmd]() {
            note_options_given(*a, *cmd);
            return run_render(*a);
          }};
}

}  // namespace parashade::cli
