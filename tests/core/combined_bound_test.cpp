// The combined method's worst-case segment errors (combined.hpp, docs/combined.md) against brute-force
// sampling: never exceeded, and how tight.
#include <cmath>
#include <algorithm>
#include <random>
#include <vector>

#include <gtest/gtest.h>
#include <glm/glm.hpp>

#include "parashade/combined.hpp"
#include "parashade/errors.hpp"

namespace parashade {
namespace {

double term(double cosine, double n) { return std::pow(std::max(0.0, cosine), n); }

// sup over placements theta0 and positions t of |f(theta0 + t phi) - chord|, f = max(0, cos)^n.
double sampled_chord_error(double phi, double n) {
  double worst = 0;
  const int placements = 1500, positions = 120;
  // A coarse grid over the circle, then fine ones around the peak (0) and the zeros (+-pi/2).
  std::vector<double> starts;
  for (int i = 0; i <= placements; ++i) starts.push_back(-M_PI + (2 * M_PI) * i / placements);
  for (double centre : {0.0, M_PI / 2, -M_PI / 2})
    for (int i = 0; i <= placements; ++i) starts.push_back(centre - phi * (-0.5 + 2.0 * i / placements));
  for (const double a : starts) {
    const double fa = term(std::cos(a), n), fb = term(std::cos(a + phi), n);
    for (int j = 1; j < positions; ++j) {
      const double t = double(j) / positions;
      worst = std::max(worst, std::abs(term(std::cos(a + t * phi), n) - (fa + (fb - fa) * t)));
    }
  }
  return worst;
}

TEST(CombinedBound, ChordBoundHoldsAndIsTight) {
  for (double n : {1.0, 1.5, 2.0, 5.0, 25.0, 60.0, 100.0, 1000.0}) {
    for (double phi : {0.005, 0.02, 0.1, 0.3, 0.8, 1.5}) {
      const double sampled = sampled_chord_error(phi, n), bound = chord_error_bound(phi, n);
      EXPECT_LE(sampled, bound * (1 + 1e-9) + 1e-15) << "n " << n << " phi " << phi;
      // n >= 2: the symmetric peak is the worst case, so the bound is attained (up to sampling);
      // n = 1: the terminator case max_a a sin(phi - a)/phi is within 10 % of phi/4 for phi <= 1.5.
      if (n >= 2.0) EXPECT_GE(sampled, 0.999 * bound) << "n " << n << " phi " << phi;
      if (n == 1.0) EXPECT_GE(sampled, 0.9 * bound) << "phi " << phi;
    }
  }
}

// The sources' diffuse bound 1 - cos(phi/2) fails across the terminator: the kink of max(0, N.L).
TEST(CombinedBound, SourcesDiffuseBoundFailsAcrossTheTerminator) {
  const double phi = 0.1;
  EXPECT_GT(sampled_chord_error(phi, 1.0), 10.0 * (1.0 - std::cos(phi / 2)));
}

// Segments of interpolated, unnormalized normals N_a' -> N_b' = N_a' + w in 3-D, ends normalized,
// the term linear in the pixel between them: the error never exceeds segment_term_bound(psi, n).
TEST(CombinedBound, SegmentBoundHoldsForRandomSegments) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(-1, 1), len(0.3, 1.0), change(0.0, 0.6), unit(0, 1);
  const double exponents[] = {1, 2, 10, 40, 100, 500};
  const auto random_unit = [&] {
    for (;;) {
      glm::dvec3 v(u(rng), u(rng), u(rng));
      if (glm::length(v) > 0.1 && glm::length(v) <= 1) return glm::normalize(v);
    }
  };
  double tightest = 0;  // largest error / bound where the bound is informative (< 0.2)
  std::vector<double> ratios;
  int checked = 0;
  for (int i = 0; i < 40000; ++i) {
    const double n = exponents[i % 6];
    const glm::dvec3 na = random_unit() * len(rng);
    const glm::dvec3 w = random_unit() * (change(rng) * glm::length(na));
    const glm::dvec3 nb = na + w;
    double min_len = 1e9;
    const int steps = 64;
    for (int j = 0; j <= steps; ++j) min_len = std::min(min_len, glm::length(na + w * (double(j) / steps)));
    // |N|^2 is a quadratic: its exact minimum on the segment.
    const double s_star = std::clamp(-glm::dot(na, w) / glm::dot(w, w), 0.0, 1.0);
    min_len = std::min(min_len, glm::length(na + w * s_star));
    const double psi = glm::length(w) / min_len;
    if (psi >= 1.0) continue;
    // Half the cases aim the light at the segment's middle, where the peak error lives.
    const glm::dvec3 mid = glm::normalize(glm::normalize(na) + glm::normalize(nb));
    const glm::dvec3 l = i % 2 ? glm::normalize(mid + 0.05 * unit(rng) * random_unit()) : random_unit();
    const double fa = term(glm::dot(glm::normalize(na), l), n), fb = term(glm::dot(glm::normalize(nb), l), n);
    double worst = 0;
    for (int j = 1; j < steps; ++j) {
      const double t = double(j) / steps;
      const double exact = term(glm::dot(glm::normalize(na + w * t), l), n);
      worst = std::max(worst, std::abs(exact - (fa + (fb - fa) * t)));
    }
    const double bound = segment_term_bound(psi, n);
    ASSERT_LE(worst, bound + 1e-12) << "n " << n << " psi " << psi;
    if (bound < 0.2) {
      tightest = std::max(tightest, worst / bound);
      ratios.push_back(worst / bound);
    }
    ++checked;
  }
  RecordProperty("checked", checked);
  std::sort(ratios.begin(), ratios.end());
  RecordProperty("largest_error_over_bound", std::to_string(tightest));
  RecordProperty("median_error_over_bound", std::to_string(ratios[ratios.size() / 2]));
  RecordProperty("informative_cases", int(ratios.size()));
  EXPECT_GT(checked, 20000);
  EXPECT_GT(tightest, 0.5) << "the bound should be reasonably tight";
}

TEST(CombinedBound, LimitMeetsTheBudget) {
  Scene s;
  Light l;
  l.color = {1.0f, 1.0f, 1.0f};
  s.lights = {l, l};
  Material m;
  m.diffuse = {0.7f, 0.6f, 0.5f};
  m.specular = {0.5f, 0.5f, 0.5f};
  m.shininess = 60.0f;
  for (double budget : {0.5, 1.5, 3.5}) {
    const double psi = psi_limit(s, m, budget);
    EXPECT_GT(psi, 0.0);
    EXPECT_LE(segment_error_levels(s, m, psi), budget);
    EXPECT_GT(segment_error_levels(s, m, psi * 1.01), budget);
  }
  EXPECT_LT(psi_limit(s, m, 0.5), psi_limit(s, m, 1.5));
}

TEST(CombinedBound, ParsesMethodNames) {
  EXPECT_EQ(parse_combined("combined:3").k, 3);
  EXPECT_FALSE(parse_combined("combined:3").automatic);
  EXPECT_TRUE(parse_combined("combined:auto").automatic);
  EXPECT_EQ(combined_name(parse_combined("combined:auto")), "combined:auto");
  for (const char* bad : {"combined:", "combined:7", "combined:-1", "combined:2x", "combined:k"})
    EXPECT_THROW(parse_combined(bad), UsageError) << bad;
}

}  // namespace
}  // namespace parashade
