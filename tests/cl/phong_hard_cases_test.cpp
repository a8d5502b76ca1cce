// Phong normalization methods and specular models in the kernel on the hard cases of issue 4: vertex
// normals exactly opposite (the interpolated normal passes through zero), equal normals (theta = 0), a
// grazing light, N.H < 0 over a whole triangle, spans up to ~250 pixels, n = 1 and n = 1000. No NaN or
// Inf may reach the image; opposite end normals must be counted as fallbacks; a triangle facing away
// from light and viewer shows ambient only (255 * k_a * I_a = 25.5 levels, worked out by hand).
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "cl_fixture.hpp"
#include "parashade/renderer.hpp"

namespace parashade {
namespace {

using namespace testing_support;

Scene hard_scene(float shininess) {
  Scene s = pixel_scene(256, 128);
  s.lights[0].direction = glm::normalize(glm::vec3(-1.0f, 0.0f, -1e-4f));  // grazing on normals facing +z
  s.materials[0].shininess = shininess;
  auto mesh = std::make_shared<Mesh>();
  auto tri = [&](glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 na, glm::vec3 nb, glm::vec3 nc) {
    const auto base = std::uint32_t(mesh->positions.size());
    mesh->positions.insert(mesh->positions.end(), {a, b, c});
    mesh->normals.insert(mesh->normals.end(), {glm::normalize(na), glm::normalize(nb), glm::normalize(nc)});
    mesh->triangles.push_back({base, base + 1, base + 2});
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
  for (const char* m : {"exact", "slerp", "quadratic:exact", "quadratic:quad", "quadratic:cubic", "quadratic:cubic-fit"})
    check(m, "exact");
}

TEST(PhongHardCases, SpecularModels) {
  for (const char* s : {"cosk:taylor:2", "cosk:lobe:4", "quadratic", "7n16", "7n16:1.78"}) check("quadratic:cubic-fit", s);
}

}  // namespace
}  // namespace parashade
