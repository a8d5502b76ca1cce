// tune --objective pareto's front without a device (host/cli/tune_pareto.cpp), on made-up points whose
// front is worked out by hand below.
#include <vector>

#include <gtest/gtest.h>

#include "../../host/cli/tune_pareto.hpp"

namespace parashade::cli {
namespace {

TEST(TunePareto, KeepsThePointsNoOtherBeatsOnBothTimeAndError) {
  const std::vector<SpeedError> points = {
      {2.0, 0.9},    // 0: the most exact: on the front
      {1.0, 100.0},  // 1: the fastest: on the front
      {1.5, 38.0},   // 2: between them: on the front
      {3.0, 0.9},    // 3: as exact as 0 and slower: off
      {1.2, 120.0},  // 4: slower and worse than 1: off
      {1.5, 40.0},   // 5: as fast as 2 and worse: off
      {2.5, 0.5},    // 6: slower than 0 but more exact: on the front
  };
  EXPECT_EQ(pareto_front(points), (std::vector<std::size_t>{1, 2, 0, 6}));
}

TEST(TunePareto, OfIdenticalPointsTheFirstAloneAndNoneOfNothing) {
  EXPECT_EQ(pareto_front({{1.0, 2.0}, {1.0, 2.0}}), (std::vector<std::size_t>{0}));
  EXPECT_EQ(pareto_front({{4.0, 1.0}}), (std::vector<std::size_t>{0}));
  EXPECT_TRUE(pareto_front({}).empty());
}

}  // namespace
}  // namespace parashade::cli
