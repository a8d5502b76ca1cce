// Figures that must stay meaningful when the frame is degenerate (issue 17, items 10 and 11): a reference
// with no spread (an ambient-only box: every pixel one colour) and a frame whose triangles all vanish
// (the sierpinski unit's vertex snap on needles). No "nan" or "inf" is printed, the JSON says why a
// figure is null, and a vanished object is warned about with its counts.
#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "cli_fixture.hpp"

namespace parashade {
namespace {

using namespace testing_support;

using CliDegenerateFigures = CliTest;

::testing::AssertionResult no_nan_or_inf(const std::string& text) {
  for (const char* bad : {"nan", "inf", "NaN", "Inf"})
    if (text.find(bad) != std::string::npos) return ::testing::AssertionFailure() << "'" << bad << "' in:\n" << text;
  return ::testing::AssertionSuccess();
}

TEST_F(CliDegenerateFigures, AmbientOnlyBoxHasFiniteNmseAndPsnr) {
  // No light: every covered pixel is k_a * I_a, a reference without spread.
  const auto scene = input("ambient.json", R"({"name": "ambient", "resolution": [64, 48], "lights": [],
    "camera": {"position": [2, 1.5, 3], "target": [0, 0, 0]}, "objects": [{"shape": "box"}]})");
  for (const char* method : {"gouraud", "phong"}) {
    const RunResult r = render(scene, {"--method", method}, ErrorFigures::compute);
    ASSERT_TRUE(succeeds(r));
    EXPECT_TRUE(no_nan_or_inf(r.out)) << method;
    const nlohmann::json rep = read_report();
    for (const char* which : {"/error/implementation", "/error/method"}) {
      const nlohmann::json e = field(rep, which);
      EXPECT_TRUE(e["nmse"].is_number()) << method << which << e.dump();
      EXPECT_GT(e["pixels_compared"].get<int>(), 100) << method << which;
      // The 8-bit image is at most half a level off (25.5 levels round to 26): with the floor of one
      // level^2 per sample NMSE is the MSE, at most 0.25 (it was 1.26e+29 or inf).
      const std::string status = e["status"];
      EXPECT_TRUE(status == "compared" || status == "identical") << status;
      EXPECT_EQ(e["psnr_db"].is_null(), status == "identical") << e.dump();
      EXPECT_LE(e["nmse"].get<double>(), 0.25 + 1e-6) << method << which << e.dump();
      EXPECT_LE(e["max_abs"].get<double>(), 0.5 + 1e-6) << method << which << e.dump();
      if (status == "compared") {
        const double mse = 255.0 * 255.0 * std::pow(10.0, -e["psnr_db"].get<double>() / 10.0);
        EXPECT_NEAR(e["nmse"].get<double>(), mse, 1e-9 + 1e-6 * mse) << method << which << e.dump();
      }
    }
  }
}

TEST_F(CliDegenerateFigures, VanishedTrianglesAreWarnedWithTheirCounts) {
  const auto scene = std::filesystem::path(PARASHADE_SOURCE_DIR) / "scenes" / "hard" / "slivers.json";
  const RunResult r = render(scene, {"--units", "sierpinski:2", "--arith", "fixed:12.4"}, ErrorFigures::compute);
  ASSERT_TRUE(succeeds(r));
  EXPECT_TRUE(no_nan_or_inf(r.out));
  EXPECT_NE(r.err.find("vertex snap made 102 of 102 screen triangles degenerate"), std::string::npos) << r;
  EXPECT_NE(r.err.find("nothing drawn: 102 triangles reached the screen"), std::string::npos) << r;
  EXPECT_NE(r.out.find("no pixel covered by both"), std::string::npos) << r;
  const nlohmann::json rep = read_report();
  EXPECT_EQ(field(rep, "/error/method/status"), "nothing compared") << rep.dump(2);
  EXPECT_TRUE(field(rep, "/error/method/nmse").is_null()) << rep.dump(2);
  EXPECT_EQ(field(rep, "/stats/parity_dropped"), 102) << rep.dump(2);
}

TEST_F(CliDegenerateFigures, AnOrdinaryFrameHasNoVanishingWarning) {
  const RunResult r = render(input("ball.json", sphere_scene()), {"--units", "classic", "--arith", "fixed:12.4"});
  ASSERT_TRUE(succeeds(r));
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << r;
}

}  // namespace
}  // namespace parashade
