// Host cost of the combined method's per-triangle choice (triangle_choice.hpp): the setup-side work that
// decides Gouraud or segments, the specular mask and the segment limit for every screen triangle, per rule,
// on one host thread (items/s = triangles/s). The kernel's saving must exceed this for the choice to pay.
#include <benchmark/benchmark.h>

#include <cstdlib>

#include "parashade/geometry_stage.hpp"
#include "parashade/parallel.hpp"
#include "parashade/triangle_choice.hpp"
#include "benchmark_schema.hpp"

namespace {

using namespace parashade;

void choose_for(benchmark::State& state, const char* scene_file, TriangleRule rule, ChoiceArithmetic arithmetic,
                const char* method, double budget) {
  set_host_threads(1);
  const Scene scene = load_scene(std::string(PARASHADE_SOURCE_DIR) + "/" + scene_file);
  ScreenGeometry g;
  build_screen_geometry(scene, {Method::combined, false, true}, g);
  CombinedConfig c = parse_combined(method);
  c.rule = rule;
  std::vector<TriangleShading> out;
  for (auto _ : state) {
    const TriangleChoiceStats st = choose_triangle_methods(scene, g, c, budget, out, arithmetic);
    benchmark::DoNotOptimize(st.gouraud);
  }
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(g.triangles.size()));
}

// combined:auto at a budget of 0.5 levels.
void choose(benchmark::State& state, const char* scene_file, TriangleRule rule, ChoiceArithmetic arithmetic) {
  choose_for(state, scene_file, rule, arithmetic, "combined:auto", 0.5);
}

// combined:0 --triangle-choice bound --max-error 4 (the budget less the 8-bit rounding's 0.5): Gouraud or Phong per
// pixel, no segment limits.
void choose_k0(benchmark::State& state, const char* scene_file) {
  choose_for(state, scene_file, TriangleRule::bound, ChoiceArithmetic::float_lanes, "combined:0", 3.5);
}

// The per-frame fixed cost with no triangle, once the tables of the scene's materials are cached (the first
// frame builds them: ~0.2 ms per material).
void choose_nothing(benchmark::State& state) {
  const Scene scene = load_scene(std::string(PARASHADE_SOURCE_DIR) + "/scenes/teapot.json");
  const ScreenGeometry g;
  const CombinedConfig c = parse_combined("combined:auto");
  std::vector<TriangleShading> out;
  for (auto _ : state) benchmark::DoNotOptimize(choose_triangle_methods(scene, g, c, 0.5, out).gouraud);
}
BENCHMARK(choose_nothing)->Unit(benchmark::kMicrosecond);

constexpr auto lanes = ChoiceArithmetic::float_lanes, reference = ChoiceArithmetic::double_reference;
BENCHMARK_CAPTURE(choose, teapot_bound, "scenes/teapot.json", TriangleRule::bound, lanes)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(choose, teapot_bound_reference, "scenes/teapot.json", TriangleRule::bound, reference)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(choose, teapot_sources, "scenes/teapot.json", TriangleRule::sources, lanes)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(choose, sphere_bound, "scenes/sphere.json", TriangleRule::bound, lanes)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(choose_k0, teapot_bound_4, "scenes/teapot.json")->Unit(benchmark::kMillisecond);
// The bunny's scene reads its mesh from PARASHADE_MESH_DIR (registered only when that is set).
const bool bunny = std::getenv("PARASHADE_MESH_DIR") &&
                   benchmark::RegisterBenchmark("choose/bunny_bound", choose, "scenes/bunny.json", TriangleRule::bound, lanes)
                       ->Unit(benchmark::kMillisecond) &&
                   benchmark::RegisterBenchmark("choose/bunny_bound_reference", choose, "scenes/bunny.json",
                                                TriangleRule::bound, reference)
                       ->Unit(benchmark::kMillisecond) &&
                   benchmark::RegisterBenchmark("choose_k0/bunny_bound_4", choose_k0, "scenes/bunny.json")
                       ->Unit(benchmark::kMillisecond);

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  parashade::add_schema_context();
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
