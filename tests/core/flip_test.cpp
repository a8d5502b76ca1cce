// LDR-FLIP (flip.hpp) on three pairs made here, held to the values NVIDIA's own implementation gives for them
// (the `flip-evaluator` package, version 1.7, evaluate(reference, test, "LDR") on the same float arrays,
// recorded below; tests/scripts/flip_agreement_test.py runs the package itself on more pairs when it can be
// installed). The tolerance, 2e-5, is float rounding: the two sum their filters in different orders.
#include "parashade/flip.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "parashade/errors.hpp"

namespace parashade {
namespace {

constexpr double kTolerance = 2e-5;

struct Pair {
  int width, height;
  std::vector<float> reference, test;
  Pair(int w, int h) : width(w), height(h), reference(3 * std::size_t(w * h)), test(3 * std::size_t(w * h)) {}
  float* ref(int x, int y) { return &reference[3 * std::size_t(y * width + x)]; }
  float* tst(int x, int y) { return &test[3 * std::size_t(y * width + x)]; }
};

// A: a red-green ramp, b 0.3, against itself 0.1 brighter (clamped).
Pair ramp_pair() {
  Pair p(64, 48);
  for (int y = 0; y < p.height; ++y)
    for (int x = 0; x < p.width; ++x) {
      const float v[3] = {float(x) / 63.0f, float(y) / 47.0f, 0.3f};
      for (int c = 0; c < 3; ++c) {
        p.ref(x, y)[c] = v[c];
        p.tst(x, y)[c] = std::min(v[c] + 0.1f, 1.0f);
      }
    }
  return p;
}

// B: a black and white checkerboard of 4-pixel squares against uniform grey 0.5.
Pair checker_pair() {
  Pair p(40, 40);
  for (int y = 0; y < p.height; ++y)
    for (int x = 0; x < p.width; ++x)
      for (int c = 0; c < 3; ++c) {
        p.ref(x, y)[c] = float((x / 4 + y / 4) % 2);
        p.tst(x, y)[c] = 0.5f;
      }
  return p;
}

// C: grey 0.2 against the same with one white pixel at (10, 10).
Pair dot_pair() {
  Pair p(32, 24);
  std::fill(p.reference.begin(), p.reference.end(), 0.2f);
  p.test = p.reference;
  for (int c = 0; c < 3; ++c) p.tst(10, 10)[c] = 1.0f;
  return p;
}

std::vector<float> flip_of(const Pair& p) { return ldr_flip(p.reference, p.test, p.width, p.height); }

TEST(Flip, MatchesFlipEvaluatorOnARamp) {
  const std::vector<float> m = flip_of(ramp_pair());
  EXPECT_NEAR(flip_figures(m).mean, 0.39569112, kTolerance);
  EXPECT_NEAR(m[0], 0.41583216, kTolerance);
  EXPECT_NEAR(m[20 * 64 + 30], 0.3713009, kTolerance);
}

TEST(Flip, MatchesFlipEvaluatorOnACheckerboard) {
  const std::vector<float> m = flip_of(checker_pair());
  EXPECT_NEAR(flip_figures(m).mean, 0.60841064, kTolerance);
  EXPECT_NEAR(flip_figures(m).max, 0.96889085, kTolerance);
}

TEST(Flip, MatchesFlipEvaluatorOnOneDot) {
  const std::vector<float> m = flip_of(dot_pair());
  EXPECT_NEAR(flip_figures(m).mean, 0.01178933, kTolerance);
  EXPECT_NEAR(m[10 * 32 + 10], 0.6583723, kTolerance);
  EXPECT_NEAR(m[10 * 32 + 11], 0.54916227, kTolerance);
  EXPECT_EQ(m[0], 0.0f);  // beyond the filters' reach: no difference
}

TEST(Flip, IdenticalImagesAreZeroEverywhereAndTheErrorIsSymmetric) {
  const Pair p = ramp_pair();
  for (float v : ldr_flip(p.reference, p.reference, p.width, p.height)) ASSERT_EQ(v, 0.0f);
  const std::vector<float> ab = flip_of(p), ba = ldr_flip(p.test, p.reference, p.width, p.height);
  for (std::size_t i = 0; i < ab.size(); ++i) ASSERT_NEAR(ab[i], ba[i], 1e-6) << i;
}

TEST(Flip, BandsOfRowsGiveTheWholeImagesMap) {
  // Taller than a band (32..256 rows) and narrower than the filters: the halo rows and the clamped edges.
  Pair p(7, 700);
  for (std::size_t i = 0; i < p.reference.size(); ++i) {
    p.reference[i] = float((i * 37) % 101) / 100.0f;
    p.test[i] = float((i * 53) % 97) / 96.0f;
  }
  const std::vector<float> m = flip_of(p);
  // Row 350 of the tall pair depends only on rows 340..360: the same rows alone, framed by their neighbours
  // repeated, are another image, so compare with the rows of a crop that holds the whole reach.
  Pair crop(7, 100);
  std::copy(p.reference.begin() + 3 * 7 * 300, p.reference.begin() + 3 * 7 * 400, crop.reference.begin());
  std::copy(p.test.begin() + 3 * 7 * 300, p.test.begin() + 3 * 7 * 400, crop.test.begin());
  const std::vector<float> c = flip_of(crop);
  for (int x = 0; x < 7; ++x) EXPECT_NEAR(m[350 * 7 + std::size_t(x)], c[50 * 7 + std::size_t(x)], 1e-6) << x;
}

TEST(Flip, SizeMismatchAndBadObserverAreRefused) {
  const Pair p = dot_pair();
  EXPECT_THROW(ldr_flip(p.reference, p.test, p.width + 1, p.height), InputError);
  EXPECT_THROW(ldr_flip(p.reference, p.test, p.width, p.height, 0.0), InputError);
}

TEST(Flip, MapPictureIsMagmaOfTheValues) {
  const RenderedImage im = flip_map_image({0.0f, 1.0f, 0.5f, std::nanf("")}, 2, 2);
  ASSERT_EQ(im.width, 2);
  EXPECT_EQ(im.rgba[0], kMagma[0][0]);
  EXPECT_EQ(im.rgba[4], kMagma[255][0]);
  EXPECT_EQ(im.rgba[9], kMagma[128][1]);
}

}  // namespace
}  // namespace parashade
