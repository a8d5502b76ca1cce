// The kernels' coverage (row_span: float estimate + exact settlement) against the reference
// rasterizer's per-pixel 64-bit edge functions: they implement the same rule independently and must
// agree on every pixel.
#include <random>

#include <gtest/gtest.h>

#include "cl_fixture.hpp"
#include "parashade/geometry_stage.hpp"
#include "parashade/reference.hpp"
#include "parashade/renderer.hpp"

namespace parashade {
namespace {

using namespace testing_support;

struct CoverageCase {
  int width, height, tile;
  float max_size;
};

class KernelCoverage : public ::testing::TestWithParam<CoverageCase> {};

TEST_P(KernelCoverage, EqualsReferenceOnRandomTriangles) {
  const CoverageCase c = GetParam();
  std::mt19937 rng(1234 + c.width + c.tile);
  Scene scene = pixel_scene(c.width, c.height);
  add_object(scene, random_triangles(400, c.width, c.height, c.max_size, rng));
  Renderer renderer(test_device(), render_options(Method::flat, false, c.tile));
  const std::vector<std::uint32_t> counts = renderer.coverage_counts(scene);
  const Frame frame = renderer.render(scene);

  ScreenGeometry g;
  build_screen_geometry(scene, {Method::flat, true}, g);
  // Per-pixel hit counts from the reference, one triangle at a time (the reference resolves depth,
  // so count by rendering each triangle alone).
  std::vector<std::uint32_t> expected(counts.size(), 0);
  ScreenGeometry one = g;
  for (std::size_t t = 0; t < g.triangles.size(); ++t) {
    one.triangles = {g.triangles[t]};
    one.material = {g.material[t]};
    one.flat_color = {g.flat_color[t]};
    const ReferenceImage r = render_reference(scene, one, Method::flat);
    for (std::size_t p = 0; p < expected.size(); ++p) expected[p] += r.covered[p];
  }
  std::size_t covered = 0, mismatched = 0, alpha_mismatch = 0;
  for (std::size_t p = 0; p < counts.size(); ++p) {
    covered += counts[p] > 0;
    mismatched += counts[p] != expected[p];
    alpha_mismatch += frame.image.covered(p) != (expected[p] > 0);
  }
  EXPECT_GT(covered, counts.size() / 20) << "the random scene should cover a good part of the frame";
  EXPECT_EQ(mismatched, 0u) << "pixels whose hit count differs from the reference rasterizer";
  EXPECT_EQ(alpha_mismatch, 0u) << "pixels whose rendered coverage differs from the reference";
}

INSTANTIATE_TEST_SUITE_P(Sizes, KernelCoverage,
                         ::testing::Values(CoverageCase{256, 192, 16, 12.0f}, CoverageCase{250, 130, 16, 60.0f},
                                           CoverageCase{333, 257, 32, 150.0f}, CoverageCase{200, 200, 64, 400.0f},
                                           CoverageCase{97, 61, 16, 3.0f}));

}  // namespace
}  // namespace parashade
