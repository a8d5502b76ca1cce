#pragma once
// tune's search strategies over the valid points of the space (tune_space.hpp), device-free so that a
// test can drive them with a made-up cost (docs/tuning.md):
//   brute  - every point: the default first, then the points without a plan, then the planned ones
//            (the slower kind, docs/planner.md), each group in an order shuffled by the seed, so that a
//            budget samples the space evenly and a resumed run continues the same sequence;
//   random - every point in an order shuffled by the seed (sampling without replacement);
//   anneal - Kernel Tuner's simulated annealing (its strategy "simulated_annealing"): a random start,
//            a random neighbour differing in one parameter, accepted when cheaper or with probability
//            exp(((old - new) / old) / T); T falls from 1 to 0.001 by 0.995 per step, the schedule
//            scaled to the evaluation budget; a walk that finds nothing new for 100 steps restarts.
// The same seed visits the same points in the same order (given the same costs).
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "tune_space.hpp"

namespace parashade::cli {

enum class TuneStrategy { brute, random, anneal };
TuneStrategy parse_tune_strategy(const std::string& name);  // UsageError listing the strategies
const char* tune_strategy_name(TuneStrategy s);

// splitmix64: the same numbers for a seed on every platform and standard library.
class TuneRandom {
 public:
  explicit TuneRandom(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next();
  std::size_t below(std::size_t n);  // uniform in [0, n), n > 0
  double unit();                     // uniform in [0, 1)
  template <typename T>
  void shuffle(std::vector<T>& v) {  // Fisher-Yates
    for (std::size_t i = v.size(); i > 1; --i) std::swap(v[i - 1], v[below(i)]);
  }

 private:
  std::uint64_t state_;
};

// brute and random: the order in which to visit `points` (indices). `first`: the default point's
// index (brute puts it first), or -1; `planned[i]`: point i has a plan.
std::vector<std::size_t> visit_order(TuneStrategy s, std::size_t points, long first, const std::vector<bool>& planned,
                                     std::uint64_t seed);

// anneal: over `points` of a space with dims[d] values of parameter d, evaluates points through `cost` (each point at most once: +infinity for a point that is not
// eligible, e.g. over the error budget) until `max_evaluations` distinct points, every point, or `stop()`;
// returns the points evaluated, in order.
std::vector<std::size_t> anneal(const std::vector<TunePoint>& points, const std::vector<int>& dims,
                                const std::function<double(std::size_t)>& cost, std::size_t max_evaluations, std::uint64_t seed, const std::function<bool()>& stop);

}  // namespace parashade::cli
