// Issue 46, "Messages and exit codes": each failure names its cause, the file or the value, with the
// documented exit code (2 usage, 3 bad input, 4 device), and nothing a terminal would interpret is printed
// raw (standard_output_test.cpp). Every test here failed before its fix (the issue gives the old behaviour).
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli_fixture.hpp"

namespace parashade {
namespace {

using namespace testing_support;
namespace fs = std::filesystem;

class CliNamedCauses : public CliTest {
 protected:
  fs::path scene_ = input("ball.json", sphere_scene());
  fs::path picture_ = input("good.ppm", std::string("P6\n2 1\n255\n") + std::string(6, '\x40'));
};

// "cannot read X: " with nothing after the colon.
TEST_F(CliNamedCauses, ATruncatedImageSaysWhy) {
  const fs::path cut = input("cut.ppm", std::string("P6\n4 4\n255\n") + std::string(10, '\x40'));
  const RunResult r = run_parashade({"compare", picture_.string(), cut.string()});
  ASSERT_TRUE(fails_with(r, kBadInput, {"cut.ppm"}));
  EXPECT_EQ(r.err.find("cut.ppm: \n"), std::string::npos) << r;
  EXPECT_EQ(r.err.find(": \n"), std::string::npos) << r;
}

// A 99999 x 99999 header in a 30-byte file: "out of host memory", no file named.
TEST_F(CliNamedCauses, AnImageTooLargeForMemoryIsNamedWithItsSize) {
  const fs::path huge = input("huge.ppm", std::string("P6\n99999 99999\n255\n") + std::string(10, '\x40'));
  const RunResult r = run_parashade({"compare", huge.string(), picture_.string()}, {}, std::chrono::seconds(30));
  EXPECT_TRUE(fails_with(r, kBadInput, {"huge.ppm", "99999x99999"}));
}

TEST_F(CliNamedCauses, CompareFailMustBeALevelCount) {
  for (const char* value : {"-1", "-0.5", "nan", "256"})
    EXPECT_TRUE(fails_with(run_parashade({"compare", picture_.string(), picture_.string(), "--fail", value}), kUsage,
                           {"--fail"}))
        << value;
}

TEST_F(CliNamedCauses, TuneMaxErrorMustBeANumberOfLevels) {
  for (const char* value : {"nan", "inf", "-1"})
    EXPECT_TRUE(fails_with(run_parashade({"tune", scene_.string(), "--max-error", value, "--cache",
                                          (out_dir() / "c.json").string()}),
                           kUsage, {"--max-error"}))
        << value;
  EXPECT_TRUE(nothing_written());
}

// --keep-going with every device of the list failed: "every device of the list failed", naming none.
TEST_F(CliNamedCauses, KeepGoingWithEveryDeviceFailedNamesEach) {
  const ScopedEnv devices("POCL_DEVICES", "pthread basic");
  const RunResult listing = run_parashade({"devices", "--json"});
  const nlohmann::json list = nlohmann::json::parse(listing.out, nullptr, false);
  if (!list.is_array() || list.size() < 2) GTEST_SKIP() << "PoCL does not offer two devices:" << listing;
  // A substring of both names (they differ in the first word only): every build fails.
  const std::string first = list[0]["name"], second = list[1]["name"];
  const std::string common = first.substr(first.find('-'));
  ASSERT_NE(second.find(common), std::string::npos) << first << " / " << second;
  const ScopedEnv fail("PARASHADE_FAIL_DEVICE", common);
  const RunResult r = render(scene_, {"--device", "pthread,basic", "--keep-going"});
  EXPECT_TRUE(fails_with(r, kDeviceFailure, {first, second, "CL_BUILD_PROGRAM_FAILURE"}));
  EXPECT_TRUE(nothing_written());
}

// "directory 'a/file' does not exist" when a/file is a file.
TEST_F(CliNamedCauses, AnOutputUnderAFileSaysItIsNotAFolder) {
  const fs::path file = input("notes.txt", "a file");
  std::vector<std::string> args = render_args(scene_);
  for (const int at : {3, 5}) {
    std::vector<std::string> a = args;
    a[at] = (file / (at == 3 ? "x.png" : "x.json")).string();
    const RunResult r = run_parashade(a);
    EXPECT_TRUE(fails_with(r, kBadInput, {"notes.txt", "is not a folder"}));
    EXPECT_EQ(r.err.find("does not exist"), std::string::npos) << r;
  }
  EXPECT_TRUE(nothing_written());
}

// A missing output folder was found after the scene was loaded (18-26 s for a large scene); it is found
// first, here before the scene's missing mesh.
TEST_F(CliNamedCauses, AMissingOutputFolderIsFoundBeforeTheSceneIsLoaded) {
  const fs::path scene = input("meshy.json", R"({"objects": [{"mesh": "gone.obj"}]})");
  std::vector<std::string> args = render_args(scene);
  for (const int at : {3, 5}) {
    std::vector<std::string> a = args;
    a[at] = (out_dir() / "no-such-folder" / (at == 3 ? "x.png" : "x.json")).string();
    const RunResult r = run_parashade(a);
    EXPECT_TRUE(fails_with(r, kBadInput, {"no-such-folder", "does not exist"}));
    EXPECT_EQ(r.err.find("gone.obj"), std::string::npos) << r;
  }
}

TEST_F(CliNamedCauses, AnOutOfRangeTileSaysWhy) {
  for (const char* tile : {"99999999999999999999", "-99999999999999999999", "1e3", "x"}) {
    const RunResult r = render(scene_, {"--tile", tile});
    EXPECT_TRUE(fails_with(r, kUsage, {"--tile", tile, "16, 32 or 64"})) << tile;
  }
}

}  // namespace
}  // namespace parashade
