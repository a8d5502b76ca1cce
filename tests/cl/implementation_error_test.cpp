// The kernels against their own ideal (the exact reference of the same method), within bounds derived
// from float arithmetic (docs/error-bounds.md), and the constant span increment seen on kernel spans.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "cl_fixture.hpp"
#include "gouraud_bound.hpp"
#include "parashade/geometry_stage.hpp"
#include "parashade/metrics.hpp"
#include "parashade/reference.hpp"
#include "parashade/renderer.hpp"
#include "parashade/setup.hpp"

namespace parashade {
namespace {

using namespace testing_support;
constexpr double kUnitRoundoff = 1.0 / (1 << 24);  // float32

struct Rendered {
  Frame frame;
  ScreenGeometry geometry;
  ReferenceImage reference;
};

Rendered render_with_reference(const Scene& scene, Method method) {
  Renderer renderer(test_device(), render_options(method, true, 16));
  Rendered r{renderer.render(scene), {}, {}};
  build_screen_geometry(scene, {method, true}, r.geometry);
  r.reference = render_reference(scene, r.geometry, method);
  return r;
}

TEST(GouraudKernel, FloatValuesWithinDerivedBoundOfIdeal) {
  std::mt19937 rng(7);
  Scene scene = pixel_scene(320, 240);
  add_object(scene, random_triangles(300, 320, 240, 80.0f, rng));
  const Rendered r = render_with_reference(scene, Method::gouraud);
  const double bound = gouraud_bound(r.geometry);
  const ErrorMetrics e = compare_to_reference(r.frame.image, r.reference.covered, r.reference.ideal, "ideal");
  RecordProperty("bound_levels", std::to_string(bound));
  RecordProperty("max_abs_levels", std::to_string(e.max_abs));
  EXPECT_GT(e.pixels_compared, 10000u);
  EXPECT_EQ(e.coverage_mismatch, 0u);
  // Visibility can only differ where two triangles' depths tie within float precision; random depths
  // over a range of 10 make that rare. Every other pixel must be within the bound.
  std::size_t beyond = 0;
  const auto& img = r.frame.image;
  for (std::size_t p = 0; p < r.reference.covered.size(); ++p) {
    if (!r.reference.covered[p]) continue;
    for (int c = 0; c < 3; ++c) {
      const double v = std::clamp(double(img.rgb_float[3 * p + c]), 0.0, 255.0);
      if (std::abs(v - r.reference.ideal[p][c]) > bound) ++beyond;
    }
  }
  EXPECT_LE(beyond, 3u) << "bound " << bound << " levels, max error " << e.max_abs;
  EXPECT_LT(bound, 0.01) << "the derived bound itself should be far below one level for these triangles";
}

TEST(GouraudKernel, EightBitOutputWithinHalfALevelPlusBound) {
  std::mt19937 rng(8);
  Scene scene = pixel_scene(256, 256);
  add_object(scene, random_triangles(60, 256, 256, 100.0f, rng));
  Rendered r = render_with_reference(scene, Method::gouraud);
  r.frame.image.rgb_float.clear();  // compare the 8-bit image
  const ErrorMetrics e = compare_to_reference(r.frame.image, r.reference.covered, r.reference.ideal, "ideal");
  EXPECT_LE(e.max_abs, 0.5 + gouraud_bound(r.geometry) + 1e-9);
  EXPECT_EQ(e.pixels_over_1_level, 0u);
}

// [Gouraud simplification]: along every span the kernel's values step by the triangle's constant increment dI_G.
TEST(GouraudKernel, SpanIncrementsEqualConstantIncrement) {
  std::mt19937 rng(99);
  for (int trial = 0; trial < 20; ++trial) {
    Scene scene = pixel_scene(200, 160);
    add_object(scene, random_triangles(1, 120, 100, 70.0f, rng));
    Renderer renderer(test_device(), render_options(Method::gouraud, true, 16));
    const Frame f = renderer.render(scene);
    const ScreenGeometry& g = renderer.geometry();
    if (g.triangles.empty()) continue;
    const glm::uvec3 t = g.triangles[0];
    const glm::dvec2 a = glm::dvec2(g.xy[t.x]) / double(kSubpixel), b = glm::dvec2(g.xy[t.y]) / double(kSubpixel),
                     c = glm::dvec2(g.xy[t.z]) / double(kSubpixel);
    std::size_t steps = 0;
    for (int ch = 0; ch < 3; ++ch) {
      const double di = constant_span_increment(a, b, c, g.color[t.x][ch], g.color[t.y][ch], g.color[t.z][ch]);
      const double imax = std::max({std::abs(g.color[t.x][ch]), std::abs(g.color[t.y][ch]), std::abs(g.color[t.z][ch])}) +
                          std::abs(di) * 200.0;
      for (int y = 0; y < scene.height; ++y)
        for (int x = 0; x + 1 < scene.width; ++x) {
          const std::size_t p = std::size_t(y) * scene.width + x;
          if (!f.image.covered(p) || !f.image.covered(p + 1)) continue;
          const double step = double(f.image.rgb_float[3 * (p + 1) + ch]) - f.image.rgb_float[3 * p + ch];
          ASSERT_NEAR(step, di, 8.0 * kUnitRoundoff * imax) << "trial " << trial << " row " << y << " x " << x;
          ++steps;
        }
    }
    if (trial == 0) EXPECT_GT(steps, 100u);
  }
}

// Phong: float normal and position planes, rsqrt (<= 2 ulp), exp2/log2 (<= 3 ulp each) for the power.
// A relative error eps in N.H becomes about n*eps in N.H^n, so the bound grows with the exponent:
// |I - I*| <= 64u * 255 * sum_l I_l (k_d + k_s (n + 1))   (docs/error-bounds.md).
double phong_bound(const Scene& s) {
  double sum = 0.0;
  for (const Light& l : s.lights)
    for (const Material& m : s.materials)
      for (int c = 0; c < 3; ++c)
        sum = std::max(sum, double(l.color[c]) * (m.diffuse[c] + m.specular[c] * (m.shininess + 1.0)));
  return 64.0 * kUnitRoundoff * 255.0 * sum * double(s.lights.size());
}

class PhongKernel : public ::testing::TestWithParam<float> {};

TEST_P(PhongKernel, FloatValuesWithinDerivedBoundOfIdeal) {
  std::mt19937 rng(11);
  Scene scene = pixel_scene(320, 240);
  scene.materials[0].shininess = GetParam();
  Light point;
  point.type = LightType::point;
  point.position = {40.0f, 80.0f, 300.0f};
  point.color = {0.7f, 0.7f, 0.9f};
  scene.lights.push_back(point);
  add_object(scene, random_triangles(200, 320, 240, 60.0f, rng));
  const Rendered r = render_with_reference(scene, Method::phong);
  const double bound = phong_bound(scene);
  std::size_t beyond = 0, compared = 0;
  double worst = 0.0;
  for (std::size_t p = 0; p < r.reference.covered.size(); ++p) {
    if (!r.reference.covered[p]) continue;
    ++compared;
    for (int c = 0; c < 3; ++c) {
      const double v = std::clamp(double(r.frame.image.rgb_float[3 * p + c]), 0.0, 255.0);
      const double err = std::abs(v - r.reference.ideal[p][c]);
      worst = std::max(worst, err);
      if (err > bound) ++beyond;
    }
  }
  EXPECT_GT(compared, 10000u);
  RecordProperty("bound_levels", std::to_string(bound));
  RecordProperty("worst_levels", std::to_string(worst));
  EXPECT_LE(beyond, 3u) << "bound " << bound << " levels, worst " << worst;
}

INSTANTIATE_TEST_SUITE_P(Exponents, PhongKernel, ::testing::Values(1.0f, 20.0f, 200.0f, 1000.0f));

}  // namespace
}  // namespace parashade
