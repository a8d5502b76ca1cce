// Lower-degree specular models ([Dembitsky 2025, software/hardware rendering] ch. 3): values worked out by hand, the lobe rule checked against the
// closed-form lobe integral of cos^2, zero thresholds, N.H <= 0, and n = 1 and n = 1000+.
#include "parashade/specular_models.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "parashade/errors.hpp"

namespace parashade {
namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(SpecularModels, Parse) {
  EXPECT_EQ(parse_specular("cosk:lobe:4").k, 4);
  EXPECT_EQ(parse_specular("cosk:taylor:2").kind, SpecularKind::cosk_taylor);
  EXPECT_EQ(parse_specular("7n16:1.78").p, 1.78);
  EXPECT_EQ(specular_name(parse_specular("7n16")), "7n16:2");
  for (const char* s : {"", "cosk", "cosk:taylor:3", "7n16:0.5", "7n16:9", "phong"})
    EXPECT_THROW(parse_specular(s), UsageError) << s;
}

TEST(SpecularModels, TaylorScaleAndZeroBeyondQuarterPeriod) {
  EXPECT_DOUBLE_EQ(taylor_scale(50, 2), 5.0);
  const SpecularModel m = parse_specular("cosk:taylor:2");
  // n = 50, a = 5: at alpha = 0.1, cos^2(0.5); zero past alpha = pi/10.
  EXPECT_NEAR(specular_value(m, 50, std::cos(0.1)), std::pow(std::cos(0.5), 2), 1e-12);
  EXPECT_EQ(specular_value(m, 50, std::cos(kPi / 10 + 1e-6)), 0.0);
}

// int_0^{pi/(2a)} cos^2(a x) sin x dx in closed form (a > 1/2): 1/2 (1 - cos X) + 1/4 [(1 - cos((1+2a)X))/(1+2a)
// + (1 - cos((1-2a)X))/(1-2a)], X = pi/(2a).
double cos2_lobe(double a) {
  const double x = kPi / (2 * a);
  return 0.5 * (1 - std::cos(x)) + 0.25 * ((1 - std::cos((1 + 2 * a) * x)) / (1 + 2 * a) +
                                           (1 - std::cos((1 - 2 * a) * x)) / (1 - 2 * a));
}

TEST(SpecularModels, LobeScaleEqualsTheLobeIntegrals) {
  for (double n : {5.0, 10.0, 100.0, 1000.0}) {
    const double a = lobe_scale(n, 2);
    EXPECT_NEAR(cos2_lobe(a), 1.0 / (n + 1), 1e-6 / (n + 1)) << n;
    EXPECT_LT(a, taylor_scale(n, 2)) << n;  // equal lobes need a wider lobe than the Taylor match
  }
  EXPECT_NEAR(lobe_scale(2, 2), 1.0, 1e-6);  // cos^2 is its own model
}

TEST(SpecularModels, QuadraticModelAndItsThreshold) {
  const SpecularModel q = parse_specular("quadratic");
  EXPECT_DOUBLE_EQ(specular_value(q, 100, 1.0), 1.0);
  EXPECT_NEAR(specular_value(q, 100, 0.99), std::pow(1 + 50 * (0.99 - 1), 2), 1e-12);  // 0.25
  EXPECT_EQ(specular_value(q, 100, 0.98 - 1e-9), 0.0);                                  // threshold 1 - 2/n
  EXPECT_GT(specular_value(q, 100, 0.98 + 1e-6), 0.0);
  const SpecularModel s = parse_specular("7n16");
  EXPECT_NEAR(specular_value(s, 16, 0.95), std::pow(1 + 7 * (0.95 - 1), 2), 1e-12);
  EXPECT_EQ(specular_value(s, 16, 1 - 16.0 / (7 * 16) - 1e-9), 0.0);
}

TEST(SpecularModels, HardCasesNeverNanAndZeroBelowTheHorizon) {
  for (const char* name : {"exact", "cosk:taylor:2", "cosk:taylor:4", "cosk:lobe:2", "cosk:lobe:4", "quadratic", "7n16"}) {
    const SpecularModel m = parse_specular(name);
    for (double n : {1.0, 2.0, 1000.0, 5000.0}) {
      for (double c : {-1.0, -1e-9, 0.0, 1e-9, 0.5, 0.999999, 1.0, 1.0 + 1e-7}) {
        const double v = specular_value(m, n, c);
        ASSERT_TRUE(std::isfinite(v)) << name << " n " << n << " c " << c;
        EXPECT_GE(v, 0.0);
        EXPECT_LE(v, 1.0);
        if (c <= 0) EXPECT_EQ(v, 0.0) << name;
      }
      EXPECT_NEAR(specular_value(m, n, 1.0), 1.0, 1e-12) << name;
    }
  }
}

}  // namespace
}  // namespace parashade
