// Image error against a reference: exact statistics on hand-computed cases, coverage mismatches,
// the float image path and the degenerate cases documented in metrics.hpp.
#include "parashade/metrics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "parashade/errors.hpp"

namespace parashade {
namespace {

struct Pixel {
  glm::dvec3 value;
  bool covered;
};

// A one-row image and the same pixels as a reference.
RenderedImage image_of(const std::vector<Pixel>& pixels) {
  RenderedImage im;
  im.width = int(pixels.size());
  im.height = 1;
  for (const Pixel& p : pixels) {
    for (int c = 0; c < 3; ++c) im.rgba.push_back(std::uint8_t(p.value[c]));
    im.rgba.push_back(p.covered ? 255 : 0);
  }
  return im;
}
std::vector<std::uint8_t> covered_of(const std::vector<Pixel>& pixels) {
  std::vector<std::uint8_t> out;
  for (const Pixel& p : pixels) out.push_back(p.covered ? 1 : 0);
  return out;
}
std::vector<glm::dvec3> values_of(const std::vector<Pixel>& pixels) {
  std::vector<glm::dvec3> out;
  for (const Pixel& p : pixels) out.push_back(p.value);
  return out;
}

TEST(Metrics, IdenticalImagesHaveNoError) {
  const std::vector<Pixel> px = {{{10, 20, 30}, true}, {{200, 100, 0}, true}, {{7, 7, 7}, false}};
  const ErrorMetrics m = compare_to_reference(image_of(px), covered_of(px), values_of(px), "ideal gouraud");
  EXPECT_EQ(m.reference, "ideal gouraud");
  EXPECT_EQ(m.nmse, 0.0);
  EXPECT_TRUE(std::isinf(m.psnr_db) && m.psnr_db > 0);
  EXPECT_EQ(m.max_abs, 0.0);
  EXPECT_EQ(m.mean_abs, 0.0);
  EXPECT_EQ(m.pixels_compared, 2u);
  EXPECT_EQ(m.pixels_over_1_level, 0u);
  EXPECT_EQ(m.coverage_mismatch, 0u);
}

TEST(Metrics, KnownPerturbationGivesTheHandComputedFigures) {
  // Reference over the three compared pixels: R = 10, 20, 30 (mean 20, spread 100 + 0 + 100), G = 0,
  // B = 100 (no spread): sum (I - mean)^2 = 200.
  const std::vector<Pixel> ref = {{{10, 0, 100}, true},  {{20, 0, 100}, true}, {{30, 0, 100}, true},
                                  {{50, 50, 50}, false}, {{90, 9, 9}, true},   {{1, 2, 3}, false}};
  // Image: +2 on G of pixel 1, +1 on B of pixel 2; pixel 3 covered only here, pixel 4 only in the reference.
  const std::vector<Pixel> img = {{{10, 0, 100}, true}, {{20, 2, 100}, true}, {{30, 0, 101}, true},
                                  {{250, 0, 0}, true},  {{0, 0, 0}, false},   {{1, 2, 3}, false}};
  const ErrorMetrics m = compare_to_reference(image_of(img), covered_of(ref), values_of(ref), "exact phong");
  EXPECT_EQ(m.pixels_compared, 3u);
  EXPECT_EQ(m.coverage_mismatch, 2u);
  // Squared error 2^2 + 1^2 = 5 over 9 channel samples.
  EXPECT_DOUBLE_EQ(m.nmse, 5.0 / 200.0);
  EXPECT_DOUBLE_EQ(m.psnr_db, 10.0 * std::log10(255.0 * 255.0 / (5.0 / 9.0)));
  EXPECT_NEAR(m.psnr_db, 50.6836, 1e-4);
  EXPECT_EQ(m.max_abs, 2.0);
  EXPECT_DOUBLE_EQ(m.mean_abs, 3.0 / 9.0);
  EXPECT_EQ(m.pixels_over_1_level, 1u);  // exactly 1 level off is not "more than 1"
}

TEST(Metrics, FloatImageIsUsedAndClampedToLevels) {
  const std::vector<Pixel> ref = {{{255, 0, 10}, true}, {{100, 50, 20}, true}};
  RenderedImage im = image_of({{{0, 0, 0}, true}, {{0, 0, 0}, true}});  // 8-bit values are ignored
  im.rgb_float = {300.0f, -5.0f, 10.0f, 100.25f, 50.0f, 20.0f};
  const ErrorMetrics m = compare_to_reference(im, covered_of(ref), values_of(ref), "ideal phong");
  EXPECT_EQ(m.max_abs, 0.25);
  EXPECT_DOUBLE_EQ(m.mean_abs, 0.25 / 6.0);
  EXPECT_EQ(m.pixels_over_1_level, 0u);
}

TEST(Metrics, NoCommonPixelsGivesUndefinedStatistics) {
  const std::vector<Pixel> ref = {{{10, 0, 0}, true}, {{0, 0, 0}, false}};
  const std::vector<Pixel> img = {{{10, 0, 0}, false}, {{0, 0, 0}, true}};
  const ErrorMetrics m = compare_to_reference(image_of(img), covered_of(ref), values_of(ref), "ideal flat");
  EXPECT_EQ(m.pixels_compared, 0u);
  EXPECT_EQ(m.coverage_mismatch, 2u);
  EXPECT_TRUE(std::isnan(m.nmse));
  EXPECT_TRUE(std::isnan(m.psnr_db));
  EXPECT_TRUE(std::isnan(m.max_abs));
  EXPECT_TRUE(std::isnan(m.mean_abs));
}

TEST(Metrics, ConstantReferenceGivesZeroOrInfiniteNmse) {
  // 0.1 + 0.1 + 0.1 != 0.3 in double: a mean computed by division is not exactly 0.1, so constancy
  // must be decided exactly or NMSE becomes a huge finite number instead of +inf.
  const std::vector<Pixel> ref = {{{0.1, 0.1, 0.1}, true}, {{0.1, 0.1, 0.1}, true}, {{0.1, 0.1, 0.1}, true}};
  RenderedImage rounded = image_of(ref);
  rounded.rgb_float.assign(9, 0.1f);  // off by float rounding only, but off
  const ErrorMetrics near = compare_to_reference(rounded, covered_of(ref), values_of(ref), "ideal flat");
  EXPECT_TRUE(std::isinf(near.nmse)) << near.nmse;

  std::vector<Pixel> exact = ref;
  for (Pixel& p : exact) p.value = glm::dvec3(82.0);
  const ErrorMetrics zero =
      compare_to_reference(image_of(exact), covered_of(exact), values_of(exact), "ideal flat");
  EXPECT_EQ(zero.nmse, 0.0);
  EXPECT_TRUE(std::isinf(zero.psnr_db));

  RenderedImage off = image_of(exact);
  off.rgba[0] += 3;
  const ErrorMetrics inf = compare_to_reference(off, covered_of(exact), values_of(exact), "ideal flat");
  EXPECT_TRUE(std::isinf(inf.nmse) && inf.nmse > 0);
  EXPECT_EQ(inf.max_abs, 3.0);
}

TEST(Metrics, SizeMismatchIsAnInputError) {
  const std::vector<Pixel> px = {{{1, 2, 3}, true}, {{4, 5, 6}, true}};
  std::vector<std::uint8_t> covered = covered_of(px);
  covered.push_back(1);
  EXPECT_THROW(compare_to_reference(image_of(px), covered, values_of(px), "ideal flat"), InputError);
}

}  // namespace
}  // namespace parashade
