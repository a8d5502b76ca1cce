// The Phong floor (phong_plane_fill.hpp, bench_llvmpipe's phong_plane_fill_limit) does a Phong frame's per-pixel
// work: on the full-screen quad its image is the frame kernel's Phong frame of that scene, whose planes the
// renderer's setup derives from the mesh while the floor's come from the quad's definition by hand. A floor
// that skipped the normalization, a light or the position planes would differ by tens of levels.
#include <algorithm>
#include <cstdlib>

#include <gtest/gtest.h>

#include "../../bench/peer/bench_scenes.hpp"
#include "cl/cl_fixture.hpp"
#include "parashade/errors.hpp"
#include "parashade/phong_plane_fill.hpp"

namespace parashade {
namespace {

using testing_support::render_options;
using testing_support::test_device;

TEST(PhongPlaneFill, ShadesTheFullScreenQuadAsTheFrameKernel) {
  const Scene& scene = bench::scene_named("fullscreen_quad", 320, 180);
  Renderer renderer(test_device(), render_options(Method::phong, false, 32));
  const RenderedImage& frame = renderer.render(scene).image;
  PhongPlaneFill fill(test_device(), scene, 320, 180);
  EXPECT_GE(fill.run_ms(), 0.0);
  const std::vector<std::uint32_t> floor = fill.pixels();
  int worst = 0, lit_range = 0;
  for (std::size_t p = 0; p < floor.size(); ++p) {
    ASSERT_TRUE(frame.covered(p)) << "pixel " << p;
    ASSERT_EQ(floor[p] >> 24, 0xFFu) << "pixel " << p;
    for (int c = 0; c < 3; ++c) {
      const int level = int((floor[p] >> (8 * c)) & 0xFF);
      worst = std::max(worst, std::abs(level - int(frame.rgba[4 * p + c])));
      lit_range = std::max(lit_range, std::abs(level - int((floor[0] >> (8 * c)) & 0xFF)));
    }
  }
  EXPECT_LE(worst, 1) << "largest channel difference, levels";
  EXPECT_GE(lit_range, 20) << "the quad's shading varies across the screen";
}

TEST(PhongPlaneFill, RefusesAWidthOffTheVectors) {
  const Scene& scene = bench::scene_named("fullscreen_quad", 100, 60);
  EXPECT_THROW(PhongPlaneFill(test_device(), scene, 100, 60), UsageError);
}

}  // namespace
}  // namespace parashade
