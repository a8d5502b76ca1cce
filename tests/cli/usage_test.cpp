// The command line itself: --help and --version, and command lines that cannot be understood (exit 2,
// the word at fault named). Each bad command line is otherwise a good render, so a check that went
// missing would show as an exit code 0 and an image.
#include <regex>

#include <gtest/gtest.h>

#include "cli_fixture.hpp"

namespace parashade {
namespace {

using namespace testing_support;

TEST(CliHelp, DocumentsCommandsAndExitCodes) {
  const RunResult r = run_parashade({"--help"});
  ASSERT_TRUE(succeeds(r));
  for (const char* text : {"devices", "render", "0 ok", "2 usage error", "3 bad input", "4 OpenCL"})
    EXPECT_NE(r.out.find(text), std::string::npos) << "--help does not mention '" << text << "':" << r;
}

TEST(CliHelp, RenderHelpListsItsOptions) {
  const RunResult r = run_parashade({"render", "--help"});
  ASSERT_TRUE(succeeds(r));
  for (const char* option : {"--output", "--method", "--device", "--size", "--report", "--frames", "--warmup",
                             "--tile", "--float", "--no-error", "--quiet"})
    EXPECT_NE(r.out.find(option), std::string::npos) << "render --help does not mention " << option << ":" << r;
}

TEST(CliHelp, VersionIsNameNumberAndCommit) {
  const RunResult r = run_parashade({"--version"});
  ASSERT_TRUE(succeeds(r));
  // The version, then the git commit it was configured from ("unknown" outside a checkout).
  EXPECT_TRUE(std::regex_match(r.out, std::regex(R"(parashade \d+\.\d+\.\d+ \(git ([0-9a-f]{7,40}(-dirty)?|unknown)\)\s*)")))
      << r;
}

TEST(CliUsage, NoCommand) {
  EXPECT_TRUE(fails_with(run_parashade({}), kUsage, {"devices", "render"}));
}

TEST(CliUsage, UnknownCommandIsNamed) {
  EXPECT_TRUE(fails_with(run_parashade({"paint"}), kUsage, {"paint"}));
}

TEST(CliUsage, UnknownTopLevelOptionIsNamed) {
  EXPECT_TRUE(fails_with(run_parashade({"--colour"}), kUsage, {"--colour"}));
}

class CliRenderUsage : public CliTest {
 protected:
  std::filesystem::path scene_ = input("ball.json", sphere_scene());
};

TEST_F(CliRenderUsage, UnknownOptionIsNamed) {
  EXPECT_TRUE(fails_with(render(scene_, {"--antialias"}), kUsage, {"--antialias"}));
  EXPECT_TRUE(nothing_written());
}

TEST_F(CliRenderUsage, MissingOutput) {
  EXPECT_TRUE(fails_with(run_parashade({"render", scene_.string(), "--no-error"}), kUsage, {"--output"}));
  EXPECT_TRUE(nothing_written());
}

TEST_F(CliRenderUsage, MissingScene) {
  EXPECT_TRUE(fails_with(run_parashade({"render", "-o", image().string()}), kUsage, {"scene"}));
  EXPECT_TRUE(nothing_written());
}

TEST_F(CliRenderUsage, UnknownMethodIsNamed) {
  EXPECT_TRUE(fails_with(render(scene_, {"--method", "toon"}), kUsage, {"toon"}));
  EXPECT_TRUE(nothing_written());
}

TEST_F(CliRenderUsage, NonNumericFramesIsNamed) {
  EXPECT_TRUE(fails_with(render(scene_, {"--frames", "many"}), kUsage, {"--frames"}));
  EXPECT_TRUE(nothing_written());
}

// A usage error is reported as such even when the scene is bad too: the command line is read first.
TEST_F(CliRenderUsage, UsageErrorComesBeforeTheScene) {
  EXPECT_TRUE(fails_with(render(in_dir() / "absent.json", {"--size", "640"}), kUsage, {"640"}));
  EXPECT_TRUE(nothing_written());
}

class CliMalformedSize : public CliTest, public ::testing::WithParamInterface<const char*> {};

TEST_P(CliMalformedSize, IsAUsageErrorNamingTheValue) {
  const std::filesystem::path scene = input("ball.json", sphere_scene());
  EXPECT_TRUE(fails_with(render(scene, {"--size", GetParam()}), kUsage, {"--size", GetParam()}));
  EXPECT_TRUE(nothing_written());
}

INSTANTIATE_TEST_SUITE_P(Cli, CliMalformedSize,
                         ::testing::Values("64", "64x", "x48", "64x48x2", "-64x48", "64*48", "64 x 48", "0x30x20",
                                           "99999999999x48", "64.5x48"),
                         StringParamName());

}  // namespace
}  // namespace parashade
