// The Bezier teapot: counts, seams, orientation, normals and extent.
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>

#include "mesh_checks.hpp"
#include "parashade/shapes.hpp"

namespace parashade {
namespace {

using namespace testing_support;

class TeapotTest : public ::testing::TestWithParam<int> {};

TEST_P(TeapotTest, CountAndNoZeroAreaTriangles) {
  const int level = GetParam();
  const Mesh m = make_teapot(level);
  // 32 patches of 2*level^2 triangles, less one per grid cell on the two collapsed rows (lid tip, bottom
  // centre) of 4 patches each.
  EXPECT_EQ(m.triangles.size(), std::size_t(64 * level * level - 8 * level));
  EXPECT_EQ(zero_area_triangles(m), 0u);
  EXPECT_EQ(bad_normals(m), 0u);
}

TEST_P(TeapotTest, SeamsWeldedWithConsistentWinding) {
  const int level = GetParam();
  const EdgeReport r = edge_report(make_teapot(level));
  EXPECT_EQ(r.same_direction, 0u);  // neighbouring patches agree on orientation
  EXPECT_EQ(r.overused, 0u);
  // What stays open is what Newell's data leaves open, one edge per grid step: the lid's lower edge
  // and the rim's inner edge (4 patches each), the spout's two ends and the handle's two ends (2 each).
  EXPECT_EQ(r.boundary, std::size_t(16 * level));
}

INSTANTIATE_TEST_SUITE_P(Levels, TeapotTest, ::testing::Values(2, 3, 6, 10));

TEST(Teapot, VertexNormalsAgreeWithWindingFromLevel6) {
  // Coarser grids fold a few triangles against the true surface normal near the knob and spout tip.
  for (int level : {6, 10, 16}) EXPECT_EQ(winding_disagreements(make_teapot(level)), 0u) << "level " << level;
}

TEST(Teapot, BoundingBoxIsNewellsYUp) {
  const Mesh m = make_teapot(10);
  glm::vec3 lo(1e9f), hi(-1e9f);
  for (const glm::vec3& p : m.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
  EXPECT_NEAR(lo.x, -3.0f, 1e-4f);   // handle
  EXPECT_NEAR(hi.x, 3.434f, 0.01f);  // spout tip (below its control point at 3.525)
  EXPECT_NEAR(lo.y, 0.0f, 1e-6f);    // base
  EXPECT_NEAR(hi.y, 3.15f, 1e-5f);   // knob
  EXPECT_NEAR(lo.z, -2.0f, 1e-4f);
  EXPECT_NEAR(hi.z, 2.0f, 1e-4f);
}

// At the vertex farthest along a direction the outward normal points that way (if the surface is smooth
// there): one check per patch group that could be flipped.
std::size_t extreme(const Mesh& m, glm::vec3 dir, const std::function<bool(glm::vec3)>& in = nullptr) {
  std::size_t best = m.positions.size();
  for (std::size_t i = 0; i < m.positions.size(); ++i)
    if (!in || in(m.positions[i]))
      if (best == m.positions.size() || glm::dot(m.positions[i], dir) > glm::dot(m.positions[best], dir)) best = i;
  return best;
}

TEST(Teapot, NormalsPointOutward) {
  const Mesh m = make_teapot(10);
  const glm::vec3 x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);  // y up
  EXPECT_GT(m.normals[extreme(m, y)].y, 0.99f);    // knob top (a collapsed patch row)
  EXPECT_LT(m.normals[extreme(m, -y)].y, -0.99f);  // bottom centre (a collapsed patch row)
  EXPECT_GT(m.normals[extreme(m, z)].z, 0.99f);    // body
  EXPECT_LT(m.normals[extreme(m, -z)].z, -0.99f);  // body
  EXPECT_LT(m.normals[extreme(m, -x)].x, -0.99f);  // handle
  const auto spout = [](glm::vec3 p) { return p.x > 2.2f; };  // beyond the body's radius 2
  EXPECT_GT(m.normals[extreme(m, z, spout)].z, 0.95f);
  EXPECT_LT(m.normals[extreme(m, -z, spout)].z, -0.95f);
  // The lid, rim and body patches are each tied to one of these by welded seams, whose consistent
  // winding SeamsWeldedWithConsistentWinding checks.
}

TEST(Teapot, CollapsedRowsGetTheAxisNormal) {
  const Mesh m = make_teapot(8);
  std::size_t on_axis = 0;
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    const glm::vec3 p = m.positions[i];
    if (p.x == 0.0f && p.z == 0.0f) {
      ++on_axis;
      EXPECT_GT(std::abs(m.normals[i].y), 0.99999f) << "y " << p.y;
    }
  }
  EXPECT_EQ(on_axis, 2u);  // knob top and bottom centre, each welded from the 4 patches meeting there
}

}  // namespace
}  // namespace parashade
