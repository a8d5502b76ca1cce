// Good renders: exit 0, an image of the asked size read back from disk with the scene's content where
// it can be known without the renderer (background in the corners, a grey object in the middle), and a
// report with the fields the README promises.
#include <cmath>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "cli_fixture.hpp"
#include "parashade/image.hpp"

namespace parashade {
namespace {

using namespace testing_support;

struct Rgb {
  int r, g, b;
  bool operator==(const Rgb& o) const { return r == o.r && g == o.g && b == o.b; }
};

std::ostream& operator<<(std::ostream& os, const Rgb& c) {
  return os << "(" << c.r << ", " << c.g << ", " << c.b << ")";
}

Rgb pixel(const RenderedImage& image, int x, int y) {
  const std::size_t i = 4 * (std::size_t(y) * image.width + x);
  return {image.rgba[i], image.rgba[i + 1], image.rgba[i + 2]};
}

using CliRender = CliTest;

TEST_F(CliRender, SphereSceneWritesImageAndReport) {
  const auto scene = input("ball.json", sphere_scene());
  const RunResult r = render(scene, {}, ErrorFigures::compute);
  ASSERT_TRUE(succeeds(r));
  EXPECT_EQ(out_entries(), (std::vector<std::string>{"image.png", "report.json"}));

  const RenderedImage img = read_image(image());
  ASSERT_EQ(img.width, 64);
  ASSERT_EQ(img.height, 48);
  // Background [0.2, 0.4, 0.6] is 51, 102, 153 in 8 bits; the sphere covers only the middle.
  const Rgb background{51, 102, 153};
  for (const auto& [x, y] : {std::pair{0, 0}, {63, 0}, {0, 47}, {63, 47}})
    EXPECT_EQ(pixel(img, x, y), background) << "corner " << x << ", " << y;
  // White material under a white light: grey, whatever the shading.
  const Rgb centre = pixel(img, 32, 24);
  EXPECT_FALSE(centre == background) << centre;
  EXPECT_TRUE(centre.r == centre.g && centre.g == centre.b) << centre;

  const nlohmann::json rep = read_report();
  EXPECT_EQ(field(rep, "/scene"), "ball");
  EXPECT_EQ(field(rep, "/method"), "gouraud");  // the default
  EXPECT_EQ(field(rep, "/width"), 64);
  EXPECT_EQ(field(rep, "/height"), 48);
  EXPECT_TRUE(field(rep, "/device/name").is_string()) << rep.dump(2);
  EXPECT_GT(field(rep, "/device/compute_units"), 0) << rep.dump(2);
  EXPECT_EQ(field(rep, "/triangles/in"), kSphereTriangles);
  // A closed sphere seen from outside, back faces culled: some but not all triangles remain.
  EXPECT_GT(field(rep, "/triangles/after_culling"), 0);
  EXPECT_LT(field(rep, "/triangles/after_culling"), kSphereTriangles);
  ASSERT_TRUE(field(rep, "/frame_ms").is_number()) << rep.dump(2);
  EXPECT_GT(field(rep, "/frame_ms"), 0.0);

  for (const std::string kind : {"/error/implementation", "/error/method"}) {
    SCOPED_TRACE(kind);
    const nlohmann::json e = field(rep, kind);
    for (const char* key : {"/nmse", "/max_abs", "/mean_abs"}) ASSERT_TRUE(field(e, key).is_number()) << e.dump(2);
    ASSERT_TRUE(e.contains("psnr_db")) << e.dump(2);
    EXPECT_TRUE(e["psnr_db"].is_number() || e["psnr_db"].is_null()) << e.dump(2);  // null: identical images
    EXPECT_GE(e["nmse"], 0.0);
    EXPECT_GE(e["max_abs"], e["mean_abs"]);
    EXPECT_GE(e["mean_abs"], 0.0);
    EXPECT_LE(e["max_abs"], 255.0);
  }
  EXPECT_EQ(field(rep, "/error/implementation/reference"), "ideal gouraud");
  EXPECT_EQ(field(rep, "/error/method/reference"), "exact phong");
  // Against its own ideal an 8-bit image is off by its rounding, under a level; against exact Phong a
  // Gouraud sphere of 64 triangles is off by much more (it misses the highlight's shape).
  EXPECT_LT(field(rep, "/error/implementation/max_abs"), 1.0);
  EXPECT_GT(field(rep, "/error/method/max_abs"), 1.0);
}

TEST_F(CliRender, SizeOverridesTheScene) {
  const RunResult r = render(input("ball.json", sphere_scene()), {"--size", "32x24"});
  ASSERT_TRUE(succeeds(r));
  const RenderedImage img = read_image(image());
  EXPECT_EQ(img.width, 32);
  EXPECT_EQ(img.height, 24);
  const nlohmann::json rep = read_report();
  EXPECT_EQ(field(rep, "/width"), 32);
  EXPECT_EQ(field(rep, "/height"), 24);
}

TEST_F(CliRender, WithoutErrorFiguresTheReportHasNone) {
  ASSERT_TRUE(succeeds(render(input("ball.json", sphere_scene()))));
  const nlohmann::json error = field(read_report(), "/error");
  EXPECT_TRUE(error.is_object() && error.empty()) << error.dump();
}

// The summary on stdout names what was written.
TEST_F(CliRender, SummarySaysWhatWasWritten) {
  const RunResult r = render(input("ball.json", sphere_scene()));
  ASSERT_TRUE(succeeds(r));
  EXPECT_NE(r.out.find(image().string()), std::string::npos) << r;
  EXPECT_NE(r.out.find(report().string()), std::string::npos) << r;
}

// -o without a folder writes into the working directory.
TEST_F(CliRender, OutputWithoutFolderGoesToTheWorkingDirectory) {
  const auto scene = input("ball.json", sphere_scene());
  std::vector<std::string> args = {"render", scene.string(), "-o", "plain.png", "--frames", "1", "--warmup", "0",
                                   "-q", "--no-error"};
  const std::vector<std::string> device = device_args();
  args.insert(args.end(), device.begin(), device.end());
  ASSERT_TRUE(succeeds(run_parashade(args, out_dir())));
  EXPECT_EQ(out_entries(), std::vector<std::string>{"plain.png"});
  EXPECT_EQ(read_image(out_dir() / "plain.png").width, 64);
}

// --float with an EXR keeps the unclamped float values: each matches the 8-bit image of the same
// render within its rounding (half a level), and the values are not all whole levels.
TEST_F(CliRender, FloatOutputToExrMatchesTheEightBitImage) {
  const auto scene = input("ball.json", sphere_scene());
  ASSERT_TRUE(succeeds(render(scene, {"--float"})));
  const RenderedImage png = read_image(image());
  const std::filesystem::path exr = out_dir() / "image.exr";
  std::vector<std::string> args = render_args(scene, {"--float"}, ErrorFigures::skip);
  for (std::size_t i = 0; i + 1 < args.size(); ++i)
    if (args[i] == "-o") args[i + 1] = exr.string();
  ASSERT_TRUE(succeeds(run_parashade(args)));
  const RenderedImage f = read_image(exr);
  ASSERT_EQ(f.width, png.width);
  ASSERT_EQ(f.rgb_float.size(), std::size_t(3) * f.width * f.height);
  std::size_t fractional = 0;
  for (std::size_t p = 0; p < std::size_t(f.width) * f.height; ++p)
    for (int c = 0; c < 3; ++c) {
      const float v = f.rgb_float[3 * p + c], level = png.rgba[4 * p + c];
      if (v >= 0.0f && v <= 255.0f) EXPECT_LE(std::abs(v - level), 0.5f + 1e-3f) << "pixel " << p;
      fractional += std::abs(v - std::round(v)) > 1e-3f;
    }
  EXPECT_GT(fractional, 100u) << "the EXR should hold the unrounded values";
}

class CliMethod : public CliTest, public ::testing::WithParamInterface<const char*> {};

TEST_P(CliMethod, IsUsedAndReported) {
  ASSERT_TRUE(succeeds(render(input("ball.json", sphere_scene()), {"--method", GetParam()})));
  EXPECT_EQ(field(read_report(), "/method"), GetParam());
  EXPECT_EQ(read_image(image()).width, 64);
}

INSTANTIATE_TEST_SUITE_P(Cli, CliMethod, ::testing::Values("flat", "gouraud", "phong"), StringParamName());

// A bare mesh is framed by the default camera: its middle is in the middle of the picture.
TEST_F(CliRender, BareMeshRenders) {
  const RunResult r = render(input("tetrahedron.obj", tetrahedron_obj()), {"--size", "64x48"});
  ASSERT_TRUE(succeeds(r));
  const RenderedImage img = read_image(image());
  ASSERT_EQ(img.width, 64);
  ASSERT_EQ(img.height, 48);
  const Rgb corner = pixel(img, 0, 0);
  for (const auto& [x, y] : {std::pair{63, 0}, {0, 47}, {63, 47}}) EXPECT_EQ(pixel(img, x, y), corner);
  // The default material is a neutral grey and the default light white (scenes/README.md).
  const Rgb centre = pixel(img, 32, 24);
  EXPECT_FALSE(centre == corner) << centre;
  EXPECT_TRUE(centre.r == centre.g && centre.g == centre.b) << centre;
  EXPECT_EQ(field(read_report(), "/triangles/in"), 4);
}

}  // namespace
}  // namespace parashade
