// combined:auto --max-error under point lights and local viewers (issue 17 item 8, docs/combined.md §2b):
// on random light and viewer positions — point lights near (just off the surface) and far, directional
// lights, a local viewer around the object — over the test scenes (procedural sphere and teapot,
// scenes/sphere.json and scenes/teapot.json, the bunny when PARASHADE_MESH_DIR is set) with several
// exponents and budgets, the float image stays within the shading budget (--max-error minus the 8-bit
// rounding) of Phong's float image, the definition of AutoStaysWithinItsBudget. Small images: seconds.
#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "cl_fixture.hpp"
#include "parashade/renderer.hpp"
#include "parashade/shapes.hpp"
#include "test_support.hpp"

namespace parashade {
namespace {

using namespace testing_support;

// The object's bounding sphere (centre of the world-space box, radius to its farthest vertex).
void bounding_sphere(const Scene& s, glm::vec3& centre, float& radius) {
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (const Object& o : s.objects)
    for (const glm::vec3& p : o.mesh->positions) {
      const glm::vec3 w = glm::vec3(o.model * glm::vec4(p, 1.0f));
      lo = glm::min(lo, w);
      hi = glm::max(hi, w);
    }
  centre = 0.5f * (lo + hi);
  radius = 0.5f * glm::length(hi - lo);
}

struct Outcome {
  int cases = 0, over = 0;
  double worst_ratio = 0.0;  // largest error / shading budget
  std::string first_over;
};

// `cases` random light and viewer placements around the scene's object.
Outcome run_cases(const Scene& base, int cases, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f), unit(0.0f, 1.0f);
  const auto random_unit = [&] {
    for (;;) {
      const glm::vec3 v(u(rng), u(rng), u(rng));
      if (glm::length(v) > 0.1f && glm::length(v) <= 1.0f) return glm::normalize(v);
    }
  };
  glm::vec3 centre;
  float radius;
  bounding_sphere(base, centre, radius);
  const float exponents[] = {10.0f, 60.0f, 200.0f, 1000.0f};
  const double budgets[] = {1.0, 2.0, 4.0};
  Outcome out;
  for (int i = 0; i < cases; ++i) {
    Scene s = base;
    s.width = 128;
    s.height = 96;
    s.local_viewer = true;
    // Close up (a part of the object fills the image: triangles many pixels wide) to the whole object.
    const float distance = radius * (1.3f + 3.0f * unit(rng));
    set_perspective(s.camera, centre + random_unit() * distance, centre + 0.5f * radius * random_unit() * unit(rng),
                    20.0f + 30.0f * unit(rng), std::max(1e-3f, distance - 1.5f * radius), distance + 1.5f * radius);
    s.camera.up = std::abs(glm::normalize(s.camera.position - centre).y) > 0.95f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    // Point lights near the surface (the case) and far; every third case also a directional light.
    Light point;
    point.type = LightType::point;
    const bool near = i % 2 == 0;
    point.position = centre + random_unit() * (radius * (near ? 1.02f + 0.6f * unit(rng) : 3.0f + 30.0f * unit(rng)));
    point.color = glm::vec3(1.0f);
    s.lights = {point};
    if (i % 3 == 0) {
      Light sun;
      sun.direction = random_unit();
      sun.color = glm::vec3(0.6f);
      s.lights.push_back(sun);
    }
    const float n = exponents[i % 4];
    for (Material& m : s.materials) {
      m.shininess = n;
      m.specular = glm::vec3(0.8f);
      m.diffuse = glm::vec3(0.6f, 0.5f, 0.4f);
    }
    CombinedConfig c = parse_combined("combined:auto");
    c.max_error = budgets[(i / 4) % 3];
    RenderOptions o;
    o.float_output = true;
    o.method = Method::phong;
    Renderer phong_renderer(test_device(), o);
    const std::vector<float> phong = phong_renderer.render(s).image.rgb_float;
    o.method = Method::combined;
    o.combined = c;
    Renderer combined_renderer(test_device(), o);
    const std::vector<float>& got = combined_renderer.render(s).image.rgb_float;
    double worst = 0.0;
    for (std::size_t p = 0; p < got.size(); ++p) worst = std::max(worst, std::abs(double(got[p]) - phong[p]));
    const double allowed = combined_shading_budget(c);
    ++out.cases;
    out.worst_ratio = std::max(out.worst_ratio, worst / allowed);
    if (worst > allowed + 1e-3) {
      if (out.over++ == 0)
        out.first_over = "case " + std::to_string(i) + ": " + std::to_string(worst) + " levels at budget " +
                         std::to_string(c.max_error) + ", n " + std::to_string(n) + (near ? ", near light" : ", far light");
    }
  }
  return out;
}

void expect_within(const std::string& name, const Outcome& o) {
  ::testing::Test::RecordProperty(name + "_cases", o.cases);
  ::testing::Test::RecordProperty(name + "_largest_error_over_budget", std::to_string(o.worst_ratio));
  EXPECT_EQ(o.over, 0) << name << ": " << o.over << " of " << o.cases << " over the budget; first " << o.first_over;
  EXPECT_GT(o.worst_ratio, 0.05) << name << ": combined:auto should interpolate somewhere";
}

Scene procedural(std::shared_ptr<const Mesh> mesh, float scale) {
  Scene s = pixel_scene(72, 54);
  add_object(s, std::move(mesh), glm::scale(glm::mat4(1.0f), glm::vec3(scale)));
  return s;
}

TEST(MovingLightBudget, ProceduralSphere) {
  expect_within("sphere", run_cases(procedural(std::make_shared<Mesh>(make_sphere(24, 12)), 1.0f), 400, 81));
}

TEST(MovingLightBudget, ProceduralTeapot) {
  expect_within("teapot", run_cases(procedural(std::make_shared<Mesh>(make_teapot(3)), 1.0f), 300, 82));
}

TEST(MovingLightBudget, ProjectScenes) {
  for (const char* name : {"sphere", "teapot"})
    expect_within(name, run_cases(load_scene(source_dir() / "scenes" / (std::string(name) + ".json")), 150, 83));
}

TEST(MovingLightBudget, Bunny) {
  PARASHADE_REQUIRE_MESH_DIR(dir);
  (void)dir;
  expect_within("bunny", run_cases(load_scene(source_dir() / "scenes" / "bunny.json"), 100, 84));
}

}  // namespace
}  // namespace parashade
