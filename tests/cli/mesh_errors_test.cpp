// Bad mesh files, given directly or through a scene: exit 3, the file (and where known, the line) named,
// nothing written. Each OBJ is a good tetrahedron with one thing wrong.
#include <ostream>
#include <string>

#include <gtest/gtest.h>

#include "cli_fixture.hpp"

namespace parashade {
namespace {

using namespace testing_support;

struct BadObj {
  const char* test_name;
  const char* text;
  const char* named;  // besides the file name: the line and value the message must give
};

void PrintTo(const BadObj& b, std::ostream* os) { *os << b.test_name; }

class CliBadObj : public CliTest, public ::testing::WithParamInterface<BadObj> {};

TEST_P(CliBadObj, IsRefusedNamingFileAndFault) {
  const BadObj& b = GetParam();
  const auto mesh = input(std::string(b.test_name) + ".obj", b.text);
  EXPECT_TRUE(fails_with(render(mesh, {"--size", "64x48"}), kBadInput, {mesh.filename().string(), b.named}));
  EXPECT_TRUE(nothing_written());
}

constexpr const char* kTetraVertices = "v 1 1 1\nv 1 -1 -1\nv -1 1 -1\nv -1 -1 1\n";

INSTANTIATE_TEST_SUITE_P(
    Cli, CliBadObj,
    ::testing::Values(
        BadObj{"index_past_the_end", "v 1 1 1\nv 1 -1 -1\nv -1 1 -1\nv -1 -1 1\nf 1 2 3\nf 1 4 5\n", ":6:"},
        BadObj{"index_zero", "v 1 1 1\nv 1 -1 -1\nv -1 1 -1\nv -1 -1 1\nf 0 1 2\n", ":5:"},
        BadObj{"negative_index_before_start", "v 1 1 1\nv 1 -1 -1\nv -1 1 -1\nf -4 -2 -1\n", ":4:"},
        BadObj{"index_not_a_number", "v 1 1 1\nv 1 -1 -1\nv -1 1 -1\nf 1 two 3\n", "two"},
        BadObj{"two_vertex_face", "v 1 1 1\nv 1 -1 -1\nv -1 1 -1\nv -1 -1 1\nf 1 2 3\nf 1 4\n", ":6:"},
        BadObj{"one_vertex_face", "v 1 1 1\nv 1 -1 -1\nv -1 1 -1\nf 1 2 3\nf 3\n", ":5:"},
        // The file ends in the middle of a record: a face cut after two corners, a vertex after two numbers.
        BadObj{"truncated_in_a_face", "v 1 1 1\nv 1 -1 -1\nv -1 1 -1\nv -1 -1 1\nf 1 2 3\nf 1 4 2\nf 1 3", ":7:"},
        BadObj{"truncated_in_a_vertex", "v 1 1 1\nv 1 -1 -1\nv -1 1 -1\nv -1 -1", ":4:"},
        BadObj{"nan_coordinate", "v 1 1 1\nv 1 nan -1\nv -1 1 -1\nf 1 2 3\n", "nan"},
        BadObj{"inf_coordinate", "v 1 1 1\nv 1 -1 -1\nv -1 1 inf\nf 1 2 3\n", "inf"},
        BadObj{"minus_inf_coordinate", "v -inf 1 1\nv 1 -1 -1\nv -1 1 -1\nf 1 2 3\n", "inf"},
        BadObj{"nan_normal", "v 1 1 1\nv 1 -1 -1\nv -1 1 -1\nvn 0 0 nan\nf 1//1 2//1 3//1\n", ":4:"},
        BadObj{"overflowing_coordinate", "v 1 1 1\nv 1e999 -1 -1\nv -1 1 -1\nf 1 2 3\n", ":2:"},
        // Empty meshes: nothing at all, vertices without faces, only a comment.
        BadObj{"empty_file", "", "empty"},
        BadObj{"no_faces", "v 1 1 1\nv 1 -1 -1\nv -1 1 -1\nv -1 -1 1\n", "no faces"},
        BadObj{"only_a_comment", "# nothing here\n", "no faces"}),
    [](const ::testing::TestParamInfo<BadObj>& info) { return std::string(info.param.test_name); });

using CliMesh = CliTest;

// Through a scene the message gives the scene, the key that names the mesh, and the mesh's own fault.
TEST_F(CliMesh, BadMeshInASceneIsNamedWithTheScene) {
  input("broken.obj", std::string(kTetraVertices) + "f 1 2 9\n");
  const auto scene = input("uses_mesh.json", R"({"resolution": [64, 48], "objects": [{"mesh": "broken.obj"}]})");
  EXPECT_TRUE(fails_with(render(scene), kBadInput, {"uses_mesh.json", "objects[0].mesh", "broken.obj:5:"}));
  EXPECT_TRUE(nothing_written());
}

TEST_F(CliMesh, MissingMeshInASceneIsNamed) {
  const auto scene = input("uses_mesh.json", R"({"resolution": [64, 48], "objects": [{"mesh": "absent.obj"}]})");
  EXPECT_TRUE(fails_with(render(scene), kBadInput, {"uses_mesh.json", "absent.obj"}));
  EXPECT_TRUE(nothing_written());
}

TEST_F(CliMesh, MissingMeshFileIsNamed) {
  EXPECT_TRUE(fails_with(render(in_dir() / "absent.obj"), kBadInput, {"absent.obj"}));
  EXPECT_TRUE(nothing_written());
}

// Issue 46, item 17: a mesh whose vertices all coincide has nothing to frame or draw. A tiny one was refused
// (too small to frame), this one rendered an empty image without a word.
TEST_F(CliMesh, AMeshOfOnePointIsRefused) {
  const auto mesh = input("point.obj", "v 1 2 3\nv 1 2 3\nv 1 2 3\nv 1 2 3\nf 1 2 3\nf 1 3 4\n");
  EXPECT_TRUE(fails_with(render(mesh, {"--size", "64x48"}), kBadInput, {"point.obj", "one point"}));
  EXPECT_TRUE(nothing_written());
}

// In a scene such a mesh is one object among others; a frame where nothing reaches the screen says so.
TEST_F(CliMesh, AFrameWhereEveryTriangleVanishesBeforeTheScreenIsWarned) {
  input("point.obj", "v 0 0 0\nv 0 0 0\nv 0 0 0\nf 1 2 3\n");
  const auto scene = input("point.json", R"({"resolution": [64, 48], "objects": [{"mesh": "point.obj"}]})");
  const RunResult r = render(scene);
  ASSERT_TRUE(succeeds(r));
  EXPECT_NE(r.err.find("warning: nothing drawn: none of the 1 triangles reached the screen (1 of zero area"),
            std::string::npos) << r;
}

// An OFF whose header promises more faces than follow: OpenMesh alone would repeat the last one.
TEST_F(CliMesh, TruncatedOffIsNamed) {
  const auto mesh = input("cut.off", "OFF\n4 4 0\n1 1 1\n1 -1 -1\n-1 1 -1\n-1 -1 1\n3 0 1 2\n3 0 3 1\n");
  EXPECT_TRUE(fails_with(render(mesh, {"--size", "64x48"}), kBadInput, {"cut.off", "2 of 4 faces"}));
  EXPECT_TRUE(nothing_written());
}

}  // namespace
}  // namespace parashade
