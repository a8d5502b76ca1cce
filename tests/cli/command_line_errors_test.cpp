// Issue 47, "CLI": a mistyped command or option is named with the nearest one when it is close; every
// error, CLI11's own parse errors included, is one "parashade: error:" line; unknown words are named in
// command-line order. (Before: "The following arguments were not expected: scenes/teapot.json rendr",
// backwards, no suggestion, and no prefix on "--output is required".)
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../../host/cli/suggest.hpp"
#include "cli_fixture.hpp"

namespace parashade {
namespace {

using namespace testing_support;

// The run failed as a usage error and every line of its stderr is an error line, a warning or the pointer
// to --help.
::testing::AssertionResult usage_error_lines(const RunResult& r) {
  if (!r.exited() || r.exit_code != kUsage) return ::testing::AssertionFailure() << "expected exit code 2:" << r;
  std::size_t start = 0, errors = 0;
  while (start < r.err.size()) {
    const std::size_t end = r.err.find('\n', start);
    const std::string line = r.err.substr(start, end == std::string::npos ? std::string::npos : end - start);
    start = end == std::string::npos ? r.err.size() : end + 1;
    if (line.rfind("parashade: error: ", 0) == 0) ++errors;
    else if (line.rfind("Run 'parashade ", 0) != 0 && line.rfind("parashade: warning: ", 0) != 0)
      return ::testing::AssertionFailure() << "a line without the prefix: '" << line << "'" << r;
  }
  if (errors == 0) return ::testing::AssertionFailure() << "no 'parashade: error:' line:" << r;
  return ::testing::AssertionSuccess();
}

class CliCommandLine : public CliTest {
 protected:
  std::filesystem::path scene_ = input("ball.json", sphere_scene());
};

TEST_F(CliCommandLine, AMistypedCommandIsNamedWithTheNearest) {
  const RunResult r = run_parashade({"rendr", scene_.string(), "-o", image().string()});
  EXPECT_TRUE(usage_error_lines(r));
  EXPECT_EQ(r.err.rfind("parashade: error: unknown command 'rendr'; did you mean 'render'?\n", 0), 0u) << r;
  for (const auto& [typed, meant] : std::vector<std::pair<std::string, std::string>>{
           {"plna", "plan"}, {"compar", "compare"}, {"devics", "devices"}, {"unit-eror", "unit-error"}}) {
    const RunResult t = run_parashade({typed});
    EXPECT_TRUE(fails_with(t, kUsage, {"unknown command '" + typed + "'; did you mean '" + meant + "'?"}));
  }
  EXPECT_TRUE(nothing_written());
}

TEST_F(CliCommandLine, AMistypedOptionIsNamedWithTheNearest) {
  EXPECT_TRUE(fails_with(render(scene_, {"--sizee", "32x24"}), kUsage,
                         {"unknown option '--sizee' of render; did you mean '--size'?"}));
  EXPECT_TRUE(fails_with(run_parashade({"tune", scene_.string(), "--budget-run", "2"}), kUsage,
                         {"'--budget-run'", "did you mean '--budget-runs'?"}));
  EXPECT_TRUE(fails_with(run_parashade({"--verison"}), kUsage, {"'--verison'; did you mean '--version'?"}));
  EXPECT_TRUE(nothing_written());
}

// An unknown word is named even when CLI11 finds a required option missing first (it checks those first).
TEST_F(CliCommandLine, AnUnknownWordIsNamedBeforeAMissingOption) {
  const RunResult r = run_parashade({"render", scene_.string(), "--outptu", image().string()});
  EXPECT_TRUE(usage_error_lines(r));
  EXPECT_EQ(r.err.rfind("parashade: error: unknown option '--outptu' of render; did you mean '--output'?\n", 0), 0u) << r;
  EXPECT_NE(r.err.find("--output is required"), std::string::npos) << r;
  EXPECT_TRUE(nothing_written());
}

TEST_F(CliCommandLine, NothingCloseIsNotGuessed) {
  for (const std::vector<std::string>& args : {std::vector<std::string>{"paint"},
                                               std::vector<std::string>{"render", scene_.string(), "-o", image().string(), "--antialias"},
                                               std::vector<std::string>{"render", scene_.string(), "-o", image().string(), "-x"}}) {
    const RunResult r = run_parashade(args);
    EXPECT_TRUE(usage_error_lines(r));
    EXPECT_NE(r.err.find("'" + args.back() + "'"), std::string::npos) << r;
    EXPECT_EQ(r.err.find("did you mean"), std::string::npos) << r;
  }
}

TEST_F(CliCommandLine, UnknownWordsAreNamedInCommandLineOrder) {
  const RunResult r = render(scene_, {"--frmaes", "3", "--sizee", "32x24"});
  EXPECT_TRUE(usage_error_lines(r));
  const std::size_t frames = r.err.find("'--frmaes'"), size = r.err.find("'--sizee'");
  ASSERT_NE(frames, std::string::npos) << r;
  ASSERT_NE(size, std::string::npos) << r;
  EXPECT_LT(frames, size) << r;
  const RunResult extra = run_parashade({"render", scene_.string(), "second.json", "-o", image().string()});
  EXPECT_TRUE(fails_with(extra, kUsage, {"unexpected argument 'second.json'"}));
  EXPECT_TRUE(nothing_written());
}

// CLI11's own errors (a missing option, a value it cannot convert, a validator's refusal, a missing value,
// two options that exclude each other) carry the prefix like parashade's.
TEST_F(CliCommandLine, EveryParseErrorHasThePrefix) {
  const std::string s = scene_.string(), o = image().string();
  const std::vector<std::vector<std::string>> lines = {
      {"render", s},                                       // --output is required
      {"render", "-o", o},                                 // scene is required
      {"render", s, "-o", o, "--frames", "many"},         // cannot convert
      {"render", s, "-o", o, "--size", "640x48O"},        // the validator
      {"render", s, "-o", o, "--frames"},                 // no value
      {"render", s, "-o", o, "--tile", "24"},             // not a tile size
      {"unit-error", "--trials", "0"},                    // out of CLI::Range
      {"phong-study", "--json", o, "--report", o + "2"},  // excluded
      {"vectors", "--unit", "classic"},                   // -o is required
      {}};                                                // no command
  for (const auto& args : lines) {
    SCOPED_TRACE(args.empty() ? std::string("(none)") : args.back());
    EXPECT_TRUE(usage_error_lines(run_parashade(args)));
  }
  EXPECT_TRUE(nothing_written());
}

TEST(CliSuggest, EditDistanceCountsASwapAsOneEdit) {
  EXPECT_EQ(cli::edit_distance("rendr", "render"), 1u);
  EXPECT_EQ(cli::edit_distance("szie", "size"), 1u);
  EXPECT_EQ(cli::edit_distance("", "abc"), 3u);
  EXPECT_EQ(cli::edit_distance("tune", "tune"), 0u);
  EXPECT_EQ(cli::did_you_mean("--q", {"-q", "--quiet"}), "");  // too short to guess from
  EXPECT_EQ(cli::did_you_mean("--rep", {"--report", "--reference-image"}), "; did you mean '--report'?");
}

}  // namespace
}  // namespace parashade
