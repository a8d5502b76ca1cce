// The report's defer_min_triangles: the threshold from which the frame's kernel shades a tile after its depth
// test (docs/pipeline.md "Deferred stamps"). Phong defers every tile by default, the combined method (combined:0,
// and since its segment walk runs on the stamps, combined:K and combined:auto) tiles of at least tile x tile / 16
// triangles; a kernel that never defers (Gouraud, span normalization) reports null, not a
// threshold it does not use; an asked threshold is reported as asked.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli_fixture.hpp"

namespace parashade {
namespace {

using namespace testing_support;

class CliDeferralReport : public CliTest {
 protected:
  nlohmann::json report_of(const std::vector<std::string>& args) {
    const auto scene = input("ball.json", sphere_scene());
    const RunResult run = render(scene, args);
    EXPECT_TRUE(succeeds(run));
    return read_report();
  }
};

TEST_F(CliDeferralReport, DefaultsPerMethod) {
  EXPECT_EQ(report_of({"--method", "phong"})["defer_min_triangles"], 0) << "Phong defers every tile by default";
  const nlohmann::json combined = report_of({"--method", "combined:0", "--tile", "32"});
  EXPECT_EQ(combined["tile"], 32);
  EXPECT_EQ(combined["defer_min_triangles"], 32 * 32 / 16);
  EXPECT_EQ(report_of({"--method", "combined:2", "--tile", "16"})["defer_min_triangles"], 16 * 16 / 16);
}

TEST_F(CliDeferralReport, NullWhereTheKernelNeverDefers) {
  EXPECT_TRUE(report_of({"--method", "gouraud"})["defer_min_triangles"].is_null());
  EXPECT_TRUE(report_of({"--method", "phong", "--normalize", "slerp"})["defer_min_triangles"].is_null());
}

TEST_F(CliDeferralReport, AskedThresholdIsReported) {
  EXPECT_EQ(report_of({"--method", "phong", "--defer-min-triangles", "5"})["defer_min_triangles"], 5);
}

// The report's kernel_build is the kernel's own -D options: a knob that reaches the kernel shows there under its
// macro's name (-D DEFER_MIN_TRIANGLES for --defer-min-triangles), and is absent where the kernel never reads it.
TEST_F(CliDeferralReport, TheKernelBuildNamesTheKnobsThatReachedIt) {
  const std::string phong = report_of({"--method", "phong", "--defer-min-triangles", "5", "--tile", "32"})["kernel_build"];
  EXPECT_NE(phong.find("-D DEFER_MIN_TRIANGLES=5"), std::string::npos) << phong;
  EXPECT_NE(phong.find("-D TILE=32"), std::string::npos) << phong;
  const std::string gouraud = report_of({"--method", "gouraud", "--defer-min-triangles", "5"})["kernel_build"];
  EXPECT_EQ(gouraud.find("DEFER_MIN_TRIANGLES"), std::string::npos) << gouraud;
}

}  // namespace
}  // namespace parashade
