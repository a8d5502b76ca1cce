// The host stages of a frame alone (Google Benchmark): FramePipeline::prepare_frame into the pipeline's
// own host arrays (no OpenCL device), so they can be timed, and counted under callgrind, without the
// kernel. Manual time = geometry + setup + binning; the three are counters (ms per frame). Scenes as
// bench_llvmpipe's (peer/bench_scenes.hpp) at 1920x1080: the sphere at three tessellations, the teapot
// and, with PARASHADE_MESH_DIR, the bunny; Gouraud and exact Phong. bench/README.md, "Run G", has the
// callgrind command (instructions of one prepared frame).
#include <cstdlib>
#include <string>

#include <benchmark/benchmark.h>

#include "parashade/frame_pipeline.hpp"
#include "peer/bench_scenes.hpp"

namespace parashade {
namespace {

void host_stages(benchmark::State& state, const std::string& scene_name, Method method) {
  const Scene* scene = nullptr;
  try {
    scene = &bench::scene_named(scene_name, 1920, 1080);
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
