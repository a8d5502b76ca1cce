// Fast unit normals ([Dembitsky 2025, software/hardware rendering] ch. 2): each method against properties worked out independently of the code
// (slerp's equal angles, the exact bisector, the quadratic through the exact mid normal), the hard
// cases of issue 4 (theta -> 0, theta -> pi, a zero interpolated normal, spans of 1, 2, 3 and 4096
// pixels) with no NaN or Inf, and the documented error bounds of every approximation.
#include "parashade/normalization.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "parashade/errors.hpp"

namespace parashade {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Unit end normals at angle theta in a plane tilted against the axes.
std::pair<glm::dvec3, glm::dvec3> ends(double theta) {
  const glm::dvec3 c = glm::normalize(glm::dvec3(0.2, -0.4, 0.9));
  const glm::dvec3 t = glm::normalize(glm::cross(c, glm::dvec3(1, 0, 0)));
  return {std::cos(theta / 2) * c - std::sin(theta / 2) * t, std::cos(theta / 2) * c + std::sin(theta / 2) * t};
}

double angle(glm::dvec3 a, glm::dvec3 b) { return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)); }

const std::vector<std::string> kAll = {"exact", "slerp", "dichotomy:exact", "dichotomy:linear", "dichotomy:quadratic",
                                       "dichotomy:linear-fit", "dichotomy:quadratic-fit:2", "quadratic:exact",
                                       "quadratic:quad", "quadratic:cubic", "quadratic:cubic-fit", "recurrence",
                                       "recurrence:table", "recurrence:table-fixed:64", "recurrence-diff",
                                       "dichotomy:quadratic:3:extrapolate"};

TEST(Normalization, ParsesEveryMethodAndRefusesOthers) {
  for (const std::string& s : kAll) EXPECT_NO_THROW(parse_normalize(s)) << s;
  EXPECT_EQ(normalize_name(parse_normalize("dichotomy:quadratic")), "dichotomy:quadratic:4");
  EXPECT_EQ(parse_normalize("recurrence:table:128").reanchor, 128);
  for (const std::string& s : {"", "Exact", "dichotomy", "dichotomy:cubic", "dichotomy:exact:9", "quadratic:linear",
                               "recurrence:1", "slerp:2", "exact "})
    EXPECT_THROW(parse_normalize(s), UsageError) << "'" << s << "'";
}

template <typename T>
void expect_finite_everywhere() {
  const std::vector<double> thetas = {0.0, 1e-9, 1e-6, 1e-3, 1.0, kPi / 2, 3.0, kPi - 1e-3, kPi - 1e-7, kPi};
  for (const std::string& s : kAll)
    for (double theta : thetas)
      for (int length : {1, 2, 3, 4, 5, 16, 17, 4096}) {
        auto [a, b] = ends(theta);
        if (theta == kPi) b = -a;  // exactly opposite
        NormalizeCounters c;
        const auto out = span_normals<T>(parse_normalize(s), glm::vec<3, T>(a), glm::vec<3, T>(b), length, &c);
        ASSERT_EQ(out.size(), std::size_t(length));
        EXPECT_EQ(c.pixels, std::uint64_t(length));
        for (const auto& v : out)
          ASSERT_TRUE(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z))
              << s << " theta " << theta << " length " << length;
      }
}
TEST(Normalization, NoNanOrInfInDoubleForAnyAngleOrLength) { expect_finite_everywhere<double>(); }
TEST(Normalization, NoNanOrInfInFloatForAnyAngleOrLength) { expect_finite_everywhere<float>(); }

TEST(Normalization, ZeroInterpolatedNormalIsZeroAndCounted) {
  const glm::dvec3 a(0, 0, 1);
  NormalizeCounters c;
  const auto out = span_normals<double>(parse_normalize("exact"), a, -a, 3, &c);
  EXPECT_EQ(out[1], glm::dvec3(0));  // ambient only in the kernel
  EXPECT_EQ(c.fallback_pixels, 1u);
  EXPECT_EQ(out[0], a);
  EXPECT_EQ(out[2], -a);
  // Opposite ends: every angular method falls back to exact and counts the whole span.
  for (const std::string& s : {"slerp", "dichotomy:exact", "quadratic:exact", "recurrence"}) {
    NormalizeCounters k;
    span_normals<double>(parse_normalize(s), a, -a, 5, &k);
    EXPECT_GE(k.fallback_pixels, 1u) << s;
  }
}

TEST(Normalization, SpanOfOnePixelIsTheFirstEndNormal) {
  const auto [a, b] = ends(1.0);
  for (const std::string& s : kAll) {
    const auto out = span_normals<double>(parse_normalize(s), a, b, 1);
    EXPECT_LT(glm::length(out[0] - a), 1e-12) << s;
  }
}

TEST(Normalization, SlerpStepsByEqualAnglesOfUnitVectors) {
  for (double theta : {1e-7, 0.01, 1.0, 3.0}) {
    const auto [a, b] = ends(theta);
    const int m = 33;
    const auto out = span_normals<double>(parse_normalize("slerp"), a, b, m);
    for (int i = 0; i < m; ++i) {
      EXPECT_NEAR(glm::length(out[i]), 1.0, 1e-12);
      if (i) EXPECT_NEAR(angle(out[i - 1], out[i]), theta / (m - 1), 1e-9) << theta;
    }
    EXPECT_LT(glm::length(out[m - 1] - b), 1e-12);
  }
}

// One segment of 2^k pixels spanning the whole span: exact dichotomy is slerp on its dyadic points.
TEST(Normalization, ExactDichotomyIsSlerpOnDyadicPoints) {
  for (double theta : {0.1, 1.0, 2.5}) {
    const auto [a, b] = ends(theta);
    const auto d = span_normals<double>(parse_normalize("dichotomy:exact:4"), a, b, 17);
    const auto s = span_normals<double>(parse_normalize("slerp"), a, b, 17);
    for (int i = 0; i < 17; ++i) EXPECT_LT(glm::length(d[i] - s[i]), 1e-12) << theta << " " << i;
  }
}

// Short spans: the last segment is bisected between its real ends, so every pixel is within half a
// dyadic step of slerp (exact where the span's steps are a power of two). The source's rule (the last
// segment 2^k long with an extrapolated end normal) leaves the span's own end far from N_b.
TEST(Normalization, DichotomyShortSpansAndTheSourcesLastSegmentRule) {
  const auto [a, b] = ends(1.0);
  for (int m : {2, 3, 4, 5, 9, 12, 17}) {  // one segment of 2^4: its ends are the span's
    const auto d = span_normals<double>(parse_normalize("dichotomy:exact:4"), a, b, m);
    const auto s = span_normals<double>(parse_normalize("slerp"), a, b, m);
    EXPECT_LT(glm::length(d[m - 1] - b), 1e-12) << m;
    // Nearest of the dyadic points, three levels finer than the span needs: half a step, theta/(16 (m-1)).
    for (int i = 0; i < m; ++i) EXPECT_LE(angle(d[i], s[i]), 1.0 / (16.0 * (m - 1)) + 1e-12) << m << " " << i;
  }
  const auto x = span_normals<double>(parse_normalize("dichotomy:exact:4:extrapolate"), a, b, 2);
  EXPECT_GT(angle(x[1], b), 0.5);
}

TEST(Normalization, RecurrenceDifferenceFormKeepsFloatPrecision) {
  const auto [a, b] = ends(1.0);
  const auto s = span_normals<double>(parse_normalize("slerp"), a, b, 4096);
  auto worst = [&](const std::string& name) {
    const auto r = span_normals<float>(parse_normalize(name), glm::vec3(a), glm::vec3(b), 4096);
    double w = 0;
    for (int i = 0; i < 4096; ++i) w = std::fmax(w, glm::length(glm::dvec3(r[i]) - s[i]));
    return w;
  };
  EXPECT_GT(worst("recurrence"), 0.1);  // 2 cos(1/4095) rounds in float
  EXPECT_LT(worst("recurrence-diff"), 1e-3);
}

// Each bisection level scales by the polynomial (relative error e on [sqrt2, 2]); four levels and exact
// ends give a length error below about 4e; a mis-scaled point tilts the later bisectors by about
// e sin(phi/2) per level, so the direction stays within 4 e theta of slerp.
TEST(Normalization, DichotomyWithPolynomialsStaysWithinTheirBound) {
  const double e_fit = 4.1e-5, e_src = 2.1e-3;  // max relative errors of quadratic-fit and the printed linear
  for (double theta : {0.05, 0.3, 0.7}) {
    const auto [a, b] = ends(theta);
    const auto s = span_normals<double>(parse_normalize("dichotomy:exact:4"), a, b, 17);
    for (const auto& [name, e] : {std::make_pair(std::string("dichotomy:quadratic-fit:4"), e_fit),
                                  std::make_pair(std::string("dichotomy:linear:4"), e_src)}) {
      const auto d = span_normals<double>(parse_normalize(name), a, b, 17);
      for (int i = 0; i < 17; ++i) {
        EXPECT_LE(std::fabs(glm::length(d[i]) - 1.0), 4 * e) << name << " " << theta << " " << i;
        EXPECT_LE(angle(d[i], s[i]), 4 * e * theta) << name;  // a mis-scaled point shifts later bisectors
      }
    }
  }
}

// Length 3: the quadratic passes through both ends and the exact mid normal h (Na + Nb).
TEST(Normalization, QuadraticPassesThroughEndsAndExactMidNormal) {
  for (double theta : {1e-5, 0.5, 1.5, 3.0}) {
    const auto [a, b] = ends(theta);
    const auto q = span_normals<double>(parse_normalize("quadratic:exact"), a, b, 3);
    EXPECT_LT(glm::length(q[0] - a), 1e-12);
    EXPECT_LT(glm::length(q[1] - glm::normalize(a + b)), 1e-12) << theta;
    EXPECT_LT(glm::length(q[2] - b), 1e-12) << theta;
    // Forward differences over 4097 pixels still land on the far end.
    const auto l = span_normals<double>(parse_normalize("quadratic:exact"), a, b, 4097);
    EXPECT_LT(glm::length(l[4096] - b), 1e-9) << theta;
    EXPECT_LT(glm::length(l[2048] - glm::normalize(a + b)), 1e-9) << theta;
  }
}

TEST(Normalization, RecurrenceInDoubleFollowsSlerpOverLongSpans) {
  for (double theta : {1e-6, 0.3, 2.0, 3.1}) {
    const auto [a, b] = ends(theta);
    for (int m : {2, 3, 4096}) {
      const auto r = span_normals<double>(parse_normalize("recurrence"), a, b, m);
      const auto s = span_normals<double>(parse_normalize("slerp"), a, b, m);
      for (int i = 0; i < m; ++i) ASSERT_LT(glm::length(r[i] - s[i]), 1e-8) << theta << " " << m << " " << i;
    }
  }
}

// Float recurrence drifts: 2 cos(dtheta) is off by up to dc = 3e-8 (half the float spacing below 2), a
// phase error of dc / sin(dtheta) per pixel; re-anchoring every R = 64 pixels bounds the angle by about
// R dc / sin(dtheta) = 64 * 3e-8 / 2.44e-4 = 7.9e-3 (measured figures: docs/phong-methods.md).
TEST(Normalization, RecurrenceReanchoringBoundsFloatDrift) {
  const auto [a, b] = ends(1.0);
  const auto s = span_normals<double>(parse_normalize("slerp"), a, b, 4096);
  auto worst = [&](const std::string& name) {
    const auto r = span_normals<float>(parse_normalize(name), glm::vec3(a), glm::vec3(b), 4096);
    double w = 0;
    for (int i = 0; i < 4096; ++i) w = std::fmax(w, glm::length(glm::dvec3(r[i]) - s[i]));
    return w;
  };
  const double free_run = worst("recurrence"), anchored = worst("recurrence:exact:64");
  EXPECT_LT(anchored, 7.9e-3);
  EXPECT_LT(anchored, free_run / 10);
}

TEST(Normalization, RecurrenceOnDotProductsMatchesTheDotsOfSlerp) {
  const auto [a, b] = ends(0.8);
  const glm::dvec3 l = glm::normalize(glm::dvec3(0.3, 0.2, 1.0));
  const int m = 100;
  const auto s = span_normals<double>(parse_normalize("slerp"), a, b, m);
  const auto d = recurrence_dots<double>(glm::dot(s[0], l), glm::dot(s[1], l), std::cos(0.8 / (m - 1)), m);
  for (int i = 0; i < m; ++i) EXPECT_NEAR(d[i], glm::dot(s[i], l), 1e-10);
}

// The approximations on their documented intervals, against 1/sqrt and acos computed here.
double worst_abs(double (*approx)(double), double (*f)(double), double lo, double hi) {
  double w = 0;
  for (int i = 0; i <= 10000; ++i) {
    const double x = lo + (hi - lo) * i / 10000.0;
    w = std::fmax(w, std::fabs(approx(x) - f(x)));
  }
  return w;
}
double bis(double u) { return 1 / std::sqrt(2 + u); }
double hmid(double r) { return 1 / std::sqrt(2 * (1 + r)); }

TEST(Normalization, BisectorScaleBounds) {
  const double s2 = std::sqrt(2.0);
  EXPECT_LT(worst_abs([](double u) { return bisector_scale(BisectorScale::quadratic_fit, u); }, bis, s2, 2), 2.1e-5);
  EXPECT_LT(worst_abs([](double u) { return bisector_scale(BisectorScale::linear_fit, u); }, bis, s2, 2), 6.2e-4);
  // The sources' printed coefficients miss their claims (0.0005 and 2e-5): measured, not assumed.
  EXPECT_GT(worst_abs([](double u) { return bisector_scale(BisectorScale::linear_source, u); }, bis, s2, 2), 1e-3);
  EXPECT_GT(worst_abs([](double u) { return bisector_scale(BisectorScale::quadratic_source, u); }, bis, s2, 2), 9e-4);
  EXPECT_NEAR(bisector_scale(BisectorScale::exact, 2.0), 0.5, 1e-15);
}

TEST(Normalization, MidScaleBounds) {
  EXPECT_LT(worst_abs([](double r) { return mid_scale(MidScale::quadratic_fit, r); }, hmid, 0, 1), 2e-3);
  EXPECT_LT(worst_abs([](double r) { return mid_scale(MidScale::cubic_fit, r); }, hmid, 0, 1), 3.8e-4);
  EXPECT_GT(worst_abs([](double r) { return mid_scale(MidScale::cubic_source, r); }, hmid, 0, 1), 3.8e-4);
  EXPECT_NEAR(mid_scale(MidScale::exact, 0.0), std::sqrt(0.5), 1e-15);
}

TEST(Normalization, ArccosTableAsPrintedFailsNearOneAndTheRefitHolds) {
  // Printed table: acos(1) should be 0 and comes out as 0.174.
  EXPECT_NEAR(arccos_approx(Arccos::table_source, 1.0), -33.838 + 74.547 - 40.535, 1e-12);
  double worst = 0;
  for (int i = 0; i < 20000; ++i) {
    const double x = -1.0 + 2.0 * i / 20000.0;
    worst = std::fmax(worst, std::fabs(arccos_approx(Arccos::table_fixed, x) - std::acos(x)) / std::acos(x));
  }
  EXPECT_LT(worst, 0.002);  // the source's 0.2 % claim, met by the refit everywhere on [-1, 1)
  EXPECT_NEAR(arccos_approx(Arccos::table_fixed, 1.0), 0.0, 1e-12);
  EXPECT_NEAR(arccos_approx(Arccos::table_fixed, -1.0), kPi, 1e-6);
}

}  // namespace
}  // namespace parashade
