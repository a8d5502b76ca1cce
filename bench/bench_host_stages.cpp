// The host stages of a frame alone (Google Benchmark): FramePipeline::prepare_frame into the pipeline's
// own host arrays (no OpenCL device), so they can be timed, and counted under callgrind, without the
// kernel. Manual time = geometry + setup + binning; the three are counters (ms per frame). Scenes as
// bench_llvmpipe's (peer/bench_scenes.hpp) at 1920x1080: the sphere at three tessellations, the teapot
// and, with PARASHADE_MESH_DIR, the bunny; Gouraud and exact Phong. bench/README.md, "Run G", has the
// callgrind command (instructions of one prepared frame).
// floor/SCENE: the least host work any frame of the scene needs, on the same threads: each vertex
// transformed and projected to an integer screen position, each triangle's facing from the signed
// area of its three positions (counted, nothing set up or binned). What a frame's host stages cannot
// go below while the host transforms and culls (bench/README.md, "The host share on sphere_2m").
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "parashade/frame_pipeline.hpp"
#include "parashade/geometry_stage.hpp"
#include "parashade/parallel.hpp"
#include "peer/bench_scenes.hpp"
#include "benchmark_schema.hpp"

namespace parashade {
namespace {

// The scene at 1920x1080, or nullptr with the benchmark skipped (a mesh that cannot be read).
const Scene* scene_or_skip(benchmark::State& state, const std::string& scene_name) {
  try {
    return &bench::scene_named(scene_name, 1920, 1080);
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return nullptr;
  }
}

void host_stages(benchmark::State& state, const std::string& scene_name, Method method) {
  const Scene* scene = scene_or_skip(state, scene_name);
  if (!scene) return;
  FrameConfig config;
  config.method = method;
  FramePipeline pipeline(config);
  for (int i = 0; i < 2; ++i) pipeline.prepare_frame(*scene);  // allocations
  double geometry = 0, setup = 0, binning = 0;
  for (auto _ : state) {
    const FrameTimings& t = pipeline.prepare_frame(*scene).timings;
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

void host_floor(benchmark::State& state, const std::string& scene_name) {
  const Scene* scene = scene_or_skip(state, scene_name);
  if (!scene) return;
  const glm::mat4 vp = view_projection(*scene);
  std::size_t vertices = 0;
  for (const Object& o : scene->objects) vertices += o.mesh->positions.size();
  std::vector<glm::ivec2> xy(vertices);
  const float sx = 0.5f * float(scene->width) * kSubpixel, sy = 0.5f * float(scene->height) * kSubpixel;
  double vertex_ms = 0, cull_ms = 0;
  std::uint64_t front = 0;
  using Clock = std::chrono::steady_clock;
  for (auto _ : state) {
    const auto t0 = Clock::now();
    std::size_t base = 0;
    for (const Object& o : scene->objects) {
      const glm::mat4 m = vp * o.model;
      const glm::vec3* p = o.mesh->positions.data();
      glm::ivec2* out = xy.data() + base;
      const std::size_t n = o.mesh->positions.size();
      parallel_for_ranges(n, balanced_chunk(n, 4096, 65536), [&](std::size_t first, std::size_t last) {
        for (std::size_t i = first; i < last; ++i) {
          const glm::vec4 c = m * glm::vec4(p[i], 1.0f);
          const float inv_w = 1.0f / c.w;
          out[i] = {int(std::lrint((c.x * inv_w + 1.0f) * sx)), int(std::lrint((1.0f - c.y * inv_w) * sy))};
        }
      });
      base += n;
    }
    const auto t1 = Clock::now();
    std::atomic<std::uint64_t> facing{0};
    base = 0;
    for (const Object& o : scene->objects) {
      const glm::uvec3* tri = o.mesh->triangles.data();
      const glm::ivec2* v = xy.data() + base;
      const std::size_t n = o.mesh->triangles.size();
      parallel_for_ranges(n, balanced_chunk(n, 4096, 65536), [&](std::size_t first, std::size_t last) {
        std::uint64_t count = 0;
        for (std::size_t t = first; t < last; ++t) {
          const glm::i64vec2 a(v[tri[t].x]), b(v[tri[t].y]), c(v[tri[t].z]);
          count += (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x) < 0;
        }
        facing += count;
      });
      base += o.mesh->positions.size();
    }
    const auto t2 = Clock::now();
    const double v_ms = std::chrono::duration<double, std::milli>(t1 - t0).count();
    const double c_ms = std::chrono::duration<double, std::milli>(t2 - t1).count();
    state.SetIterationTime((v_ms + c_ms) * 1e-3);
    vertex_ms += v_ms;
    cull_ms += c_ms;
    front = facing.load();
  }
  const double n = double(state.iterations());
  state.counters["vertex_ms"] = vertex_ms / n;
  state.counters["cull_ms"] = cull_ms / n;
  state.counters["front_facing"] = double(front);  // keeps the count live, and says what was counted
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
    benchmark::RegisterBenchmark(("floor/" + std::string(scene)).c_str(), host_floor, std::string(scene))
        ->UseManualTime()
        ->Unit(benchmark::kMillisecond);
  }
}

}  // namespace
}  // namespace parashade

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  parashade::add_schema_context();
  parashade::register_all();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
