// Scene and mesh files that exist but cannot be read (mode 000): exit 3 naming the file. Root reads
// them anyway, so there the tests skip.
#include <fstream>

#include <gtest/gtest.h>

#include "cli_fixture.hpp"

namespace parashade {
namespace {

using namespace testing_support;

class CliUnreadable : public CliTest {
 protected:
  // Takes every permission away; false when this user can still open the file.
  static bool make_unreadable(const std::filesystem::path& file) {
    std::filesystem::permissions(file, std::filesystem::perms::none);
    return !std::ifstream(file);
  }
};

TEST_F(CliUnreadable, SceneFile) {
  const auto scene = input("locked.json", sphere_scene());
  if (!make_unreadable(scene)) GTEST_SKIP() << "a mode 000 file is readable for this user (root?)";
  EXPECT_TRUE(fails_with(render(scene), kBadInput, {"locked.json"}));
  EXPECT_TRUE(nothing_written());
}

TEST_F(CliUnreadable, MeshFile) {
  const auto mesh = input("locked.obj", tetrahedron_obj());
  if (!make_unreadable(mesh)) GTEST_SKIP() << "a mode 000 file is readable for this user (root?)";
  EXPECT_TRUE(fails_with(render(mesh, {"--size", "64x48"}), kBadInput, {"locked.obj"}));
  EXPECT_TRUE(nothing_written());
}

TEST_F(CliUnreadable, MeshFileOfAScene) {
  const auto mesh = input("locked.obj", tetrahedron_obj());
  const auto scene = input("uses_mesh.json", R"({"resolution": [64, 48], "objects": [{"mesh": "locked.obj"}]})");
  if (!make_unreadable(mesh)) GTEST_SKIP() << "a mode 000 file is readable for this user (root?)";
  EXPECT_TRUE(fails_with(render(scene), kBadInput, {"uses_mesh.json", "locked.obj"}));
  EXPECT_TRUE(nothing_written());
}

}  // namespace
}  // namespace parashade
