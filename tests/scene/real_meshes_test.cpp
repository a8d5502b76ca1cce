// The shared test meshes (PARASHADE_MESH_DIR): counts as the files have them, usable normals.
#include <gtest/gtest.h>

#include "mesh_checks.hpp"
#include "parashade/mesh.hpp"
#include "test_support.hpp"

namespace parashade {
namespace {

using namespace testing_support;

struct RealMesh {
  const char* file;
  std::size_t faces, triangles, polygons;
  bool normals_from_file;
};

void PrintTo(const RealMesh& m, std::ostream* os) { *os << m.file; }

class RealMeshTest : public ::testing::TestWithParam<RealMesh> {};

TEST_P(RealMeshTest, LoadsWithTheFilesCounts) {
  PARASHADE_REQUIRE_MESH_DIR(dir);
  const RealMesh& expected = GetParam();
  MeshLoadStats stats;
  const Mesh m = load_mesh(dir / expected.file, &stats);
  EXPECT_EQ(stats.faces_read, expected.faces);
  EXPECT_EQ(m.triangles.size(), expected.triangles);
  EXPECT_EQ(stats.polygons_triangulated, expected.polygons);
  EXPECT_EQ(stats.faces_dropped, 0u);
  EXPECT_EQ(stats.non_manifold_faces, 0u);
  EXPECT_EQ(stats.normals_from_file, expected.normals_from_file);
  EXPECT_EQ(stats.normals_recomputed, 0u);
  EXPECT_EQ(bad_normals(m), 0u);
  EXPECT_NO_THROW(validate_mesh(m, expected.file));
  // Smooth vertex normals agree with the winding of most faces (sharp features aside: suzanne, coarse,
  // disagrees on 3%); a flipped orientation or corners mixed up by the loader would disagree on most.
  EXPECT_LT(winding_disagreements(m), m.triangles.size() / 10) << expected.file;
}

// suzanne.obj: 468 quads and 32 triangles (the meshes README says 500 quads), normals from Blender.
INSTANTIATE_TEST_SUITE_P(Files, RealMeshTest,
                         ::testing::Values(RealMesh{"suzanne.obj", 500, 968, 468, true},
                                           RealMesh{"teapot.obj", 6320, 6320, 0, false},
                                           RealMesh{"stanford-bunny.obj", 69451, 69451, 0, false},
                                           RealMesh{"fandisk.obj", 12946, 12946, 0, false}),
                         [](const auto& info) {
                           std::string n = info.param.file;
                           return n.substr(0, n.find_first_of(".-"));
                         });

TEST(RealMeshes, FandiskIsClosedAndTheBunnyHasHoles) {
  PARASHADE_REQUIRE_MESH_DIR(dir);
  EXPECT_TRUE(closed(edge_report(load_mesh(dir / "fandisk.obj"))));
  const EdgeReport bunny = edge_report(load_mesh(dir / "stanford-bunny.obj"));
  EXPECT_GT(bunny.boundary, 0u);  // the scan's holes in its base (scenes/README.md)
  EXPECT_EQ(bunny.same_direction, 0u);
}

}  // namespace
}  // namespace parashade
