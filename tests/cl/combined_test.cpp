// Combined Gouraud/Phong (kernels/method_combined.h): exact Phong at segment ends, linear inside,
// segments counted from each span's left pixel whatever the tiles; combined:auto within its budget.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "cl_fixture.hpp"
#include "parashade/renderer.hpp"

namespace parashade {
namespace {

using namespace testing_support;

std::vector<float> render_float(const Scene& scene, Method method, CombinedConfig combined = {}, int tile = 16) {
  RenderOptions o;
  o.method = method;
  o.float_output = true;
  o.tile_size = tile;
  o.combined = combined;
  Renderer renderer(test_device(), o);
  return renderer.render(scene).image.rgb_float;
}

CombinedConfig fixed_k(int k) {
  CombinedConfig c;
  c.k = k;
  return c;
}

CombinedConfig automatic(double levels) {
  CombinedConfig c;
  c.automatic = true;
  c.max_error = levels;
  return c;
}

// Random overlapping triangles with strongly varying normals, a point light besides the directional one.
Scene busy_scene(bool point_light) {
  std::mt19937 rng(5);
  Scene scene = pixel_scene(320, 240);
  scene.materials[0].shininess = 40.0f;
  if (point_light) {
    Light point;
    point.type = LightType::point;
    point.position = {40.0f, 80.0f, 300.0f};
    point.color = {0.7f, 0.7f, 0.9f};
    scene.lights.push_back(point);
  }
  add_object(scene, random_triangles(150, 320, 240, 90.0f, rng));
  return scene;
}

// One large triangle (no overlap: each row's covered pixels are exactly its span) with a highlight.
Scene one_triangle() {
  Scene scene = pixel_scene(256, 192);
  scene.materials[0].shininess = 30.0f;
  auto mesh = std::make_shared<Mesh>();
  mesh->positions = {{-120.0f, -90.0f, 0.0f}, {125.0f, -70.0f, 0.0f}, {-20.0f, 93.0f, 0.0f}};
  mesh->normals = {glm::normalize(glm::vec3(-0.8f, -0.5f, 1.0f)), glm::normalize(glm::vec3(0.9f, -0.3f, 1.0f)),
                   glm::normalize(glm::vec3(0.1f, 0.9f, 1.0f))};
  mesh->triangles = {{0, 1, 2}};
  add_object(scene, mesh);
  return scene;
}

TEST(CombinedKernel, KZeroIsPhong) {
  const Scene scene = busy_scene(true);
  const auto phong = render_float(scene, Method::phong);
  const auto combined = render_float(scene, Method::combined, fixed_k(0));
  ASSERT_EQ(phong.size(), combined.size());
  std::size_t differ = 0;
  for (std::size_t i = 0; i < phong.size(); ++i) differ += phong[i] != combined[i];
  EXPECT_EQ(differ, 0u);
}

class CombinedSegments : public ::testing::TestWithParam<int> {};

// At x = xl + m 2^K the pixel is Phong's; between two ends inside the span it is their interpolation.
TEST_P(CombinedSegments, EndsArePhongAndInsideIsLinear) {
  const int k = GetParam(), len = 1 << k;
  const Scene scene = one_triangle();
  const auto phong = render_float(scene, Method::phong);
  const auto combined = render_float(scene, Method::combined, fixed_k(k));
  const int w = scene.width;
  const auto at = [&](const std::vector<float>& img, int x, int y, int c) { return img[3 * (std::size_t(y) * w + x) + c]; };
  std::size_t ends = 0, inner = 0;
  double worst_end = 0, worst_inner = 0, largest_departure = 0;
  for (int y = 0; y < scene.height; ++y) {
    // The span: the covered run of the row (background is black and every covered value is > 0).
    int xl = -1, xr = -1;
    for (int x = 0; x < w; ++x)
      if (at(phong, x, y, 0) > 0.0f) {
        if (xl < 0) xl = x;
        xr = x;
      }
    if (xl < 0) continue;
    for (int x = xl; x <= xr; ++x) {
      const int v = (x - xl) % len, a = x - v, b = a + len;
      for (int c = 0; c < 3; ++c) {
        const double got = at(combined, x, y, c);
        if (v == 0) {
          worst_end = std::max(worst_end, std::abs(got - at(phong, x, y, c)));
          ++ends;
        } else if (b <= xr) {
          const double ia = at(phong, a, y, c), ib = at(phong, b, y, c);
          worst_inner = std::max(worst_inner, std::abs(got - (ia + (ib - ia) * v / len)));
          largest_departure = std::max(largest_departure, std::abs(got - at(phong, x, y, c)));
          ++inner;
        }
      }
    }
  }
  EXPECT_GT(ends, 1000u);
  EXPECT_LE(worst_end, 0.0) << "segment ends must be Phong's pixels exactly";
  if (k > 0) {
    EXPECT_GT(inner, 1000u);
    EXPECT_LE(worst_inner, 1e-3);
    EXPECT_GT(largest_departure, 0.01) << "inside a segment the intensity is interpolated, not Phong's";
  }
}

INSTANTIATE_TEST_SUITE_P(K, CombinedSegments, ::testing::Values(0, 1, 2, 3, 5));

TEST(CombinedKernel, TilesDoNotChangeThePixels) {
  const Scene scene = busy_scene(true);
  for (const CombinedConfig& c : {fixed_k(3), automatic(2.0)}) {
    const auto a = render_float(scene, Method::combined, c, 16);
    const auto b = render_float(scene, Method::combined, c, 64);
    std::size_t differ = 0;
    for (std::size_t i = 0; i < a.size(); ++i) differ += a[i] != b[i];
    EXPECT_EQ(differ, 0u) << combined_name(c);
  }
}

// Directional light, distant viewer: the bound's assumptions hold exactly, so the float image stays
// within the shading budget (the budget minus 0.5 for rounding) of Phong's float image.
TEST(CombinedKernel, AutoStaysWithinItsBudget) {
  const Scene scene = busy_scene(false);
  const auto phong = render_float(scene, Method::phong);
  for (double levels : {1.0, 4.0}) {
    const auto got = render_float(scene, Method::combined, automatic(levels));
    double worst = 0;
    std::size_t interpolated = 0;
    for (std::size_t i = 0; i < got.size(); ++i) {
      const double d = std::abs(double(got[i]) - phong[i]);
      worst = std::max(worst, d);
      interpolated += d > 1e-3;
    }
    RecordProperty("worst_levels_budget_" + std::to_string(int(levels)), std::to_string(worst));
    EXPECT_LE(worst, combined_shading_budget(automatic(levels)) + 1e-3) << "budget " << levels;
    EXPECT_GT(interpolated, 1000u) << "auto should interpolate somewhere at budget " << levels;
  }
}

// Point light and local viewer (H varies over a triangle): skipping the specular term where the test
// says no highlight falls changes no pixel by more than the negligible level per light.
TEST(CombinedKernel, HighlightTestChangesNothingVisible) {
  Scene scene = busy_scene(true);
  scene.materials[0].shininess = 300.0f;
  scene.camera.projection = Projection::perspective;
  scene.camera.position = {0.0f, 0.0f, 400.0f};
  scene.camera.fov_y_degrees = 40.0f;
  scene.camera.near_plane = 100.0f;
  scene.camera.far_plane = 800.0f;
  scene.local_viewer = true;
  const auto plain = render_float(scene, Method::combined, fixed_k(0));
  RenderOptions o;
  o.method = Method::combined;
  o.float_output = true;
  o.combined = fixed_k(0);
  o.combined.highlight_test = true;
  Renderer renderer(test_device(), o);
  const Frame& f = renderer.render(scene);
  // Not vacuous: some terms are skipped (4 by the cone test on lanes; the exact bound skipped a few more).
  EXPECT_GT(f.stats.highlight.light_terms_skipped, 0u);
  EXPECT_LT(f.stats.highlight.without_highlight, f.stats.highlight.triangles);
  double worst = 0;
  for (std::size_t i = 0; i < plain.size(); ++i) worst = std::max(worst, std::abs(double(f.image.rgb_float[i]) - plain[i]));
  EXPECT_LE(worst, 2 * o.combined.negligible_specular + 1e-3);
}

}  // namespace
}  // namespace parashade
