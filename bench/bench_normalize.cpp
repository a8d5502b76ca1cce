// Per-pixel cost of the normalization methods in scalar float C++ (the host library,
// host/phong/normalization.cpp) on spans of 16 and 256 pixels, end normals 0.3 rad apart (Google Benchmark).
// [Dembitsky 2025, software/hardware rendering] ch. 2 claims per-pixel speed-ups over the exact per-pixel normalization (2-2.4x, 3.6x, 1.7x) for
// software; compare items_per_second of one run (docs/phong-methods.md). mid/*: the span's middle normal
// alone ([Dembitsky 2025, software/hardware rendering] ch. 2: h(r) by a quadratic, "mid normal 2.5x faster"), exact normalize(Na + Nb) against
// (Na + Nb) * h(Na.Nb) with the minimax quadratic h, over 256 normal pairs.
#include <cmath>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "parashade/normalization.hpp"
#include "benchmark_schema.hpp"

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

void mid_normal_benchmark(benchmark::State& state, bool approximate) {
  std::vector<glm::vec3> a(256), b(256), mid(256);
  for (int i = 0; i < 256; ++i) {  // end normals 0..~1.3 rad apart (r = Na.Nb in [0.27, 1], h's range)
    a[i] = glm::normalize(glm::vec3(0.2f, 0.1f, 1.0f));
    b[i] = glm::normalize(glm::vec3(0.2f + 0.015f * i, 0.1f - 0.004f * i, 1.0f));
  }
  const std::vector<double>& c = mid_polys()[0].coeffs;  // quadratic_fit: c0 + c1 r + c2 r^2
  const float c0 = float(c[0]), c1 = float(c[1]), c2 = float(c[2]);
  for (auto _ : state) {
    for (int i = 0; i < 256; ++i) {
      const glm::vec3 s = a[i] + b[i];
      if (approximate) {
        const float r = glm::dot(a[i], b[i]);
        mid[i] = s * (c0 + r * (c1 + r * c2));
      } else {
        mid[i] = s / std::sqrt(glm::dot(s, s));
      }
    }
    benchmark::DoNotOptimize(mid.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * 256);
}

void register_all() {
  benchmark::RegisterBenchmark("mid/exact", [](benchmark::State& st) { mid_normal_benchmark(st, false); });
  benchmark::RegisterBenchmark("mid/quadratic-fit", [](benchmark::State& st) { mid_normal_benchmark(st, true); });
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
  parashade::add_schema_context();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
