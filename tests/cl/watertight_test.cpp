// Watertightness of the kernels' coverage on closed meshes under random rotations: count per pixel
// how many front faces (F) and how many back faces (B) cover it (B by flipping every triangle's
// winding, which turns back faces into front faces). A ray through a closed surface enters it as
// often as it leaves it, so F == B at every pixel; a hole or a doubly covered shared edge breaks that
// at the pixel. For a convex mesh, additionally F <= 1: every covered pixel is hit exactly once.
#include <random>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <gtest/gtest.h>

#include "cl_fixture.hpp"
#include "parashade/mesh.hpp"
#include "parashade/renderer.hpp"
#include "parashade/shapes.hpp"
#include "test_support.hpp"

namespace parashade {
namespace {

using namespace testing_support;

Mesh flipped(const Mesh& m) {
  Mesh f = m;
  for (auto& t : f.triangles) std::swap(t[1], t[2]);
  for (auto& n : f.normals) n = -n;
  return f;
}

// A uniformly random rotation (Shoemake) and a sub-pixel-scale random shift.
glm::mat4 random_pose(std::mt19937& rng, float scale) {
  std::uniform_real_distribution<float> u(0.0f, 1.0f), shift(-0.05f, 0.05f);
  const float u1 = u(rng), u2 = 6.2831853f * u(rng), u3 = 6.2831853f * u(rng);
  const glm::quat q(std::sqrt(u1) * std::cos(u3), std::sqrt(1 - u1) * std::sin(u2), std::sqrt(1 - u1) * std::cos(u2),
                    std::sqrt(u1) * std::sin(u3));
  const glm::mat4 t = glm::translate(glm::mat4(1.0f), glm::vec3(shift(rng), shift(rng), shift(rng)));
  return t * glm::mat4_cast(q) * glm::scale(glm::mat4(1.0f), glm::vec3(scale));
}

Scene camera_scene() {
  Scene s = pixel_scene(160, 120);
  set_perspective(s.camera, {0.0f, 0.0f, 4.0f}, {0.0f, 0.0f, 0.0f}, 40.0f, 0.5f, 20.0f);
  s.cull_backfaces = true;
  return s;
}

struct Result {
  std::size_t covered = 0, unbalanced = 0, overdrawn = 0;
};

// Runs `poses` random poses of `mesh` (normalized to a radius of about `radius`) and accumulates.
Result check_closed_mesh(const Mesh& mesh, float scale, int poses, unsigned seed, int tile) {
  auto front = std::make_shared<Mesh>(mesh);
  auto back = std::make_shared<Mesh>(flipped(mesh));
  Renderer renderer(test_device(), render_options(Method::flat, false, tile));
  std::mt19937 rng(seed);
  Result r;
  for (int i = 0; i < poses; ++i) {
    const glm::mat4 pose = random_pose(rng, scale);
    Scene f = camera_scene(), b = camera_scene();
    add_object(f, front, pose);
    add_object(b, back, pose);
    const std::vector<std::uint32_t> fc = renderer.coverage_counts(f);
    const std::vector<std::uint32_t> bc = renderer.coverage_counts(b);
    for (std::size_t p = 0; p < fc.size(); ++p) {
      r.covered += fc[p] > 0;
      r.unbalanced += fc[p] != bc[p];
      r.overdrawn += fc[p] > 1;
    }
  }
  return r;
}

constexpr int kPoses = 200;

TEST(Watertight, ConvexSphereIsCoveredExactlyOnce) {
  const Result r = check_closed_mesh(make_sphere(24, 13), 1.3f, kPoses, 11, 16);
  EXPECT_GT(r.covered, std::size_t(kPoses) * 5000) << "the sphere should fill a good part of the frame";
  EXPECT_EQ(r.unbalanced, 0u) << "pixels where front and back coverage differ (holes or double hits)";
  EXPECT_EQ(r.overdrawn, 0u) << "pixels of a convex mesh covered by more than one front face";
}

TEST(Watertight, ConvexBoxAndCappedCylinderAreCoveredExactlyOnce) {
  Result box = check_closed_mesh(make_box({1.4f, 0.9f, 1.1f}), 1.0f, kPoses, 12, 32);
  Result cyl = check_closed_mesh(make_cylinder(0.8f, 1.5f, 17, true), 1.0f, kPoses, 13, 16);
  for (const Result& r : {box, cyl}) {
    EXPECT_GT(r.covered, std::size_t(kPoses) * 2000);
    EXPECT_EQ(r.unbalanced, 0u);
    EXPECT_EQ(r.overdrawn, 0u);
  }
}

TEST(Watertight, TorusFrontAndBackCoverageBalance) {
  // Not convex: a pixel may see the torus twice, but never a hole or a doubly hit edge.
  const Result r = check_closed_mesh(make_torus(1.0f, 0.4f, 40, 16), 1.1f, kPoses, 14, 16);
  EXPECT_GT(r.covered, std::size_t(kPoses) * 3000);
  EXPECT_GT(r.overdrawn, 0u) << "some poses should show the torus overlapping itself";
  EXPECT_EQ(r.unbalanced, 0u);
}

TEST(Watertight, FandiskFromMeshDirectory) {
  PARASHADE_REQUIRE_MESH_DIR(dir);
  Mesh m = load_mesh(dir / "fandisk.obj");
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (const auto& p : m.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
  const glm::vec3 c = 0.5f * (lo + hi);
  for (auto& p : m.positions) p -= c;
  const Result r = check_closed_mesh(m, 2.4f / glm::length(hi - lo), 50, 15, 16);
  EXPECT_GT(r.covered, 50u * 2000);
  EXPECT_EQ(r.unbalanced, 0u);
}

}  // namespace
}  // namespace parashade
