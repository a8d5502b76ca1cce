// The vertex stage and primitive assembly: snapping to the sub-pixel grid, winding, back-face culling,
// near-plane and guard-band clipping (new vertices on the plane, attributes interpolated in clip
// space), invalid coordinates, and independence from the thread count. Expected values come from the
// formulas of screen_geometry.hpp and [Dembitsky 2025, software/hardware rendering] §4.1 (lighting.hpp), not from the code under test.
#include <cmath>
#include <memory>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "parashade/geometry_stage.hpp"
#include "parashade/lighting.hpp"
#include "parashade/parallel.hpp"
#include "parashade/reference.hpp"
#include "parashade/vertex_lighting.hpp"
#include "parashade/shapes.hpp"
#include "test_support.hpp"

namespace parashade {
namespace {

using namespace testing_support;

std::int64_t area2(const ScreenGeometry& g, const glm::uvec3& t) {
  const glm::i64vec2 a(g.xy[t.x]), b(g.xy[t.y]), c(g.xy[t.z]);
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

TEST(GeometryStage, SnapsToEightFractionBitsWithPixelCentresAt128) {
  Scene s = ortho_scene(64, 32);
  // Pixel (10, 5)'s centre is world (10.5 - 32, 16 - 5.5); a quarter pixel right of it and an eighth below.
  add_mesh(s, {{10.5f - 32 + 0.25f, 16 - 5.5f - 0.125f, 0}, {20 - 32.0f, 16 - 20.0f, 0}, {5 - 32.0f, 16 - 25.0f, 0}},
           {{0, 1, 2}});
  ScreenGeometry g;
  build_screen_geometry(s, {Method::gouraud, false}, g);
  EXPECT_EQ(g.xy[0], glm::ivec2(256 * 10 + 128 + 64, 256 * 5 + 128 + 32));
  EXPECT_EQ(g.xy[1], glm::ivec2(256 * 20, 256 * 20));
  EXPECT_EQ(g.xy[2], glm::ivec2(256 * 5, 256 * 25));
}

TEST(GeometryStage, FrontFacesAreOrderedAndBackFacesCulledOnlyWhenAsked) {
  for (bool cull : {false, true}) {
    Scene s = ortho_scene(64, 64);
    s.cull_backfaces = cull;
    // Counter-clockwise seen from the camera (front), then the same triangle clockwise (back).
    add_mesh(s, {{-10, -10, 0}, {10, -10, 0}, {0, 10, 0}}, {{0, 1, 2}, {0, 2, 1}});
    ScreenGeometry g;
    build_screen_geometry(s, {Method::flat, false}, g);
    ASSERT_EQ(g.triangles.size(), cull ? 1u : 2u);
    EXPECT_EQ(g.stats.culled_backface, cull ? 1u : 0u);
    for (const auto& t : g.triangles) EXPECT_GT(area2(g, t), 0) << "E01(V2) > 0 order";
  }
}

TEST(GeometryStage, NearPlaneClippingPutsNewVerticesOnThePlaneWithInterpolatedColour) {
  Scene s = ortho_scene(100, 100);
  s.camera.near_plane = 5.0f;  // the plane z = 5 in world space (camera at z = 10)
  // One vertex in front of the near plane (z = 8: 2 from the camera), two behind it.
  const std::vector<glm::vec3> p = {{-20, -20, 0}, {20, -20, 0}, {0, 20, 8}};
  const std::vector<glm::vec3> n = {glm::normalize(glm::vec3(-0.5f, 0.2f, 1.0f)), glm::vec3(0, 0, 1),
                                    glm::normalize(glm::vec3(0.6f, -0.3f, 1.0f))};
  add_mesh(s, p, {{0, 1, 2}}, n);
  ScreenGeometry g;
  build_screen_geometry(s, {Method::gouraud, true}, g);
  ASSERT_EQ(g.stats.clipped, 1u);
  ASSERT_EQ(g.triangles.size(), 2u) << "one vertex cut off leaves a quadrilateral";
  ASSERT_EQ(g.xy.size(), 5u) << "three scene vertices and two made by clipping";
  // Orthographic depth is linear in z: window depth 0 at the near plane.
  const double z_near = 10.0 - s.camera.near_plane;
  for (std::size_t v = 3; v < 5; ++v) {
    EXPECT_NEAR(g.depth[v], 0.0, 1e-6) << "new vertex " << v << " on the near plane";
    EXPECT_NEAR(g.world[v].z, z_near, 1e-4);
    // It lies on the edge from vertex 0 or 1 (inside) to vertex 2 (outside): t = (z_near - z_in) / (8 - z_in).
    const std::size_t from = std::abs(g.world[v].x - (-20 + 20 * (z_near / 8))) < 1e-3 ? 0 : 1;
    const double t = z_near / 8.0;
    const glm::dvec3 expected_world = glm::dvec3(p[from]) + t * (glm::dvec3(p[2]) - glm::dvec3(p[from]));
    EXPECT_NEAR(glm::length(glm::dvec3(g.world[v]) - expected_world), 0.0, 1e-4);
    // Gouraud colour: the lit colours of the edge's ends, interpolated with the same t ([Dembitsky 2025, software/hardware rendering] §4.1 formula).
    const glm::dvec3 c_from = blinn_phong(s, s.materials[0], p[from], n[from]);
    const glm::dvec3 c_to = blinn_phong(s, s.materials[0], p[2], n[2]);
    const glm::dvec3 expected = c_from + t * (c_to - c_from);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(g.color[v][c], expected[c], 1e-2) << "channel " << c;
  }
  // The scene vertices that remain are lit by the same formula.
  for (std::size_t v = 0; v < 2; ++v) {
    const glm::dvec3 expected = blinn_phong(s, s.materials[0], p[v], n[v]);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(g.color[v][c], expected[c], 1e-2);
  }
}

TEST(GeometryStage, PerspectiveTriangleThroughTheCameraPlaneIsClippedNotExploded) {
  Scene s = ortho_scene(200, 100);
  s.camera.projection = Projection::perspective;
  s.camera.near_plane = 0.5f;
  // A floor triangle running from in front of the camera to behind it (w <= 0 there).
  add_mesh(s, {{-5, -1, -20}, {5, -1, -20}, {0, -1, 30}}, {{0, 1, 2}});
  ScreenGeometry g;
  build_screen_geometry(s, {Method::phong, true}, g);
  ASSERT_GE(g.triangles.size(), 1u);
  const int limit = 3 * 256 * 200;  // the guard band, generously
  for (const auto& t : g.triangles) {
    for (int k = 0; k < 3; ++k) {
      const glm::ivec2 xy = g.xy[t[k]];
      EXPECT_LT(std::abs(xy.x), limit);
      EXPECT_LT(std::abs(xy.y), limit);
      EXPECT_GE(g.depth[t[k]], -1e-6f);
      EXPECT_LE(g.depth[t[k]], 1.0f + 1e-6f);
    }
    EXPECT_GT(area2(g, t), 0);
  }
}

TEST(GeometryStage, TrianglesBeyondTheGuardBandAreClippedToIt) {
  Scene s = ortho_scene(100, 100);
  add_mesh(s, {{-5000, -5000, 0}, {5000, -5000, 0}, {0, 5000, 0}}, {{0, 1, 2}});
  ScreenGeometry g;
  build_screen_geometry(s, {Method::flat, false}, g);
  EXPECT_EQ(g.stats.clipped, 1u);
  ASSERT_GE(g.triangles.size(), 1u);
  for (const auto& t : g.triangles)
    for (int k = 0; k < 3; ++k) {
      // Guard band |ndc| <= 3: x in [-W, 2W] pixels (plus rounding).
      EXPECT_GE(g.xy[t[k]].x, -100 * 256 - 1);
      EXPECT_LE(g.xy[t[k]].x, 200 * 256 + 1);
    }
}

TEST(GeometryStage, CameraInsideALargeSphereSeesItsInsideWithinTheGuardBand) {
  // Many scene vertices lie far outside the guard band (behind or beside the camera); the triangles
  // that reach the screen must use only clipped vertices within it, and the reference must accept them.
  Scene s = ortho_scene(64, 48);
  s.camera.projection = Projection::perspective;
  s.camera.position = {0.0f, 0.0f, 0.5f};
  s.camera.far_plane = 1e5f;
  auto sphere = std::make_shared<Mesh>(make_sphere(32, 17));
  Object o;
  o.mesh = sphere;
  o.model = glm::scale(glm::mat4(1.0f), glm::vec3(1e4f));
  s.objects.push_back(o);
  ScreenGeometry g;
  build_screen_geometry(s, {Method::gouraud, true}, g);
  EXPECT_GT(g.stats.clipped, 0u);
  ASSERT_GT(g.triangles.size(), 0u);
  for (const auto& t : g.triangles)
    for (int k = 0; k < 3; ++k) {
      EXPECT_LE(std::abs(g.xy[t[k]].x), 3 * 64 * 256);
      EXPECT_LE(std::abs(g.xy[t[k]].y), 3 * 48 * 256);
    }
  const ReferenceImage r = render_reference(s, g, Method::gouraud);
  std::size_t covered = 0;
  for (auto c : r.covered) covered += c;
  EXPECT_EQ(covered, std::size_t(64 * 48)) << "inside a closed sphere every pixel sees it";
}

TEST(GeometryStage, NonFiniteAndOutsideTrianglesAreDroppedAndCounted) {
  Scene s = ortho_scene(64, 64);
  const float nan = std::nanf("");
  add_mesh(s, {{nan, 0, 0}, {10, 0, 0}, {0, 10, 0}, {100, 100, 0}, {110, 100, 0}, {100, 110, 0}},
           {{0, 1, 2}, {3, 4, 5}});
  ScreenGeometry g;
  build_screen_geometry(s, {Method::gouraud, false}, g);
  EXPECT_EQ(g.triangles.size(), 0u);
  EXPECT_EQ(g.stats.non_finite, 1u);
  EXPECT_EQ(g.stats.outside, 1u);
}

// Flat values come from the scene's vertex order (its face normal), also for a back face the stage
// reorders to screen winding; every screen triangle keeps its scene face index.
TEST(GeometryStage, FlatValueUsesTheSceneFaceNormalAndFacesAreKept) {
  Scene s = ortho_scene(320, 240);
  s.cull_backfaces = false;
  const glm::vec3 a(0, 0, 0), b(50, 0, 0), c(0, 50, 0);
  add_mesh(s, {a, b, c, {-80, -80, 0}}, {{0, 1, 2}, {0, 2, 1}, {3, 3, 3}, {0, 2, 1}});  // front, back, none, back
  ScreenGeometry g;
  build_screen_geometry(s, {Method::flat, false}, g);
  ASSERT_EQ(g.triangles.size(), 3u);
  EXPECT_EQ(g.face, (std::vector<std::uint32_t>{0, 1, 3}));
  const VertexLighting lighting(s);
  const glm::vec3 centroid = (a + b + c) / 3.0f;
  const glm::vec3 front = lighting.shade(0, centroid, {0, 0, 1}), back = lighting.shade(0, centroid, {0, 0, -1});
  ASSERT_NE(front, back);
  EXPECT_EQ(g.flat_color[0], front);
  EXPECT_EQ(g.flat_color[1], back);
  EXPECT_EQ(g.flat_color[2], back);
}

// Many triangles (the stage lights them in lanes): each screen triangle's flat value is the scalar
// lighting of its scene face at the centroid with the face normal, bit for bit, also for the pieces of
// a triangle clipped at the guard band and for faces seen from behind, under a point light and a local
// viewer (the specular power on most of them).
TEST(GeometryStage, FlatValuesOfManyTrianglesAreTheirFacesLighting) {
  Scene s = ortho_scene(320, 240);
  s.cull_backfaces = false;
  s.camera.projection = Projection::perspective;
  Light point;
  point.type = LightType::point;
  point.position = {30.0f, 40.0f, 25.0f};
  s.lights.push_back(point);
  s.materials.front().shininess = 23.0f;
  std::vector<glm::vec3> p;
  std::vector<glm::uvec3> t;
  std::uint32_t seed = 777;
  const auto rnd = [&] { return float((seed = seed * 1664525u + 1013904223u) >> 8) / float(1 << 24) - 0.5f; };
  for (std::uint32_t i = 0; i < 3 * 301; ++i) {  // not a multiple of the lanes
    // Every tenth triangle reaches far beyond the guard band (clipped into pieces).
    const float spread = (i / 3) % 10 == 0 ? 400.0f : 2.0f;
    if (i % 3 == 0) p.push_back({12 * rnd(), 9 * rnd(), 4 * rnd()});
    else p.push_back(p[i - i % 3] + glm::vec3(spread * rnd(), spread * rnd(), 2 * rnd()));
    if (i % 3 == 2) t.push_back({i - 2, i - 1, i});
  }
  add_mesh(s, p, t);
  ScreenGeometry g;
  build_screen_geometry(s, {Method::flat, false}, g);
  ASSERT_GT(g.triangles.size(), 250u);
  EXPECT_GT(g.stats.clipped, 10u);
  const VertexLighting lighting(s);
  for (std::size_t k = 0; k < g.triangles.size(); ++k) {
    const glm::uvec3 f = t[g.face[k]];
    const glm::vec3 a = p[f.x], b = p[f.y], c = p[f.z];
    const glm::vec3 m = glm::cross(b - a, c - a), n = m / glm::length(m);
    const glm::vec3 expected = lighting.shade(0, (a + b + c) / 3.0f, n);
    ASSERT_EQ(g.flat_color[k], expected) << "screen triangle " << k << " of face " << g.face[k];
  }
}

TEST(GeometryStage, OutputDoesNotDependOnTheThreadCount) {
  Scene s = ortho_scene(320, 240);
  s.camera.projection = Projection::perspective;
  std::vector<glm::vec3> p;
  std::vector<glm::uvec3> t;
  std::uint32_t seed = 12345;
  const auto rnd = [&] { return float((seed = seed * 1664525u + 1013904223u) >> 8) / float(1 << 24) - 0.5f; };
  for (std::uint32_t i = 0; i < 180000; ++i) {  // several assembly chunks
    // Small triangles around random centres; some cross the near plane or leave the guard band.
    if (i % 3 == 0) p.push_back({60 * rnd(), 60 * rnd(), 30 * rnd()});
    else p.push_back(p[i - i % 3] + glm::vec3(3 * rnd(), 3 * rnd(), 3 * rnd()));
    if (i % 3 == 2) t.push_back({i - 2, i - 1, i});
  }
  add_mesh(s, p, t);
  ScreenGeometry one, two;
  set_host_threads(1);
  build_screen_geometry(s, {Method::gouraud, true}, one);
  set_host_threads(2);
  build_screen_geometry(s, {Method::gouraud, true}, two);
  EXPECT_GT(one.stats.clipped, 100u);
  EXPECT_EQ(one.triangles, two.triangles);
  EXPECT_EQ(one.xy, two.xy);
  EXPECT_EQ(one.color, two.color);
  EXPECT_EQ(one.face, two.face);
  EXPECT_EQ(one.material, two.material);

  // The stage keeps its working buffers across frames: a geometry that held a larger, different frame
  // (more chunks, other clip-made vertices) and then this one gives what a fresh one gives.
  Scene big = s;
  big.objects.push_back(big.objects[0]);
  big.cull_backfaces = !s.cull_backfaces;
  ScreenGeometry reused;
  build_screen_geometry(big, {Method::flat, true}, reused);
  build_screen_geometry(s, {Method::gouraud, true}, reused);
  EXPECT_EQ(reused.triangles, two.triangles);
  EXPECT_EQ(reused.xy, two.xy);
  EXPECT_EQ(reused.color, two.color);
  EXPECT_EQ(reused.normal, two.normal);
  EXPECT_EQ(reused.stats.triangles_out, two.stats.triangles_out);
  EXPECT_EQ(reused.stats.clipped, two.stats.clipped);
  EXPECT_TRUE(reused.flat_color.empty());
}

}  // namespace
}  // namespace parashade
