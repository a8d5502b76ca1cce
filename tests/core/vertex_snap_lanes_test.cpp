// transform_vertices (the vertex stage's lanes) against the scalar definitions, element for element and
// bit for bit: clip position, outcode, snapped sub-pixel position, depth and 1/w must not depend on
// whether a vertex went through a lane or the scalar tail. Hard inputs: rounding ties of the sub-pixel
// snap (ties to even), points on the clip planes, w <= 0, tiny and huge w, points far outside the guard
// band (clamped), NaN and Inf coordinates, -0; perspective and orthographic matrices.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "parashade/screen_geometry.hpp"
#include "parashade/vertex_snap.hpp"

namespace parashade {
namespace {

template <typename T>
std::uint32_t bits(T v) {
  static_assert(sizeof(T) == 4);
  std::uint32_t b;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

std::vector<glm::vec3> hard_positions() {
  const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  std::vector<glm::vec3> p = {{0, 0, 0},       {-0.0f, -0.0f, -0.0f}, {1e30f, 1e30f, 1e30f}, {-1e30f, 0, 0},
                              {nan, 0, 0},     {0, inf, 0},           {0, 0, -inf},          {1e-40f, -1e-40f, 0},
                              {3e38f, 3e38f, 3e38f}, {0, 0, 5.0f},    {0, 0, -5.0f},         {100, -100, 0.5f}};
  // On each clip plane under the identity matrix (w = 1): guard band |x|, |y| = 3, near z = -1, far z = 1.
  for (const glm::vec3& v : {glm::vec3(3, 0, 0), glm::vec3(-3, 0, 0), glm::vec3(0, 3, 0), glm::vec3(0, -3, 0),
                             glm::vec3(0, 0, 1), glm::vec3(0, 0, -1), glm::vec3(-3, 3, -1)})
    p.push_back(v);
  // Ties of the snap under the identity matrix at width = height = 1: x = (c*0.5 + 0.5) * 256 = k + 0.5.
  for (int k = -300; k < 600; ++k) {
    const float c = float((k + 0.5) / 128.0 - 1.0);
    p.push_back({c, -c, c});
  }
  std::uint32_t seed = 11;
  const auto rnd = [&] { return float((seed = seed * 1664525u + 1013904223u) >> 8) / float(1 << 24) - 0.5f; };
  for (int i = 0; i < 4000; ++i) p.push_back({20 * rnd(), 20 * rnd(), 20 * rnd()});
  return p;
}

void expect_same_as_scalar(const glm::mat4& m, const std::vector<glm::vec3>& p, int width, int height,
                           const char* what) {
  const std::size_t n = p.size();
  std::vector<glm::vec4> clip(n);
  std::vector<std::uint8_t> outcode(n);
  std::vector<glm::ivec2> xy(n);
  std::vector<float> depth(n), inv_w(n);
  // From offsets 0..2, so each vertex is seen in a lane position and, near the end, in the scalar tail.
  for (std::size_t first = 0; first < 3; ++first) {
    transform_vertices(m, p.data() + first, n - first, width, height,
                       {clip.data(), outcode.data(), xy.data(), depth.data(), inv_w.data()});
    for (std::size_t i = 0; i + first < n; ++i) {
      const glm::vec4 want = m * glm::vec4(p[i + first], 1.0f);
      const Snapped s = snap(want, width, height);
      for (int c = 0; c < 4; ++c) ASSERT_EQ(bits(clip[i][c]), bits(want[c])) << what << " vertex " << i + first;
      ASSERT_EQ(outcode[i], outcode_of(want)) << what << " vertex " << i + first;
      ASSERT_EQ(xy[i], s.xy) << what << " vertex " << i + first << " clip " << want.x << " " << want.y << " " << want.w;
      ASSERT_EQ(bits(depth[i]), bits(s.depth)) << what << " vertex " << i + first;
      ASSERT_EQ(bits(inv_w[i]), bits(s.inv_w)) << what << " vertex " << i + first;
    }
  }
  // Without the clip positions (the vertex stage's call): the rest unchanged.
  std::vector<glm::ivec2> xy_alone(n);
  transform_vertices(m, p.data(), n, width, height,
                     {nullptr, outcode.data(), xy_alone.data(), depth.data(), inv_w.data()});
  for (std::size_t i = 0; i < n; ++i)
    ASSERT_EQ(xy_alone[i], snap(m * glm::vec4(p[i], 1.0f), width, height).xy) << what << " vertex " << i << ", no clip";
}

glm::mat4 view() { return glm::lookAt(glm::vec3(0.0f, 0.6f, 4.0f), glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f)); }
glm::mat4 perspective() { return glm::perspective(glm::radians(40.0f), 16.0f / 9.0f, 0.5f, 20.0f) * view(); }

TEST(VertexSnapLanes, EqualsScalarBitForBit) {
  const std::vector<glm::vec3> p = hard_positions();
  expect_same_as_scalar(glm::mat4(1.0f), p, 1, 1, "identity, 1x1");
  expect_same_as_scalar(glm::mat4(1.0f), p, 1920, 1080, "identity, 1920x1080");
  expect_same_as_scalar(perspective(), p, 3840, 2160, "perspective");
  expect_same_as_scalar(glm::ortho(-2.0f, 2.0f, -1.5f, 1.5f, 0.1f, 10.0f) * view(), p, 641, 479, "orthographic");
  // Every entry of the matrix nonzero (a model turned about a skew axis, scaled and moved), so each clip
  // coordinate sums four products and the order of the sums shows.
  const glm::mat4 model = glm::scale(glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(0.3f, -0.2f, 0.5f)), 0.7f,
                                                 glm::vec3(0.3f, 1.0f, -0.2f)),
                                     glm::vec3(1.5f, 0.75f, 1.25f));
  expect_same_as_scalar(perspective() * model, p, 1920, 1080, "perspective, skew model");
}

// The inputs reach every branch whose lanes could differ from the scalar code.
TEST(VertexSnapLanes, HardInputsReachEveryCase) {
  const std::vector<glm::vec3> p = hard_positions();
  int ties = 0, clamped = 0, behind = 0, non_finite = 0;
  for (const glm::vec3& v : p) {
    const glm::vec4 c(v, 1.0f);
    const double x = (double(c.x) * 0.5 + 0.5) * kSubpixel;
    ties += x == std::floor(x) + 0.5;
    clamped += std::abs(x) > double(1 << 30);
    non_finite += outcode_of(c) == kNonFinite;
    behind += !((perspective() * c).w > 0.0f);
  }
  EXPECT_GT(ties, 800);
  EXPECT_GT(clamped, 1);
  EXPECT_GT(behind, 500);
  EXPECT_GE(non_finite, 3);
}

}  // namespace
}  // namespace parashade
