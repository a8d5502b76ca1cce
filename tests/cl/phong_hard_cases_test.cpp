// Phong normalization methods and specular models in the kernel on the hard cases of issue 4: vertex
// normals exactly opposite (the interpolated normal passes through zero), equal normals (theta = 0), a
// grazing light, N.H < 0 over a whole triangle, spans up to ~250 pixels, n = 1 and n = 1000. No NaN or
// Inf may reach the image; opposite end normals must be counted as fallbacks; a triangle facing away
// from light and viewer shows ambient only (255 * k_a * I_a = 25.5 levels, worked out by hand).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "cl_fixture.hpp"
#include "parashade/combined.hpp"
#include "parashade/geometry_stage.hpp"
#include "parashade/reference.hpp"
#include "parashade/renderer.hpp"

namespace parashade {
namespace {

using namespace testing_support;

// A triangle with its vertex normals (normalized here).
void add_triangle(Mesh& mesh, std::array<glm::vec3, 3> p, std::array<glm::vec3, 3> n) {
  const auto base = std::uint32_t(mesh.positions.size());
  for (int k = 0; k < 3; ++k) {
    mesh.positions.push_back(p[k]);
    mesh.normals.push_back(glm::normalize(n[k]));
  }
  mesh.triangles.push_back({base, base + 1, base + 2});
}

Scene hard_scene(float shininess) {
  Scene s = pixel_scene(256, 128);
  s.lights[0].direction = glm::normalize(glm::vec3(-1.0f, 0.0f, -1e-4f));  // grazing on normals facing +z
  s.materials[0].shininess = shininess;
  auto mesh = std::make_shared<Mesh>();
  auto tri = [&](glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 na, glm::vec3 nb, glm::vec3 nc) {
    add_triangle(*mesh, {a, b, c}, {na, nb, nc});
  };
  // A wide triangle whose rows run from +z to -z normals: the spans' end normals are (nearly) opposite.
  tri({-125, 60, 0}, {125, 60, 0}, {0, 5, 0}, {0, 0, 1}, {0, 0, -1}, {0, 1e-3f, -1});
  // Equal normals everywhere (theta = 0).
  tri({-120, -5, 0}, {-20, -5, 0}, {-70, -60, 0}, {0.3f, 0.2f, 1}, {0.3f, 0.2f, 1}, {0.3f, 0.2f, 1});
  // Facing away from light and viewer: N.L < 0 and N.H < 0 over the whole triangle.
  tri({10, -5, 0}, {120, -5, 0}, {65, -60, 0}, {0, 0, -1}, {-0.1f, 0, -1}, {0, 0.1f, -1});
  add_object(s, mesh);
  return s;
}

void check(const std::string& normalize, const std::string& specular) {
  for (float n : {1.0f, 1000.0f}) {
    const Scene scene = hard_scene(n);
    RenderOptions o;
    o.method = Method::phong;
    o.float_output = true;
    o.normalize = parse_normalize(normalize);
    o.specular = parse_specular(specular);
    Renderer renderer(test_device(), o);
    const Frame& f = renderer.render(scene);
    const auto& img = f.image;
    std::size_t ambient_checked = 0;
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x) {
        const std::size_t p = std::size_t(y) * img.width + x;
        for (int c = 0; c < 3; ++c)
          ASSERT_TRUE(std::isfinite(img.rgb_float[3 * p + c])) << normalize << " " << specular << " n " << n << " at " << x << "," << y;
        // Well inside the away-facing triangle (its rows at screen y 72..80 cover x 146..240).
        if (x >= 170 && x <= 210 && y >= 72 && y <= 80) {
          for (int c = 0; c < 3; ++c) EXPECT_NEAR(img.rgb_float[3 * p + c], 25.5f, 1e-3f) << normalize << " " << specular;
          ++ambient_checked;
        }
      }
    EXPECT_GT(ambient_checked, 100u);
    if (o.normalize.kind != NormalizeKind::exact) EXPECT_GT(f.stats.normalize_fallback_spans, 0u) << normalize;
  }
}

TEST(PhongHardCases, NormalizationMethods) {
  for (const char* m : {"exact", "slerp", "quadratic:exact", "quadratic:quad", "quadratic:cubic", "quadratic:cubic-fit",
                        "dichotomy:exact", "dichotomy:linear:3", "dichotomy:quadratic-fit:6:extrapolate", "recurrence",
                        "recurrence:table", "recurrence-diff:table-fixed:16"})
    check(m, "exact");
}

// The widest screen (4096 px): rows 0-2 are spans of 4096 pixels of one triangle reaching past both
// screen edges (its normals turn by 1.6 rad across the screen); below, an apex whose first rows are
// spans of 1, 2 and 3 pixels, and triangles whose spans have exactly opposite, nearly opposite
// (1 + cos = 8e-6, above the fallback limit) and nearly equal end normals.
Scene wide_scene() {
  Scene s = pixel_scene(4096, 32);
  auto mesh = std::make_shared<Mesh>();
  auto tri = [&](glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 na, glm::vec3 nb, glm::vec3 nc) {
    add_triangle(*mesh, {a, b, c}, {na, nb, nc});
  };
  // World (x, y) is screen (x + 2048, 16 - y). Vertex normals in the plane y = 0 of the normal space:
  // interpolated, (x/2000, 0, 1) along the top rows, (+-1.02, 0, 1) at the screen's edges.
  tri({-6000, 16, 0}, {6000, 16, 0}, {0, 12, 0}, {-3, 0, 1}, {3, 0, 1}, {0, 0, 1});
  tri({-1500, 0, 0}, {-1490, 0, 0}, {-1500, 10.25f, 0}, {0, 0, 1}, {0.8f, 0, 1}, {0, 0.5f, 1});
  tri({-500, 0, 0}, {-300, 0, 0}, {-400, 10, 0}, {0, 0, 1}, {0, 0, -1}, {0, 1e-3f, -1});
  tri({100, 0, 0}, {300, 0, 0}, {200, 10, 0}, {-1, 0, 0.002f}, {1, 0, 0.002f}, {0, 0.001f, 1});
  tri({600, 0, 0}, {800, 0, 0}, {700, 10, 0}, {0.3f, 0.2f, 1}, {0.3f, 0.2f + 1e-6f, 1}, {0.3f, 0.2f, 1 + 1e-6f});
  add_object(s, mesh);
  return s;
}

struct Rendered {
  std::vector<float> rgb;     // float levels
  std::vector<bool> covered;
  FrameStats stats;
};

Rendered render_wide(const std::string& normalize) {
  RenderOptions o;
  o.method = Method::phong;
  o.float_output = true;
  o.normalize = parse_normalize(normalize);
  Renderer renderer(test_device(), o);
  const Frame& f = renderer.render(wide_scene());
  Rendered r{f.image.rgb_float, std::vector<bool>(f.image.rgba.size() / 4), f.stats};
  for (std::size_t p = 0; p < r.covered.size(); ++p) r.covered[p] = f.image.covered(p);
  return r;
}

// Every method on spans of 1, 2, 3 and 4096 pixels and on (nearly) opposite and equal end normals:
// finite everywhere, the opposite spans counted as fallbacks, the recurrence's steps counted. Where a
// method is accurate, its image is held to a reference within half a level (float): dichotomy with exact
// or fitted scales to exact Phong (exact at segment ends, bisection inside 2^K pixels at most 0.026 rad
// apart here), the recurrence in difference form or re-anchored at every pixel to slerp (same arc, same
// parametrization; float error over 4096 steps below 2e-4: 0.34 levels measured). A run walked over the
// wrong pixels (one too far) is 200 levels off at the apex, whose short spans turn by up to 0.7 rad
// per pixel.
TEST(PhongHardCases, SpanLengthsAndNearlyOppositeEnds) {
  const Rendered exact = render_wide("exact"), slerp = render_wide("slerp");
  const int width = 4096;
  // The preconditions: rows 0-2 fully covered, the apex's rows 6-8 covered by 1, 2, 3 pixels.
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < width; ++x) ASSERT_TRUE(exact.covered[std::size_t(y) * width + x]) << x << "," << y;
  for (int y = 6; y < 9; ++y) {
    int run = 0;
    for (int x = 520; x < 580; ++x) run += exact.covered[std::size_t(y) * width + x];
    ASSERT_EQ(run, y - 5) << "apex row " << y;
  }
  struct Case {
    const char* normalize;
    const Rendered* reference;  // nullptr: finite only
  };
  for (const Case& c : {Case{"dichotomy:exact", &exact}, Case{"dichotomy:quadratic-fit:6", &exact},
                        Case{"dichotomy:exact:1", &exact}, Case{"dichotomy:exact:4:extrapolate", nullptr},
                        Case{"dichotomy:linear:3", nullptr}, Case{"recurrence-diff:exact", &slerp},
                        Case{"recurrence:exact:2", &slerp}, Case{"recurrence:exact", nullptr},
                        Case{"recurrence:table", nullptr}, Case{"recurrence-diff:table-fixed:64", nullptr}}) {
    const Rendered r = render_wide(c.normalize);
    double worst = 0;
    std::size_t worst_at = 0;
    for (std::size_t i = 0; i < r.rgb.size(); ++i) {
      ASSERT_TRUE(std::isfinite(r.rgb[i])) << c.normalize << " at pixel " << i / 3;
      const int x = int(i / 3 % width), y = int(i / 3 / width);
      const bool held = y < 3 || (y >= 6 && y < 9 && x >= 520 && x < 580);  // the long spans and the apex
      const double diff = c.reference && held && r.covered[i / 3] ? std::fabs(r.rgb[i] - c.reference->rgb[i]) : 0.0;
      if (diff > worst) worst = diff, worst_at = i / 3;
    }
    EXPECT_LE(worst, 0.5) << c.normalize << " at " << worst_at % width << "," << worst_at / width;
    EXPECT_GT(r.stats.normalize_fallback_spans, 0u) << c.normalize;
    const bool sequential = std::string(c.normalize).rfind("recurrence", 0) == 0;
    EXPECT_EQ(r.stats.normalize_sequential_steps > 0, sequential) << c.normalize;
    std::printf("%s: %llu span setups, %llu fallback spans, %llu sequential steps; max |difference| %.3f levels\n",
                c.normalize, (unsigned long long)r.stats.normalize_span_setups,
                (unsigned long long)r.stats.normalize_fallback_spans,
                (unsigned long long)r.stats.normalize_sequential_steps, worst);
  }
}

TEST(PhongHardCases, SpecularModels) {
  for (const char* s : {"cosk:taylor:2", "cosk:lobe:4", "quadratic", "7n16", "7n16:1.78"}) check("quadratic:cubic-fit", s);
}

// Inside the equal-normals triangle of hard_scene (screen (8,69), (108,69), (58,124)) and inside the one
// facing away (ambient only, 25.5 levels).
bool in_equal_triangle(int x, int y) { return x >= 50 && x <= 66 && y >= 80 && y <= 100; }
bool in_away_triangle(int x, int y) { return x >= 170 && x <= 210 && y >= 72 && y <= 80; }

// Phong through the fixed-point units (issue 17, item 15): the registers carry the normal's components,
// which pass through zero on the opposite-normals triangle. Finite everywhere; where the normals are
// equal, the unit's quantized normal shades within half a level of float Phong; the away-facing
// triangle stays ambient.
TEST(PhongHardCases, FixedPointUnitsWithOppositeNormals) {
  for (float n : {1.0f, 1000.0f}) {
    const Scene scene = hard_scene(n);
    RenderOptions plain;
    plain.method = Method::phong;
    plain.float_output = true;
    Renderer phong(test_device(), plain);
    const std::vector<float> exact = phong.render(scene).image.rgb_float;
    for (const auto& [unit, arith] : {std::pair{"classic", "fixed:12.8"}, std::pair{"counter", "fixed:9.4"},
                                      std::pair{"interleave:2:own", "fixed:12.12"}, std::pair{"segment:8", "fixed:10.6"}}) {
      RenderOptions o = plain;
      o.units = parse_units(unit);
      o.arith = parse_arith(arith);
      Renderer renderer(test_device(), o);
      const Frame& f = renderer.render(scene);
      std::size_t equal = 0, away = 0;
      for (int y = 0; y < f.image.height; ++y)
        for (int x = 0; x < f.image.width; ++x) {
          const std::size_t p = std::size_t(y) * f.image.width + x;
          for (int c = 0; c < 3; ++c) {
            const float v = f.image.rgb_float[3 * p + c];
            ASSERT_TRUE(std::isfinite(v)) << unit << " " << arith << " n " << n << " at " << x << "," << y;
            if (in_equal_triangle(x, y)) EXPECT_NEAR(v, exact[3 * p + c], 0.5f) << unit << " " << arith << " n " << n;
            if (in_away_triangle(x, y)) EXPECT_NEAR(v, 25.5f, 1e-3f) << unit << " " << arith;
          }
          equal += in_equal_triangle(x, y);
          away += in_away_triangle(x, y);
        }
      EXPECT_GT(equal, 200u);
      EXPECT_GT(away, 100u);
    }
  }
}

// combined:auto on the same triangles (infinite viewer, directional light: the case its bound covers):
// finite, and the 8-bit image within the budget of exact Phong wherever exact Phong is defined (the
// interpolated normal is not zero).
TEST(PhongHardCases, CombinedAutoWithOppositeNormalsMeetsItsBudget) {
  for (float n : {1.0f, 1000.0f}) {
    Scene scene = hard_scene(n);
    scene.local_viewer = false;
    for (const double budget : {1.0, 4.0}) {
      RenderOptions o;
      o.method = Method::combined;
      o.combined = parse_combined("combined:auto");
      o.combined.max_error = budget;
      o.float_output = true;
      Renderer renderer(test_device(), o);
      const Frame& f = renderer.render(scene);
      ScreenGeometry g;
      build_screen_geometry(scene, {Method::phong, true}, g);
      const ReferenceImage ref = render_reference(scene, g, Method::phong);
      double worst = 0;
      std::size_t compared = 0;
      for (std::size_t p = 0; p < ref.covered.size(); ++p) {
        for (int c = 0; c < 3; ++c) ASSERT_TRUE(std::isfinite(f.image.rgb_float[3 * p + c])) << "pixel " << p;
        if (!ref.covered[p] || !f.image.covered(p) || !std::isfinite(ref.exact[p].x)) continue;
        for (int c = 0; c < 3; ++c)
          worst = std::max(worst, std::abs(double(f.image.rgba[4 * p + c]) - std::clamp(ref.exact[p][c], 0.0, 255.0)));
        ++compared;
      }
      EXPECT_GT(compared, 5000u);
      EXPECT_LE(worst, budget) << "n " << n << ", budget " << budget;
    }
  }
}

}  // namespace
}  // namespace parashade
