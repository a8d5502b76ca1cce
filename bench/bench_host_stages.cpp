// The host stages of a frame alone (Google Benchmark): FramePipeline::prepare_frame into the pipeline's
// own host arrays (no OpenCL device), so they can be timed, and counted under callgrind, without the
// kernel. Manual time = geometry + setup + binning; the three are counters (ms per frame). Scenes as
// bench_frame's: the sphere at three tessellations, the teapot and, with PARASHADE_MESH_DIR, the bunny,
// at 1920x1080; Gouraud and exact Phong. bench/README.md, "Run G", says how it was used.
//   callgrind (one line): valgrind --tool=callgrind --toggle-collect="*FramePipeline::prepare_frame*"
//     build/bench/bench_host_stages --benchmark_filter=host/sphere_2m/gouraud --benchmark_min_time=0.01
#include <cstdlib>
#include <map>
#include <memory>
#include <string>
#include <utility>

#include <benchmark/benchmark.h>

#include "parashade/frame_pipeline.hpp"
#include "parashade/scene.hpp"
#include "parashade/shapes.hpp"

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

void host_stages(benchmark::State& state, const std::string& scene_name, Method method) {
  const Scene* scene = nullptr;
  try {
    scene = &scene_named(scene_name);
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  FramePipeline pipeline;
  FrameConfig config;
  config.method = method;
  for (int i = 0; i < 2; ++i) pipeline.prepare_frame(*scene, config);  // allocations
  double geometry = 0, setup = 0, binning = 0;
  for (auto _ : state) {
    const FrameTimings& t = pipeline.prepare_frame(*scene, config).timings;
    state.SetIterationTime((t.geometry_ms + t.setup_ms + t.binning_ms) * 1e-3);
    geometry += t.geometry_ms;
    setup += t.setup_ms;
    binning += t.binning_ms;
  }
  const double n = double(state.iterations());
  state.counters["geometry_ms"] = geometry / n;
  state.counters["setup_ms"] = setup / n;
  state.counters["binning_ms"] = binning / n;
}

void register_all() {
  const bool meshes = std::getenv("PARASHADE_MESH_DIR") != nullptr;
  for (const char* scene : {"sphere_8k", "sphere_131k", "sphere_2m", "teapot", "bunny"}) {
    if (std::string(scene) == "bunny" && !meshes) continue;
    for (Method method : {Method::gouraud, Method::phong})
      benchmark::RegisterBenchmark(("host/" + std::string(scene) + "/" + method_name(method)).c_str(), host_stages,
                                   std::string(scene), method)
          ->UseManualTime()
          ->Unit(benchmark::kMillisecond);
  }
}

}  // namespace
}  // namespace parashade

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  parashade::register_all();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
