// The frame kernel's coverage (the alpha of the image it renders) against the exact spans of the frame's
// records, computed on the host from their integer edge functions (planner.hpp's for_each_span): the same
// pixels, however a tile's spans are found (the span search, a block the triangle covers whole, small
// triangles' per-pixel tests, row segments or stamps). Large random triangles reaching past the frame,
// small ones, tiles 16, 32 and 64, Gouraud on row segments (RenderOptions::stamps off) and Phong on stamps.
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "cl_fixture.hpp"
#include "parashade/frame_pipeline.hpp"
#include "parashade/planner.hpp"
#include "parashade/renderer.hpp"

namespace parashade {
namespace {

using namespace testing_support;

std::vector<char> exact_coverage(const Scene& scene, Method method) {
  FrameConfig config;
  config.method = method;
  FramePipeline pipeline(config);
  const PreparedFrame& f = pipeline.prepare_frame(scene);
  std::vector<char> covered(std::size_t(scene.width) * scene.height, 0);
  for (std::size_t i = 0; i < f.records; ++i) {
    const TriangleGeometry& r = f.arrays.triangles[i];
    for_each_span(r, [&](int dy, int xl, int xr) {
      for (int x = r.x0 + xl; x <= r.x0 + xr; ++x) covered[std::size_t(r.y0 + dy) * scene.width + x] = 1;
    });
  }
  return covered;
}

void expect_exact_coverage(const Scene& scene, const char* what) {
  for (Method method : {Method::gouraud, Method::phong}) {
    const std::vector<char> exact = exact_coverage(scene, method);
    for (int tile : {16, 32, 64}) {
      RenderOptions options = render_options(method, false, tile);
      options.stamps = method == Method::phong;  // both layouts: Gouraud's row segments, Phong's stamps
      Renderer renderer(test_device(), options);
      const RenderedImage& image = renderer.render(scene).image;
      std::size_t differ = 0, covered = 0;
      for (std::size_t p = 0; p < exact.size(); ++p) {
        covered += exact[p];
        differ += image.covered(p) != bool(exact[p]);
      }
      EXPECT_GT(covered, 1000u) << what;
      EXPECT_EQ(differ, 0u) << what << ", " << method_name(method) << ", tile " << tile;
    }
  }
}

TEST(RenderCoverage, LargeTrianglesMatchTheirExactSpans) {
  std::mt19937 rng(20261202);
  Scene s = pixel_scene(301, 211);
  add_object(s, random_triangles(24, 301, 211, 160.0f, rng));  // extents up to 320 pixels: large, clipped
  expect_exact_coverage(s, "large triangles");
}

TEST(RenderCoverage, SmallTrianglesMatchTheirExactSpans) {
  std::mt19937 rng(7);
  Scene s = pixel_scene(301, 211);
  add_object(s, random_triangles(400, 301, 211, 12.0f, rng));
  expect_exact_coverage(s, "small triangles");
}

}  // namespace
}  // namespace parashade
