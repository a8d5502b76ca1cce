// parashade against Mesa llvmpipe frame by frame in one process: each pair renders one parashade frame and one
// llvmpipe frame of the same scene right after each other, in alternating order, and the figure is the median of
// the pairs' ratios llvmpipe / parashade with its 10th and 90th percentiles. A noisy spell of a shared host then
// slows both sides of the pairs it falls on, where bench_llvmpipe (Google Benchmark, one case at a time) can see
// it on one side only. The frames are bench_llvmpipe's: parashade's whole frame (vertex stage to read-back) at
// `parashade render`'s default tile, llvmpipe's clear, draw and glReadPixels with the meshes resident;
// LP_NUM_THREADS is the OpenCL device's compute units unless already set.
//
//   bench_peer_pairs [--scenes sphere_8k,sphere_131k,sphere_2m,teapot,bunny,fullscreen_quad]
//                    [--methods gouraud,phong] [--size 1920x1080] [--pairs 30] [--json FILE]
//
// Scenes by bench_llvmpipe's names (bench/peer/bench_scenes.hpp); bunny and fandisk need PARASHADE_MESH_DIR
// and are skipped with a message without it. The device is PARASHADE_DEVICE's (as `render --device`).
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "bench_device.hpp"
#include "comma_list.hpp"
#include "json_output.hpp"
#include "parashade/errors.hpp"
#include "parashade/host_clock.hpp"
#include "parashade/method.hpp"
#include "parashade/renderer.hpp"
#include "parashade/statistics.hpp"
#include "parashade/tile_choice.hpp"
#include "peer/bench_scenes.hpp"
#include "peer/llvmpipe_peer.hpp"
#include "parashade/report_header.hpp"
#include "tool_main.hpp"

namespace parashade {
namespace {

struct Case {
  std::string scene;
  Method method;
  std::vector<double> parashade_ms, llvmpipe_ms, ratio;  // per pair; ratio = llvmpipe / parashade
};

Case measure(peer::LlvmpipePeer& gl, const Scene& scene, const std::string& name, Method method, int pairs) {
  RenderOptions options;
  options.method = method;
  options.tile_size = default_tile_size(scene, options, options.band_record_bytes);
  Renderer renderer(bench_device(), options);
  RenderedImage peer_image;
  gl.load(scene);
  for (int i = 0; i < 2; ++i) {  // programs, shader JIT, allocations
    renderer.render(scene);
    gl.render(scene, method, peer_image);
  }
  Case c{name, method, {}, {}, {}};
  for (int i = 0; i < pairs; ++i) {
    double ours = 0, theirs = 0;
    for (int j = 0; j < 2; ++j) {
      if ((j == 0) == (i % 2 == 0)) {  // parashade first in even pairs, llvmpipe first in odd ones
        ours = renderer.render(scene).timings.total_ms;
      } else {
        const auto t0 = Clock::now();
        gl.render(scene, method, peer_image);
        theirs = ms_since(t0);
      }
    }
    c.parashade_ms.push_back(ours);
    c.llvmpipe_ms.push_back(theirs);
    c.ratio.push_back(theirs / ours);
  }
  return c;
}

std::unique_ptr<peer::LlvmpipePeer> open_peer() {
  try {
    return std::make_unique<peer::LlvmpipePeer>();
  } catch (const std::runtime_error& e) {  // no EGL display or no OpenGL 3.3 context
    throw DeviceError(std::string("llvmpipe: ") + e.what());
  }
}

int run(int argc, char** argv) {
  CLI::App app{"parashade against Mesa llvmpipe, frame by frame in one process: medians of the pairs' ratios"};
  std::string scenes_text = "sphere_8k,sphere_131k,sphere_2m,teapot,bunny,fullscreen_quad";
  std::string methods_text = "gouraud,phong", size = "1920x1080", json_path;
  int pairs = 30;
  app.add_option("--scenes", scenes_text, "Comma-separated bench scenes (bench_llvmpipe's names)");
  app.add_option("--methods", methods_text, "Comma-separated methods: gouraud, phong (default both)");
  app.add_option("--size", size, "Resolution WIDTHxHEIGHT (default 1920x1080)");
  app.add_option("--pairs", pairs, "Timed pairs of frames per scene and method (default 30)")
      ->check(CLI::Range(1, 100000));
  app.add_option("--json", json_path, "Also write every pair's times and the medians to this JSON file");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : int(ExitCode::usage);
  }
  // Everything that can be wrong with the command line fails before the first frame.
  const auto wh = parse_size(size);
  if (!wh) throw UsageError("--size needs WIDTHxHEIGHT");
  const auto [width, height] = *wh;
  check_resolution(width, height, "--size " + size);
  std::vector<Method> methods;
  for (const std::string& m : comma_list(methods_text)) {
    const Method method = parse_method(m);
    if (method != Method::gouraud && method != Method::phong)
      throw UsageError("--methods: the peer renders gouraud and phong, not '" + m + "'");
    methods.push_back(method);
  }
  const char* mesh_dir = std::getenv("PARASHADE_MESH_DIR");
  std::vector<std::string> scenes;
  for (const std::string& s : comma_list(scenes_text)) {
    if (bench::needs_mesh_dir(s) && !(mesh_dir && *mesh_dir)) {
      std::fprintf(stderr, "bench_peer_pairs: PARASHADE_MESH_DIR is not set: %s skipped\n", s.c_str());
      continue;
    }
    bench::scene_named(s, width, height);  // an unknown name or a bad mesh: InputError now
    scenes.push_back(s);
  }
  if (methods.empty() || scenes.empty()) throw UsageError("nothing to measure: no method or no scene left");
  JsonOutput json(json_path);

  const DeviceInfo& d = bench_device().info();
  // Mesa reads LP_NUM_THREADS when the driver loads: set it before the first EGL call.
  setenv("LP_NUM_THREADS", std::to_string(d.compute_units).c_str(), 0);
  const std::unique_ptr<peer::LlvmpipePeer> peer = open_peer();
  peer::LlvmpipePeer& gl = *peer;
  if (gl.info().renderer.find("llvmpipe") == std::string::npos)
    throw DeviceError("the GL renderer is " + gl.info().renderer + ", not llvmpipe; set GALLIUM_DRIVER=llvmpipe");
  const std::string threads = std::getenv("LP_NUM_THREADS");
  std::printf("%s with LP_NUM_THREADS %s against %s (%d compute units), %dx%d, %d pairs each\n",
              gl.info().renderer.c_str(), threads.c_str(), d.name.c_str(), int(d.compute_units), width, height, pairs);
  std::printf("%-16s %-8s %13s %12s   %s\n", "scene", "method", "parashade ms", "llvmpipe ms",
              "llvmpipe/parashade: median of the pairs [p10, p90]");

  nlohmann::json cases = nlohmann::json::array();
  for (const std::string& name : scenes)
    for (const Method method : methods) {
      std::fprintf(stderr, "bench_peer_pairs: %s %s ...\n", name.c_str(), method_name(method));
      const Case c = measure(gl, bench::scene_named(name, width, height), name, method, pairs);
      const double r = median(c.ratio), p10 = quantile(c.ratio, 0.1), p90 = quantile(c.ratio, 0.9);
      std::printf("%-16s %-8s %13.3f %12.3f   %.2f [%.2f, %.2f]\n", name.c_str(), method_name(method),
                  median(c.parashade_ms), median(c.llvmpipe_ms), r, p10, p90);
      std::fflush(stdout);
      cases.push_back({{"scene", name},
                       {"method", method_name(method)},
                       {"parashade_median_ms", median(c.parashade_ms)},
                       {"llvmpipe_median_ms", median(c.llvmpipe_ms)},
                       {"ratio_median", r},
                       {"ratio_p10", p10},
                       {"ratio_p90", p90},
                       {"parashade_ms", c.parashade_ms},
                       {"llvmpipe_ms", c.llvmpipe_ms}});
    }
  nlohmann::json body = {{"device", d.name},
                         {"compute_units", d.compute_units},
                         {"gl_renderer", gl.info().renderer},
                         {"gl_version", gl.info().version},
                         {"lp_num_threads", threads},
                         {"width", width},
                         {"height", height},
                         {"pairs", pairs},
                         {"cases", cases}};
  json.write(stamp_report(body, "peer-pairs"));
  return 0;
}

}  // namespace
}  // namespace parashade

int main(int argc, char** argv) { return parashade::tool_main("bench_peer_pairs", parashade::run, argc, argv); }
