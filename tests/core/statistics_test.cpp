// statistics.hpp's median and quantile on small hand-made samples (the benchmarks' summaries).
#include <gtest/gtest.h>

#include "parashade/statistics.hpp"

namespace parashade {
namespace {

TEST(Statistics, MedianOfOddAndEvenCounts) {
  EXPECT_EQ(median({}), 0.0);
  EXPECT_EQ(median({3.0}), 3.0);
  EXPECT_EQ(median({5.0, 1.0, 3.0}), 3.0);
  EXPECT_EQ(median({4.0, 1.0, 3.0, 2.0}), 2.5);
}

TEST(Statistics, QuantileIsTheNearestRank) {
  const std::vector<double> v = {10, 1, 9, 2, 8, 3, 7, 4, 6, 5};  // 1..10
  EXPECT_EQ(quantile({}, 0.5), 0.0);
  EXPECT_EQ(quantile(v, 0.0), 1.0);
  EXPECT_EQ(quantile(v, 0.1), 1.0);
  EXPECT_EQ(quantile(v, 0.11), 2.0);
  EXPECT_EQ(quantile(v, 0.5), 5.0);
  EXPECT_EQ(quantile(v, 0.9), 9.0);
  EXPECT_EQ(quantile(v, 0.91), 10.0);
  EXPECT_EQ(quantile(v, 1.0), 10.0);
  EXPECT_EQ(quantile(v, 7.0), 10.0);   // clamped
  EXPECT_EQ(quantile(v, -1.0), 1.0);
}

}  // namespace
}  // namespace parashade
