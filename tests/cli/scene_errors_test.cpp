// Bad scene files and resolutions: exit 3, a message that names the file and the value at fault, and
// nothing written. Each scene is the good sphere scene with one thing wrong, so that a check that went
// missing would show as a successful render.
#include <ostream>
#include <regex>
#include <string>

#include <gtest/gtest.h>

#include "cli_fixture.hpp"

namespace parashade {
namespace {

using namespace testing_support;

// The sphere scene with `key`'s value replaced by `value` (the key must be at the top level).
std::string sphere_scene_with(const std::string& key, const std::string& value) {
  nlohmann::json scene = nlohmann::json::parse(sphere_scene());
  scene[key] = nlohmann::json::parse(value);
  return scene.dump(2);
}

using CliScene = CliTest;

// Issue 46, item 17: a light of colour 3e38 overflowed single-precision shading (255 x 3e38 is inf) and gave
// an all-black image, exit 0 and no word, where the reference is white. Too bright a light or material is
// refused naming it; a merely bright one (1000 times white) still renders.
TEST_F(CliScene, ALightTooBrightForSinglePrecisionIsRefused) {
  const std::string blinding = R"([{"type": "directional", "direction": [0, 0, -1], "color": [3e38, 3e38, 3e38]}])";
  EXPECT_TRUE(fails_with(render(input("blinding.json", sphere_scene_with("lights", blinding))), kBadInput,
                         {"blinding.json", "lights[0]", "3e+38"}));
  const std::string times = R"([{"type": "directional", "direction": [0, 0, -1], "color": [1, 1, 1], "intensity": 1e37}])";
  EXPECT_TRUE(fails_with(render(input("intense.json", sphere_scene_with("lights", times))), kBadInput,
                         {"intense.json", "lights[0]"}));
  const std::string material = R"({"default": {"kd": 1e38}})";
  EXPECT_TRUE(fails_with(render(input("material.json", sphere_scene_with("materials", material))), kBadInput,
                         {"material.json", "materials.default"}));
  EXPECT_TRUE(nothing_written());
  const std::string bright = R"([{"type": "directional", "direction": [0, 0, -1], "intensity": 1000}])";
  EXPECT_TRUE(succeeds(render(input("bright.json", sphere_scene_with("lights", bright)))));
}

TEST_F(CliScene, MissingFileIsNamed) {
  EXPECT_TRUE(fails_with(render(in_dir() / "absent.json"), kBadInput, {"absent.json"}));
  EXPECT_TRUE(nothing_written());
}

TEST_F(CliScene, DirectoryIsNotAScene) {
  std::filesystem::create_directories(in_dir() / "folder.json");
  EXPECT_TRUE(fails_with(render(in_dir() / "folder.json"), kBadInput, {"folder.json", "directory"}));
  EXPECT_TRUE(nothing_written());
}

TEST_F(CliScene, UnknownExtensionIsNamed) {
  const auto scene = input("ball.yaml", sphere_scene());
  EXPECT_TRUE(fails_with(render(scene), kBadInput, {"ball.yaml", ".yaml"}));
  EXPECT_TRUE(nothing_written());
}

TEST_F(CliScene, EmptyFile) {
  EXPECT_TRUE(fails_with(render(input("empty.json", "")), kBadInput, {"empty.json"}));
  EXPECT_TRUE(nothing_written());
}

// The text stops inside the objects array on line 3; the message says where it ended.
TEST_F(CliScene, TruncatedJsonGivesThePosition) {
  const auto scene =
      input("cut.json", "{\"resolution\": [64, 48],\n \"cull_backfaces\": true,\n \"objects\": [{\"shape\": ");
  const RunResult r = render(scene);
  EXPECT_TRUE(fails_with(r, kBadInput, {"cut.json", "line 3"}));
  EXPECT_TRUE(std::regex_search(r.err, std::regex(R"(line 3, column \d+)"))) << r;
  EXPECT_TRUE(nothing_written());
}

// Line 2 closes the array with '}'.
TEST_F(CliScene, SyntaxErrorGivesThePosition) {
  const auto scene = input("typo.json", "{\"resolution\": [64, 48],\n \"objects\": [{\"shape\": \"sphere\"} }\n");
  const RunResult r = render(scene);
  EXPECT_TRUE(fails_with(r, kBadInput, {"typo.json", "line 2"}));
  EXPECT_TRUE(std::regex_search(r.err, std::regex(R"(line 2, column \d+)"))) << r;
  EXPECT_TRUE(nothing_written());
}

TEST_F(CliScene, TopLevelArrayIsRefused) {
  EXPECT_TRUE(fails_with(render(input("list.json", "[" + sphere_scene() + "]")), kBadInput, {"list.json", "object"}));
  EXPECT_TRUE(nothing_written());
}

TEST_F(CliScene, UnknownKeyIsNamed) {
  const auto scene = input("extra.json", sphere_scene_with("backgorund", "[0, 0, 0]"));
  EXPECT_TRUE(fails_with(render(scene), kBadInput, {"extra.json", "backgorund", "unknown key"}));
  EXPECT_TRUE(nothing_written());
}

TEST_F(CliScene, UnknownNestedKeyIsNamedWithItsPath) {
  const auto scene = input("nested.json", sphere_scene_with("camera", R"({"position": [0, 0, 4], "fvo": 40})"));
  EXPECT_TRUE(fails_with(render(scene), kBadInput, {"nested.json", "camera.fvo"}));
  EXPECT_TRUE(nothing_written());
}

TEST_F(CliScene, KeyGivenTwiceIsNamed) {
  const auto scene = input("twice.json", R"({"resolution": [64, 48], "resolution": [32, 24],
                                             "objects": [{"shape": "sphere"}]})");
  EXPECT_TRUE(fails_with(render(scene), kBadInput, {"twice.json", "resolution"}));
  EXPECT_TRUE(nothing_written());
}

TEST_F(CliScene, ObjectsAreRequired) {
  const auto scene = input("empty_world.json", R"({"resolution": [64, 48]})");
  EXPECT_TRUE(fails_with(render(scene), kBadInput, {"empty_world.json", "objects"}));
  EXPECT_TRUE(nothing_written());
}

TEST_F(CliScene, UnknownMaterialIsNamed) {
  const auto scene =
      input("paint.json", sphere_scene_with("objects", R"([{"shape": "sphere", "material": "chrome"}])"));
  EXPECT_TRUE(fails_with(render(scene), kBadInput, {"paint.json", "chrome"}));
  EXPECT_TRUE(nothing_written());
}

// A finite double that is infinite as a float (scenes are float) would reach the renderer as inf.
TEST_F(CliScene, NumberBeyondFloatRangeIsNamed) {
  const auto scene = input("huge.json", sphere_scene_with(
                                            "objects", R"([{"shape": "sphere", "transform": {"scale": 1e300}}])"));
  EXPECT_TRUE(fails_with(render(scene), kBadInput, {"huge.json", "objects[0].transform.scale"}));
  EXPECT_TRUE(nothing_written());
}

// A number beyond double range fails in the JSON parser itself (found by fuzzing: it escaped as an
// internal error, exit 1).
TEST_F(CliScene, NumberBeyondDoubleRangeIsBadInput) {
  const auto scene = input("overflow.json", R"({"objects": [{"shape": "sphere", "transform": {"scale": 4e999}}]})");
  EXPECT_TRUE(fails_with(render(scene), kBadInput, {"overflow.json", "invalid JSON", "4e999"}));
  EXPECT_TRUE(nothing_written());
}

// One wrong type per case: the key (and where it is) must be in the message.
struct WrongType {
  const char* key;
  const char* value;
  const char* named;  // the path the message must give
};

void PrintTo(const WrongType& w, std::ostream* os) { *os << '"' << w.key << "\": " << w.value; }

class CliWrongType : public CliTest, public ::testing::WithParamInterface<WrongType> {};

TEST_P(CliWrongType, IsNamedWithItsPath) {
  const WrongType& w = GetParam();
  const auto scene = input("types.json", sphere_scene_with(w.key, w.value));
  EXPECT_TRUE(fails_with(render(scene), kBadInput, {"types.json", w.named}));
  EXPECT_TRUE(nothing_written());
}

INSTANTIATE_TEST_SUITE_P(
    Cli, CliWrongType,
    ::testing::Values(WrongType{"resolution", R"("64x48")", "resolution"},
                      WrongType{"resolution", "[64.5, 48]", "resolution[0]"},
                      WrongType{"resolution", "[64]", "resolution"},
                      WrongType{"background", R"("blue")", "background"},
                      WrongType{"background", R"([0.2, "0.4", 0.6])", "background[1]"},
                      WrongType{"camera", R"({"position": [0, 0, 4], "fov": "wide"})", "camera.fov"},
                      WrongType{"cull_backfaces", "1", "cull_backfaces"},
                      WrongType{"lights", R"({"type": "point"})", "lights"},
                      WrongType{"lights", R"([{"type": "directional", "direction": [0, 0, -1], "intensity": "high"}])",
                                "lights[0].intensity"},
                      WrongType{"objects", R"([{"shape": {"type": "sphere", "slices": "many"}}])",
                                "objects[0].shape.slices"},
                      WrongType{"name", "42", "name"}),
    [](const ::testing::TestParamInfo<WrongType>& info) {
      return name_from(info.param.named) + "_" + std::to_string(info.index);
    });

// The 12-bit screen addresses of the sources: at most 4096 in each direction.
TEST_F(CliScene, SceneResolutionBeyond4096IsNamed) {
  for (const char* resolution : {"[4097, 48]", "[64, 4097]", "[0, 48]"}) {
    SCOPED_TRACE(resolution);
    const auto scene = input("big.json", sphere_scene_with("resolution", resolution));
    EXPECT_TRUE(fails_with(render(scene), kBadInput, {"big.json", "resolution"}));
    EXPECT_TRUE(nothing_written());
  }
}

// A --size out of range is a usage error like a malformed one (--size 640x48O), unlike the same resolution
// in a scene file (bad input, above): the command line is at fault, whatever the scene holds. (It was exit 3.)
TEST_F(CliScene, SizeBeyond4096IsNamed) {
  const auto scene = input("ball.json", sphere_scene());
  for (const char* size : {"4097x48", "64x4097", "0x48", "64x0"}) {
    SCOPED_TRACE(size);
    EXPECT_TRUE(fails_with(render(scene, {"--size", size}), kUsage, {"--size", size}));
    EXPECT_TRUE(nothing_written());
  }
}

}  // namespace
}  // namespace parashade
