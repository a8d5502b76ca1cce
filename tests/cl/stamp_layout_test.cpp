// The kernel's 4x4 stamps (RenderOptions::stamps, the plain path of Phong, Gouraud, flat and the combined method)
// against its 1x16 row segments: the same pixels are covered and shaded with the same operations, so the images
// must be byte-identical, for each method (combined:0 also with its highlight test, the per-triangle specular
// mask, and with the per-triangle choice of Gouraud, whose triangles a deferred tile shades in its walk; the
// combined method's segment walk, combined:2 and combined:auto, which reads and writes the stamps a row at a time
// and leaves no winner where it shades, deferred or not).
// The scenes cover what the stamp walk treats apart: small triangles (per-pixel edge tests) and large
// ones (row spans), tiles of 16, 32 and 64, a frame whose width and height are not multiples of the
// stamp or the tile, slivers, a fan, near-plane clipping, point lights and a local viewer. (Each scene
// and tile is a kernel build: the hard scenes run on the default tile only, to keep the test quick.)
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "cl_fixture.hpp"
#include "parashade/renderer.hpp"
#include "parashade/scene.hpp"
#include "parashade/shapes.hpp"

namespace parashade {
namespace {

using namespace testing_support;

constexpr int kNeverDefer = kMaxDeferMinTriangles;  // a deferral threshold no tile reaches

// A case of the comparison: the method, the deferral threshold, the combined method's highlight test, triangle
// choice (bound, budget 2 levels) and segments (k = 0: none; k > 0: 2^k pixels; automatic: combined:auto).
struct Variant {
  Method method;
  int defer_min = -1;
  bool highlight_test = false;
  TriangleRule rule = TriangleRule::none;
  int k = 0;
  bool automatic = false;
};

std::vector<std::uint8_t> render_rgba(const Scene& scene, const Variant& v, bool stamps, int tile) {
  RenderOptions o = render_options(v.method, false, tile);
  o.stamps = stamps;
  o.defer_min_triangles = v.defer_min;
  o.combined.k = v.k;
  o.combined.automatic = v.automatic;
  o.combined.highlight_test = v.highlight_test;
  o.combined.rule = v.rule;
  o.combined.max_error = 2.0;
  Renderer renderer(test_device(), o);
  const auto& rgba = renderer.render(scene).image.rgba;
  return {rgba.begin(), rgba.end()};
}

void expect_same_image(const Scene& scene, const std::string& what, std::initializer_list<int> tiles = {16}) {
  // Phong's stamps deferred in every tile (its default: shaded after the walk by each pixel's winner) and in none;
  // the combined method's also with every tile deferred; its deferred, choosing and walking variants at the first
  // tile size only (each is a kernel build).
  const TriangleRule bound = TriangleRule::bound;
  for (const Variant& v :
       {Variant{Method::phong}, Variant{Method::phong, kNeverDefer}, Variant{Method::gouraud}, Variant{Method::flat},
        Variant{Method::combined}, Variant{Method::combined, -1, true}, Variant{Method::combined, 0, true},
        Variant{Method::combined, -1, false, bound}, Variant{Method::combined, 0, false, bound},
        Variant{Method::combined, -1, false, TriangleRule::none, 2}, Variant{Method::combined, 0, false, TriangleRule::none, 2},
        Variant{Method::combined, -1, false, bound, 0, true}, Variant{Method::combined, 0, false, bound, 0, true}}) {
    for (int tile : tiles) {
      const bool first_tile_only =
          v.method == Method::combined && (v.defer_min == 0 || v.rule == bound || v.k > 0 || v.automatic);
      if (first_tile_only && tile != *tiles.begin()) continue;
      const auto rows = render_rgba(scene, v, false, tile), stamps = render_rgba(scene, v, true, tile);
      ASSERT_EQ(rows.size(), stamps.size());
      std::size_t covered = 0;
      for (std::size_t i = 3; i < rows.size(); i += 4) covered += rows[i] != 0;
      EXPECT_GT(covered, 0u) << what << ": nothing drawn, nothing compared";
      std::size_t differ = 0, first = rows.size();
      for (std::size_t i = 0; i < rows.size(); ++i)
        if (rows[i] != stamps[i]) {
          ++differ;
          first = std::min(first, i);
        }
      EXPECT_EQ(differ, 0u) << what << ", " << method_name(v.method)
                            << (v.defer_min == 0 ? " deferred" : v.defer_min == kNeverDefer ? " never deferred" : "")
                            << (v.highlight_test ? " highlight test" : "")
                            << (v.rule == bound ? " triangle choice" : "")
                            << (v.automatic ? " segments auto" : v.k > 0 ? " segments " + std::to_string(1 << v.k) : "")
                            << ", tile " << tile
                            << ": first differing byte at pixel " << first / 4 << " (x " << (first / 4) % scene.width
                            << ", y " << (first / 4) / scene.width << ")";
    }
  }
}

Scene scene_file(const std::string& relative) {
  return load_scene(std::filesystem::path(PARASHADE_SOURCE_DIR) / "scenes" / relative);
}

TEST(StampLayout, SameImageAsRowSegmentsOnTheProjectScenes) {
  for (const char* name : {"teapot.json", "sphere.json", "robot.json"}) {
    Scene s = scene_file(name);
    s.width = 643;  // not a multiple of 4, 16 or 64: stamps and tiles cut by the frame's edges
    s.height = 357;
    expect_same_image(s, name, {16, 32, 64});
  }
}

TEST(StampLayout, SameImageAsRowSegmentsOnTheHardScenes) {
  for (const char* name : {"slivers.json", "fan.json", "big.json", "near_plane.json", "one_pixel.json",
                           "pixel_centres.json", "t_junction.json"}) {
    expect_same_image(scene_file(std::string("hard/") + name), name);
  }
}

// Many small triangles overlapping in depth, so stamps of different triangles compete per pixel.
TEST(StampLayout, SameImageAsRowSegmentsOnOverlappingSmallTriangles) {
  const Scene s = overlapping_spheres_scene();
  expect_same_image(s, "overlapping spheres", {16, 64});
}

}  // namespace
}  // namespace parashade
