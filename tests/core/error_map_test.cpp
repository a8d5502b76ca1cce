// The per-pixel error, its colour map on each scale and its legend (metrics.hpp pixel_errors, error_map.hpp) on
// a known pair: a ramp and the ramp with three pixels changed by amounts chosen here, so every expected figure is
// known without the code under test.
#include "parashade/error_map.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <tuple>
#include <vector>

#include "parashade/errors.hpp"
#include "parashade/metrics.hpp"

namespace parashade {
namespace {

constexpr int W = 32, H = 8;

// Reference: a ramp, R = 8x, G = 16y, B = 100. The image: the ramp with (3,2) G + 7, (10,5) R - 20 and
// B + 5, (20,1) + 1 on every channel; (0,7) not covered by the image.
struct KnownPair {
  RenderedImage image;
  std::vector<std::uint8_t> covered = std::vector<std::uint8_t>(W * H, 1);
  std::vector<glm::dvec3> reference;
  KnownPair() {
    image.width = W;
    image.height = H;
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x) {
        const glm::dvec3 v(8 * x, 16 * y, 100);
        reference.push_back(v);
        glm::dvec3 out = v;
        if (x == 3 && y == 2) out.g += 7;
        if (x == 10 && y == 5) out += glm::dvec3(-20, 0, 5);
        if (x == 20 && y == 1) out += glm::dvec3(1);
        for (int c = 0; c < 3; ++c) image.rgba.push_back(std::uint8_t(out[c]));
        image.rgba.push_back(x == 0 && y == 7 ? 0 : 255);
      }
  }
};

std::size_t at(int x, int y) { return std::size_t(y) * W + std::size_t(x); }

TEST(PixelErrors, KnownPairGivesTheChangedAmountsAndNaNWhereNotCompared) {
  const KnownPair k;
  const std::vector<double> e = pixel_errors(k.image, k.covered, k.reference);
  ASSERT_EQ(e.size(), std::size_t(W * H));
  EXPECT_EQ(e[at(3, 2)], 7.0);
  EXPECT_EQ(e[at(10, 5)], 20.0);  // the larger of the two changed channels
  EXPECT_EQ(e[at(20, 1)], 1.0);
  EXPECT_TRUE(std::isnan(e[at(0, 7)]));
  int zero = 0;
  for (double v : e) zero += v == 0.0;
  EXPECT_EQ(zero, W * H - 4);
}

TEST(PixelErrors, LargestIsTheMetricsMax) {
  const KnownPair k;
  const std::vector<double> e = pixel_errors(k.image, k.covered, k.reference);
  const ErrorMetrics m = compare_to_reference(k.image, k.covered, k.reference, "ramp");
  EXPECT_EQ(m.max_abs, 20.0);
  EXPECT_EQ(error_scale_top(e), m.max_abs);
}

TEST(PixelErrors, SizeMismatchIsRefused) {
  const KnownPair k;
  std::vector<glm::dvec3> short_reference(k.reference.begin(), k.reference.end() - 1);
  std::vector<std::uint8_t> short_covered(k.covered.begin(), k.covered.end() - 1);
  EXPECT_THROW(pixel_errors(k.image, short_covered, short_reference), InputError);
}

TEST(ErrorScale, TopIsTheLargestFiniteErrorAndAtLeastOneLevel) {
  const double nan = std::nan("");
  EXPECT_EQ(error_scale_top({nan, 0.25, 0.5}), 1.0);
  EXPECT_EQ(error_scale_top({nan, nan}), 1.0);
  EXPECT_EQ(error_scale_top({3.0, 124.5, nan}), 124.5);  // never clipped
  EXPECT_EQ(error_colour_index(0.0, 20.0), 0);
  EXPECT_EQ(error_colour_index(20.0, 20.0), 255);
  EXPECT_EQ(error_colour_index(10.0, 20.0), 128);  // 127.5 rounds up
  EXPECT_EQ(error_colour_index(7.0, 20.0), 89);     // 255 * 7 / 20 = 89.25
}

::testing::AssertionResult has_colour(const RenderedImage& im, int x, int y, const std::array<std::uint8_t, 3>& rgb) {
  const std::uint8_t* p = &im.rgba[4 * (std::size_t(y) * std::size_t(im.width) + std::size_t(x))];
  if (p[0] == rgb[0] && p[1] == rgb[1] && p[2] == rgb[2] && p[3] == 255) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "(" << x << "," << y << ") is " << int(p[0]) << "," << int(p[1]) << ","
                                       << int(p[2]) << ", expected " << int(rgb[0]) << "," << int(rgb[1]) << ","
                                       << int(rgb[2]);
}

constexpr ErrorScale kLinear{ErrorScale::linear, 1.0};

TEST(ErrorMapImage, MapHasTheImagesSizeAndItsPixelsTheirColoursOnTheScale) {
  const KnownPair k;
  const RenderedImage map = error_map_image(pixel_errors(k.image, k.covered, k.reference), W, H, kLinear);
  ASSERT_EQ(map.width, W);  // pixel for pixel over the image: no scale beside it (issue 47)
  ASSERT_EQ(map.height, H);
  EXPECT_TRUE(has_colour(map, 10, 5, kViridis[255]));  // the maximum: the top colour
  EXPECT_TRUE(has_colour(map, 3, 2, kViridis[89]));
  EXPECT_TRUE(has_colour(map, 20, 1, kViridis[13]));   // 255 / 20 = 12.75
  EXPECT_TRUE(has_colour(map, 0, 0, kViridis[0]));
  EXPECT_TRUE(has_colour(map, 0, 7, {255, 255, 255}));  // not compared
  int top_coloured = 0;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) top_coloured += has_colour(map, x, y, kViridis[255]) ? 1 : 0;
  EXPECT_EQ(top_coloured, 1);
}

TEST(ErrorMapImage, GammaAndLogColourByTheirFormulas) {
  const KnownPair k;
  const std::vector<double> e = pixel_errors(k.image, k.covered, k.reference);
  const RenderedImage gamma = error_map_image(e, W, H, ErrorScale{});  // the default: gamma 0.4
  const RenderedImage log = error_map_image(e, W, H, {ErrorScale::log, 1.0});
  for (const auto& [x, y, err] : {std::tuple{3, 2, 7.0}, std::tuple{20, 1, 1.0}, std::tuple{10, 5, 20.0}}) {
    EXPECT_TRUE(has_colour(gamma, x, y, kViridis[std::size_t(std::lround(255 * std::pow(err / 20, 0.4)))]));
    EXPECT_TRUE(has_colour(log, x, y, kViridis[std::size_t(std::lround(255 * std::log(1 + err) / std::log(21.0)))]));
  }
}

TEST(ErrorScale, TheDefaultShowsOneLevelBesideA49LevelMaximum) {
  // Issue 47: a 49-level maximum with a 0.31 mean gave a black map on the linear scale.
  EXPECT_EQ(error_colour_index(1.0, 49.0, kLinear), 5);
  EXPECT_EQ(error_colour_index(1.0, 49.0, ErrorScale{}), 54);  // 255 (1/49)^0.4 = 53.9
  EXPECT_EQ(error_colour_index(1.0, 49.0, {ErrorScale::log, 1.0}), 45);  // 255 ln 2 / ln 50 = 45.2
  EXPECT_EQ(error_colour_index(0.0, 49.0, ErrorScale{}), 0);
  EXPECT_EQ(error_colour_index(49.0, 49.0, {ErrorScale::log, 1.0}), 255);
}

TEST(ErrorScale, ParsesItsNamesAndRefusesOthers) {
  EXPECT_EQ(parse_error_scale("linear").kind, ErrorScale::linear);
  EXPECT_EQ(parse_error_scale("log").kind, ErrorScale::log);
  EXPECT_EQ(parse_error_scale("gamma").exponent, 0.4);
  EXPECT_EQ(parse_error_scale("gamma:0.5").exponent, 0.5);
  EXPECT_EQ(error_scale_name(parse_error_scale("gamma:0.5")), "gamma 0.5");
  for (const char* bad : {"", "Linear", "gamma:", "gamma:0", "gamma:x", "gamma:5", "log:2"})
    EXPECT_THROW(parse_error_scale(bad), UsageError) << bad;
}

TEST(ErrorLegendImage, TheBarRunsFromNoErrorAtTheBottomToTheTopColourWithLabels) {
  for (const ErrorScale& scale : {kLinear, ErrorScale{}, ErrorScale{ErrorScale::log, 1.0}}) {
    const RenderedImage legend = error_legend_image(20.0, true, scale, H);
    EXPECT_GE(legend.height, H);
    int top_row = -1, bottom_row = -1, black = 0;
    for (int y = 0; y < legend.height; ++y)
      for (int x = 0; x < legend.width; ++x) {
        if (has_colour(legend, x, y, kViridis[255]) && top_row < 0) top_row = y;
        if (has_colour(legend, x, y, kViridis[0])) bottom_row = y;
        black += has_colour(legend, x, y, {0, 0, 0}) ? 1 : 0;
      }
    ASSERT_GE(top_row, 0) << "no top colour in the bar";
    ASSERT_GE(bottom_row, 0) << "no zero colour in the bar";
    EXPECT_LT(top_row, bottom_row);
    EXPECT_GT(bottom_row - top_row, 40);  // the bar is taller than the 8-row map
    EXPECT_GT(black, 100);                // frame, ticks and digits
  }
  EXPECT_EQ(error_legend_image(20.0, true, ErrorScale{}, 600).height, 600);  // as tall as a tall map
}

TEST(ErrorMapImage, WrongCountIsRefused) { EXPECT_THROW(error_map_image({1.0, 2.0}, 3, 1, ErrorScale{}), InputError); }

}  // namespace
}  // namespace parashade
