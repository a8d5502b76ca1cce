// world_and_normals (the vertex stage's lanes for Phong's and Gouraud's lighting inputs) against
// world_position and unit_normal, element for element and bit for bit. Hard inputs: zero, tiny (the
// squared length underflows to 0) and huge (it overflows to Inf) normals, NaN, -0, a singular normal
// matrix; each vertex both in a lane and in the scalar tail.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "parashade/vertex_world.hpp"

namespace parashade {
namespace {

std::uint32_t bits(float v) {
  std::uint32_t b;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

void expect_same_as_scalar(const glm::mat4& model, const std::vector<glm::vec3>& p, const std::vector<glm::vec3>& n,
                           const char* what) {
  const glm::mat3 normal_matrix = glm::transpose(glm::inverse(glm::mat3(model)));
  const std::size_t count = p.size();
  std::vector<glm::vec3> world(count), normal(count);
  for (std::size_t first = 0; first < 3; ++first) {  // every vertex in a lane and, near the end, in the tail
    world_and_normals(model, normal_matrix, p.data() + first, n.data() + first, count - first, world.data(),
                      normal.data());
    for (std::size_t i = 0; i + first < count; ++i) {
      const glm::vec3 w = world_position(model, p[i + first]), u = unit_normal(normal_matrix, n[i + first]);
      for (int c = 0; c < 3; ++c) {
        ASSERT_EQ(bits(world[i][c]), bits(w[c])) << what << " vertex " << i + first << " component " << c;
        ASSERT_EQ(bits(normal[i][c]), bits(u[c])) << what << " vertex " << i + first << " component " << c;
      }
    }
  }
  // Either output alone.
  std::vector<glm::vec3> only(count);
  world_and_normals(model, normal_matrix, p.data(), nullptr, count, only.data(), nullptr);
  for (std::size_t i = 0; i < count; ++i) {
    const glm::vec3 w = world_position(model, p[i]);
    for (int c = 0; c < 3; ++c) ASSERT_EQ(bits(only[i][c]), bits(w[c])) << what;
  }
  world_and_normals(model, normal_matrix, p.data(), n.data(), count, nullptr, only.data());
  for (std::size_t i = 0; i < count; ++i) {
    const glm::vec3 u = unit_normal(normal_matrix, n[i]);
    for (int c = 0; c < 3; ++c) ASSERT_EQ(bits(only[i][c]), bits(u[c])) << what;
  }
}

TEST(VertexWorldLanes, EqualsScalarBitForBit) {
  const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  std::vector<glm::vec3> p = {{0, 0, 0}, {-0.0f, 0, 0}, {1e30f, -1e30f, 3e38f}, {nan, 1, 2}, {inf, 0, 0}};
  std::vector<glm::vec3> n = {{0, 0, 0}, {1e-30f, 0, 0}, {3e30f, 3e30f, 0}, {nan, 0, 0}, {0, -0.0f, 1}};
  std::uint32_t seed = 5;
  const auto rnd = [&] { return float((seed = seed * 1664525u + 1013904223u) >> 8) / float(1 << 24) - 0.5f; };
  for (int i = 0; i < 3000; ++i) {
    p.push_back({10 * rnd(), 10 * rnd(), 10 * rnd()});
    n.push_back({rnd(), rnd(), rnd()});
  }
  const glm::mat4 rotate = glm::rotate(glm::mat4(1.0f), 0.7f, glm::vec3(0.3f, 1.0f, -0.2f));
  expect_same_as_scalar(glm::mat4(1.0f), p, n, "identity");
  expect_same_as_scalar(glm::translate(glm::scale(rotate, glm::vec3(2.0f, 0.5f, 3.0f)), glm::vec3(1, -2, 0.25f)), p, n,
                        "scaled, rotated, moved");
  expect_same_as_scalar(glm::scale(glm::mat4(1.0f), glm::vec3(1.0f, 1.0f, 0.0f)), p, n, "singular");
  // The hard normals reach the zero-length fallback and the unit case.
  const glm::mat3 identity(1.0f);
  EXPECT_EQ(unit_normal(identity, n[0]), glm::vec3(0, 0, 1));
  EXPECT_EQ(unit_normal(identity, n[1]), glm::vec3(0, 0, 1));  // 1e-60 underflows to 0
}

}  // namespace
}  // namespace parashade
