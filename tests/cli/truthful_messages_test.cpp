// Messages that tell the truth (issue 17, item 16): each case used to print a message that named the
// wrong cause (or a stray compiler line came first); now the message says what is wrong, with the exit
// code of its kind.
#include <array>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli_fixture.hpp"

namespace parashade {
namespace {

using namespace testing_support;

using CliTruthfulMessages = CliTest;

// A binary STL: 80-byte header, `count` as written in the file, then the facets given.
std::string binary_stl(std::uint32_t count, const std::vector<std::array<float, 9>>& facets) {
  std::string s(80, ' ');
  s.replace(0, 6, "binary");
  s.append(reinterpret_cast<const char*>(&count), 4);
  for (const auto& f : facets) {
    const float normal[3] = {0, 0, 1};
    s.append(reinterpret_cast<const char*>(normal), sizeof normal);
    s.append(reinterpret_cast<const char*>(f.data()), sizeof(float) * 9);
    s.append(2, '\0');
  }
  return s;
}

TEST_F(CliTruthfulMessages, BinaryStlWithAWrongCountSaysSo) {
  const auto mesh = input("count.stl", binary_stl(5, {{0, 0, 0, 1, 0, 0, 0, 1, 0}}));
  EXPECT_TRUE(fails_with(render(mesh), kBadInput, {"count.stl", "header says 5 facets", "134 bytes"}));
}

TEST_F(CliTruthfulMessages, BinaryStlWithANanVertexNamesIt) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const auto mesh = input("nan.stl", binary_stl(2, {{0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 0, 0, 1, nan, 0, 0, 1, 0}}));
  EXPECT_TRUE(fails_with(render(mesh), kBadInput, {"nan.stl", "facet 1, vertex 1", "NaN"}));
}

TEST_F(CliTruthfulMessages, SymbolicLinkLoopIsNotAMissingFile) {
  const auto a = in_dir() / "a.json", b = in_dir() / "b.json";
  std::filesystem::create_directories(in_dir());
  std::filesystem::create_symlink(b, a);
  std::filesystem::create_symlink(a, b);
  const RunResult r = render(a);
  EXPECT_TRUE(fails_with(r, kBadInput, {"a.json", "Too many levels of symbolic links"}));
  EXPECT_EQ(r.err.find("no such file"), std::string::npos) << r;
  // A mesh named by a scene, through a loop, likewise.
  std::filesystem::create_symlink(in_dir() / "m2.obj", in_dir() / "m1.obj");
  std::filesystem::create_symlink(in_dir() / "m1.obj", in_dir() / "m2.obj");
  const auto scene = input("s.json", R"({"objects": [{"mesh": "m1.obj"}]})");
  EXPECT_TRUE(fails_with(render(scene), kBadInput, {"m1.obj", "Too many levels of symbolic links"}));
}

TEST_F(CliTruthfulMessages, AFieldOfViewTooNarrowForFloatSaysSo) {
  const auto scene = input("fov.json", R"({"camera": {"fov": 1e-300}, "objects": [{"shape": "box"}]})");
  const RunResult r = render(scene);
  EXPECT_TRUE(fails_with(r, kBadInput, {"camera.fov", "too narrow", "1e-300"}));
  EXPECT_EQ(r.err.find("(0, 180)"), std::string::npos) << r;
}

TEST_F(CliTruthfulMessages, AHugeResolutionIsNamedWithTheResolutionLimit) {
  for (const char* value : {"4000000000", "-4000000000", "9223372036854775807"}) {
    const auto scene = input("res.json", std::string(R"({"resolution": [)") + value + R"(, 48], "objects": [{"shape": "box"}]})");
    const RunResult r = render(scene);
    EXPECT_TRUE(fails_with(r, kBadInput, {"resolution", "width"})) << value;
    EXPECT_NE(r.err.find(value[0] == '-' ? "must be at least 1" : "12-bit screen address limit 4096"), std::string::npos) << r;
    EXPECT_EQ(r.err.find("1000000000"), std::string::npos) << r;
  }
}

TEST_F(CliTruthfulMessages, HugeCoordinatesArePrintedShort) {
  const auto mesh = input("huge.obj", "v 1e38 0 0\nv 0 1e38 0\nv 0 0 1\nf 1 2 3\n");
  const RunResult r = render(mesh);
  EXPECT_TRUE(fails_with(r, kBadInput, {"huge.obj", "coordinates reach 1.41e+38", "1e18"}));
}

TEST_F(CliTruthfulMessages, AnUnusablePoclCacheDirIsNamed) {
  const auto file = input("plain-file", "not a folder");
  {
    const ScopedEnv cache("POCL_CACHE_DIR", (file / "cache").string());
    EXPECT_TRUE(fails_with(render(input("ball.json", sphere_scene())), kDeviceFailure,
                           {"POCL_CACHE_DIR", "plain-file", "is not a folder"}));
    EXPECT_TRUE(fails_with(run_parashade({"devices"}), kDeviceFailure, {"POCL_CACHE_DIR"}));
  }
  EXPECT_TRUE(nothing_written());
}

TEST_F(CliTruthfulMessages, TheCompilersOwnLinesGoIntoTheBuildError) {
  // PoCL's clang prints "1 error generated." to stderr itself; it used to come before parashade's message.
  const ScopedEnv fail("PARASHADE_FAIL_DEVICE", "pthread");
  const RunResult r = render(input("ball.json", sphere_scene()), {"--device", "pthread"});
  ASSERT_TRUE(fails_with(r, kDeviceFailure, {"CL_BUILD_PROGRAM_FAILURE"}));
  EXPECT_EQ(r.err.rfind("parashade: error: ", 0), 0u) << "something precedes the message:" << r;
}

}  // namespace
}  // namespace parashade
