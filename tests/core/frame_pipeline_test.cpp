// The frame prepared on the host alone (frame_pipeline.hpp): records, bins, band and plan as the device
// renderer gets them, with no OpenCL in the process. Each check is a property of binning or planning
// stated here (a triangle is in a tile's list iff its box and edges may cover a pixel of it), not a copy
// of the code's output.
#include <algorithm>
#include <memory>
#include <set>

#include <gtest/gtest.h>

#include "parashade/combinations.hpp"
#include "parashade/frame_pipeline.hpp"
#include "parashade/scene.hpp"
#include "parashade/shapes.hpp"

namespace parashade {
namespace {

Scene teapot(int w, int h) {
  Scene s = load_scene(std::string(PARASHADE_SOURCE_DIR) + "/scenes/teapot.json");
  s.width = w;
  s.height = h;
  return s;
}

// Every triangle with pixels is in the list of every tile its pixels fall in, and nowhere outside its box.
void expect_bins_hold_the_pixels(const PreparedFrame& f) {
  ASSERT_EQ(f.tile_start[0], 0u);
  std::vector<std::set<std::uint32_t>> listed(std::size_t(f.tiles()));
  for (int t = 0; t < f.tiles(); ++t) {
    ASSERT_LE(f.tile_start[t], f.tile_start[t + 1]);
    for (std::uint32_t e = f.tile_start[t]; e < f.tile_start[t + 1]; ++e) {
      const std::uint32_t i = f.tile_list[e];
      ASSERT_LT(i, f.records);
      listed[std::size_t(t)].insert(i);
      const TriangleGeometry& r = f.arrays.triangles[i];
      const int tx = (t % f.tiles_x) * f.tile_size, ty = (t / f.tiles_x) * f.tile_size;
      EXPECT_TRUE(r.x0 < tx + f.tile_size && r.x1 >= tx && r.y0 < ty + f.tile_size && r.y1 >= ty)
          << "triangle " << i << " listed in tile " << t << " outside its box";
    }
  }
  for (std::size_t i = 0; i < f.records; ++i) {
    const TriangleGeometry& r = f.arrays.triangles[i];
    for_each_span(r, [&](int dy, int xl, int xr) {  // a row's covered pixels, from the box corner
      const int y = r.y0 + dy;
      for (int px = r.x0 + xl; px <= r.x0 + xr; ++px) {
        const int t = (y / f.tile_size) * f.tiles_x + px / f.tile_size;
        EXPECT_EQ(listed[std::size_t(t)].count(std::uint32_t(i)), 1u) << "pixel " << px << "," << y << " of " << i;
      }
    });
  }
}

TEST(FramePipeline, PreparesRecordsAndBinsWithoutADevice) {
  const Scene scene = teapot(320, 180);
  FrameConfig config;
  config.tile_size = 32;
  FramePipeline pipeline(config);
  const PreparedFrame& f = pipeline.prepare_frame(scene);
  EXPECT_EQ(f.records, f.geometry->triangles.size());
  EXPECT_GT(f.records, 1000u);
  EXPECT_EQ(f.tiles_x, 10);
  EXPECT_EQ(f.tiles_y, 6);  // 180 / 32 rounded up
  EXPECT_EQ(f.stats.bin_entries, f.bin_entries());
  EXPECT_EQ(f.plan, nullptr);
  expect_bins_hold_the_pixels(f);
}

TEST(FramePipeline, ABandKeepsItsTilesAndEmptiesTheRest) {
  const Scene scene = teapot(320, 180);
  FrameConfig config;
  FramePipeline whole_pipeline(config);
  const PreparedFrame& whole = whole_pipeline.prepare_frame(scene);
  config.band_first = 3;
  config.band_rows = 4;
  FramePipeline band_pipeline(config);
  const PreparedFrame& band = band_pipeline.prepare_frame(scene);
  for (int t = 0; t < band.tiles(); ++t) {
    const int row = t / band.tiles_x;
    const std::uint32_t n = band.tile_start[t + 1] - band.tile_start[t];
    if (row < 3 || row >= 7) {
      EXPECT_EQ(n, 0u) << "tile " << t;
      continue;
    }
    ASSERT_EQ(n, whole.tile_start[t + 1] - whole.tile_start[t]) << "tile " << t;
    for (std::uint32_t k = 0; k < n; ++k)
      EXPECT_EQ(band.tile_list[band.tile_start[t] + k], whole.tile_list[whole.tile_start[t] + k]);
  }
}

TEST(FramePipeline, APlanCoversEveryTriangleOnce) {
  const Scene scene = teapot(320, 180);
  FrameConfig config;
  config.plan = PlanOptions{};
  config.plan->units = 3;
  FramePipeline pipeline(config);
  const PreparedFrame& f = pipeline.prepare_frame(scene);
  ASSERT_NE(f.plan, nullptr);
  ASSERT_TRUE(f.stats.plan);
  EXPECT_EQ(f.plan->report.units, 3);
  // LPT deals whole triangles: the units together start every record with a pixel box exactly once.
  std::uint64_t with_box = 0, started = 0;
  for (std::size_t i = 0; i < f.records; ++i) with_box += f.arrays.triangles[i].x0 <= f.arrays.triangles[i].x1;
  for (const UnitLoad& l : f.plan->report.load) started += l.triangles;
  EXPECT_GT(with_box, 0u);
  EXPECT_EQ(started, with_box);
  // Unresolved units (0: the device's compute units) need a device to resolve them.
  config.plan->units = 0;
  EXPECT_THROW(FramePipeline(config).prepare_frame(scene), UsageError);
}

TEST(FramePipeline, TheExtraTriangulationSplitsEveryRecord) {
  const Scene scene = teapot(320, 180);
  FrameConfig config;
  config.units = parse_units("sierpinski:2");
  FramePipeline pipeline(config);
  const PreparedFrame& f = pipeline.prepare_frame(scene);
  EXPECT_EQ(f.records, 16 * f.geometry->triangles.size());
  EXPECT_NE(f.arrays.leaves, nullptr);
}

// Plain host arrays for prepare_band.
class Arrays : public FrameStorage {
 public:
  FrameRecords records(std::size_t n, std::size_t attribute_floats, bool, bool) override {
    triangles_.resize(n);
    attributes_.resize(n * attribute_floats);
    return {triangles_.data(), attributes_.data(), nullptr, nullptr};
  }
  std::uint32_t* tile_list(std::size_t entries) override {
    list_.resize(std::max<std::size_t>(entries, 1));
    return list_.data();
  }

 private:
  std::vector<TriangleGeometry> triangles_;
  std::vector<float> attributes_;
  std::vector<std::uint32_t> list_;
};

// The default records budget: a frame streams only when its records exceed 16 MiB plus its colour and
// depth bytes (8 a pixel), and then in bands of at most 16 MiB; a given budget is both.
TEST(FramePipeline, DefaultBudgetStreamsAboveTheFramesOwnBytesInBandsOf16MiB) {
  constexpr std::size_t MiB = std::size_t(1) << 20;
  EXPECT_EQ(default_band_mib(1920, 1080), 32);  // 15.8 MiB of pixels, rounded up
  EXPECT_EQ(default_band_mib(3840, 2160), 80);  // 63.3 MiB
  EXPECT_EQ(default_band_mib(1, 1), 17);
  EXPECT_EQ(record_budget(kBandBytesByFrame, 3840, 2160).stream_above, 80 * MiB);
  EXPECT_EQ(record_budget(kBandBytesByFrame, 3840, 2160).band, 16 * MiB);
  EXPECT_EQ(record_budget(5 * MiB, 3840, 2160).stream_above, 5 * MiB);
  EXPECT_EQ(record_budget(5 * MiB, 3840, 2160).band, 5 * MiB);

  // The benchmark's sphere_2m at 3840x2160: Gouraud's records (~70 MiB) stay whole, Phong's (~100) stream.
  Scene scene = load_scene(std::string(PARASHADE_SOURCE_DIR) + "/scenes/sphere.json");
  scene.objects[0].mesh = std::make_shared<Mesh>(make_sphere(1024, 1025));
  scene.width = 3840;
  scene.height = 2160;
  for (Method method : {Method::gouraud, Method::phong}) {
    FrameConfig config;
    config.method = method;
    FramePipeline pipeline(config);
    const int bands = pipeline.begin_frame(scene, kBandBytesByFrame);
    const std::size_t bytes = pipeline.geometry().triangles.size() * triangle_record_bytes(method);
    ASSERT_GT(bytes, 16 * MiB) << method_name(method);
    EXPECT_EQ(bands == 1, bytes <= 80 * MiB) << method_name(method) << ": " << bytes / MiB << " MiB of records";
    std::size_t largest = 0;
    Arrays storage;
    for (int b = 0; b < bands; ++b)
      largest = std::max(largest, pipeline.prepare_band(scene, storage, b).records);
    if (bands > 1) EXPECT_LE(largest * triangle_record_bytes(method), 16 * MiB) << method_name(method);
    EXPECT_EQ(bands, method == Method::gouraud ? 1 : 7) << "the sphere's records against this budget";
  }
}

// The configuration is checked once, when the pipeline is made: before any frame's work.
TEST(FramePipeline, ARefusedCombinationStopsBeforeAnyWork) {
  FrameConfig config;
  config.method = Method::flat;
  config.arith = parse_arith("fixed:12.12");
  EXPECT_THROW(FramePipeline pipeline(config), ConfigError);
}

}  // namespace
}  // namespace parashade
