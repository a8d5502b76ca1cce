// Per-pixel cost of the normalization methods in scalar float C++ (the host library, host/core/
// normalization.cpp) on spans of 16 and 256 pixels, end normals 0.3 rad apart (Google Benchmark).
// SEEDS §7 claims per-pixel speed-ups over the exact per-pixel normalization (2-2.4x, 3.6x, 1.7x) for
// software; compare items_per_second of one run (docs/phong-methods.md).
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "parashade/normalization.hpp"

namespace parashade {
namespace {

void span_benchmark(benchmark::State& state, const std::string& method) {
  const NormalizeMethod m = parse_normalize(method);
  const int length = int(state.range(0));
  const glm::vec3 a = glm::normalize(glm::vec3(0.2f, 0.1f, 1.0f)), b = glm::normalize(glm::vec3(0.5f, 0.2f, 0.9f));
  for (auto _ : state) {
    std::vector<glm::vec3> n = span_normals<float>(m, a, b, length);
    benchmark::DoNotOptimize(n.data());
  }
  state.SetItemsProcessed(state.iterations() * length);
}

void register_all() {
  for (const char* m : {"exact", "slerp", "dichotomy:exact", "dichotomy:quadratic-fit", "quadratic:exact",
                        "quadratic:cubic-fit", "recurrence", "recurrence-diff"})
    benchmark::RegisterBenchmark((std::string("normalize/") + m).c_str(),
                                 [m](benchmark::State& st) { span_benchmark(st, m); })
        ->Arg(16)
        ->Arg(256);
}

}  // namespace
}  // namespace parashade

int main(int argc, char** argv) {
  parashade::register_all();
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
