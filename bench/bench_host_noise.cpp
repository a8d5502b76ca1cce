// How steady the host is right now, before its timings are believed. On every CPU at once (one pinned thread
// each) two fixed probes alternate for a few seconds: an ALU loop (a xorshift chain, no memory) and a memory
// sweep (64 MiB a CPU, past the last-level cache: a load per cache line, a store to every eighth). Each
// probe's spread is its samples' quantiles over its fastest sample.
//
//   bench_host_noise [--seconds 4] [--max-alu-spread 1.10] [--max-memory-spread 2.00] [--require-steady] [--json FILE]
//
// "steady" means every CPU's p90/min is at most the probe's threshold. The thresholds are calibrated on the
// 2-vCPU VMs this project runs on (bench/README.md, "Is the host steady?"): idle, a fresh VM's ALU loop reads
// 1.02-1.03 and its memory sweep 1.35-1.87 (the two CPUs' sweeps share one memory system; one CPU alone reads
// 1.13-1.26); with one other busy process the ALU loop reads 1.8-2.7 and the sweep 3.1-3.3. Exit 0 (with
// --require-steady: 1 when not steady), 2 on a bad command line.
#include <pthread.h>
#include <sched.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "parashade/errors.hpp"
#include "parashade/host_clock.hpp"
#include "parashade/statistics.hpp"
#include "json_output.hpp"
#include "parashade/report_header.hpp"
#include "tool_main.hpp"

namespace parashade {
namespace {

// About 5 ms of dependent integer operations: no memory traffic, no frequency-sensitive vector units.
double alu_probe() {
  const auto t0 = Clock::now();
  std::uint64_t x = 88172645463325252ull;
  for (int i = 0; i < 3000000; ++i) {
    x ^= x << 13;
    x ^= x >> 7;
    x ^= x << 17;
  }
  asm volatile("" : : "r"(x));
  return ms_since(t0);
}

// One pass over `lines` cache lines: a load from each, a store to every eighth (dirty lines to write back).
double memory_probe(std::vector<std::uint64_t>& lines) {
  const auto t0 = Clock::now();
  std::uint64_t sum = 0;
  for (std::size_t k = 0; k < lines.size(); k += 8) sum += lines[k];
  for (std::size_t k = 0; k < lines.size(); k += 64) lines[k] = sum;
  asm volatile("" : : "r"(sum));
  return ms_since(t0);
}

struct Samples {
  std::vector<double> alu, memory;
};

struct Spread {
  double min_ms, median, p90, max;  // the quantiles over the fastest sample
};

Spread spread_of(const std::vector<double>& v) {
  const double fastest = quantile(v, 0.0);
  return {fastest, median(v) / fastest, quantile(v, 0.9) / fastest, quantile(v, 1.0) / fastest};
}

nlohmann::json to_json(const Spread& s, std::size_t n) {
  return {{"samples", n}, {"min_ms", s.min_ms}, {"median_over_min", s.median}, {"p90_over_min", s.p90},
          {"max_over_min", s.max}};
}

int run(int argc, char** argv) {
  CLI::App app{"How steady the host's timings are now: an ALU loop and a memory sweep on every CPU at once"};
  double seconds = 4.0, max_alu_spread = 1.10, max_memory_spread = 2.00;
  bool require_steady = false;
  std::string json_path;
  app.add_option("--seconds", seconds, "How long the probes run (default 4)")->check(CLI::Range(0.1, 600.0));
  app.add_option("--max-alu-spread", max_alu_spread, "Largest p90/min of a steady ALU loop (default 1.10)")
      ->check(CLI::Range(1.0, 100.0));
  app.add_option("--max-memory-spread", max_memory_spread,
                 "Largest p90/min of a steady memory sweep (default 2.00; an idle 2-vCPU VM reads 1.35-1.87)")
      ->check(CLI::Range(1.0, 100.0));
  app.add_flag("--require-steady", require_steady, "Exit with 1 when the host is not steady");
  app.add_option("--json", json_path, "Also write every CPU's spreads to this JSON file");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : int(ExitCode::usage);
  }

  JsonOutput json(json_path);  // a bad path fails now, not after the probes

  const unsigned cpus = std::max(1u, std::thread::hardware_concurrency());
  std::vector<Samples> samples(cpus);
  std::atomic<unsigned> ready{0};
  std::vector<std::thread> threads;
  for (unsigned c = 0; c < cpus; ++c)
    threads.emplace_back([&, c] {
      cpu_set_t set;
      CPU_ZERO(&set);
      CPU_SET(c, &set);
      pthread_setaffinity_np(pthread_self(), sizeof set, &set);  // unpinned where refused: still a probe
      std::vector<std::uint64_t> lines(std::size_t(8) << 20, 1);  // 64 MiB, touched once before timing
      memory_probe(lines);
      ++ready;
      while (ready.load() < cpus) std::this_thread::yield();  // every CPU busy from the first sample on
      const auto t0 = Clock::now();
      while (ms_since(t0) < 1000.0 * seconds) {
        samples[c].alu.push_back(alu_probe());
        samples[c].memory.push_back(memory_probe(lines));
      }
    });
  for (std::thread& t : threads) t.join();

  bool steady = true;
  double worst_alu = 1.0, worst_memory = 1.0;
  nlohmann::json per_cpu = nlohmann::json::array();
  for (unsigned c = 0; c < cpus; ++c) {
    const Spread alu = spread_of(samples[c].alu), memory = spread_of(samples[c].memory);
    worst_alu = std::max(worst_alu, alu.p90);
    worst_memory = std::max(worst_memory, memory.p90);
    steady = steady && alu.p90 <= max_alu_spread && memory.p90 <= max_memory_spread;
    std::printf("cpu %u: ALU loop %.2f ms, median/min %.3f, p90/min %.3f, max/min %.3f | memory sweep %.2f ms, "
                "median/min %.3f, p90/min %.3f, max/min %.3f\n",
                c, alu.min_ms, alu.median, alu.p90, alu.max, memory.min_ms, memory.median, memory.p90, memory.max);
    per_cpu.push_back({{"cpu", c},
                       {"alu", to_json(alu, samples[c].alu.size())},
                       {"memory", to_json(memory, samples[c].memory.size())}});
  }
  std::printf("%s: worst p90/min ALU %.3f, memory %.3f (steady: ALU at most %.2f and memory at most %.2f on every "
              "CPU)\n",
              steady ? "steady" : "NOT steady", worst_alu, worst_memory, max_alu_spread, max_memory_spread);
  if (!json_path.empty()) {
    nlohmann::json j = {{"seconds", seconds},
                        {"max_alu_spread", max_alu_spread},
                        {"max_memory_spread", max_memory_spread},
                        {"cpus", cpus},
                        {"steady", steady},
                        {"worst_alu_p90_over_min", worst_alu},
                        {"worst_memory_p90_over_min", worst_memory},
                        {"per_cpu", per_cpu}};
    json.write(stamp_report(j, "host-noise"));
  }
  return require_steady && !steady ? 1 : 0;
}

}  // namespace
}  // namespace parashade

int main(int argc, char** argv) { return parashade::tool_main("bench_host_noise", parashade::run, argc, argv); }
