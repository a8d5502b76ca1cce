// A frame streamed in bands of tile rows (RenderOptions::band_record_bytes, FramePipeline::begin_frame)
// against the same frame prepared whole: each tile still gets its triangles in primitive order and the
// same records, so the images must be byte-identical. A budget of a few records' bytes forces many
// bands, down to one tile row each, with triangles crossing the bands' borders, on every method that
// streams, tiles of 16 and 64, a frame whose height is not a multiple of the tile, clipping and
// overlapping small triangles (depth order across band borders).
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "cl_fixture.hpp"
#include "parashade/renderer.hpp"
#include "parashade/scene.hpp"
#include "parashade/setup.hpp"
#include "parashade/shapes.hpp"

namespace parashade {
namespace {

using namespace testing_support;

struct Rendered {
  std::vector<std::uint8_t> rgba;
  FrameStats stats;
};

Rendered render(const Scene& scene, Method method, int tile, std::size_t band_record_bytes) {
  RenderOptions o = render_options(method, false, tile);
  o.band_record_bytes = band_record_bytes;
  Renderer renderer(test_device(), o);
  const Frame& f = renderer.render(scene);
  return {{f.image.rgba.begin(), f.image.rgba.end()}, f.stats};
}

// Room for `records` records per band: with few, a band per tile row or a few.
void expect_same_image(const Scene& scene, const std::string& what, std::initializer_list<int> tiles,
                       std::size_t records) {
  for (Method method : {Method::flat, Method::gouraud, Method::phong}) {
    for (int tile : tiles) {
      const std::string where = what + ", " + method_name(method) + ", tile " + std::to_string(tile);
      const Rendered whole = render(scene, method, tile, SIZE_MAX);
      const std::size_t record = sizeof(TriangleGeometry) + attribute_floats(method) * sizeof(float);
      const Rendered bands = render(scene, method, tile, records * record);
      EXPECT_EQ(whole.stats.bands, 1) << where;
      EXPECT_GT(bands.stats.bands, 1) << where << ": the frame did not stream";
      EXPECT_EQ(bands.stats.triangles_without_pixels, whole.stats.triangles_without_pixels) << where;
      ASSERT_EQ(whole.rgba.size(), bands.rgba.size());
      std::size_t covered = 0;
      for (std::size_t i = 3; i < whole.rgba.size(); i += 4) covered += whole.rgba[i] != 0;
      EXPECT_GT(covered, 0u) << where << ": nothing drawn, nothing compared";
      std::size_t differ = 0, first = whole.rgba.size();
      for (std::size_t i = 0; i < whole.rgba.size(); ++i)
        if (whole.rgba[i] != bands.rgba[i]) {
          ++differ;
          first = std::min(first, i);
        }
      EXPECT_EQ(differ, 0u) << where << ": first differing byte at pixel " << first / 4 << " (x "
                            << (first / 4) % scene.width << ", y " << (first / 4) / scene.width << ")";
    }
  }
}

Scene scene_file(const std::string& relative) {
  return load_scene(std::filesystem::path(PARASHADE_SOURCE_DIR) / "scenes" / relative);
}

TEST(StreamedBands, SameImageAsTheWholeFrameOnTheProjectScenes) {
  for (const char* name : {"teapot.json", "sphere.json"}) {
    Scene s = scene_file(name);
    s.width = 643;
    s.height = 357;  // the last tile row is cut by the frame
    expect_same_image(s, name, {16, 64}, 40);
  }
}

TEST(StreamedBands, SameImageAsTheWholeFrameOnTheHardScenes) {
  for (const char* name : {"big.json", "near_plane.json", "slivers.json"})
    expect_same_image(scene_file(std::string("hard/") + name), name, {16}, 1);
}

// Many small triangles overlapping in depth: a tile's triangles must stay in primitive order in every band.
TEST(StreamedBands, SameImageAsTheWholeFrameOnOverlappingSmallTriangles) {
  const Scene s = overlapping_spheres_scene();
  expect_same_image(s, "overlapping spheres", {16}, 40);
}

}  // namespace
}  // namespace parashade
