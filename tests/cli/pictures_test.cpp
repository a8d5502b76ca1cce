// Issue 18, pictures: `compare A B` on a known pair (a ramp and the ramp with pixels changed by amounts
// chosen here), its --fail boundary and bad inputs; `render --error-map / --reference-image`: the map's top
// colour sits where the error, computed here from the written image and reference, is largest, and equals
// the report's max; refused combinations.
#include <cmath>
#include <fstream>

#include <gtest/gtest.h>

#include "cli_fixture.hpp"
#include "parashade/error_map.hpp"
#include "parashade/image.hpp"

namespace parashade {
namespace {

using namespace testing_support;
namespace fs = std::filesystem;

constexpr int W = 16, H = 16;

// R = 16x, G = 16y, B = 40; `changed`: (3,4) G + 9, (12,7) R - 20, (5,13) B + 2.
RenderedImage ramp(bool changed) {
  RenderedImage im;
  im.width = W;
  im.height = H;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      int r = 16 * x, g = 16 * y, b = 40;
      if (changed && x == 3 && y == 4) g += 9;
      if (changed && x == 12 && y == 7) r -= 20;
      if (changed && x == 5 && y == 13) b += 2;
      im.rgba.insert(im.rgba.end(), {std::uint8_t(r), std::uint8_t(g), std::uint8_t(b), 255});
    }
  return im;
}

const std::uint8_t* rgba_at(const RenderedImage& im, int x, int y) {
  return &im.rgba[4 * (std::size_t(y) * std::size_t(im.width) + std::size_t(x))];
}
bool is_colour(const std::uint8_t* p, const std::array<std::uint8_t, 3>& c) {
  return p[0] == c[0] && p[1] == c[1] && p[2] == c[2];
}

class CliCompare : public CliTest {
 protected:
  CliCompare() {
    fs::create_directories(in_dir());
    write_image(a(), ramp(true));
    write_image(b(), ramp(false));
  }
  fs::path a() const { return in_dir() / "changed.png"; }
  fs::path b() const { return in_dir() / "ramp.png"; }
  RunResult compare(std::vector<std::string> extra = {}) const {
    std::vector<std::string> args = {"compare", a().string(), b().string()};
    args.insert(args.end(), extra.begin(), extra.end());
    return run_parashade(args);
  }
};

TEST_F(CliCompare, KnownPairGivesTheChangedAmounts) {
  const RunResult r = compare({"--report", report().string()});
  ASSERT_EQ(r.exit_code, kOk) << r;
  EXPECT_NE(r.out.find("max 20.000 levels"), std::string::npos) << r;
  EXPECT_NE(r.out.find("differing pixels: 3 of 256, 3 more than 1 level off"), std::string::npos) << r;
  const nlohmann::json j = read_report();
  EXPECT_EQ(field(j, "/error/max_abs"), 20.0);
  EXPECT_EQ(field(j, "/pixels_differing"), 3);
  EXPECT_NEAR(field(j, "/error/mean_abs").get<double>(), (9.0 + 20 + 2) / (3 * 256), 1e-12);
  EXPECT_EQ(field(j, "/passed"), true);
}

TEST_F(CliCompare, IdenticalImagesDifferNowhere) {
  const RunResult r = run_parashade({"compare", b().string(), b().string(), "--fail", "0"});
  ASSERT_EQ(r.exit_code, kOk) << r;
  EXPECT_NE(r.out.find("max 0.000 levels"), std::string::npos) << r;
  EXPECT_NE(r.out.find("differing pixels: 0 of 256"), std::string::npos) << r;
  EXPECT_NE(r.out.find("PSNR inf dB"), std::string::npos) << r;
}

TEST_F(CliCompare, FailLimitEqualPassesAboveFails) {
  const RunResult equal = compare({"--fail", "20"});
  EXPECT_EQ(equal.exit_code, kOk) << equal;
  EXPECT_NE(equal.out.find("PASS"), std::string::npos) << equal;
  const RunResult over = compare({"--fail", "19.99"});
  EXPECT_EQ(over.exit_code, 1) << over;
  EXPECT_NE(over.out.find("FAIL"), std::string::npos) << over;
}

TEST_F(CliCompare, DiffMapHasTheTopColourOnlyAtTheLargestError) {
  const fs::path map_file = out_dir() / "diff.png";
  const RunResult r = compare({"--diff", map_file.string()});
  ASSERT_EQ(r.exit_code, kOk) << r;
  const RenderedImage map = read_image(map_file);
  ASSERT_GT(map.width, W);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const std::uint8_t* p = rgba_at(map, x, y);
      if (x == 12 && y == 7) EXPECT_TRUE(is_colour(p, kViridis[255]));
      else if (x == 3 && y == 4) EXPECT_TRUE(is_colour(p, kViridis[115])) << "255 * 9 / 20 = 114.75";
      else if (x == 5 && y == 13) EXPECT_TRUE(is_colour(p, kViridis[26])) << "255 * 2 / 20 = 25.5";
      else EXPECT_TRUE(is_colour(p, kViridis[0])) << x << "," << y;
    }
}

TEST_F(CliCompare, DifferentSizesAreNamed) {
  RenderedImage small = ramp(false);
  small.height = H - 1;
  small.rgba.resize(4 * W * (H - 1));
  const fs::path other = in_dir() / "small.png";
  write_image(other, small);
  const RunResult r = run_parashade({"compare", a().string(), other.string(), "--diff", (out_dir() / "d.png").string()});
  EXPECT_TRUE(fails_with(r, kBadInput, {"16x16", "16x15", "small.png"}));
  EXPECT_TRUE(nothing_written());
}

TEST_F(CliCompare, ChannelMismatchIsNamed) {
  const fs::path grey = in_dir() / "grey.pgm";  // a one-channel image of the same size
  std::ofstream(grey, std::ios::binary) << "P5\n16 16\n255\n" << std::string(W * H, '\x40');
  const RunResult r = run_parashade({"compare", a().string(), grey.string()});
  EXPECT_TRUE(fails_with(r, kBadInput, {"changed.png has 3 channels", "grey.pgm has 1"}));
}

TEST_F(CliCompare, UnreadableAndMissingFilesAreNamed) {
  const fs::path junk = input("junk.png", "not an image");
  EXPECT_TRUE(fails_with(run_parashade({"compare", a().string(), junk.string()}), kBadInput, {"junk.png"}));
  EXPECT_TRUE(fails_with(run_parashade({"compare", (in_dir() / "none.png").string(), b().string()}), kBadInput,
                         {"none.png"}));
}

TEST_F(CliCompare, OutputsOverInputsOrEachOtherAreRefused) {
  EXPECT_TRUE(fails_with(compare({"--diff", a().string()}), kUsage, {"--diff", "changed.png"}));
  EXPECT_TRUE(fails_with(compare({"--diff", report().string(), "--report", report().string()}), kUsage,
                         {"--diff", "--report"}));
  EXPECT_TRUE(fails_with(compare({"--fail", "-3"}), kUsage, {"--fail"}));
  EXPECT_TRUE(nothing_written());
}

// The per-pixel error of the written image against the written EXR reference, computed here.
std::vector<double> errors_from_files(const RenderedImage& image, const RenderedImage& reference) {
  std::vector<double> e(std::size_t(image.width) * std::size_t(image.height));
  for (std::size_t p = 0; p < e.size(); ++p) {
    double worst = 0;
    for (int c = 0; c < 3; ++c)
      worst = std::max(worst, std::abs(double(reference.rgb_float[3 * p + c]) - double(image.rgba[4 * p + c])));
    e[p] = worst;
  }
  return e;
}

TEST_F(CliTest, ErrorMapOfARenderHasItsTopColourWhereTheErrorIsTheReportsMax) {
  const fs::path scene = input("ball.json", sphere_scene()), map_file = out_dir() / "map.png",
                 ref_file = out_dir() / "reference.exr";
  const RunResult r = render(scene,
                             // against exact Phong: Gouraud misses the highlight, tens of levels
                             {"--units", "classic", "--arith", "fixed:10.4", "--error-reference", "exact", "--error-map",
                              map_file.string(), "--reference-image", ref_file.string()},
                             ErrorFigures::compute);
  ASSERT_EQ(r.exit_code, kOk) << r;
  const double report_max = field(read_report(), "/error/method/max_abs").get<double>();
  const RenderedImage rendered = read_image(image()), reference = read_image(ref_file), map = read_image(map_file);
  ASSERT_EQ(reference.rgb_float.size(), 3u * 64 * 48);
  ASSERT_GT(map.width, 64);
  const std::vector<double> e = errors_from_files(rendered, reference);
  double largest = 0;
  int top_coloured = 0, compared = 0;
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 64; ++x) {
      const std::uint8_t* p = rgba_at(map, x, y);
      if (is_colour(p, {255, 255, 255})) continue;  // not covered: not compared
      ++compared;
      const double err = e[std::size_t(y) * 64 + std::size_t(x)];
      largest = std::max(largest, err);
      if (is_colour(p, kViridis[255])) {
        ++top_coloured;
        EXPECT_GE(err, report_max * (1 - 1.0 / 255) - 1e-3) << "top colour at a smaller error, " << x << "," << y;
      }
    }
  EXPECT_GT(compared, 200);
  EXPECT_NEAR(largest, report_max, 1e-3);
  EXPECT_GE(top_coloured, 1);
  EXPECT_GT(report_max, 10.0) << "Gouraud against exact Phong should be visibly off";
}

TEST_F(CliTest, ReferenceImageHoldsTheValuesThePhongReportMeasures) {
  // Phong: image and reference cover the same pixels, and the background is exact in both (levels 51,
  // 102, 153), so the largest error over the whole EXR is the report's max.
  const fs::path scene = input("ball.json", sphere_scene()), ref_file = out_dir() / "reference.exr";
  const RunResult r = render(scene, {"--method", "phong", "--reference-image", ref_file.string()}, ErrorFigures::compute);
  ASSERT_EQ(r.exit_code, kOk) << r;
  const double report_max = field(read_report(), "/error/implementation/max_abs").get<double>();
  const std::vector<double> e = errors_from_files(read_image(image()), read_image(ref_file));
  EXPECT_NEAR(*std::max_element(e.begin(), e.end()), report_max, 1e-3);
  EXPECT_GT(report_max, 0.0);
}

TEST_F(CliTest, ErrorPicturesAreRefusedWithoutTheReferenceOrOverOtherFiles) {
  const fs::path scene = input("ball.json", sphere_scene());
  EXPECT_TRUE(fails_with(render(scene, {"--error-map", (out_dir() / "m.png").string()}), kUsage,
                         {"--error-map", "--no-error"}));
  EXPECT_TRUE(fails_with(render(scene, {"--reference-image", (out_dir() / "r.png").string()}), kUsage,
                         {"--reference-image", "--no-error"}));
  EXPECT_TRUE(fails_with(render(scene, {"--error-map", image().string()}, ErrorFigures::compute), kUsage,
                         {"-o", "--error-map"}));
  EXPECT_TRUE(fails_with(render(scene, {"--reference-image", scene.string()}, ErrorFigures::compute), kUsage,
                         {"--reference-image", "ball.json"}));
  EXPECT_TRUE(fails_with(render(scene, {"--error-map", (out_dir() / "m.png").string(), "--reference-image",
                                        (out_dir() / "m.png").string()},
                                ErrorFigures::compute),
                         kUsage, {"--reference-image", "--error-map"}));
  EXPECT_TRUE(fails_with(render(scene, {"--error-map", (out_dir() / "m.xyz").string()}, ErrorFigures::compute),
                         kBadInput, {"m.xyz"}));
  EXPECT_TRUE(fails_with(render(scene, {"--error-reference", "best"}, ErrorFigures::compute), kUsage,
                         {"--error-reference", "best"}));
  EXPECT_TRUE(nothing_written());
}

}  // namespace
}  // namespace parashade
