// The highlight-presence bound (highlight.hpp): the largest N.H over a triangle's normalized
// interpolated normals, against dense sampling of barycentric weights.
#include <algorithm>
#include <random>

#include <gtest/gtest.h>
#include <glm/glm.hpp>

#include "parashade/highlight.hpp"

namespace parashade {
namespace {

TEST(HighlightBound, MaxCosineOverNormalsIsExact) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  const auto random_unit = [&] {
    for (;;) {
      glm::dvec3 v(u(rng), u(rng), u(rng));
      if (glm::length(v) > 0.1 && glm::length(v) <= 1) return glm::normalize(v);
    }
  };
  double worst_gap = 0;
  for (int i = 0; i < 3000; ++i) {
    // Normals within ~50 degrees of a common direction, as on a mesh; h anywhere.
    const glm::dvec3 c = random_unit();
    glm::dvec3 n[3];
    for (auto& v : n) v = glm::normalize(c + 0.6 * random_unit());
    const glm::dvec3 h = i % 3 ? random_unit() : glm::normalize(c + 0.3 * random_unit());
    double sampled = -1;
    const int steps = 60;
    for (int a = 0; a <= steps; ++a)
      for (int b = 0; a + b <= steps; ++b) {
        const glm::dvec3 m = glm::normalize(double(a) * n[0] + double(b) * n[1] + double(steps - a - b) * n[2]);
        sampled = std::max(sampled, glm::dot(m, h));
      }
    const double bound = max_cosine_over_normals(n[0], n[1], n[2], h);
    ASSERT_GE(bound, sampled - 1e-12) << i;
    worst_gap = std::max(worst_gap, bound - sampled);
  }
  EXPECT_LT(worst_gap, 2e-3) << "the bound is the maximum, not just above it";
}

}  // namespace
}  // namespace parashade
