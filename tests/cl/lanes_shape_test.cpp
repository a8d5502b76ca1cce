// The lanes kernel shape (RenderOptions::kernel_shape = lanes, kernels/render_lanes.cl: a work-group per tile, a
// work-item per block of pixels) against the vector shape (render_tiles.cl): the same coverage rule, depth test and
// shading operations per pixel, so the same image. Flat and Gouraud compute with +, * and copies only: their 8-bit
// and float images must be the same bytes on any conforming device. Phong and the combined method also call rsqrt,
// exp2 and divisions, which a device may implement differently for one lane than for sixteen: their coverage must be
// the same bytes, their float values within twice float Phong's documented bound of each other
// (docs/error-bounds.md; on PoCL and Oclgrind they are the same bytes too) and their 8-bit values within one level.
// The scenes cover what the walks treat apart: small triangles (32-bit edges) and large ones (64-bit), every tile
// size with a work-group that gives each work-item 1 to 64 pixels, frames cut by the tile, the hard scenes' slivers,
// fans, shared edges and pixel centres, and small triangles overlapping in depth (the primitive order per pixel).
#include <cmath>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "cl_fixture.hpp"
#include "parashade/combined.hpp"
#include "parashade/renderer.hpp"
#include "parashade/scene.hpp"

namespace parashade {
namespace {

using namespace testing_support;

// A method as render's --method names it, with the combined method's triangle choice (bound, 2 levels) when asked.
struct Shading {
  const char* method;
  bool choice = false;
};

RenderOptions options_for(const Shading& s, int tile, bool float_output) {
  RenderOptions o = render_options(parse_method(s.method), float_output, tile);
  if (o.method == Method::combined) o.combined = parse_combined(s.method);
  if (s.choice) {
    o.combined.rule = TriangleRule::bound;
    o.combined.max_error = 2.0;
  }
  return o;
}

RenderedImage render_shape(const Scene& scene, RenderOptions o, KernelShape shape, int group) {
  o.kernel_shape = shape;
  o.work_group_size = shape == KernelShape::lanes ? group : 0;
  Renderer renderer(test_device(), o);
  return renderer.render(scene).image;
}

// What differs between the two images: bytes (RGBA), coverage (alpha), the largest 8-bit and float differences.
struct Difference {
  std::size_t bytes = 0, coverage = 0;
  int max_levels = 0;
  double max_float = 0.0;
  std::string first;
};

Difference compare(const RenderedImage& vector, const RenderedImage& lanes) {
  Difference d;
  for (std::size_t i = 0; i < vector.rgba.size(); ++i) {
    if (vector.rgba[i] == lanes.rgba[i]) continue;
    if (d.bytes++ == 0) {
      std::ostringstream s;
      s << "first differing byte at pixel (" << (i / 4) % vector.width << ", " << (i / 4) / vector.width
        << "), channel " << i % 4 << ": " << int(vector.rgba[i]) << " vs " << int(lanes.rgba[i]);
      d.first = s.str();
    }
    if (i % 4 == 3) ++d.coverage;
    else d.max_levels = std::max(d.max_levels, std::abs(int(vector.rgba[i]) - int(lanes.rgba[i])));
  }
  for (std::size_t i = 0; i < vector.rgb_float.size(); ++i) {
    const double v = vector.rgb_float[i], l = lanes.rgb_float[i];
    if (std::memcmp(&vector.rgb_float[i], &lanes.rgb_float[i], sizeof(float)) == 0) continue;
    ++d.bytes;
    d.max_float = std::max(d.max_float, std::isfinite(v - l) ? std::abs(v - l) : INFINITY);
  }
  return d;
}

// Renders `scene` in both shapes (the lanes shape with work-groups of `group`) and holds them to the rules above;
// the float image too where `float_output`.
void expect_same_image(const Scene& scene, const std::string& what, const Shading& s, int tile, int group,
                       bool float_output) {
  const RenderOptions o = options_for(s, tile, float_output);
  const RenderedImage vector = render_shape(scene, o, KernelShape::vector, 0);
  const RenderedImage lanes = render_shape(scene, o, KernelShape::lanes, group);
  ASSERT_EQ(vector.rgba.size(), lanes.rgba.size());
  ASSERT_EQ(vector.rgb_float.size(), lanes.rgb_float.size());
  std::size_t covered = 0;
  for (std::size_t i = 3; i < vector.rgba.size(); i += 4) covered += vector.rgba[i] != 0;
  EXPECT_GT(covered, 0u) << what << ": nothing drawn, nothing compared";
  const Difference d = compare(vector, lanes);
  const std::string where = what + ", " + s.method + (s.choice ? " triangle choice" : "") + ", tile " +
                            std::to_string(tile) + ", work-group " + std::to_string(group) +
                            (float_output ? ", --float" : "") + ": " + d.first;
  ::testing::Test::RecordProperty(what + " " + s.method + " differing", std::to_string(d.bytes));
  EXPECT_EQ(d.coverage, 0u) << where;
  if (o.method == Method::flat || o.method == Method::gouraud) {
    EXPECT_EQ(d.bytes, 0u) << where;
    return;
  }
  const double bound = phong_float_error_bound(scene);
  EXPECT_LE(d.max_levels, 1) << where;
  EXPECT_LE(d.max_float, 2.0 * bound) << where << " (float values differ by " << d.max_float << " levels)";
}

Scene scene_file(const std::string& relative) {
  return load_scene(std::filesystem::path(PARASHADE_SOURCE_DIR) / "scenes" / relative);
}

const Shading kFlat{"flat"}, kGouraud{"gouraud"}, kPhong{"phong"}, kCombinedChoice{"combined:auto", true},
    kCombinedSegments{"combined:2"};

// Each scene at a tile size of its own, with a work-group that gives each work-item 16 or 4 pixels (blocks of 4x4 and
// 2x2), in a frame the tiles cut; each method once, the float image of Phong and Gouraud. (Each case is a kernel
// build, seconds each on PoCL: the cases are few.)
TEST(LanesShape, SameImageAsVectorOnTheProjectScenes) {
  struct Case {
    const char* scene;
    int tile, group;
    Shading shading;
    bool float_output;
  };
  for (const Case& c : {Case{"teapot.json", 16, 16, kFlat, false}, Case{"teapot.json", 16, 16, kGouraud, false},
                        Case{"teapot.json", 16, 16, kPhong, false}, Case{"teapot.json", 16, 16, kCombinedChoice, false},
                        Case{"sphere.json", 32, 256, kGouraud, true}, Case{"sphere.json", 32, 256, kPhong, true},
                        Case{"sphere.json", 32, 256, kCombinedSegments, false},
                        Case{"robot.json", 64, 256, kGouraud, false}, Case{"robot.json", 64, 256, kPhong, false}}) {
    Scene s = scene_file(c.scene);
    s.width = 643;
    s.height = 357;
    expect_same_image(s, c.scene, c.shading, c.tile, c.group, c.float_output);
  }
}

// The coverage rule's hard cases, on the lanes shape's default work-group.
TEST(LanesShape, SameImageAsVectorOnTheHardScenes) {
  for (const char* name : {"back_faces.json", "slivers.json", "fan.json", "big.json", "near_plane.json", "one_pixel.json",
                           "pixel_centres.json", "t_junction.json", "coplanar.json", "limit_12bit.json"}) {
    const Scene s = scene_file(std::string("hard/") + name);
    for (const Shading& m : {kGouraud, kPhong}) expect_same_image(s, name, m, 32, 0, false);
  }
}

// Many small triangles overlapping in depth: each pixel keeps its nearest triangle. (The primitive order decides only
// ties, which hard/coplanar.json holds: walking a batch backwards fails the hard scenes' test there, not this one.)
TEST(LanesShape, SameImageAsVectorOnOverlappingSmallTriangles) {
  const Scene s = overlapping_spheres_scene();
  for (const Shading& m : {kGouraud, kPhong}) expect_same_image(s, "overlapping spheres", m, 16, 64, false);
}

// A streamed frame (bands of tile rows, each launched from its first tile: a global offset of whole work-groups).
TEST(LanesShape, SameImageInStreamedBands) {
  const Scene s = overlapping_spheres_scene();
  RenderOptions o = options_for(kGouraud, 16, false);
  const RenderedImage vector = render_shape(s, o, KernelShape::vector, 0);
  o.kernel_shape = KernelShape::lanes;
  o.work_group_size = 64;
  o.band_record_bytes = 64 << 10;  // the spheres' records are about 0.7 MiB
  Renderer renderer(test_device(), o);
  const Frame& f = renderer.render(s);
  EXPECT_GT(f.stats.bands, 2);
  RecordProperty("bands", f.stats.bands);
  EXPECT_EQ(compare(vector, f.image).bytes, 0u) << compare(vector, f.image).first;
}

// Small frames for a slow device (the anydevice label runs this on Oclgrind, whose checks see the local memory and
// barriers): small and large triangles, each work-item one pixel and sixteen, the combined method's segments.
TEST(LanesShape, SameImageAsVectorOnSmallFrames) {
  Scene teapot = scene_file("teapot.json");
  teapot.width = 90;
  teapot.height = 50;
  for (const Shading& m : {kGouraud, kPhong, kCombinedChoice}) expect_same_image(teapot, "teapot", m, 16, 16, false);
  Scene big = scene_file("hard/big.json");
  big.width = 72;
  big.height = 40;
  expect_same_image(big, "big", kGouraud, 16, 256, true);
}

}  // namespace
}  // namespace parashade
