// Whole frames on an OpenCL device (Google Benchmark): frame time from the renderer's own clock
// (manual time: vertex stage, setup, binning, kernel, read-back), the stage breakdown, Mpixel/s and
// Mtriangle/s, for the procedural sphere at three tessellations, the teapot, the robot and the Stanford
// bunny (PARASHADE_MESH_DIR) at 1920x1080, each method; Gouraud on the teapot through the modeled shading
// units (units/teapot/UNIT/ARITH, with the modeled clocks); and the device's fill limit as the ceiling.
//   PARASHADE_DEVICE  device index or name substring (default: the default device, device.hpp)
//   PARASHADE_MESH_DIR  the shared meshes; the bunny is skipped (with a message) without it
// Write results with --benchmark_out=FILE --benchmark_out_format=json (PoCL may print to stdout).
#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>
#include <string>
#include <utility>

#include <benchmark/benchmark.h>

#include "bench_device.hpp"

#include "parashade/device.hpp"
#include "parashade/renderer.hpp"
#include "parashade/scene.hpp"
#include "parashade/shapes.hpp"
#include "parashade/units.hpp"
#include "benchmark_schema.hpp"

namespace parashade {
namespace {

std::string source_path(const std::string& relative) { return std::string(PARASHADE_SOURCE_DIR) + "/" + relative; }

// scenes/sphere.json with its sphere re-tessellated: 2 * slices * (stacks - 1) triangles.
Scene sphere_scene(int slices, int stacks) {
  Scene s = load_scene(source_path("scenes/sphere.json"));
  s.objects.at(0).mesh = std::make_shared<Mesh>(make_sphere(slices, stacks));
  s.name = "sphere_" + std::to_string(2 * slices * (stacks - 1));
  return s;
}

const Scene& scene_named(const std::string& name) {
  static std::map<std::string, Scene> cache;
  auto it = cache.find(name);
  if (it != cache.end()) return it->second;
  Scene s;
  if (name == "sphere_8k") s = sphere_scene(64, 65);
  else if (name == "sphere_131k") s = sphere_scene(256, 257);
  else if (name == "sphere_2m") s = sphere_scene(1024, 1025);
  else s = load_scene(source_path("scenes/" + name + ".json"));
  return cache.emplace(name, std::move(s)).first->second;
}

// 8-bit output, the default tiles (TILE_DEFAULT), the device's work-items (device_layout.hpp; the
// defaults), plain method path.
RenderOptions method_options(Method method) {
  RenderOptions o;
  o.method = method;
  return o;
}

void frame_benchmark(benchmark::State& state, const std::string& scene_name, const RenderOptions& options) {
  const Scene* scene = nullptr;
  try {
    scene = &scene_named(scene_name);
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  Renderer renderer(bench_device(), options);
  for (int i = 0; i < 2; ++i) renderer.render(*scene);  // program build, work-group compilation, allocations
  FrameTimings sum;
  std::uint64_t triangles_out = 0;
  ModeledClocks clocks;
  for (auto _ : state) {
    const Frame& f = renderer.render(*scene);
    clocks = f.stats.clocks;  // the same every frame
    state.SetIterationTime(f.timings.total_ms * 1e-3);
    sum.total_ms += f.timings.total_ms;
    sum.geometry_ms += f.timings.geometry_ms;
    sum.setup_ms += f.timings.setup_ms;
    sum.binning_ms += f.timings.binning_ms;
    sum.kernel_ms += f.timings.kernel_ms;
    sum.readback_ms += f.timings.readback_ms;
    triangles_out = f.stats.geometry.triangles_out;
  }
  const double n = double(state.iterations());
  const double frame_ms = sum.total_ms / n;
  // Plain values, not kIsRate: Google Benchmark 1.7 divides rates by CPU time, and this thread mostly
  // waits for the device.
  state.counters["frame_ms"] = frame_ms;
  state.counters["geometry_ms"] = sum.geometry_ms / n;
  state.counters["setup_ms"] = sum.setup_ms / n;
  state.counters["binning_ms"] = sum.binning_ms / n;
  state.counters["kernel_ms"] = sum.kernel_ms / n;
  state.counters["readback_ms"] = sum.readback_ms / n;
  state.counters["mpixel_per_s"] = double(scene->width) * scene->height / (frame_ms * 1e3);
  state.counters["mtriangle_per_s"] = double(scene->triangle_count()) / (frame_ms * 1e3);
  state.counters["triangles_in"] = double(scene->triangle_count());
  state.counters["triangles_after_culling"] = double(triangles_out);
  if (options.unit_path()) {  // the modeled hardware's cost of the same frame
    state.counters["modeled_clocks"] = double(clocks.clocks);
    state.counters["pixels_per_clock"] = clocks.clocks ? double(clocks.pixels) / double(clocks.clocks) : 0.0;
  }
}

// The ceiling: a kernel that only writes every pixel of a 1920x1080 RGBA8 frame.
void fill_limit(benchmark::State& state) { run_fill_limit(state, bench_device(), 1920, 1080); }

void register_all() {
  const char* mesh_dir = std::getenv("PARASHADE_MESH_DIR");
  const bool have_meshes = mesh_dir && *mesh_dir;
  if (!have_meshes) std::fprintf(stderr, "bench_frame: PARASHADE_MESH_DIR is not set: the bunny is skipped\n");
  std::vector<std::string> scenes = {"sphere_8k", "sphere_131k", "sphere_2m", "teapot", "robot"};
  if (have_meshes) scenes.push_back("bunny");
  for (const std::string& scene : scenes)
    for (Method method : {Method::flat, Method::gouraud, Method::phong})
      benchmark::RegisterBenchmark(("frame/" + scene + "/" + method_name(method)).c_str(),
                                   [scene, method](benchmark::State& st) {
                                     frame_benchmark(st, scene, method_options(method));
                                   })
          ->UseManualTime()
          ->Unit(benchmark::kMillisecond);
  // Gouraud through the modeled shading units on the teapot (1920x1080): the same frame, a different unit
  // or span arithmetic; modeled_clocks and pixels_per_clock beside the measured time.
  const std::pair<const char*, const char*> unit_cases[] = {
      {"classic", "fixed:12.12"},      {"counter", "fixed:12.12"},          {"interleave:2", "fixed:12.12"},
      {"interleave:4", "fixed:12.12"}, {"interleave:4:own", "fixed:12.12"}, {"segment:8", "fixed:12.12"},
      {"segment:64", "fixed:12.12"},   {"classic", "float"}};
  for (const auto& [unit, arith] : unit_cases) {
    RenderOptions options = method_options(Method::gouraud);
    options.units = parse_units(unit);
    options.arith = parse_arith(arith);
    benchmark::RegisterBenchmark(("units/teapot/" + std::string(unit) + "/" + arith).c_str(),
                                 [options](benchmark::State& st) { frame_benchmark(st, "teapot", options); })
        ->UseManualTime()
        ->Unit(benchmark::kMillisecond);
  }
  benchmark::RegisterBenchmark("fill_limit/1920x1080", fill_limit)->UseManualTime()->Unit(benchmark::kMillisecond);
}

}  // namespace
}  // namespace parashade

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  parashade::add_schema_context();
  try {
    const parashade::DeviceInfo& d = parashade::bench_device().info();
    benchmark::AddCustomContext("device", d.name);
    benchmark::AddCustomContext("platform", d.platform);
    benchmark::AddCustomContext("driver", d.driver);
    benchmark::AddCustomContext("compute_units", std::to_string(d.compute_units));
    parashade::register_all();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_frame: %s\n", e.what());
    return 4;
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
