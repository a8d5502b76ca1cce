// parashade against the peer a user would pick, Mesa llvmpipe (EGL surfaceless, OpenGL 3.3 core), in one
// run (Google Benchmark; use --benchmark_enable_random_interleaving=true so a noisy spell on this shared
// machine does not fall on one side only). Cases, each at every --sizes resolution:
//   llvmpipe/SCENE/WxH/gouraud|phong   the peer (bench/peer/llvmpipe_peer.hpp)
//   parashade/SCENE/WxH/flat|gouraud|phong, parashade/teapot/WxH/gouraud:UNIT:ARITH (modeled units)
//   fill_limit/WxH                     a kernel that only writes every pixel: the device's ceiling
//   plane_fill_limit/WxH               every pixel's Gouraud colour and depth from planes, packed and
//                                      written: the least per-pixel work of a full-screen triangle
//   phong_plane_fill_limit/WxH         every pixel's normal and position from planes, normalized, lit by
//                                      fullscreen_quad's lights, packed and written (phong_plane_fill.hpp)
// Frame time: llvmpipe — clear, draw, glReadPixels (the meshes stay in vertex buffers uploaded once
// before timing, as an application keeps them); parashade — the renderer's whole frame (host vertex
// stage, clip and cull, setup, binning with the upload of the frame's triangles, kernel, read-back).
// Two untimed frames first on both sides. Counters (plain values): frame_ms, mpixel_per_s,
// mtriangle_per_s (scene triangles per second), triangles_in; error of the frame against parashade's
// exact Phong reference (nmse, psnr_db, max_abs, coverage_mismatch: pixels covered in one only, flip_mean:
// LDR-FLIP's mean over the frame, flip.hpp, about 0.8 s of CPU time a 1920x1080 case, once per case);
// peak_rss_mib (process peak resident memory during the case, reset before it through
// /proc/self/clear_refs; it includes everything the process holds) with memory_budget_mib =
// 2 x (frame buffers + mesh) + 64 MiB; modeled_clocks on the unit path.
// LP_NUM_THREADS is set to the OpenCL device's compute units unless already set (context: lp_num_threads).
//   --scenes=a,b,...  (default sphere_8k,sphere_131k,sphere_2m,teapot,robot,bunny,fandisk,fullscreen_quad)
//   --sizes=WxH,...   (default 1920x1080)
//   --no-error        skip the error figures (no reference rendering)
//   --images=DIR      write each case's frame (DIR/CASE.png, '/' as '_') and the exact reference
//                     (DIR/SCENE_WxH_exact.png) when its error is computed: the report's image strip
//   PARASHADE_DEVICE, PARASHADE_MESH_DIR as for bench_frame.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <benchmark/benchmark.h>

#include "bench_device.hpp"
#include "comma_list.hpp"

#include "parashade/device.hpp"
#include "parashade/flip.hpp"
#include "parashade/frame_pipeline.hpp"
#include "parashade/geometry_stage.hpp"
#include "parashade/image.hpp"
#include "parashade/lane_utilization.hpp"
#include "parashade/metrics.hpp"
#include "parashade/phong_plane_fill.hpp"
#include "parashade/reference.hpp"
#include "parashade/renderer.hpp"
#include "parashade/tile_choice.hpp"
#include "parashade/units.hpp"
#include "peer/bench_scenes.hpp"
#include "peer/llvmpipe_peer.hpp"
#include "benchmark_schema.hpp"

namespace parashade {
namespace {

peer::LlvmpipePeer& llvmpipe() {
  static peer::LlvmpipePeer p;
  return p;
}

bool g_errors = true;
std::string g_image_dir;

std::string file_name(std::string name) {
  for (char& c : name)
    if (c == '/' || c == ':') c = '_';
  return name;
}

// The exact reference as an 8-bit image (rounded, alpha 255 where covered).
RenderedImage exact_image(const ReferenceImage& ref) {
  RenderedImage img;
  img.width = ref.width;
  img.height = ref.height;
  img.rgba.resize(std::size_t(ref.width) * ref.height * 4);
  for (std::size_t i = 0; i < ref.exact.size(); ++i) {
    for (int c = 0; c < 3; ++c)
      img.rgba[4 * i + c] = std::uint8_t(std::lround(std::clamp(ref.exact[i][c], 0.0, 255.0)));
    img.rgba[4 * i + 3] = ref.covered[i] ? 255 : 0;
  }
  return img;
}

// Resident memory of this process in MiB, from /proc/self/status ("VmHWM" peak, "VmRSS" current).
double status_mib(const char* field) {
  std::ifstream f("/proc/self/status");
  std::string line;
  const std::string key = std::string(field) + ":";
  while (std::getline(f, line))
    if (line.compare(0, key.size(), key) == 0) return std::stod(line.substr(key.size())) / 1024.0;  // kB
  return NAN;
}
void reset_peak_rss() { std::ofstream("/proc/self/clear_refs") << "5"; }

double memory_budget_mib(const Scene& s) {
  double mesh = 0;
  for (const Object& o : s.objects)
    mesh += double(o.mesh->positions.size()) * 24.0 + double(o.mesh->triangles.size()) * 12.0;
  const double frame_buffers = double(s.width) * s.height * 8.0;  // RGBA8 colour + 32-bit depth
  return 2.0 * (frame_buffers + mesh) / (1024.0 * 1024.0) + 64.0;
}

// Error against the exact Phong reference, computed once per case (the reference is freed right after,
// so it does not count in the next case's peak memory).
std::map<std::string, ErrorMetrics>& error_cache() {
  static std::map<std::string, ErrorMetrics> m;
  return m;
}
void set_error_counters(benchmark::State& state, const std::string& name, const Scene& scene,
                        const RenderedImage& image) {
  if (!g_errors) return;
  auto it = error_cache().find(name);
  if (it == error_cache().end()) {
    ScreenGeometry g;
    build_screen_geometry(scene, {Method::phong, true}, g);
    const ReferenceImage ref = render_reference(scene, g, Method::phong);
    ErrorMetrics m = compare_to_reference(image, ref.covered, ref.exact, "exact phong");
    m.flip = flip_figures(ldr_flip(flip_input(ref.exact), flip_input(image), image.width, image.height));
    it = error_cache().emplace(name, m).first;
    if (!g_image_dir.empty()) {
      const std::string size = std::to_string(scene.width) + "x" + std::to_string(scene.height);
      write_image(g_image_dir + "/" + file_name(name) + ".png", image);
      const std::string exact = g_image_dir + "/" + scene.name + "_" + size + "_exact.png";
      if (!std::filesystem::exists(exact)) write_image(exact, exact_image(ref));
    }
  }
  const ErrorMetrics& e = it->second;
  state.counters["nmse"] = e.nmse;
  state.counters["psnr_db"] = e.psnr_db;
  state.counters["max_abs"] = e.max_abs;
  state.counters["coverage_mismatch"] = double(e.coverage_mismatch);
  state.counters["pixels_compared"] = double(e.pixels_compared);
  if (e.flip) state.counters["flip_mean"] = e.flip->mean;
}

void common_counters(benchmark::State& state, const Scene& scene, double frame_ms, double peak_mib) {
  state.counters["frame_ms"] = frame_ms;
  state.counters["mpixel_per_s"] = double(scene.width) * scene.height / (frame_ms * 1e3);
  state.counters["mtriangle_per_s"] = double(scene.triangle_count()) / (frame_ms * 1e3);
  state.counters["triangles_in"] = double(scene.triangle_count());
  state.counters["peak_rss_mib"] = peak_mib;
  state.counters["memory_budget_mib"] = memory_budget_mib(scene);
}

const Scene* scene_or_skip(benchmark::State& state, const std::string& name, int w, int h) {
  try {
    return &bench::scene_named(name, w, h);
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return nullptr;
  }
}

void llvmpipe_frame(benchmark::State& state, const std::string& case_name, const std::string& scene_name, int w, int h,
                    Method method) {
  const Scene* scene = scene_or_skip(state, scene_name, w, h);
  if (!scene) return;
  peer::LlvmpipePeer& gl = llvmpipe();
  RenderedImage image;
  reset_peak_rss();
  gl.load(*scene);
  for (int i = 0; i < 2; ++i) gl.render(*scene, method, image);  // shader JIT, framebuffer allocation
  double sum_ms = 0;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    gl.render(*scene, method, image);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    state.SetIterationTime(ms * 1e-3);
    sum_ms += ms;
  }
  const double peak = status_mib("VmHWM");
  common_counters(state, *scene, sum_ms / double(state.iterations()), peak);
  set_error_counters(state, case_name, *scene, image);
}

void parashade_frame(benchmark::State& state, const std::string& case_name, const std::string& scene_name, int w,
                     int h, const RenderOptions& options) {
  const Scene* scene = scene_or_skip(state, scene_name, w, h);
  if (!scene) return;
  reset_peak_rss();
  RenderOptions chosen = options;  // the tile `parashade render` takes by default
  chosen.tile_size = default_tile_size(*scene, options, options.band_record_bytes);
  Renderer renderer(bench_device(), chosen);
  for (int i = 0; i < 2; ++i) renderer.render(*scene);  // program build, work-group compilation, allocations
  double sum_ms = 0, kernel_ms = 0;
  const Frame* last = nullptr;
  for (auto _ : state) {
    last = &renderer.render(*scene);
    state.SetIterationTime(last->timings.total_ms * 1e-3);
    sum_ms += last->timings.total_ms;
    kernel_ms += last->timings.kernel_ms;
  }
  const double peak = status_mib("VmHWM");
  const double n = double(state.iterations());
  common_counters(state, *scene, sum_ms / n, peak);
  state.counters["kernel_ms"] = kernel_ms / n;
  state.counters["tile"] = chosen.tile_size;
  state.counters["triangles_after_culling"] = double(last->stats.geometry.triangles_out);
  if (options.unit_path()) state.counters["modeled_clocks"] = double(last->stats.clocks.clocks);
  if (!options.unit_path() && options.method != Method::combined) {  // the plain path's walk, counted on the host
    FramePipeline pipeline(chosen);
    const LaneUtilization lanes = lane_utilization(pipeline.prepare_frame(*scene));
    state.counters["lanes_rows"] = lanes.rows();
    state.counters["lanes_stamps"] = lanes.stamps();
  }
  set_error_counters(state, case_name, *scene, last->image);
}

// The Phong floor at w x h with the full-screen quad's lights, material and viewer (phong_plane_fill.hpp).
void phong_fill_limit(benchmark::State& state, int w, int h) {
  const Scene* scene = scene_or_skip(state, "fullscreen_quad", w, h);
  if (!scene) return;
  PhongPlaneFill fill(bench_device(), *scene, w, h);
  time_floor_launches(state, [&] { return fill.run_ms(); }, w, h);
}

// The fastest repetition beside Google Benchmark's median: on a shared machine other processes only add
// time, so the minimum of interleaved repetitions is the steadier estimate of a frame's own cost.
double minimum(const std::vector<double>& v) { return v.empty() ? 0.0 : *std::min_element(v.begin(), v.end()); }

void register_all(const std::vector<std::string>& scenes, const std::vector<std::pair<int, int>>& sizes) {
  const char* mesh_dir = std::getenv("PARASHADE_MESH_DIR");
  const bool have_meshes = mesh_dir && *mesh_dir;
  for (const auto& [w, h] : sizes) {
    const std::string size = std::to_string(w) + "x" + std::to_string(h);
    for (const std::string& scene : scenes) {
      if (bench::needs_mesh_dir(scene) && !have_meshes) {
        std::fprintf(stderr, "bench_llvmpipe: PARASHADE_MESH_DIR is not set: %s skipped\n", scene.c_str());
        continue;
      }
      for (Method method : {Method::gouraud, Method::phong}) {
        const std::string name = "llvmpipe/" + scene + "/" + size + "/" + method_name(method);
        benchmark::RegisterBenchmark(name.c_str(), [=](benchmark::State& st) {
          llvmpipe_frame(st, name, scene, w, h, method);
        })->UseManualTime()->Unit(benchmark::kMillisecond)->ComputeStatistics("min", minimum);
      }
      for (Method method : {Method::flat, Method::gouraud, Method::phong}) {
        RenderOptions o;
        o.method = method;
        const std::string name = "parashade/" + scene + "/" + size + "/" + method_name(method);
        benchmark::RegisterBenchmark(name.c_str(), [=](benchmark::State& st) { parashade_frame(st, name, scene, w, h, o); })
            ->UseManualTime()
            ->Unit(benchmark::kMillisecond)
            ->ComputeStatistics("min", minimum);
      }
    }
    // The modeled shading units on the teapot (methods x units x arithmetic).
    const std::pair<const char*, const char*> unit_cases[] = {
        {"classic", "fixed:12.12"}, {"interleave:4", "fixed:12.12"}, {"segment:64", "fixed:12.12"}, {"classic", "float"}};
    for (const auto& [unit, arith] : unit_cases) {
      RenderOptions o;
      o.method = Method::gouraud;
      o.units = parse_units(unit);
      o.arith = parse_arith(arith);
      const std::string name = "parashade/teapot/" + size + "/gouraud:" + unit + ":" + arith;
      benchmark::RegisterBenchmark(name.c_str(),
                                   [=](benchmark::State& st) { parashade_frame(st, name, "teapot", w, h, o); })
          ->UseManualTime()
          ->Unit(benchmark::kMillisecond)
          ->ComputeStatistics("min", minimum);
    }
    benchmark::RegisterBenchmark(("phong_plane_fill_limit/" + size).c_str(),
                                 [=](benchmark::State& st) { phong_fill_limit(st, w, h); })
        ->UseManualTime()
        ->Unit(benchmark::kMillisecond)
        ->ComputeStatistics("min", minimum);
    for (const bool plane : {false, true})
      benchmark::RegisterBenchmark(((plane ? "plane_fill_limit/" : "fill_limit/") + size).c_str(),
                                   [=](benchmark::State& st) { run_fill_limit(st, bench_device(), w, h, plane); })
          ->UseManualTime()
          ->Unit(benchmark::kMillisecond)
          ->ComputeStatistics("min", minimum);
  }
}

}  // namespace
}  // namespace parashade

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  parashade::add_schema_context();
  std::vector<std::string> scenes = {"sphere_8k", "sphere_131k", "sphere_2m", "teapot",
                                     "robot",     "bunny",       "fandisk",   "fullscreen_quad"};
  std::vector<std::pair<int, int>> sizes = {{1920, 1080}};
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a.rfind("--scenes=", 0) == 0) {
      scenes = parashade::comma_list(a.substr(9));
    } else if (a.rfind("--sizes=", 0) == 0) {
      sizes.clear();
      for (const std::string& s : parashade::comma_list(a.substr(8))) {
        int w = 0, h = 0;
        char x = 0, extra = 0;
        if (std::sscanf(s.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || x != 'x' || w < 1 || h < 1 ||
            w > parashade::kMaxResolution || h > parashade::kMaxResolution) {
          std::fprintf(stderr, "bench_llvmpipe: bad size '%s' (WIDTHxHEIGHT, at most %d)\n", s.c_str(),
                       parashade::kMaxResolution);
          return 2;
        }
        sizes.emplace_back(w, h);
      }
    } else if (a.rfind("--images=", 0) == 0) {
      parashade::g_image_dir = a.substr(9);
      std::filesystem::create_directories(parashade::g_image_dir);
    } else if (a == "--no-error") {
      parashade::g_errors = false;
    } else {
      std::fprintf(stderr, "bench_llvmpipe: unknown argument '%s'\n", a.c_str());
      return 2;
    }
  }
  try {
    const parashade::DeviceInfo& d = parashade::bench_device().info();
    // Mesa reads LP_NUM_THREADS when the driver loads: set it before the first EGL call.
    setenv("LP_NUM_THREADS", std::to_string(d.compute_units).c_str(), 0);
    const parashade::peer::PeerInfo& gl = parashade::llvmpipe().info();
    benchmark::AddCustomContext("device", d.name);
    benchmark::AddCustomContext("platform", d.platform);
    benchmark::AddCustomContext("driver", d.driver);
    benchmark::AddCustomContext("compute_units", std::to_string(d.compute_units));
    benchmark::AddCustomContext("gl_renderer", gl.renderer);
    benchmark::AddCustomContext("gl_version", gl.version);
    benchmark::AddCustomContext("lp_num_threads", std::getenv("LP_NUM_THREADS"));
    std::fprintf(stderr, "bench_llvmpipe: GL_RENDERER %s, GL_VERSION %s, LP_NUM_THREADS %s; OpenCL %s, %d compute units\n",
                 gl.renderer.c_str(), gl.version.c_str(), std::getenv("LP_NUM_THREADS"), d.name.c_str(),
                 d.compute_units);
    if (gl.renderer.find("llvmpipe") == std::string::npos) {
      std::fprintf(stderr, "bench_llvmpipe: the GL renderer is not llvmpipe; set GALLIUM_DRIVER=llvmpipe\n");
      return 4;
    }
    parashade::register_all(scenes, sizes);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_llvmpipe: %s\n", e.what());
    return 4;
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
