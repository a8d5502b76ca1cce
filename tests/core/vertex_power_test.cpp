// vertex_lanes::power (the vertex stage's x^n, vertex_power.hpp) against std::pow in double precision:
// its relative error before the rounding to float, the floats it returns, exact cases, and its lanes
// against one value at a time, bit for bit.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "parashade/vertex_power.hpp"

namespace parashade {
namespace {

using namespace vertex_lanes;

std::int64_t ulps_apart(float a, float b) {  // for finite floats of one sign
  std::int32_t ia, ib;
  std::memcpy(&ia, &a, sizeof ia);
  std::memcpy(&ib, &b, sizeof ib);
  return std::llabs(std::int64_t(ia) - std::int64_t(ib));
}

// The exponents the scenes use and the edges: 0, fractions, 1, large.
const float kExponents[] = {0.0f, 0.25f, 0.5f, 1.0f, 2.0f, 7.3f, 32.0f, 40.0f, 128.0f, 1000.0f, 20000.0f};

// N.H near 1 matters most (the highlight); the sweep covers (0, 1.0002] and a dense run just below 1.
std::vector<float> sweep() {
  std::vector<float> x;
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0002f);
  for (int i = 0; i < 200000; ++i) x.push_back(uniform(rng));
  float v = 1.0002f;
  for (int i = 0; i < 20000; ++i) x.push_back(v = std::nextafter(v, 0.0f));
  for (float e = 1e-38f; e < 1.0f; e *= 3.7f) x.push_back(e);
  x.erase(std::remove_if(x.begin(), x.end(), [](float f) { return !(f > 0.0f); }), x.end());
  return x;
}

TEST(VertexPower, RelativeErrorBeforeRoundingBelow1e10) {
  double worst = 0.0;
  for (float n : kExponents)
    for (float x : sweep()) {
      const double want = std::pow(double(x), double(n));
      if (!(want > 0x1p-150) || !(want < 0x1p127)) continue;  // zero or infinite as a float either way
      const double got = power_detail::power<double>(double(x), double(n));
      worst = std::max(worst, std::abs(got - want) / want);
    }
  EXPECT_LT(worst, 1e-10);
  EXPECT_GT(worst, 0.0);  // the sweep reached the polynomials' error
}

TEST(VertexPower, FloatsWithinOneUlpOfTheRoundedPower) {
  std::size_t compared = 0, differ = 0;
  for (float n : kExponents)
    for (float x : sweep()) {
      const float want = float(std::pow(double(x), double(n))), got = power(x, n);
      ++compared;
      if (got == want) continue;
      ++differ;
      ASSERT_LE(ulps_apart(got, want), 1) << "x " << x << " n " << n;
    }
  // Off only within 1e-10 of a rounding boundary: a few per million.
  EXPECT_LT(double(differ), 1e-4 * double(compared)) << differ << " of " << compared;
}

TEST(VertexPower, ExactCasesAndUnderflow) {
  for (float x : {1e-30f, 0.3f, 0.999f, 1.0f, 1.0001f, 7.5f}) {
    EXPECT_EQ(power(x, 0.0f), 1.0f) << x;
    EXPECT_EQ(power(x, 1.0f), x) << x;
  }
  EXPECT_EQ(power(1.0f, 40.0f), 1.0f);
  EXPECT_EQ(power(0.5f, 3.0f), 0.125f);
  EXPECT_EQ(power(0.01f, 40.0f), 0.0f);   // 1e-80: below float's least subnormal
  EXPECT_EQ(power(1e-30f, 20000.0f), 0.0f);
  EXPECT_EQ(power(0.5f, 140.0f), float(std::pow(0.5, 140.0)));  // a subnormal float, rounded as std::pow's
  EXPECT_TRUE(std::isinf(power(1e30f, 40.0f)));
}

TEST(VertexPower, LanesEqualOneAtATimeBitForBit) {
  const std::vector<float> x = sweep();
  for (float n : kExponents)
    for (std::size_t i = 0; i + kLanes <= x.size(); i += kLanes) {
      Floats v;
      for (int k = 0; k < kLanes; ++k) v[k] = x[i + std::size_t(k)];
      const Floats got = power(v, n);
      for (int k = 0; k < kLanes; ++k) {
        const float one = power(v[k], n);
        ASSERT_EQ(std::memcmp(&got[k], &one, sizeof one), 0) << "x " << v[k] << " n " << n;
      }
    }
}

}  // namespace
}  // namespace parashade
