// tune's strategies without a device (host/cli/tune_strategy.cpp): each is a fixed sequence for a seed,
// keeps to its budget, and annealing walks by changing one parameter at a time. The costs here are made
// up, so the expected behaviour does not depend on any timing.
#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <vector>

#include <gtest/gtest.h>

#include "../../host/cli/tune_strategy.hpp"

namespace parashade::cli {
namespace {

// A 4 x 5 x 3 grid, every point valid.
std::vector<TunePoint> grid(std::vector<int> dims) {
  std::vector<TunePoint> out;
  for (int a = 0; a < dims[0]; ++a)
    for (int b = 0; b < dims[1]; ++b)
      for (int c = 0; c < dims[2]; ++c) out.push_back({a, b, c});
  return out;
}
const std::vector<int> kDims = {4, 5, 3};

// A bowl with its minimum at (3, 1, 2); costs > 0 as frame times are.
double bowl(const TunePoint& p) { return 1.0 + std::pow(p[0] - 3, 2) + std::pow(p[1] - 1, 2) + std::pow(p[2] - 2, 2); }

std::vector<std::size_t> run_anneal(std::uint64_t seed, std::size_t budget, const std::vector<TunePoint>& points,
                                    std::vector<std::size_t>* evaluated = nullptr) {
  std::vector<std::size_t> calls;
  const auto order = anneal(
      points, kDims, [&](std::size_t i) { calls.push_back(i); return bowl(points[i]); }, budget, seed,
      [] { return false; });
  if (evaluated) *evaluated = calls;
  return order;
}

TEST(TuneStrategy, AnnealIsTheSameSequenceForTheSameSeed) {
  const auto points = grid(kDims);
  const auto a = run_anneal(11, 25, points), b = run_anneal(11, 25, points), c = run_anneal(12, 25, points);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c) << "another seed walks the same way";
}

TEST(TuneStrategy, AnnealKeepsToItsBudgetAndEvaluatesEachPointOnce) {
  const auto points = grid(kDims);
  std::vector<std::size_t> calls;
  const auto order = run_anneal(5, 17, points, &calls);
  EXPECT_EQ(order.size(), 17u);
  EXPECT_EQ(calls, order) << "a point was measured twice, or the order is not what was measured";
  EXPECT_EQ(std::set<std::size_t>(order.begin(), order.end()).size(), order.size());
  // A budget above the space's size stops at the space.
  EXPECT_EQ(run_anneal(5, 1000, points).size(), points.size());
}

TEST(TuneStrategy, AnnealStopsWhenToldTo) {
  const auto points = grid(kDims);
  int evaluations = 0;
  const auto order = anneal(
      points, kDims, [&](std::size_t i) { ++evaluations; return bowl(points[i]); }, 50, 3,
      [&] { return evaluations >= 4; });
  EXPECT_EQ(order.size(), 4u);
}

TEST(TuneStrategy, AnnealMovesOneParameterAtATime) {
  // Every point is infeasible but the start: a walk accepts no move (new infeasible, old feasible), so
  // every evaluated point after the start is a neighbour of the start (one parameter changed), until the
  // walk is stuck for 100 steps and restarts.
  const auto points = grid(kDims);
  std::size_t start = points.size();
  const auto order = anneal(
      points, kDims,
      [&](std::size_t i) {
        if (start == points.size()) start = i;
        return i == start ? 1.0 : std::numeric_limits<double>::infinity();
      },
      6, 9, [] { return false; });
  ASSERT_EQ(order.size(), 6u);
  for (std::size_t k = 1; k < order.size(); ++k) {
    int changed = 0;
    for (std::size_t d = 0; d < kDims.size(); ++d) changed += points[order[k]][d] != points[start][d];
    EXPECT_EQ(changed, 1) << "evaluation " << k;
  }
}

TEST(TuneStrategy, AnnealFindsTheBowlsMinimumWithinHalfTheSpace) {
  const auto points = grid(kDims);
  for (std::uint64_t seed : {1, 2, 3}) {
    const auto order = run_anneal(seed, points.size() / 2, points);
    double best = 1e9;
    for (std::size_t i : order) best = std::min(best, bowl(points[i]));
    EXPECT_LE(best, 2.0) << "seed " << seed;  // the minimum (1) or a neighbour of it
  }
}

TEST(TuneStrategy, RandomIsAPermutationFixedBySeed) {
  const std::vector<bool> planned(60, false);
  const auto a = visit_order(TuneStrategy::random, 60, -1, planned, 7);
  EXPECT_EQ(a, visit_order(TuneStrategy::random, 60, -1, planned, 7));
  EXPECT_NE(a, visit_order(TuneStrategy::random, 60, -1, planned, 8));
  std::vector<std::size_t> sorted = a;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t i = 0; i < sorted.size(); ++i) EXPECT_EQ(sorted[i], i);
}

TEST(TuneStrategy, BruteVisitsTheDefaultFirstThenPlainThenPlanned) {
  std::vector<bool> planned(20, false);
  for (std::size_t i = 0; i < 20; i += 3) planned[i] = true;
  const auto order = visit_order(TuneStrategy::brute, 20, 4, planned, 2026);
  ASSERT_EQ(order.size(), 20u);
  EXPECT_EQ(order.front(), 4u);
  const auto first_planned = std::find_if(order.begin() + 1, order.end(), [&](std::size_t i) { return planned[i]; });
  EXPECT_TRUE(std::all_of(first_planned, order.end(), [&](std::size_t i) { return planned[i]; }));
  EXPECT_EQ(std::set<std::size_t>(order.begin(), order.end()).size(), 20u);
}

TEST(TuneStrategy, NamesRoundTripAndUnknownOnesAreRefused) {
  for (const char* n : {"brute", "random", "anneal"}) EXPECT_STREQ(tune_strategy_name(parse_tune_strategy(n)), n);
  try {
    parse_tune_strategy("genetic");
    FAIL() << "no error";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("brute, random, anneal"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace parashade::cli
