// Lane utilization (lane_utilization.hpp) on frames worked out by hand: which lanes the kernel's row
// segments and 4x4 stamps evaluate for a one-pixel triangle and for a one-pixel-high strip.
#include <gtest/gtest.h>

#include "parashade/frame_pipeline.hpp"
#include "parashade/lane_utilization.hpp"
#include "test_support.hpp"

namespace parashade {
namespace {

using namespace testing_support;

// Screen (x, y) of a W x H ortho_scene as world coordinates.
glm::vec3 at(const Scene& s, float x, float y) { return {x - 0.5f * float(s.width), 0.5f * float(s.height) - y, 0.0f}; }

LaneUtilization measure(const Scene& s) {
  FrameConfig config;
  config.method = Method::gouraud;
  FramePipeline pipeline(config);
  return lane_utilization(pipeline.prepare_frame(s));
}

TEST(LaneUtilization, OnePixelTriangleUsesOneLaneOfSixteen) {
  Scene s = ortho_scene(64, 32);
  s.cull_backfaces = false;
  // Covers only the centre (5.5, 5.5): x + y = 11 < 11.2, and no other centre lies in its box.
  add_mesh(s, {at(s, 4.8f, 4.8f), at(s, 6.4f, 4.8f), at(s, 4.8f, 6.4f)}, {{0, 1, 2}});
  const LaneUtilization u = measure(s);
  EXPECT_EQ(u.covered, 1u);
  EXPECT_EQ(u.row_lanes, 16u);    // one row, one segment
  EXPECT_EQ(u.stamp_lanes, 16u);  // one stamp
  EXPECT_DOUBLE_EQ(u.rows(), 1.0 / 16.0);
}

TEST(LaneUtilization, OneRowStripFillsRowSegmentsAndAQuarterOfStamps) {
  Scene s = ortho_scene(128, 16);
  s.cull_backfaces = false;
  // Pixels 0..95 of row 0 as two triangles wider than a small one (96 > 64 pixels): the diagonal crosses
  // row 0's centres at x = 48, so one triangle covers 0..47 (tiles 0-2), the other 48..95 (tiles 3-5).
  add_mesh(s, {at(s, 0, 0), at(s, 96, 0), at(s, 96, 1), at(s, 0, 1)}, {{0, 1, 2}, {0, 2, 3}});
  const LaneUtilization u = measure(s);
  EXPECT_EQ(u.covered, 96u);
  EXPECT_EQ(u.row_lanes, 96u);       // per tile one row, one 16-pixel segment
  EXPECT_EQ(u.stamp_lanes, 6u * 64u);  // per tile four stamps, each with one row of four covered
  EXPECT_DOUBLE_EQ(u.rows(), 1.0);
  EXPECT_DOUBLE_EQ(u.stamps(), 0.25);
}

TEST(LaneUtilization, CoveredNeverExceedsEvaluatedOnTheTeapot) {
  Scene s = load_scene(source_dir() / "scenes" / "teapot.json");
  s.width = 480;
  s.height = 270;
  const LaneUtilization u = measure(s);
  EXPECT_GT(u.covered, 10000u);
  EXPECT_LE(u.covered, u.row_lanes);
  EXPECT_LE(u.covered, u.stamp_lanes);
}

}  // namespace
}  // namespace parashade
