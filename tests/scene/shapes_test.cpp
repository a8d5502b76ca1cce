// Procedural sphere, torus, box and cylinder: counts, closedness, outward normals, winding.
#include <gtest/gtest.h>

#include <cmath>
#include <tuple>

#include "mesh_checks.hpp"
#include "parashade/errors.hpp"
#include "parashade/shapes.hpp"

namespace parashade {
namespace {

using namespace testing_support;

class SphereTest : public ::testing::TestWithParam<std::tuple<int, int>> {};

TEST_P(SphereTest, CountClosedOutwardAndOnTheUnitSphere) {
  const auto [slices, stacks] = GetParam();
  const Mesh m = make_sphere(slices, stacks);
  EXPECT_EQ(m.triangles.size(), std::size_t(2 * slices * (stacks - 1)));
  EXPECT_EQ(m.positions.size(), std::size_t(slices * (stacks - 1) + 2));
  EXPECT_TRUE(closed(edge_report(m)));
  EXPECT_EQ(bad_normals(m), 0u);
  EXPECT_EQ(zero_area_triangles(m), 0u);
  EXPECT_EQ(winding_disagreements(m), 0u);
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    EXPECT_NEAR(glm::length(m.positions[i]), 1.0f, 1e-5f);
    EXPECT_GT(glm::dot(m.normals[i], m.positions[i]), 0.999f);  // analytic: the normal is the position
  }
}

INSTANTIATE_TEST_SUITE_P(Sizes, SphereTest,
                         ::testing::Values(std::make_tuple(3, 2), std::make_tuple(8, 5), std::make_tuple(64, 65)));

TEST(Sphere, ShippedSizeHas8192Triangles) { EXPECT_EQ(make_sphere(64, 65).triangles.size(), 8192u); }

TEST(Sphere, PolesOnTheYAxis) {
  const Mesh m = make_sphere(16, 9);
  float top = -2.0f, bottom = 2.0f;
  for (const glm::vec3& p : m.positions) top = std::max(top, p.y), bottom = std::min(bottom, p.y);
  EXPECT_FLOAT_EQ(top, 1.0f);
  EXPECT_FLOAT_EQ(bottom, -1.0f);
}

TEST(Torus, CountClosedAndNormalsPointAwayFromTheTubeCentre) {
  const float major = 2.0f, minor = 0.5f;
  const Mesh m = make_torus(major, minor, 24, 12);
  EXPECT_EQ(m.triangles.size(), 2u * 24u * 12u);
  EXPECT_TRUE(closed(edge_report(m)));
  EXPECT_EQ(bad_normals(m), 0u);
  EXPECT_EQ(zero_area_triangles(m), 0u);
  EXPECT_EQ(winding_disagreements(m), 0u);
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    const glm::vec3 p = m.positions[i];
    // The torus is not convex: "outward" is away from the nearest point of the tube's centre circle.
    const glm::vec3 tube_centre = major * glm::normalize(glm::vec3(p.x, 0.0f, p.z));
    EXPECT_NEAR(glm::length(p - tube_centre), minor, 1e-5f);
    EXPECT_GT(glm::dot(m.normals[i], glm::normalize(p - tube_centre)), 0.999f);
  }
}

TEST(Box, TwentyFourVerticesClosedByPositionFlatOutwardNormals) {
  const glm::vec3 size(2.0f, 1.0f, 0.5f);
  const Mesh m = make_box(size);
  EXPECT_EQ(m.positions.size(), 24u);
  EXPECT_EQ(m.triangles.size(), 12u);
  EXPECT_FALSE(closed(edge_report(m)));  // each face has its own vertices...
  EXPECT_TRUE(closed(edge_report(m, true)));  // ...which meet by position
  EXPECT_EQ(bad_normals(m), 0u);
  for (const glm::uvec3& t : m.triangles) {
    const glm::vec3 n = glm::normalize(face_normal(m, t));
    for (int k = 0; k < 3; ++k) EXPECT_GT(glm::dot(n, m.normals[t[k]]), 0.9999f);  // flat
    EXPECT_GT(glm::dot(n, m.positions[t.x]), 0.0f);  // outward: the box is centred at the origin
  }
  for (const glm::vec3& p : m.positions) EXPECT_EQ(glm::abs(p), 0.5f * size);
}

TEST(Cylinder, WithCapsClosedByPosition) {
  const Mesh m = make_cylinder(0.5f, 2.0f, 16, true);
  EXPECT_EQ(m.triangles.size(), 4u * 16u);
  EXPECT_TRUE(closed(edge_report(m, true)));
  EXPECT_EQ(bad_normals(m), 0u);
  EXPECT_EQ(zero_area_triangles(m), 0u);
  EXPECT_EQ(winding_disagreements(m), 0u);
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    EXPECT_GT(glm::dot(m.normals[i], m.positions[i]), 0.0f);  // convex, centred at the origin
    EXPECT_NEAR(std::abs(m.positions[i].y), 1.0f, 1e-6f);
  }
}

TEST(Cylinder, SideNormalsAreRadialCapNormalsAxial) {
  const Mesh m = make_cylinder(1.0f, 1.0f, 8, true);
  std::size_t radial = 0, axial = 0;
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    const glm::vec3 n = m.normals[i], p = m.positions[i];
    if (std::abs(n.y) > 0.999f) {
      ++axial;
      EXPECT_EQ(n.y > 0.0f, p.y > 0.0f);
    } else {
      ++radial;
      EXPECT_NEAR(n.y, 0.0f, 1e-6f);
      EXPECT_GT(glm::dot(n, glm::normalize(glm::vec3(p.x, 0.0f, p.z))), 0.9999f);
    }
  }
  EXPECT_EQ(radial, 16u);
  EXPECT_EQ(axial, 18u);
}

TEST(Cylinder, WithoutCapsIsAnOpenTube) {
  const Mesh m = make_cylinder(0.5f, 2.0f, 16, false);
  EXPECT_EQ(m.triangles.size(), 2u * 16u);
  const EdgeReport r = edge_report(m);
  EXPECT_EQ(r.boundary, 2u * 16u);  // the two rims
  EXPECT_EQ(r.same_direction, 0u);
  EXPECT_EQ(winding_disagreements(m), 0u);
}

TEST(Shapes, OutOfRangeParametersThrowInputError) {
  EXPECT_THROW(make_sphere(2, 5), InputError);
  EXPECT_THROW(make_sphere(8, 1), InputError);
  EXPECT_THROW(make_torus(1.0f, 1.0f, 8, 8), InputError);
  EXPECT_THROW(make_torus(1.0f, 0.0f, 8, 8), InputError);
  EXPECT_THROW(make_torus(1.0f, 0.5f, 2, 8), InputError);
  EXPECT_THROW(make_box({1.0f, 0.0f, 1.0f}), InputError);
  EXPECT_THROW(make_box({1.0f, NAN, 1.0f}), InputError);
  EXPECT_THROW(make_cylinder(1.0f, 1.0f, 2, true), InputError);
  EXPECT_THROW(make_cylinder(-1.0f, 1.0f, 8, true), InputError);
  EXPECT_THROW(make_teapot(1), InputError);
}

}  // namespace
}  // namespace parashade
