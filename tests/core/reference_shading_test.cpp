// The reference's values: each method's ideal, exact (perspective-correct) Phong, depth and background.
// Expected values are computed here independently, from pixel-unit geometry.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "parashade/lighting.hpp"
#include "parashade/parallel.hpp"
#include "parashade/reference.hpp"
#include "screen_fixtures.hpp"

namespace parashade {
namespace {

using test_fixtures::centre;
using test_fixtures::GeometryBuilder;
using test_fixtures::simple_scene;
using test_fixtures::Vertex;

std::size_t index(const ReferenceImage& r, int x, int y) { return std::size_t(y) * r.width + x; }

// Screen-space barycentrics of the centre of pixel (x, y), from signed areas in pixel units.
glm::dvec3 barycentrics(const ScreenGeometry& g, std::size_t t, int x, int y) {
  const glm::uvec3 idx = g.triangles[t];
  const glm::dvec2 p(x + 0.5, y + 0.5);
  glm::dvec2 v[3];
  for (int k = 0; k < 3; ++k) v[k] = glm::dvec2(g.xy[idx[k]]) / double(kSubpixel);
  auto area = [](glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  };
  const double whole = area(v[0], v[1], v[2]);
  return {area(p, v[1], v[2]) / whole, area(v[0], p, v[2]) / whole, area(v[0], v[1], p) / whole};
}

// A point light near the surface and a local viewer: L and V vary per pixel.
Scene lit_scene() {
  Scene s;
  s.camera.position = {0.3f, -0.2f, 4.0f};
  s.local_viewer = true;
  s.ambient_light = glm::vec3(0.2f);
  Light light;
  light.type = LightType::point;
  light.position = {1.0f, 1.5f, 2.0f};
  light.color = glm::vec3(0.6f);
  s.lights = {light};
  Material m;
  m.ambient = {0.1f, 0.1f, 0.15f};
  m.diffuse = {0.5f, 0.4f, 0.3f};
  m.specular = glm::vec3(0.3f);
  m.shininess = 12.0f;
  s.materials = {m};
  return s;
}

// One triangle over a 16x16 screen with strongly varying normals and positions.
GeometryBuilder phong_triangle(float inv_w0, float inv_w1, float inv_w2) {
  GeometryBuilder b(16, 16);
  Vertex v0, v1, v2;
  v0.xy = {301, 517};
  v1.xy = {3900, 1100};
  v2.xy = {1500, 3700};
  v0.world = {-1.0f, 1.0f, 0.0f};
  v1.world = {1.0f, 0.8f, -0.5f};
  v2.world = {-0.2f, -1.0f, 0.4f};
  v0.normal = glm::normalize(glm::vec3(0.0f, 0.0f, 1.0f));
  v1.normal = glm::normalize(glm::vec3(1.0f, 0.1f, 0.2f));
  v2.normal = glm::normalize(glm::vec3(-0.3f, 1.0f, 0.3f));
  v0.inv_w = inv_w0;
  v1.inv_w = inv_w1;
  v2.inv_w = inv_w2;
  b.triangle(b.vertex(v0), b.vertex(v1), b.vertex(v2));
  return b;
}

TEST(ReferenceShading, GouraudIdealIsThePlaneThroughTheVertexColours) {
  GeometryBuilder b(16, 16);
  const glm::dvec2 pos[3] = {{301, 517}, {3900, 1100}, {1500, 3700}};
  const glm::dvec3 col[3] = {{10, 200, 30}, {250, 20, 100}, {40, 90, 240}};
  std::uint32_t ids[3];
  for (int k = 0; k < 3; ++k) {
    Vertex v;
    v.xy = glm::ivec2(pos[k]);
    v.color = glm::vec3(col[k]);
    ids[k] = b.vertex(v);
  }
  b.triangle(ids[0], ids[1], ids[2]);

  // Plane c = a x + b y + d per channel through the three vertices (pixel units), by Cramer's rule.
  glm::dvec2 p[3];
  for (int k = 0; k < 3; ++k) p[k] = pos[k] / double(kSubpixel);
  const double det = p[0].x * (p[1].y - p[2].y) + p[1].x * (p[2].y - p[0].y) + p[2].x * (p[0].y - p[1].y);
  auto plane_at = [&](double x, double y) {
    glm::dvec3 out;
    for (int c = 0; c < 3; ++c) {
      const double a =
          (col[0][c] * (p[1].y - p[2].y) + col[1][c] * (p[2].y - p[0].y) + col[2][c] * (p[0].y - p[1].y)) /
          det;
      const double bb =
          (col[0][c] * (p[2].x - p[1].x) + col[1][c] * (p[0].x - p[2].x) + col[2][c] * (p[1].x - p[0].x)) /
          det;
      const double d = col[0][c] - a * p[0].x - bb * p[0].y;
      out[c] = a * x + bb * y + d;
    }
    return out;
  };

  const ReferenceImage r = render_reference(simple_scene(), b.geometry(), Method::gouraud);
  int compared = 0;
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      const std::size_t i = index(r, x, y);
      if (!r.covered[i]) continue;
      ++compared;
      const glm::dvec3 want = plane_at(x + 0.5, y + 0.5);
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(r.ideal[i][c], want[c], 1e-9) << "pixel (" << x << ", " << y << ")";
    }
  EXPECT_GT(compared, 40);
}

TEST(ReferenceShading, IdealIsClampedToLevels) {
  GeometryBuilder b(8, 8);
  Vertex v;
  v.color = {400.0f, -50.0f, 100.0f};
  v.xy = {centre(0), centre(0)};
  const auto a = b.vertex(v);
  v.xy = {centre(7), centre(0)};
  const auto c = b.vertex(v);
  v.xy = {centre(0), centre(7)};
  b.triangle(a, c, b.vertex(v), glm::vec3(300.0f, -1.0f, 7.0f));
  const ReferenceImage g = render_reference(simple_scene(), b.geometry(), Method::gouraud);
  const glm::dvec3 gouraud = g.ideal[index(g, 2, 2)];
  EXPECT_EQ(gouraud.x, 255.0);
  EXPECT_EQ(gouraud.y, 0.0);
  EXPECT_NEAR(gouraud.z, 100.0, 1e-9);  // interpolating a constant, up to rounding
  const ReferenceImage f = render_reference(simple_scene(), b.geometry(), Method::flat);
  EXPECT_EQ(f.ideal[index(f, 2, 2)], glm::dvec3(255.0, 0.0, 7.0));
}

TEST(ReferenceShading, PhongIdealEqualsExactWhenOneOverWIsConstant) {
  const GeometryBuilder b = phong_triangle(0.5f, 0.5f, 0.5f);
  const ReferenceImage r = render_reference(lit_scene(), b.geometry(), Method::phong);
  int compared = 0;
  for (std::size_t i = 0; i < r.covered.size(); ++i) {
    if (!r.covered[i]) continue;
    ++compared;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(r.ideal[i][c], r.exact[i][c], 1e-9);
  }
  EXPECT_GT(compared, 40);
}

TEST(ReferenceShading, ExactPhongIsPerspectiveCorrectIdealIsScreenSpace) {
  const Scene scene = lit_scene();
  const GeometryBuilder b = phong_triangle(1.0f, 0.25f, 0.5f);
  const ScreenGeometry& g = b.geometry();
  const ReferenceImage r = render_reference(scene, g, Method::phong);

  const int x = 7, y = 7;
  const std::size_t i = index(r, x, y);
  ASSERT_TRUE(r.covered[i]);
  const glm::dvec3 bc = barycentrics(g, 0, x, y);
  const glm::uvec3 idx = g.triangles[0];
  auto interpolate = [&](const std::vector<glm::vec3>& attr, glm::dvec3 w) {
    return w.x * glm::dvec3(attr[idx.x]) + w.y * glm::dvec3(attr[idx.y]) + w.z * glm::dvec3(attr[idx.z]);
  };
  // Perspective-correct weights: b_k / w_k, renormalized.
  glm::dvec3 pc = bc * glm::dvec3(g.inv_w[idx.x], g.inv_w[idx.y], g.inv_w[idx.z]);
  pc /= pc.x + pc.y + pc.z;

  const Material& m = scene.materials[0];
  const glm::dvec3 ideal =
      blinn_phong(scene, m, interpolate(g.world, bc), glm::normalize(interpolate(g.normal, bc)));
  const glm::dvec3 exact =
      blinn_phong(scene, m, interpolate(g.world, pc), glm::normalize(interpolate(g.normal, pc)));
  for (int c = 0; c < 3; ++c) {
    // Nothing is clamped at this pixel.
    ASSERT_GT(std::min(ideal[c], exact[c]), 0.0);
    ASSERT_LT(std::max(ideal[c], exact[c]), 255.0);
    EXPECT_NEAR(r.ideal[i][c], ideal[c], 1e-9);
    EXPECT_NEAR(r.exact[i][c], exact[c], 1e-9);
    EXPECT_NEAR(r.exact[i][c] - r.ideal[i][c], exact[c] - ideal[c], 1e-9);
  }
  // The perspective difference is large here, so the test would notice if exact ignored 1/w.
  EXPECT_GT(glm::length(exact - ideal), 2.0);
}

TEST(ReferenceShading, ZeroInterpolatedNormalFallsBackToTheFaceNormalTowardTheViewer) {
  Scene scene = lit_scene();
  scene.local_viewer = false;  // viewer along +z
  scene.camera.position = {0.0f, 0.0f, 5.0f};
  GeometryBuilder b(8, 8);
  Vertex v;
  v.normal = glm::vec3(0.0f);
  // World triangle in z = 0 wound so that its cross product points to -z: the fallback must flip it.
  v.xy = {centre(0), centre(0)};
  v.world = {0.0f, 0.0f, 0.0f};
  const auto a = b.vertex(v);
  v.xy = {centre(7), centre(0)};
  v.world = {0.0f, 1.0f, 0.0f};
  const auto c = b.vertex(v);
  v.xy = {centre(0), centre(7)};
  v.world = {1.0f, 0.0f, 0.0f};
  b.triangle(a, c, b.vertex(v));
  const ReferenceImage r = render_reference(scene, b.geometry(), Method::phong);
  const std::size_t i = index(r, 2, 3);
  ASSERT_TRUE(r.covered[i]);
  const ScreenGeometry& g = b.geometry();
  const glm::dvec3 bc = barycentrics(g, 0, 2, 3);
  const glm::uvec3 idx = g.triangles[0];
  const glm::dvec3 pos = bc.x * glm::dvec3(g.world[idx.x]) + bc.y * glm::dvec3(g.world[idx.y]) +
                         bc.z * glm::dvec3(g.world[idx.z]);
  const glm::dvec3 want = blinn_phong(scene, scene.materials[0], pos, glm::dvec3(0, 0, 1));
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(r.ideal[i][c], want[c], 1e-9);
    EXPECT_NEAR(r.exact[i][c], want[c], 1e-9);
  }
}

TEST(ReferenceShading, DepthTiesGoToTheEarlierTriangle) {
  const Scene scene = simple_scene();
  const glm::vec3 red(255, 0, 0), green(0, 255, 0);
  auto two_triangles = [&](float depth_first, float depth_second) {
    GeometryBuilder b(8, 8);
    const glm::ivec2 corners[3] = {{centre(0), centre(0)}, {centre(7), centre(0)}, {centre(0), centre(7)}};
    std::uint32_t first[3], second[3];
    for (int k = 0; k < 3; ++k) first[k] = b.vertex(corners[k], depth_first);
    for (int k = 0; k < 3; ++k) second[k] = b.vertex(corners[k], depth_second);
    b.triangle(first[0], first[1], first[2], red);
    b.triangle(second[0], second[1], second[2], green);
    return render_reference(scene, b.geometry(), Method::flat);
  };
  const ReferenceImage tie = two_triangles(0.5f, 0.5f);
  EXPECT_EQ(tie.triangle[index(tie, 2, 2)], 0);
  EXPECT_EQ(tie.ideal[index(tie, 2, 2)], glm::dvec3(red));
  const ReferenceImage nearer_second = two_triangles(0.5f, 0.4f);
  EXPECT_EQ(nearer_second.triangle[index(nearer_second, 2, 2)], 1);
  EXPECT_EQ(nearer_second.ideal[index(nearer_second, 2, 2)], glm::dvec3(green));
  const ReferenceImage nearer_first = two_triangles(0.3f, 0.4f);
  EXPECT_EQ(nearer_first.triangle[index(nearer_first, 2, 2)], 0);
}

TEST(ReferenceShading, DepthIsInterpolatedAcrossTheTriangle) {
  // A tilted square (depth 0.25 at the left, 0.8 at the right) against a later flat one at 0.5: the
  // tilted one is visible where its depth is below 0.5 (no pixel centre sits at the crossing).
  GeometryBuilder b(17, 4);
  const int x0 = centre(0), x1 = centre(16), y0 = centre(0), y1 = centre(3);
  const auto a0 = b.vertex({x0, y0}, 0.25f), a1 = b.vertex({x1, y0}, 0.8f);
  const auto a2 = b.vertex({x1, y1}, 0.8f), a3 = b.vertex({x0, y1}, 0.25f);
  b.triangle(a0, a1, a2);
  b.triangle(a0, a2, a3);
  const auto f0 = b.vertex({x0, y0}, 0.5f), f1 = b.vertex({x1, y0}, 0.5f);
  const auto f2 = b.vertex({x1, y1}, 0.5f), f3 = b.vertex({x0, y1}, 0.5f);
  b.triangle(f0, f1, f2);
  b.triangle(f0, f2, f3);
  const ReferenceImage r = render_reference(simple_scene(), b.geometry(), Method::flat);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 16; ++x) {
      const double tilted_depth = 0.25 + 0.55 * x / 16.0;  // pixel centres x + 0.5 lie at 16ths of the width
      const bool tilted_visible = tilted_depth < 0.5;
      EXPECT_EQ(r.triangle[index(r, x, y)] < 2, tilted_visible) << "pixel (" << x << ", " << y << ")";
    }
}

TEST(ReferenceShading, UncoveredPixelsAreBackground) {
  Scene scene = simple_scene();
  scene.background = {0.2f, 0.4f, 1.0f};
  GeometryBuilder b(8, 8);
  b.triangle(b.vertex({centre(0), centre(0)}), b.vertex({centre(3), centre(0)}),
             b.vertex({centre(0), centre(3)}));
  const ReferenceImage r = render_reference(scene, b.geometry(), Method::phong);
  const std::size_t i = index(r, 6, 6);
  EXPECT_EQ(r.covered[i], 0);
  EXPECT_EQ(r.triangle[i], -1);
  const glm::dvec3 bg = 255.0 * glm::dvec3(scene.background);
  EXPECT_EQ(r.ideal[i], bg);
  EXPECT_EQ(r.exact[i], bg);
}

TEST(ReferenceShading, ResultDoesNotDependOnTheThreadCount) {
  // Many overlapping triangles at varying depths over several bands.
  GeometryBuilder b(64, 64);
  std::uint32_t state = 99;
  auto next = [&state](int n) {
    state = state * 1664525u + 1013904223u;
    return int((state >> 8) % std::uint32_t(n));
  };
  for (int t = 0; t < 300; ++t) {
    Vertex v[3];
    std::uint32_t ids[3];
    for (int k = 0; k < 3; ++k) {
      v[k].xy = {next(64 * kSubpixel), next(64 * kSubpixel)};
      v[k].depth = float(next(4)) / 4.0f;  // coarse depths: many ties
      v[k].inv_w = 0.2f + float(next(100)) / 100.0f;
      v[k].world = glm::vec3(next(100), next(100), next(100)) / 50.0f - 1.0f;
      v[k].normal = glm::normalize(glm::vec3(next(100) - 50, next(100) - 50, next(100) + 1));
      v[k].color = glm::vec3(next(256), next(256), next(256));
      ids[k] = b.vertex(v[k]);
    }
    const std::int64_t area2 = std::int64_t(v[1].xy.x - v[0].xy.x) * (v[2].xy.y - v[0].xy.y) -
                               std::int64_t(v[1].xy.y - v[0].xy.y) * (v[2].xy.x - v[0].xy.x);
    if (area2 != 0) b.triangle(ids[0], ids[1], ids[2], glm::vec3(float(t % 256)));
  }
  const Scene scene = lit_scene();
  const unsigned threads = host_threads();
  set_host_threads(1);
  const ReferenceImage serial = render_reference(scene, b.geometry(), Method::phong);
  set_host_threads(4);
  const ReferenceImage parallel = render_reference(scene, b.geometry(), Method::phong);
  set_host_threads(threads);
  EXPECT_EQ(serial.covered, parallel.covered);
  EXPECT_EQ(serial.triangle, parallel.triangle);
  EXPECT_EQ(serial.ideal, parallel.ideal);
  EXPECT_EQ(serial.exact, parallel.exact);
}

}  // namespace
}  // namespace parashade
