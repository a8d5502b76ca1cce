// Two builds of the frame kernel on one scene, frame by frame in one process: A with the kernel as it is
// (plus --a's build options), B with --b's (for example -D NAME that an #ifdef in the kernel source reads), or
// the two kernel shapes: --b-shape lanes [--b-group N] (docs/pipeline.md), each side's shape and work-group
// (--a-shape, --a-group) as render's --kernel-shape and --work-group-size.
// Each pair renders A and B one right after the other, in alternating order, so a noisy host slows both alike;
// the figures are the medians of the pairs' ratios B/A. On a 2-vCPU VM whose separate runs of one binary
// differed by up to a third, two identical builds measured this way stayed within 0.96-1.03 (bench/README.md,
// "A kernel change on a noisy host"). The images of the two builds are compared too.
//
//   bench_kernel_ab SCENE --b "-D NAME" [--a OPTIONS] [--a-shape S --a-group N --a-tile T, the same for B]
//                   [--method phong] [--max-error L] [--size WxH]
//                   [--tile N] [--pairs 200] [--same-image] [--json FILE]
//
// The device is PARASHADE_DEVICE's (as `render --device`), else the default device. Not a Google Benchmark
// program: Google Benchmark times one case at a time, and the host's phases then fall on one side.
#include <algorithm>
#include <cstdio>
#include <string>
#include <tuple>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "bench_device.hpp"
#include "parashade/combined.hpp"
#include "parashade/errors.hpp"
#include "parashade/method.hpp"
#include "parashade/renderer.hpp"
#include "parashade/scene.hpp"
#include "parashade/statistics.hpp"
#include "parashade/tile_choice.hpp"
#include "json_output.hpp"
#include "parashade/report_header.hpp"
#include "tool_main.hpp"

namespace parashade {
namespace {

struct Side {
  std::vector<double> kernel_ms, frame_ms;
};

std::vector<double> ratios(const std::vector<double>& b, const std::vector<double>& a) {
  std::vector<double> r;
  for (std::size_t i = 0; i < a.size(); ++i) r.push_back(b[i] / a[i]);
  return r;
}

// A side's build: its extra -D options, kernel shape and work-group size.
struct Build {
  std::string defines, shape = "vector";
  int group = 0, tile = 0;  // tile 0: --tile's
  bool operator==(const Build& o) const {
    return defines == o.defines && shape == o.shape && group == o.group && tile == o.tile;
  }
  std::string text() const {
    std::string t = defines.empty() ? std::string("(the kernel as it is)") : defines;
    if (shape != "vector" || group != 0) t += " [" + shape + ", work-group " + std::to_string(group) + "]";
    if (tile != 0) t += " [tile " + std::to_string(tile) + "]";
    return t;
  }
  void apply(RenderOptions& o) const {
    o.kernel_defines = defines;
    o.kernel_shape = parse_kernel_shape(shape);
    o.work_group_size = group;
    if (tile != 0) o.tile_size = tile;
  }
};

int run(int argc, char** argv) {
  CLI::App app{"Frame-by-frame comparison of two builds of the frame kernel (A: --a's options, B: --b's)"};
  std::string scene_path, method_text = "phong", size, json_path;
  Build build_a, build_b;
  int pairs = 200, tile = 0;
  double max_error = 0.0;
  bool require_same_image = false;
  app.add_option("scene", scene_path, "Scene file (JSON) or bare mesh")->required();
  app.add_option("--a", build_a.defines, "Build options added to A's kernel (default none: the kernel as it is)");
  app.add_option("--b", build_b.defines, "Build options added to B's kernel, e.g. \"-D NAME=1\"");
  app.add_option("--a-shape", build_a.shape, "A's kernel shape, vector (default) or lanes");
  app.add_option("--b-shape", build_b.shape, "B's kernel shape, vector (default) or lanes");
  app.add_option("--a-group", build_a.group, "A's work-group size, as render's --work-group-size (default 0)");
  app.add_option("--b-group", build_b.group, "B's work-group size (default 0)");
  app.add_option("--a-tile", build_a.tile, "A's tile size (default --tile's)");
  app.add_option("--b-tile", build_b.tile, "B's tile size (default --tile's)");
  app.add_option("--method", method_text, "Shading method, as render's --method (default phong)");
  const CLI::Option* max_error_given =
      app.add_option("--max-error", max_error, "combined:auto's error budget in levels, as render's (default render's)");
  app.add_option("--size", size, "Resolution WIDTHxHEIGHT, overriding the scene's");
  app.add_option("--tile", tile, "Tile size (default: render's choice for the scene)");
  app.add_option("--pairs", pairs, "Timed pairs of frames (default 200)")->check(CLI::Range(1, 100000));
  app.add_flag("--same-image", require_same_image, "Exit with 1 when the two builds' images differ (a lever that must not change them)");
  app.add_option("--json", json_path, "Also write the medians and every pair's times to this JSON file");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : int(ExitCode::usage);  // --help: 0; a bad command line: 2, as parashade's
  }
  if (build_a == build_b) throw UsageError("--a and --b are the same build: give B other options, shape or work-group");
  JsonOutput json(json_path);  // a bad path fails now, not after the pairs

  const auto wh = parse_size(size);  // its syntax before the scene is read
  Scene scene = load_scene(scene_path);
  if (wh) {
    std::tie(scene.width, scene.height) = *wh;
    check_resolution(scene.width, scene.height, "--size " + size);
  }
  RenderOptions options;
  options.method = parse_method(method_text);
  if (options.method == Method::combined) options.combined = parse_combined(method_text);
  if (max_error_given->count() > 0) {
    if (!options.combined.automatic) throw UsageError("--max-error applies to combined:auto only");
    if (!(max_error > 0 && max_error <= 255)) throw UsageError("--max-error must be in (0, 255] levels");
    options.combined.max_error = max_error;
  }
  options.tile_size = tile > 0 ? tile : default_tile_size(scene, options, options.band_record_bytes);
  RenderOptions a = options, b = options;
  build_a.apply(a);
  build_b.apply(b);
  Renderer ra(bench_device(), a), rb(bench_device(), b);

  // Builds, work-group compilation and allocations; then the images of the two builds.
  for (int i = 0; i < 2; ++i) {
    ra.render(scene);
    rb.render(scene);
  }
  const auto& image_a = ra.render(scene).image.rgba;
  const std::vector<std::uint8_t> first(image_a.begin(), image_a.end());
  const auto& image_b = rb.render(scene).image.rgba;
  const bool same_image = std::equal(first.begin(), first.end(), image_b.begin(), image_b.end());

  Side sa, sb;
  for (int i = 0; i < pairs; ++i) {
    for (int j = 0; j < 2; ++j) {
      const bool b_now = (j == 0) == (i % 2 == 1);  // A first in even pairs, B first in odd ones
      const Frame& f = (b_now ? rb : ra).render(scene);
      Side& s = b_now ? sb : sa;
      s.kernel_ms.push_back(f.timings.kernel_ms);
      s.frame_ms.push_back(f.timings.total_ms);
    }
    if (pairs >= 50 && (i + 1) % (pairs / 5) == 0) std::fprintf(stderr, "  %d of %d pairs\n", i + 1, pairs);
  }
  const double kernel_ratio = median(ratios(sb.kernel_ms, sa.kernel_ms));
  const double frame_ratio = median(ratios(sb.frame_ms, sa.frame_ms));
  const DeviceInfo& d = bench_device().info();
  std::printf("%s, %s, %dx%d, tile %d, device %s (%d compute units)\n", scene_path.c_str(), method_text.c_str(),
              scene.width, scene.height, options.tile_size, d.name.c_str(), int(d.compute_units));
  std::printf("A: %s\nB: %s\n", build_a.text().c_str(), build_b.text().c_str());
  std::printf("images: %s\n", same_image ? "identical" : "DIFFERENT");
  std::printf("kernel ms: A %.3f, B %.3f (medians); B/A %.3f (median of %d pairs)\n", median(sa.kernel_ms),
              median(sb.kernel_ms), kernel_ratio, pairs);
  std::printf("frame ms:  A %.3f, B %.3f (medians); B/A %.3f\n", median(sa.frame_ms), median(sb.frame_ms), frame_ratio);
  if (!json_path.empty()) {
    nlohmann::json j = {{"scene", scene_path},
                        {"method", method_text},
                        {"width", scene.width},
                        {"height", scene.height},
                        {"tile", options.tile_size},
                        {"device", d.name},
                        {"compute_units", d.compute_units},
                        {"a_options", build_a.defines},
                        {"b_options", build_b.defines},
                        {"a_shape", build_a.shape},
                        {"b_shape", build_b.shape},
                        {"a_group", build_a.group},
                        {"b_group", build_b.group},
                        {"pairs", pairs},
                        {"images_identical", same_image},
                        {"kernel_ratio_median", kernel_ratio},
                        {"frame_ratio_median", frame_ratio},
                        {"a", {{"kernel_ms", sa.kernel_ms}, {"frame_ms", sa.frame_ms}}},
                        {"b", {{"kernel_ms", sb.kernel_ms}, {"frame_ms", sb.frame_ms}}}};
    json.write(stamp_report(j, "kernel-ab"));
  }
  if (require_same_image && !same_image) {
    std::fprintf(stderr, "bench_kernel_ab: the two builds' images differ (--same-image)\n");
    return 1;
  }
  return 0;
}

}  // namespace
}  // namespace parashade

int main(int argc, char** argv) { return parashade::tool_main("bench_kernel_ab", parashade::run, argc, argv); }
