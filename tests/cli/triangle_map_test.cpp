// render --triangle-map: the ID buffer of the reference's visibility. A square of two triangles split along
// its diagonal, seen head-on from its centre line, must show the first triangle below the diagonal's image
// and the second above it, nothing outside the square, and nothing where the rendered image shows the
// background; lossy formats and a map without the reference are refused.
#include <cstdlib>

#include <gtest/gtest.h>

#include "cli_fixture.hpp"
#include "parashade/image.hpp"

namespace parashade {
namespace {

using namespace testing_support;
namespace fs = std::filesystem;

constexpr int W = 96, H = 96;

class CliTriangleMap : public CliTest {
 protected:
  CliTriangleMap() {
    // Counter-clockwise from +z: triangle 0 (v1 v2 v3) lies where x > y, triangle 1 (v1 v3 v4) where x < y.
    input("square.obj", "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3\nf 1 3 4\n");
    scene_ = input("square.json", R"({
  "name": "square",
  "resolution": [96, 96],
  "background": [0, 0, 1],
  "camera": {"position": [0, 0, 4], "target": [0, 0, 0], "fov": 40, "near": 1, "far": 10},
  "lights": [{"type": "directional", "direction": [0, 0, -1]}],
  "objects": [{"mesh": "square.obj"}],
  "cull_backfaces": true
})");
  }
  fs::path map_file() const { return out_dir() / "triangles.png"; }
  fs::path scene_;
};

TEST_F(CliTriangleMap, FirstTriangleBelowTheDiagonalSecondAboveNothingOutside) {
  const RunResult r = render(scene_, {"--triangle-map", map_file().string()}, ErrorFigures::compute);
  ASSERT_EQ(r.exit_code, kOk) << r;
  const RenderedImage map = read_image(map_file()), shown = read_image(image());
  ASSERT_EQ(map.width, W);
  ASSERT_EQ(map.height, H);
  // The square spans +-1 at distance 4 with a 40-degree field: half-width 1 / (4 tan 20deg) = 0.687 of
  // the half-image, about 33 pixels either side of the centre.
  const double c = W / 2.0, half = 0.687 * W / 2.0;
  int below = 0, above = 0;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const std::uint8_t* p = &map.rgba[4 * (std::size_t(y) * W + std::size_t(x))];
      const std::uint32_t id = (std::uint32_t(p[0]) << 16) | (std::uint32_t(p[1]) << 8) | p[2];
      const double dx = x + 0.5 - c, dy = c - (y + 0.5);  // world-like axes: y up
      const std::uint8_t* s = &shown.rgba[4 * (std::size_t(y) * W + std::size_t(x))];
      const bool background = s[0] == 0 && s[1] == 0 && s[2] == 255;
      EXPECT_EQ(id == 0, background) << "at " << x << "," << y << " id " << id;
      if (std::abs(dx) > half + 1.5 || std::abs(dy) > half + 1.5) EXPECT_EQ(id, 0u) << "outside at " << x << "," << y;
      if (std::abs(dx) > half - 1.5 || std::abs(dy) > half - 1.5) continue;  // near the square's edges
      if (dx - dy > 1.5) {
        EXPECT_EQ(id, 1u) << "below the diagonal at " << x << "," << y;
        ++below;
      } else if (dy - dx > 1.5) {
        EXPECT_EQ(id, 2u) << "above the diagonal at " << x << "," << y;
        ++above;
      }
    }
  EXPECT_GT(below, 1000);
  EXPECT_GT(above, 1000);
}

TEST_F(CliTriangleMap, SameForEveryMethod) {
  // The reference's geometry keeps the frame's triangles in order whatever the method shades.
  const fs::path other = out_dir() / "triangles-phong.png";
  ASSERT_EQ(render(scene_, {"--triangle-map", map_file().string()}, ErrorFigures::compute).exit_code, kOk);
  ASSERT_EQ(render(scene_, {"--method", "phong", "--triangle-map", other.string()}, ErrorFigures::compute).exit_code,
            kOk);
  EXPECT_EQ(read_image(map_file()).rgba, read_image(other).rgba);
}

TEST_F(CliTriangleMap, LossyFormatsAndNoReferenceAreRefused) {
  EXPECT_TRUE(fails_with(render(scene_, {"--triangle-map", (out_dir() / "t.jpg").string()}, ErrorFigures::compute),
                         kBadInput, {"t.jpg", "lossless"}));
  EXPECT_TRUE(fails_with(render(scene_, {"--triangle-map", (out_dir() / "t.png").string()}), kUsage,
                         {"--triangle-map", "--no-error"}));
  EXPECT_TRUE(fails_with(render(scene_, {"--triangle-map", image().string()}, ErrorFigures::compute), kUsage,
                         {"-o", "--triangle-map"}));
  EXPECT_TRUE(nothing_written());
}

}  // namespace
}  // namespace parashade
