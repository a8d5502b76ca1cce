// Planned frames (--cu, --partition) against the plain frame: the same bytes for every strategy, unit
// count and repeated run, with the units on one device or on its sub-devices; and the planner's host
// span walk against the kernel's modeled clocks.
#include <algorithm>
#include <cstring>
#include <memory>
#include <random>

#include <gtest/gtest.h>

#include "cl_fixture.hpp"
#include "parashade/geometry_stage.hpp"
#include "parashade/renderer.hpp"
#include "parashade/errors.hpp"
#include "parashade/setup.hpp"
#include "parashade/sub_devices.hpp"
#include "test_support.hpp"

namespace parashade {
namespace {

using namespace testing_support;

// Random triangles, each also drawn a second time with other normals: the copies tie in depth with
// their originals at every pixel, so the tie rule (first in primitive order) decides half the image.
Scene tie_scene(int width, int height) {
  std::mt19937 rng(77);
  Scene scene = pixel_scene(width, height);
  auto mesh = random_triangles(300, width, height, 40.0f, rng);
  auto twin = std::make_shared<Mesh>(*mesh);
  for (glm::vec3& n : twin->normals) n = glm::normalize(glm::vec3(-n.x, n.y * 0.5f, n.z));
  add_object(scene, mesh);
  add_object(scene, twin);
  return scene;
}

using Bytes = std::vector<std::uint8_t>;

Bytes render_bytes(const Scene& scene, RenderOptions o, Device& device = test_device()) {
  Renderer r(device, o);
  const auto& rgba = r.render(scene).image.rgba;
  return Bytes(rgba.begin(), rgba.end());
}

template <typename A>
std::size_t differing_pixels(const A& a, const Bytes& b) {
  std::size_t n = 0;
  for (std::size_t p = 0; p + 3 < a.size(); p += 4) n += std::memcmp(&a[p], &b[p], 4) != 0;
  return n;
}

// On `device`, or with the units' pass spread over `unit_devices` (sub-devices of `device`).
void expect_planned_equal(const Scene& scene, RenderOptions base, const std::vector<int>& units,
                          Device& device = test_device(), const std::vector<Device*>& unit_devices = {}) {
  const Bytes plain = render_bytes(scene, base, device);
  for (Partition p : {Partition::round_robin, Partition::lpt, Partition::tiles, Partition::dynamic})
    for (int u : units) {
      RenderOptions o = base;
      PlanOptions plan;
      plan.partition = p;
      plan.units = u;
      plan.batch = 16;
      o.plan = plan;
      Renderer r(device, o, unit_devices);
      for (int run = 0; run < 2; ++run) {
        const Frame& f = r.render(scene);
        ASSERT_EQ(f.image.rgba.size(), plain.size());
        EXPECT_EQ(differing_pixels(f.image.rgba, plain), 0u)
            << partition_name(p) << " U=" << u << " run " << run << " on " << unit_devices.size()
            << " sub-device(s): pixels differing from the plain frame";
        ASSERT_TRUE(f.stats.plan.has_value());
        EXPECT_EQ(f.stats.plan->units, u);
        // Every unit and every packet of the work lists runs on exactly one device, in contiguous blocks.
        ASSERT_EQ(f.stats.unit_pass.size(), std::max<std::size_t>(1, unit_devices.size()));
        EXPECT_EQ(f.stats.unit_pass_on_sub_devices, !unit_devices.empty());
        ASSERT_EQ(f.timings.unit_pass_share_ms.size(), f.stats.unit_pass.size());
        int next_unit = 0, next_packet = 0;
        for (const UnitPassShare& s : f.stats.unit_pass) {
          EXPECT_EQ(s.first_unit, next_unit);
          EXPECT_EQ(s.first_packet, next_packet);
          next_unit += s.units;
          next_packet += s.packets;
        }
        EXPECT_EQ(next_unit, u);
        EXPECT_EQ(next_packet, p == Partition::dynamic ? next_packet : u);
      }
    }
}

TEST(PlannedFrame, SameBytesAsPlainForEveryStrategyAndUnitCount) {
  const Scene scene = tie_scene(320, 200);
  RenderOptions o;
  o.method = Method::gouraud;
  expect_planned_equal(scene, o, {1, 2, 3, 8});
}

TEST(PlannedFrame, SameBytesWithPhongAndLargeTiles) {
  const Scene scene = tie_scene(257, 131);
  RenderOptions o;
  o.method = Method::phong;
  o.tile_size = 32;
  expect_planned_equal(scene, o, {2, 3});
}

TEST(PlannedFrame, SameBytesOnTheFixedPointUnitPath) {
  const Scene scene = tie_scene(300, 170);
  RenderOptions o;
  o.units = parse_units("interleave:4");
  o.arith = parse_arith("fixed:12.12");
  expect_planned_equal(scene, o, {3, 8});
}

TEST(PlannedFrame, SameBytesOnASharedMesh) {
  PARASHADE_REQUIRE_MESH_DIR(dir);
  Scene scene = scene_for_mesh(dir / "stanford-bunny.obj");
  scene.width = 480;
  scene.height = 360;
  RenderOptions o;
  expect_planned_equal(scene, o, {1, 3, 8});
}

// The units' depth pass spread over sub-devices of PoCL's pthread device (parent and sub-devices in one
// context; each sub-device's units into keys of its own, min-merged on the parent): the same bytes.
TEST(PlannedFrame, SameBytesWithUnitsOnSubDevices) {
  std::unique_ptr<Device> pthread;
  try {
    pthread = open_device("pthread");
  } catch (const DeviceError& e) {
    GTEST_SKIP() << "no PoCL pthread device: " << e.what();
  }
  if (pthread->info().compute_units < 2)
    GTEST_SKIP() << "'" << pthread->info().name << "' offers " << pthread->info().compute_units
                 << " compute unit(s); two sub-devices of one need 2";
  const Scene scene = tie_scene(320, 200);
  const RenderOptions o;
  for (const char* selector : {"sub:pthread:1", "sub:pthread:1+1"}) {
    SCOPED_TRACE(selector);
    const SubDevices sub = open_sub_devices(selector, SubDeviceContext::shared);
    std::vector<Device*> units_on;
    for (const auto& d : sub.subs) units_on.push_back(d.get());
    ASSERT_GE(units_on.size(), 2u);
    expect_planned_equal(scene, o, {1, 2, 3, 8}, *sub.parent, units_on);
  }
}

TEST(PlannedFrame, HostSpanClocksEqualTheKernelsCount) {
  // With no setup clocks, a triangle partition's total is the sum over all spans of load + span clocks,
  // walked on the host by integer edge functions; the kernel counts the same spans its own way.
  const Scene scene = tie_scene(320, 200);
  for (const char* unit : {"classic", "counter", "segment:8"}) {
    RenderOptions o;
    o.units = parse_units(unit);
    PlanOptions plan;
    plan.partition = Partition::round_robin;
    plan.units = 3;
    plan.setup_clocks = 0;
    o.plan = plan;
    Renderer r(test_device(), o);
    const Frame& f = r.render(scene);
    ASSERT_TRUE(f.stats.plan.has_value());
    std::uint64_t spans = 0, pixels = 0;
    for (const UnitLoad& l : f.stats.plan->load) {
      spans += l.spans;
      pixels += l.pixels;
    }
    EXPECT_GT(f.stats.clocks.clocks, 0u);
    EXPECT_EQ(f.stats.plan->total_clocks(), f.stats.clocks.clocks) << unit;
    EXPECT_EQ(spans, f.stats.clocks.spans) << unit;
    EXPECT_EQ(pixels, f.stats.clocks.pixels) << unit;
  }
}

TEST(PlannerSpans, EqualBruteForceEdgeFunctions) {
  std::mt19937 rng(5);
  Scene scene = pixel_scene(200, 150);
  add_object(scene, random_triangles(200, 200, 150, 90.0f, rng));
  ScreenGeometry g;
  build_screen_geometry(scene, {Method::gouraud, false}, g);
  std::vector<TriangleGeometry> tris(g.triangles.size());
  std::vector<float> attrs(tris.size() * attribute_floats(Method::gouraud));
  setup_triangles(g, Method::gouraud, tris.data(), attrs.data());
  std::size_t checked = 0;
  for (const TriangleGeometry& t : tris) {
    if (t.x0 > t.x1) continue;
    std::vector<int> lo(std::size_t(t.y1 - t.y0 + 1), 1), hi(lo.size(), 0);
    for_each_span(t, [&](int dy, int xl, int xr) {
      lo[std::size_t(dy)] = xl;
      hi[std::size_t(dy)] = xr;
    });
    for (int dy = 0; dy <= t.y1 - t.y0; ++dy)
      for (int dx = 0; dx <= t.x1 - t.x0; ++dx) {
        bool inside = true;
        for (int e = 0; e < 3; ++e)
          inside &= t.edge_c[e] + std::int64_t(t.edge_a[e]) * dx + std::int64_t(t.edge_b[e]) * dy >= 0;
        const bool spanned = dx >= lo[std::size_t(dy)] && dx <= hi[std::size_t(dy)];
        ASSERT_EQ(inside, spanned) << "pixel (" << dx << ", " << dy << ") of a triangle";
        ++checked;
      }
  }
  EXPECT_GT(checked, 10000u);
}

}  // namespace
}  // namespace parashade
