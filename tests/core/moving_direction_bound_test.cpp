// The chord bound for a moving light and viewer (moving_direction_bound.hpp, docs/combined.md §2b) against
// brute-force sampling of random segments in double precision: the kernel's segment (normal and position
// interpolated linearly, normalized, L = normalize(P - p), V = normalize(E - p), H = normalize(L + V)),
// with point lights and local viewers near and far, directional lights and distant viewers. Never exceeded.
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>
#include <glm/glm.hpp>

#include "parashade/moving_direction_bound.hpp"

namespace parashade {
namespace {

double term(double cosine, double n) { return std::pow(std::max(0.0, cosine), n); }

// Distance from q to the segment a + s d, s in [0, 1].
double distance_to_segment(const glm::dvec3& q, const glm::dvec3& a, const glm::dvec3& d) {
  const double s = std::clamp(glm::dot(q - a, d) / std::max(1e-300, glm::dot(d, d)), 0.0, 1.0);
  return glm::length(q - (a + s * d));
}

struct Direction {
  bool at_point = false;  // a point light / a local viewer (else the constant `dir`)
  glm::dvec3 where{0.0}, dir{0.0, 0.0, 1.0};
  glm::dvec3 at(const glm::dvec3& p) const { return at_point ? glm::normalize(where - p) : dir; }
};

TEST(MovingDirectionBound, HoldsOnRandomSegments) {
  std::mt19937 rng(1708);
  std::uniform_real_distribution<double> u(-1, 1), unit(0, 1);
  const double exponents[] = {2, 10, 40, 200, 1000};
  const auto random_unit = [&] {
    for (;;) {
      glm::dvec3 v(u(rng), u(rng), u(rng));
      if (glm::length(v) > 0.1 && glm::length(v) <= 1) return glm::normalize(v);
    }
  };
  const auto random_direction = [&](const glm::dvec3& p, double scale) {
    Direction d;
    d.at_point = unit(rng) < 0.8;
    // Near (a few segment lengths) to far (thousands).
    d.where = p + random_unit() * (scale * std::pow(10.0, 0.3 + 3.0 * unit(rng)));
    d.dir = random_unit();
    return d;
  };
  int checked = 0, informative = 0, crossing = 0;
  double tightest = 0.0;
  const int steps = 96;
  for (int i = 0; i < 60000; ++i) {
    const bool specular = i % 3 != 0;
    const double n = specular ? exponents[(i / 3) % 5] : 1.0;
    // The kernel's segment: unnormalized end normals, positions moving by dp.
    const glm::dvec3 na = random_unit() * (0.4 + 0.6 * unit(rng));
    const glm::dvec3 dn = random_unit() * (std::pow(10.0, -3.0 + 2.5 * unit(rng)) * glm::length(na));
    const glm::dvec3 pa = random_unit() * unit(rng);
    const double move = std::pow(10.0, -3.0 + 2.0 * unit(rng));
    const glm::dvec3 dp = random_unit() * move;
    const Direction light = random_direction(pa, move), view = random_direction(pa, move);
    // Half the specular cases put the highlight at the segment's middle (the peak error lives there).
    Direction aimed_view = view;
    if (specular && i % 2 && light.at_point && view.at_point) {
      const glm::dvec3 pm = pa + 0.5 * dp, nm = glm::normalize(na + 0.5 * dn);
      const glm::dvec3 l = light.at(pm), h = glm::normalize(nm + 0.03 * unit(rng) * random_unit());
      const glm::dvec3 v = 2.0 * glm::dot(l, h) * h - l;  // V with normalize(L + V) = h
      if (glm::dot(v, h) > 0.1) aimed_view.where = pm + v * glm::length(view.where - pa);
    }
    // The rates the kernel's limits give (psi = |dn| / min|N|, |dp| / nearest distance) and |L + V|'s floor.
    const double s_star = std::clamp(-glm::dot(na, dn) / glm::dot(dn, dn), 0.0, 1.0);
    const double min_len = std::min({glm::length(na), glm::length(na + dn), glm::length(na + s_star * dn)});
    SegmentRates r;
    r.normal = glm::length(dn) / min_len;
    r.light = light.at_point ? move / distance_to_segment(light.where, pa, dp) : 0.0;
    r.view = aimed_view.at_point ? move / distance_to_segment(aimed_view.where, pa, dp) : 0.0;
    const glm::dvec3 pm = pa + 0.5 * dp;
    const double chord_l = light.at_point ? move / glm::length(light.where - pm) : 0.0;
    const double chord_v = aimed_view.at_point ? move / glm::length(aimed_view.where - pm) : 0.0;
    r.half_min = glm::length(light.at(pm) + aimed_view.at(pm)) - chord_l - chord_v;
    if (!(r.normal < 1.0) || !(r.light < 1.0) || !(r.view < 1.0)) continue;
    const auto value = [&](double s) {
      const glm::dvec3 p = pa + s * dp, nn = glm::normalize(na + s * dn), l = light.at(p);
      if (!specular) return term(glm::dot(nn, l), 1.0);
      return term(glm::dot(nn, glm::normalize(l + aimed_view.at(p))), n);
    };
    const double fa = value(0.0), fb = value(1.0);
    double worst = 0.0, lowest = 1.0, highest = -1.0;
    for (int j = 0; j <= steps; ++j) {
      const double s = double(j) / steps;
      worst = std::max(worst, std::abs(value(s) - (fa + (fb - fa) * s)));
      const glm::dvec3 p = pa + s * dp;
      const double c = glm::dot(glm::normalize(na + s * dn), light.at(p));
      lowest = std::min(lowest, c);
      highest = std::max(highest, c);
    }
    // The kink-free diffuse bound only where N.L keeps its sign with room to spare (the caller's check).
    const bool crosses = !specular && !(lowest > 0.02 || highest < -0.02);
    crossing += crosses;
    const double bound = moving_term_bound(r, n, specular, crosses);
    ASSERT_LE(worst, bound + 1e-12) << "case " << i << " n " << n << " rates " << r.normal << " " << r.light << " "
                                    << r.view << " half " << r.half_min;
    if (bound < 0.1 && bound > 1e-6) {
      ++informative;
      tightest = std::max(tightest, worst / bound);
    }
    ++checked;
  }
  RecordProperty("checked", checked);
  RecordProperty("informative_cases", informative);
  RecordProperty("largest_error_over_bound", std::to_string(tightest));
  EXPECT_GT(checked, 40000);
  EXPECT_GT(crossing, 100);
  EXPECT_GT(informative, 10000);
  EXPECT_GT(tightest, 0.1) << "the bound should not be vacuous";
}

// n < 2 has no bounded second derivative at the specular clamp: no bound.
TEST(MovingDirectionBound, NoBoundForSpecularExponentsBelowTwo) {
  SegmentRates r;
  r.normal = 1e-3;
  EXPECT_EQ(moving_term_bound(r, 1.5, true, false), 1.0);
  EXPECT_LT(moving_term_bound(r, 2.0, true, false), 1e-4);
}

}  // namespace
}  // namespace parashade
