// The sources' edge-walking DDA: its pixels, its coverage against the pixel-centre top-left rule, and
// the edge intensity error delta_E against the sources' bound |I_C - I_A| / (2 MP) ([Malovanyi 2019, parallel Gouraud] §2.2).
#include <cmath>
#include <cstdio>
#include <random>
#include <set>

#include <gtest/gtest.h>

#include "parashade/edge_dda.hpp"
#include "parashade/screen_geometry.hpp"

namespace parashade {
namespace {

TEST(EdgeDda, SegmentWorkedByHand) {
  // BP = 5, MP = 2, OF0 = 2: OF = 4, 6-5=1 (step), 3, 5-5=0 (step), 2.
  const std::vector<glm::ivec2> expect = {{0, 0}, {1, 0}, {2, 1}, {3, 1}, {4, 2}, {5, 2}};
  EXPECT_EQ(dda_segment({0, 0}, {5, 2}), expect);
  const std::vector<glm::ivec2> up = {{3, 3}, {3, 2}, {2, 1}, {2, 0}};  // y-major, both directions negative
  EXPECT_EQ(dda_segment({3, 3}, {2, 0}), up);
}

TEST(EdgeDda, SegmentsEndAtTheirEndsWithinHalfAPixelOfTheLine) {
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> u(-200, 200);
  for (int t = 0; t < 2000; ++t) {
    const glm::ivec2 a(u(rng), u(rng)), b(u(rng), u(rng));
    const auto px = dda_segment(a, b);
    const int bp = std::max(std::abs(b.x - a.x), std::abs(b.y - a.y));
    ASSERT_EQ(px.size(), std::size_t(bp) + 1);
    EXPECT_EQ(px.front(), a);
    EXPECT_EQ(px.back(), b);
    for (std::size_t i = 0; i < px.size(); ++i) {
      // Distance along the minor axis from the ideal line at the same major coordinate.
      const double s = bp ? double(i) / bp : 0.0;
      const glm::dvec2 ideal = glm::dvec2(a) + s * glm::dvec2(b - a);
      const double e = std::abs(b.x - a.x) >= std::abs(b.y - a.y) ? px[i].y - ideal.y : px[i].x - ideal.x;
      EXPECT_LE(std::abs(e), 0.5 + 1e-12);
    }
  }
}

// Pixel-centre top-left coverage of the triangle whose vertices are the centres of pixels a, b, c.
std::set<std::pair<int, int>> centre_coverage(glm::ivec2 a, glm::ivec2 b, glm::ivec2 c) {
  glm::ivec2 v[3] = {a * kSubpixel + kSubpixel / 2, b * kSubpixel + kSubpixel / 2, c * kSubpixel + kSubpixel / 2};
  const auto e = [](glm::ivec2 i, glm::ivec2 j, glm::ivec2 p) {
    return std::int64_t(j.x - i.x) * (p.y - i.y) - std::int64_t(j.y - i.y) * (p.x - i.x);
  };
  if (e(v[0], v[1], v[2]) < 0) std::swap(v[1], v[2]);
  std::set<std::pair<int, int>> out;
  const int x0 = std::min({a.x, b.x, c.x}), x1 = std::max({a.x, b.x, c.x});
  const int y0 = std::min({a.y, b.y, c.y}), y1 = std::max({a.y, b.y, c.y});
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      const glm::ivec2 p(x * kSubpixel + kSubpixel / 2, y * kSubpixel + kSubpixel / 2);
      bool in = true;
      for (int k = 0; k < 3; ++k) in &= e(v[k], v[(k + 1) % 3], p) >= edge_bias(v[k], v[(k + 1) % 3]);
      if (in) out.insert({x, y});
    }
  return out;
}

// The DDA fill holds every pixel the centre rule covers, plus edge pixels; two triangles sharing an
// edge both take that edge's pixels (double coverage the centre rule does not have).
TEST(EdgeDda, FillContainsCentreCoverageAndDoublesSharedEdges) {
  std::mt19937 rng(9);
  std::uniform_int_distribution<int> u(0, 60);
  std::uint64_t centre = 0, extra = 0, shared_double = 0, shared_edge_pixels = 0;
  for (int t = 0; t < 500; ++t) {
    const glm::ivec2 a(u(rng), u(rng)), b(u(rng), u(rng)), c(u(rng), u(rng)), d(u(rng), u(rng));
    const auto side = [&](glm::ivec2 p) { return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x); };
    if (side(c) == 0 || side(d) == 0 || (side(c) > 0) == (side(d) > 0)) continue;  // c, d on opposite sides of ab
    const auto fill = dda_fill(a, b, c);
    const std::set<std::pair<int, int>> dda = [&] {
      std::set<std::pair<int, int>> s;
      for (auto p : fill) s.insert({p.x, p.y});
      return s;
    }();
    ASSERT_EQ(dda.size(), fill.size()) << "each pixel once";
    const auto ref = centre_coverage(a, b, c);
    for (const auto& p : ref) EXPECT_TRUE(dda.count(p)) << "centre-covered pixel missing from the DDA fill";
    centre += ref.size();
    extra += dda.size() - ref.size();
    std::set<std::pair<int, int>> other;
    for (auto p : dda_fill(a, b, d)) other.insert({p.x, p.y});
    for (const auto& p : dda) shared_double += other.count(p);
    shared_edge_pixels += std::max(std::abs(b.x - a.x), std::abs(b.y - a.y)) + 1;
  }
  std::printf("DDA fill over 500 random triangles: %llu centre-covered pixels, %llu extra edge pixels (%.1f%%); "
              "pairs sharing an edge: %llu doubly covered pixels for %llu shared-edge pixels\n",
              (unsigned long long)centre, (unsigned long long)extra, 100.0 * double(extra) / double(centre),
              (unsigned long long)shared_double, (unsigned long long)shared_edge_pixels);
  EXPECT_GT(extra, 0u);
  EXPECT_GE(shared_double, shared_edge_pixels / 2) << "shared edges are drawn by both triangles";
}

// delta_E: the edge interpolator's value at a displaced pixel differs from the plane's there by the plane
// gradient across the edge times the displacement (<= 1/2), which is what bounds it; the sources' bound
// |I_C - I_A| / (2 MP) uses the edge's own slope instead and fails when the plane varies across the edge.
TEST(EdgeDda, EdgeIntensityErrorBoundedByPlaneGradientNotByTheSourcesBound) {
  // A counterexample: I_A = I_C, so the sources' bound is 0, but the plane varies in x across AC.
  const EdgeIntensityError ce = edge_intensity_error({0, 0}, {3, 10}, {10, 5}, 0.0, 0.0, 100.0);
  EXPECT_EQ(ce.source_bound, 0.0);
  EXPECT_GT(ce.max_error, 1.0);
  EXPECT_LE(ce.max_error, ce.plane_bound + 1e-9);

  std::mt19937 rng(21);
  std::uniform_int_distribution<int> u(0, 400);
  std::uniform_real_distribution<double> ui(0.0, 255.0);
  int edges = 0, source_violations = 0;
  double worst_ratio = 0.0;
  for (int t = 0; t < 3000; ++t) {
    const glm::ivec2 a(u(rng), u(rng)), b(u(rng), u(rng)), c(u(rng), u(rng));
    if ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x) == 0) continue;
    const EdgeIntensityError r = edge_intensity_error(a, b, c, ui(rng), ui(rng), ui(rng));
    if (r.minor == 0) continue;  // axis-parallel: no displacement
    ++edges;
    EXPECT_LE(r.max_error, r.plane_bound + 1e-9);
    if (r.max_error > r.source_bound + 1e-9) ++source_violations;
    if (r.source_bound > 0) worst_ratio = std::max(worst_ratio, r.max_error / r.source_bound);
  }
  std::printf("delta_E over %d random edges: the sources' bound |I_C - I_A|/(2 MP) exceeded on %d (%.1f%%), "
              "worst measured/bound %.1f\n", edges, source_violations, 100.0 * source_violations / edges, worst_ratio);
  EXPECT_GT(source_violations, 0);
}

}  // namespace
}  // namespace parashade
