// Issue 7, item 1: out-of-range render parameters are usage errors (exit 2) naming the value, with
// nothing written; odd but valid geometry (the camera inside or behind the geometry, a light on the
// surface) renders, exit 0, with finite error figures. The remaining cases have their tests elsewhere
// (docs/robustness.md, "Bad input").
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli_fixture.hpp"

namespace parashade {
namespace {

using namespace testing_support;

struct BadOption {
  const char* label;
  std::vector<std::string> args;
  const char* named;
};

void PrintTo(const BadOption& b, std::ostream* os) { *os << b.label; }

class CliBadOption : public CliTest, public ::testing::WithParamInterface<BadOption> {};

TEST_P(CliBadOption, IsAUsageErrorNamingTheValue) {
  const auto scene = input("ball.json", sphere_scene());
  // the value and the option (args[0]): the library names the value, the CLI adds its flag
  EXPECT_TRUE(fails_with(render(scene, GetParam().args), kUsage, {GetParam().named, GetParam().args[0]}));
  EXPECT_TRUE(nothing_written());
}

INSTANTIATE_TEST_SUITE_P(
    Cli, CliBadOption,
    ::testing::Values(BadOption{"interleave_M_0", {"--units", "interleave:0"}, "interleave:0"},
                      BadOption{"segment_P_3", {"--units", "segment:3"}, "not a power of two"},
                      BadOption{"segment_P_128", {"--units", "segment:128"}, "segment:128"},
                      BadOption{"fraction_wider_than_register", {"--arith", "fixed:20.20"}, "exceeds the 32-bit register"},
                      BadOption{"too_few_integer_bits", {"--arith", "fixed:8.8"}, "fixed:8.8"},
                      BadOption{"zero_fraction_bits", {"--arith", "fixed:12.0"}, "fixed:12.0"},
                      BadOption{"shiftadd_N_31", {"--div", "shiftadd:31"}, "shiftadd:31"},
                      BadOption{"negative_size", {"--size", "-64x48"}, "-64x48"},
                      BadOption{"tile_24", {"--tile", "24"}, "--tile"},
                      BadOption{"negative_work_items", {"--work-items", "-1"}, "--work-items"},
                      BadOption{"negative_defer_min_triangles", {"--defer-min-triangles", "-2"}, "--defer-min-triangles"},
                      BadOption{"zero_frames", {"--frames", "0"}, "--frames"}),
    [](const auto& info) { return std::string(info.param.label); });

// A scene with the ball scene's camera and light replaced.
std::string ball_with(const std::string& camera, const std::string& lights) {
  return R"({"resolution": [64, 48], "camera": )" + camera + R"(, "lights": )" + lights +
         R"(, "objects": [{"shape": {"type": "sphere", "slices": 8, "stacks": 5}}], "cull_backfaces": false})";
}

class CliOddGeometry : public CliTest {
 protected:
  // Renders with the error figures; the run succeeds and every figure in the report is a finite number.
  // nothing_in_view: no pixel is covered, so there is nothing to compare; the report then has no error
  // figures (null) and pixels_compared 0.
  void expect_finite_render(const std::string& scene_text, bool nothing_in_view = false) {
    const auto scene = input("odd.json", scene_text);
    const RunResult r = render(scene, {}, ErrorFigures::compute);
    ASSERT_TRUE(succeeds(r));
    EXPECT_TRUE(std::filesystem::exists(image()));
    const nlohmann::json report = read_report();
    if (nothing_in_view) {
      EXPECT_EQ(field(report, "/error/method/pixels_compared"), 0) << report.dump(2);
      EXPECT_TRUE(field(report, "/stats").is_object()) << report.dump(2);
      return;
    }
    EXPECT_GT(field(report, "/error/method/pixels_compared").get<double>(), 0.0) << report.dump(2);
    const nlohmann::json psnr = field(report, "/error/method/psnr_db");
    const nlohmann::json max_abs = field(report, "/error/method/max_abs");
    ASSERT_TRUE(max_abs.is_number()) << report.dump(2);  // NaN would be written as null
    EXPECT_TRUE(std::isfinite(max_abs.get<double>())) << report.dump(2);
    EXPECT_FALSE(psnr.is_null()) << report.dump(2);
  }
};

// Inside the unit sphere, looking out: only back faces in view (drawn: culling is off).
TEST_F(CliOddGeometry, CameraInsideTheGeometryRenders) {
  expect_finite_render(ball_with(R"({"position": [0, 0, 0.2], "target": [0, 0, -1], "near": 0.05, "far": 10})",
                                 R"([{"type": "point", "position": [0, 0, 0]}])"));
}

// Looking away from the sphere: nothing in the view volume, an image of background.
TEST_F(CliOddGeometry, GeometryBehindTheCameraRenders) {
  expect_finite_render(ball_with(R"({"position": [0, 0, 4], "target": [0, 0, 8]})",
                                 R"([{"type": "directional", "direction": [0, 0, -1]}])"),
                       /*nothing_in_view=*/true);
}

// A point light exactly at a vertex of the sphere (the pole): L = 0 there, which must not give NaN.
TEST_F(CliOddGeometry, PointLightOnTheSurfaceRenders) {
  expect_finite_render(ball_with(R"({"position": [0, 0, 4], "target": [0, 0, 0]})",
                                 R"([{"type": "point", "position": [0, 1, 0]}, {"type": "point", "position": [0, 0, 1]}])"));
}

// Non-manifold meshes are accepted: three triangles on one edge (a fin) render, with a warning that
// counts the non-manifold faces, and so does a face with a repeated vertex (dropped and counted).
TEST_F(CliOddGeometry, NonManifoldMeshRendersWithAWarningAndCount) {
  const auto mesh = input("fin.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 0 -1 0\nf 1 2 3\nf 2 1 4\nf 1 2 5\nf 1 2 1\n");
  const RunResult r = render(mesh, {"--size", "64x48"});
  EXPECT_TRUE(succeeds(r));
  EXPECT_NE(r.err.find("warning: " + mesh.string() + ": 1 non-manifold face kept, 1 face with a repeated vertex dropped"),
            std::string::npos) << r;
  EXPECT_TRUE(std::filesystem::exists(image()));
}

}  // namespace
}  // namespace parashade
