// Command lines of the combined method that cannot be honoured: exit 2, the word at fault named, nothing
// written.
#include <algorithm>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli_fixture.hpp"

namespace parashade {
namespace {

using namespace testing_support;

class CliCombinedUsage : public CliTest {
 protected:
  std::filesystem::path scene_ = input("ball.json", sphere_scene());
};

TEST_F(CliCombinedUsage, SegmentLog2OutOfRangeIsNamed) {
  EXPECT_TRUE(fails_with(render(scene_, {"--method", "combined:9"}), kUsage, {"combined:9"}));
  EXPECT_TRUE(fails_with(render(scene_, {"--method", "combined:x"}), kUsage, {"combined:x"}));
  EXPECT_TRUE(nothing_written());
}

TEST_F(CliCombinedUsage, MaxErrorNeedsCombinedAutoOrTheBoundChoice) {
  EXPECT_TRUE(fails_with(render(scene_, {"--method", "phong", "--max-error", "2"}), kUsage, {"--max-error"}));
  EXPECT_TRUE(fails_with(render(scene_, {"--method", "combined:2", "--max-error", "2"}), kUsage, {"--max-error"}));
  EXPECT_TRUE(fails_with(render(scene_, {"--method", "combined:0", "--triangle-choice", "sources", "--max-error", "2"}),
                         kUsage, {"--max-error", "sources"}));
  EXPECT_TRUE(nothing_written());
}

TEST_F(CliCombinedUsage, MaxErrorMustBePositive) {
  EXPECT_TRUE(fails_with(render(scene_, {"--method", "combined:auto", "--max-error", "-1"}), kUsage, {"--max-error"}));
  EXPECT_TRUE(nothing_written());
}

// Issue 46, item 18: a budget below what float Phong itself reaches (the 8-bit rounding, 0.5, plus its own float
// error) was accepted without a word. render says the floor (a note: -q leaves it out).
TEST_F(CliCombinedUsage, MaxErrorBelowTheFloorIsNoted) {
  const auto run = [&](const std::vector<std::string>& extra) {
    std::vector<std::string> args = render_args(scene_, extra);
    args.erase(std::find(args.begin(), args.end(), "-q"));
    return run_parashade(args);
  };
  for (const char* method : {"combined:auto", "combined:0"}) {
    std::vector<std::string> extra = {"--method", method, "--max-error", "0.5"};
    if (std::string(method) == "combined:0") extra.insert(extra.end(), {"--triangle-choice", "bound"});
    const RunResult r = run(extra);
    ASSERT_TRUE(succeeds(r));
    EXPECT_NE(r.err.find("note: --max-error 0.5 is below its floor"), std::string::npos) << r;
    EXPECT_NE(r.err.find("float Phong's own error"), std::string::npos) << r;
  }
  const RunResult above = run({"--method", "combined:auto", "--max-error", "2"});
  ASSERT_TRUE(succeeds(above));
  EXPECT_EQ(above.err.find("floor"), std::string::npos) << above;
  const RunResult quiet = render(scene_, {"--method", "combined:auto", "--max-error", "0.5"});
  ASSERT_TRUE(succeeds(quiet));
  EXPECT_EQ(quiet.err.find("floor"), std::string::npos) << quiet;
}

TEST_F(CliCombinedUsage, HighlightTestNeedsCombined) {
  EXPECT_TRUE(fails_with(render(scene_, {"--method", "gouraud", "--highlight-test"}), kUsage, {"--highlight-test"}));
  EXPECT_TRUE(nothing_written());
}

TEST_F(CliCombinedUsage, TriangleChoiceIsCheckedAndNamed) {
  EXPECT_TRUE(fails_with(render(scene_, {"--method", "phong", "--triangle-choice", "bound"}), kUsage, {"--triangle-choice"}));
  EXPECT_TRUE(fails_with(render(scene_, {"--method", "combined:2", "--triangle-choice", "best"}), kUsage,
                         {"--triangle-choice", "best"}));
  EXPECT_TRUE(fails_with(render(scene_, {"--method", "combined:0", "--triangle-choice", "sources:2,0.004,0.008"}), kUsage,
                         {"sources:2,0.004,0.008"}));
  EXPECT_TRUE(fails_with(render(scene_, {"--method", "combined:0", "--triangle-choice", "bound:1,1,1"}), kUsage,
                         {"bound:1,1,1"}));
  EXPECT_TRUE(fails_with(render(scene_, {"--method", "combined:0", "--triangle-choice", "sources:0.9,0.004"}), kUsage,
                         {"sources:0.9,0.004"}));
  EXPECT_TRUE(nothing_written());
}

// combined:auto chooses per triangle by default; the report gives the mix, and it adds up.
TEST_F(CliCombinedUsage, ReportGivesTheMix) {
  ASSERT_TRUE(succeeds(render(scene_, {"--method", "combined:auto", "--max-error", "2"})));
  const auto r = read_report();
  ASSERT_TRUE(r.contains("stats") && r["stats"].contains("triangle_choice"));
  const auto& c = r["stats"]["triangle_choice"];
  EXPECT_EQ(r["triangle_choice_rule"], "bound");
  EXPECT_EQ(c["gouraud"].get<long>() + c["segments"].get<long>() + c["phong"].get<long>(), c["triangles"].get<long>());
  EXPECT_GT(c["triangles"].get<long>(), 0);
  EXPECT_LE(c["largest_expected_gouraud_levels"].get<double>(), 1.5);
  // combined:0 with the bound: Gouraud within the given budget (this coarse ball's triangles need a large one),
  // else Phong per pixel, no segments.
  ASSERT_TRUE(succeeds(render(scene_, {"--method", "combined:0", "--triangle-choice", "bound", "--max-error", "40"},
                              ErrorFigures::compute)));
  const auto b = read_report()["stats"]["triangle_choice"];
  EXPECT_EQ(b["segments"].get<long>(), 0);
  EXPECT_GT(b["gouraud"].get<long>(), 0);
  EXPECT_LE(b["largest_expected_gouraud_levels"].get<double>(), 39.5);
  EXPECT_GT(b["largest_expected_gouraud_levels"].get<double>(), 1.5);
  // The visible pixels per method: every pixel the error figures compare, Gouraud's and Phong's both present.
  const auto e = read_report()["error"]["method"];
  ASSERT_EQ(e["coverage_mismatch"].get<long>(), 0);
  ASSERT_TRUE(b.contains("visible_pixels"));
  const auto& v = b["visible_pixels"];
  EXPECT_EQ(v["gouraud"].get<long>() + v["segments"].get<long>() + v["phong"].get<long>(),
            e["pixels_compared"].get<long>());
  EXPECT_EQ(v["segments"].get<long>(), 0);
  EXPECT_GT(v["gouraud"].get<long>(), 0);
  EXPECT_EQ(v["phong"].get<long>() > 0, b["phong"].get<long>() > 0);
  // Without the exact reference there is no visibility to count them on.
  ASSERT_TRUE(succeeds(render(scene_, {"--method", "combined:0", "--triangle-choice", "bound", "--max-error", "40"})));
  EXPECT_FALSE(read_report()["stats"]["triangle_choice"].contains("visible_pixels"));
  ASSERT_TRUE(succeeds(render(scene_, {"--method", "combined:0", "--triangle-choice", "sources:0.95,0.01,0.02"})));
  EXPECT_EQ(read_report()["triangle_choice_rule"], "sources");
}

}  // namespace
}  // namespace parashade
