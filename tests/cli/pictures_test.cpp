// Issue 18, pictures: `compare A B` on a known pair (a ramp and the ramp with pixels changed by amounts
// chosen here), its --fail boundary and bad inputs; `render --error-map / --reference-image`: the map's top
// colour sits where the error, computed here from the written image and reference, is largest, and equals
// the report's max; refused combinations. Issue 47: maps of the image's size with the legend apart, the
// colour scales, EXR maps of values, where the max is, --fail-percent as idiff's, "exact", FLIP.
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
  EXPECT_NE(r.out.find("max 20.000 levels at (12, 7) channel R"), std::string::npos) << r;
  EXPECT_NE(r.out.find("differing pixels: 3 of 256, 3 more than 1 level off"), std::string::npos) << r;
  const nlohmann::json j = read_report();
  EXPECT_EQ(field(j, "/error/max_abs"), 20.0);
  EXPECT_EQ(field(j, "/pixels_differing"), 3);
  EXPECT_NEAR(field(j, "/error/mean_abs").get<double>(), (9.0 + 20 + 2) / (3 * 256), 1e-12);
  EXPECT_EQ(field(j, "/passed"), true);
  // Where the largest error is, as idiff says it (issue 47): x, y and the channel.
  EXPECT_EQ(field(j, "/max_at"), nlohmann::json({{"x", 12}, {"y", 7}, {"channel", "R"}}));
  EXPECT_EQ(field(j, "/exact"), false);
}

TEST_F(CliCompare, IdenticalImagesAreExactNeverInfinite) {
  const RunResult r = run_parashade({"compare", b().string(), b().string(), "--fail", "0", "--report", report().string()});
  ASSERT_EQ(r.exit_code, kOk) << r;
  EXPECT_NE(r.out.find("exact: max 0.000 levels"), std::string::npos) << r;
  EXPECT_NE(r.out.find("PSNR exact"), std::string::npos) << r;
  EXPECT_EQ(r.out.find("inf"), std::string::npos) << r;
  EXPECT_NE(r.out.find("differing pixels: 0 of 256"), std::string::npos) << r;
  const nlohmann::json j = read_report();
  EXPECT_EQ(field(j, "/exact"), true);
  EXPECT_EQ(field(j, "/error/status"), "identical");
  EXPECT_TRUE(field(j, "/error/psnr_db").is_null());  // JSON has no infinity: the status says why
  EXPECT_TRUE(field(j, "/max_at").is_null());
}

TEST_F(CliCompare, FailLimitEqualPassesAboveFails) {
  const RunResult equal = compare({"--fail", "20"});
  EXPECT_EQ(equal.exit_code, kOk) << equal;
  EXPECT_NE(equal.out.find("PASS"), std::string::npos) << equal;
  const RunResult over = compare({"--fail", "19.99"});
  EXPECT_EQ(over.exit_code, 1) << over;
  EXPECT_NE(over.out.find("FAIL"), std::string::npos) << over;
}

// idiff's rule: fail when more than P % of the pixels are more than --fail off. Of the 256 pixels, 3 are off by
// more than 1 level (9, 20, 2: 1.17 %), 2 by more than 5 (0.78 %), 1 by more than 10 (0.39 %).
TEST_F(CliCompare, FailPercentFailsOnlyWhenMoreThanThatShareOfPixelsFail) {
  const RunResult over = compare({"--fail", "1", "--fail-percent", "1", "--report", report().string()});
  EXPECT_EQ(over.exit_code, 1) << over;
  EXPECT_NE(over.out.find("FAIL: 3 pixels (1.17%) more than 1 levels off"), std::string::npos) << over;
  EXPECT_EQ(field(read_report(), "/pixels_over_fail"), 3);
  EXPECT_EQ(field(read_report(), "/fail_percent"), 1.0);
  EXPECT_EQ(compare({"--fail", "1", "--fail-percent", "2"}).exit_code, kOk);
  EXPECT_EQ(compare({"--fail", "5", "--fail-percent", "0.5"}).exit_code, 1);
  const RunResult within = compare({"--fail", "10", "--fail-percent", "0.5"});  // the max, 20, alone does not fail
  EXPECT_EQ(within.exit_code, kOk) << within;
  EXPECT_NE(within.out.find("PASS"), std::string::npos) << within;
  // Without --fail a pixel fails when it differs at all (idiff's default limit is 1e-6 of the range).
  EXPECT_EQ(compare({"--fail-percent", "1.1"}).exit_code, 1);
  EXPECT_EQ(compare({"--fail-percent", "1.2"}).exit_code, kOk);
  EXPECT_TRUE(fails_with(compare({"--fail-percent", "101"}), kUsage, {"--fail-percent"}));
}

TEST_F(CliCompare, ErrorMapHasTheImagesSizeOnTheDefaultGammaScale) {
  const fs::path map_file = out_dir() / "map.png", legend_file = out_dir() / "legend.png";
  const RunResult r = compare({"--error-map", map_file.string(), "--error-legend", legend_file.string()});
  ASSERT_EQ(r.exit_code, kOk) << r;
  const RenderedImage map = read_image(map_file), legend = read_image(legend_file);
  ASSERT_EQ(map.width, W);  // overlays the image pixel for pixel
  ASSERT_EQ(map.height, H);
  EXPECT_GE(legend.height, H);
  const auto gamma = [](double e) { return kViridis[std::size_t(std::lround(255 * std::pow(e / 20, 0.4)))]; };
  EXPECT_TRUE(is_colour(rgba_at(map, 12, 7), kViridis[255]));
  EXPECT_TRUE(is_colour(rgba_at(map, 3, 4), gamma(9)));
  EXPECT_TRUE(is_colour(rgba_at(map, 5, 13), gamma(2)));
  EXPECT_TRUE(is_colour(rgba_at(map, 0, 0), kViridis[0]));
  const auto log_scale = [](double e) { return kViridis[std::size_t(std::lround(255 * std::log1p(e) / std::log1p(20)))]; };
  ASSERT_EQ(compare({"--error-map", map_file.string(), "--error-scale", "log"}).exit_code, kOk);
  EXPECT_TRUE(is_colour(rgba_at(read_image(map_file), 5, 13), log_scale(2)));
  EXPECT_TRUE(fails_with(compare({"--error-scale", "cubic"}), kUsage, {"--error-scale", "cubic"}));
}

TEST_F(CliCompare, ExrErrorMapHoldsTheErrorsInLevels) {
  const fs::path map_file = out_dir() / "map.exr";
  const RunResult r = compare({"--error-map", map_file.string()});
  ASSERT_EQ(r.exit_code, kOk) << r;
  int channels = 0;
  const RenderedImage map = read_image(map_file, &channels);
  EXPECT_EQ(channels, 1);
  ASSERT_EQ(map.rgb_float.size(), 3u * W * H);
  const auto level = [&](int x, int y) { return map.rgb_float[3 * std::size_t(y * W + x)] / 255.0f; };  // read x255
  EXPECT_FLOAT_EQ(level(12, 7), 20.0f);
  EXPECT_FLOAT_EQ(level(3, 4), 9.0f);
  EXPECT_FLOAT_EQ(level(5, 13), 2.0f);
  EXPECT_FLOAT_EQ(level(0, 0), 0.0f);
  EXPECT_TRUE(fails_with(compare({"--error-map", map_file.string(), "--error-legend", (out_dir() / "l.png").string()}),
                         kUsage, {"--error-legend", "EXR"}));
}

TEST_F(CliCompare, DiffIsTheDeprecatedSpellingOfErrorMap) {
  const fs::path map_file = out_dir() / "diff.png";
  const RunResult r = compare({"--diff", map_file.string(), "--error-scale", "linear"});
  ASSERT_EQ(r.exit_code, kOk) << r;
  EXPECT_NE(r.err.find("--diff is deprecated"), std::string::npos) << r;
  const RenderedImage map = read_image(map_file);
  ASSERT_EQ(map.width, W);
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
  EXPECT_TRUE(fails_with(compare({"--error-map", a().string()}), kUsage, {"--error-map", "changed.png"}));
  EXPECT_TRUE(fails_with(compare({"--error-map", report().string(), "--report", report().string()}), kUsage,
                         {"--error-map", "--report"}));
  EXPECT_TRUE(fails_with(compare({"--flip-map", b().string()}), kUsage, {"--flip-map", "ramp.png"}));
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
                             {"--units", "classic", "--arith", "fixed:10.4", "--error-reference", "exact", "--error-scale",
                              "linear", "--error-map",
                              map_file.string(), "--reference-image", ref_file.string()},
                             ErrorFigures::compute);
  ASSERT_EQ(r.exit_code, kOk) << r;
  const double report_max = field(read_report(), "/error/method/max_abs").get<double>();
  const RenderedImage rendered = read_image(image()), reference = read_image(ref_file), map = read_image(map_file);
  ASSERT_EQ(reference.rgb_float.size(), 3u * 64 * 48);
  ASSERT_EQ(map.width, 64);
  ASSERT_EQ(map.height, 48);
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

// Issue 47: the map of a render overlays its image; its legend is a file of its own; to EXR the map holds the
// errors themselves, those computed here from the written image and reference.
TEST_F(CliTest, RenderErrorMapOverlaysTheImageAndToExrHoldsTheErrors) {
  const fs::path scene = input("ball.json", sphere_scene()), map_png = out_dir() / "map.png",
                 legend = out_dir() / "legend.png", map_exr = out_dir() / "map.exr", ref_file = out_dir() / "ref.exr";
  const std::vector<std::string> common = {"--error-reference", "exact", "--reference-image", ref_file.string()};
  std::vector<std::string> args = common;
  args.insert(args.end(), {"--error-map", map_png.string(), "--error-legend", legend.string()});
  const RunResult r = render(scene, args, ErrorFigures::compute);
  ASSERT_EQ(r.exit_code, kOk) << r;
  const RenderedImage map = read_image(map_png);
  EXPECT_EQ(map.width, 64);
  EXPECT_EQ(map.height, 48);
  EXPECT_GE(read_image(legend).height, 48);
  args = common;
  args.insert(args.end(), {"--error-map", map_exr.string()});
  ASSERT_EQ(render(scene, args, ErrorFigures::compute).exit_code, kOk);
  int channels = 0;
  const RenderedImage values = read_image(map_exr, &channels);
  EXPECT_EQ(channels, 1);
  const std::vector<double> e = errors_from_files(read_image(image()), read_image(ref_file));
  int compared = 0;
  for (std::size_t p = 0; p < e.size(); ++p) {
    const float v = values.rgb_float[3 * p] / 255.0f;
    if (std::isnan(v)) continue;  // not compared: background, or covered in one image only
    ++compared;
    EXPECT_NEAR(v, e[p], 1e-3) << p;
  }
  EXPECT_GT(compared, 200);
}

// Issue 47: render --flip's mean is compare --flip's on the files it wrote (the image against the EXR reference,
// which holds the reference unrounded), and its FLIP map to EXR is compare's.
TEST_F(CliTest, RenderFlipIsCompareFlipOfTheWrittenFiles) {
  const fs::path scene = input("ball.json", sphere_scene()), ref_file = out_dir() / "ref.exr",
                 flip_exr = out_dir() / "flip.exr", compare_flip = out_dir() / "compare-flip.exr",
                 compare_report = out_dir() / "compare.json";
  const RunResult r = render(scene, {"--error-reference", "exact", "--reference-image", ref_file.string(), "--flip-map",
                                     flip_exr.string()},
                             ErrorFigures::compute);
  ASSERT_EQ(r.exit_code, kOk) << r;
  const nlohmann::json j = read_report();
  const double mean = field(j, "/error/method/flip/mean").get<double>();
  EXPECT_GT(mean, 0.001) << "Gouraud against exact Phong differs visibly";
  EXPECT_LT(mean, 0.5);
  EXPECT_EQ(field(j, "/error/method/flip/metric"), "LDR-FLIP");
  EXPECT_FALSE(j["error"]["implementation"].contains("flip"));
  const RunResult c = run_parashade({"compare", image().string(), ref_file.string(), "--flip", "--flip-map",
                                     compare_flip.string(), "--report", compare_report.string()});
  ASSERT_EQ(c.exit_code, kOk) << c;
  EXPECT_NE(c.out.find("FLIP "), std::string::npos) << c;
  std::ifstream in(compare_report);
  const nlohmann::json cj = nlohmann::json::parse(in);
  EXPECT_NEAR(cj["error"]["flip"]["mean"].get<double>(), mean, 1e-6);
  const RenderedImage a = read_image(flip_exr), b = read_image(compare_flip);
  ASSERT_EQ(a.rgb_float.size(), b.rgb_float.size());
  // read_image gives EXR values x255; the two differ by the reference's float rounding in ref.exr only.
  for (std::size_t i = 0; i < a.rgb_float.size(); ++i) ASSERT_NEAR(a.rgb_float[i] / 255, b.rgb_float[i] / 255, 1e-5) << i;
  EXPECT_TRUE(fails_with(render(scene, {"--flip"}), kUsage, {"--flip", "--no-error"}));
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
