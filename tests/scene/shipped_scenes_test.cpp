// The scene files in scenes/: each loads, is framed by its camera, and has what scenes/README.md says.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "framing.hpp"
#include "parashade/scene.hpp"
#include "temp_dir.hpp"
#include "test_support.hpp"

namespace parashade {
namespace {

using namespace testing_support;

struct Shipped {
  const char* file;
  std::size_t triangles;
  int width, height;
  bool cull_backfaces;
  bool needs_mesh_dir;
};

void PrintTo(const Shipped& s, std::ostream* os) { *os << s.file; }

const Shipped kShipped[] = {
    {"sphere.json", 8192, 1920, 1080, true, false},  {"teapot.json", 6320, 1920, 1080, false, false},
    {"robot.json", 17608, 1920, 1080, true, false},  {"default.json", 10188, 1280, 720, false, false},
    {"bunny.json", 69451, 1920, 1080, true, true},   {"fandisk.json", 12946, 1920, 1080, true, true},
};

class ShippedScene : public ::testing::TestWithParam<Shipped> {
 protected:
  Scene load() {
    return load_scene(source_dir() / "scenes" / GetParam().file);
  }
};

TEST_P(ShippedScene, LoadsWithItsDocumentedSettings) {
  if (GetParam().needs_mesh_dir) {
    PARASHADE_REQUIRE_MESH_DIR(dir);
  }
  const Scene s = load();
  EXPECT_EQ(s.triangle_count(), GetParam().triangles);
  EXPECT_EQ(s.width, GetParam().width);
  EXPECT_EQ(s.height, GetParam().height);
  EXPECT_EQ(s.cull_backfaces, GetParam().cull_backfaces);
  EXPECT_FALSE(s.lights.empty());
  for (const Object& o : s.objects) EXPECT_LT(o.material, s.materials.size()) << o.name;
}

TEST_P(ShippedScene, CameraFramesEveryVertexAndFillsTheFrame) {
  if (GetParam().needs_mesh_dir) {
    PARASHADE_REQUIRE_MESH_DIR(dir);
  }
  const Framing f = framing(load());
  EXPECT_EQ(f.outside, 0u) << "of " << f.vertices;
  EXPECT_GE(f.height_fraction(), 0.5f) << "projected box " << f.lo.x << "," << f.lo.y << " .. " << f.hi.x << "," << f.hi.y;
}

INSTANTIATE_TEST_SUITE_P(Scenes, ShippedScene, ::testing::ValuesIn(kShipped), [](const auto& info) {
  std::string n = info.param.file;
  return n.substr(0, n.find('.'));
});

TEST(ShippedScenes, EveryJsonFileInScenesIsCovered) {
  std::set<std::string> listed;
  for (const Shipped& s : kShipped) listed.insert(s.file);
  for (const auto& entry : std::filesystem::directory_iterator(source_dir() / "scenes"))
    if (entry.path().extension() == ".json") {
      EXPECT_TRUE(listed.count(entry.path().filename().string())) << entry.path();
    }
}

TEST(ShippedScenes, SphereHasTheSourcesTriangleCountAndBothLightKinds) {
  const Scene s = load_scene(source_dir() / "scenes" / "sphere.json");
  ASSERT_EQ(s.objects.size(), 1u);
  EXPECT_EQ(s.objects[0].mesh->triangles.size(), 8192u);
  std::set<LightType> kinds;
  for (const Light& l : s.lights) kinds.insert(l.type);
  EXPECT_EQ(kinds, (std::set<LightType>{LightType::directional, LightType::point}));
}

TEST(ShippedScenes, RobotSharesMeshesBetweenEqualParts) {
  const Scene s = load_scene(source_dir() / "scenes" / "robot.json");
  EXPECT_GE(s.objects.size(), 20u);
  EXPECT_GE(s.materials.size(), 4u);
  std::map<std::string, const Mesh*> by_name;
  for (const Object& o : s.objects) by_name[o.name] = o.mesh.get();
  std::size_t pairs = 0;
  for (const auto& [name, mesh] : by_name)
    if (name.rfind("left ", 0) == 0) {
      ++pairs;
      ASSERT_TRUE(by_name.count("right " + name.substr(5))) << name;
      EXPECT_EQ(mesh, by_name["right " + name.substr(5)]) << name;
    }
  EXPECT_GE(pairs, 8u);
  EXPECT_EQ(by_name["left knee"], by_name["left shoulder"]);  // scaled copies of one sphere
}

// The example in scenes/README.md is a scene that loads.
TEST(ShippedScenes, ReadmeExampleLoads) {
  std::ifstream in(source_dir() / "scenes" / "README.md");
  ASSERT_TRUE(in);
  std::stringstream text;
  text << in.rdbuf();
  const std::string md = text.str();
  const std::size_t begin = md.find("```json\n");
  ASSERT_NE(begin, std::string::npos);
  const std::size_t end = md.find("```", begin + 8);
  ASSERT_NE(end, std::string::npos);
  TempDir dir;
  const Scene s = load_scene(dir.write("example.json", md.substr(begin + 8, end - begin - 8)));
  EXPECT_GT(s.triangle_count(), 0u);
  EXPECT_EQ(framing(s).outside, 0u);
}

}  // namespace
}  // namespace parashade
