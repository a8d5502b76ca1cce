// Renderer::set_band: a renderer whose band of tile rows is moved between frames (what a sort-first rank
// does when the measured speeds move its band) renders byte for byte what a renderer built with that band
// renders, rows outside the band included (background), and set_band(0, -1) gives the whole frame back.
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cl_fixture.hpp"
#include "parashade/errors.hpp"
#include "parashade/renderer.hpp"
#include "parashade/scene.hpp"

namespace parashade {
namespace {

using namespace testing_support;

std::vector<std::uint8_t> fresh(const Scene& scene, Method method, int first, int rows) {
  RenderOptions o = render_options(method, false, 16);
  o.band_first = first;
  o.band_rows = rows;
  Renderer renderer(test_device(), o);
  const Frame& f = renderer.render(scene);
  return {f.image.rgba.begin(), f.image.rgba.end()};
}

TEST(MovedBand, SameImageAsARendererBuiltWithTheBand) {
  Scene scene = load_scene(std::filesystem::path(PARASHADE_SOURCE_DIR) / "scenes" / "teapot.json");
  scene.width = 320;
  scene.height = 180;  // 12 tile rows
  for (Method method : {Method::gouraud, Method::phong}) {
    RenderOptions o = render_options(method, false, 16);
    o.band_first = 0;
    o.band_rows = 4;
    Renderer moved(test_device(), o);
    // Down, up, to one row, to the whole frame: each frame against a renderer built for it.
    for (auto [first, rows] : std::vector<std::pair<int, int>>{{0, 4}, {5, 6}, {2, 3}, {11, 1}, {0, -1}}) {
      const std::string where = std::string(method_name(method)) + ", rows " + std::to_string(first) + " +" +
                                std::to_string(rows);
      moved.set_band(first, rows);
      const Frame& f = moved.render(scene);
      const std::vector<std::uint8_t> want = fresh(scene, method, first, rows);
      ASSERT_EQ(f.image.rgba.size(), want.size()) << where;
      std::size_t differ = 0;
      for (std::size_t i = 0; i < want.size(); ++i) differ += f.image.rgba[i] != want[i];
      EXPECT_EQ(differ, 0u) << where;
    }
  }
}

TEST(MovedBand, ABandTheFrameConfigRefusesIsRefusedAndTheOldBandKept) {
  RenderOptions o = render_options(Method::gouraud, false, 16);
  o.band_first = 1;
  o.band_rows = 2;
  Renderer renderer(test_device(), o);
  EXPECT_THROW(renderer.set_band(-3, 2), UsageError);
  EXPECT_EQ(renderer.options().band_first, 1);
  EXPECT_EQ(renderer.options().band_rows, 2);
}

}  // namespace
}  // namespace parashade
