// VertexLighting::shade_lanes (the vertex stage's lit lanes) against shade(), element for element and
// bit for bit: Gouraud vertex colours, and so the images, must not depend on which path lit a vertex.
// Hard inputs: zero normals, a vertex at the eye or at the point light, a light opposite the viewer
// (H = 0), huge and tiny coordinates, NaN, N.H at and around 0; local and infinite viewer.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "parashade/vertex_lighting.hpp"
#include "test_support.hpp"

namespace parashade {
namespace {

using testing_support::ortho_scene;

std::uint32_t bits(float f) {
  std::uint32_t b;
  std::memcpy(&b, &f, sizeof b);
  return b;
}

Scene lit_scene(bool local_viewer, bool perspective) {
  Scene s = ortho_scene(64, 64);
  if (perspective) s.camera.projection = Projection::perspective;
  s.camera.position = {0.5f, 1.0f, 4.0f};
  s.local_viewer = local_viewer;
  s.lights.clear();
  Light d;
  d.direction = {1.0f, -1.0f, -1.0f};
  d.color = {0.8f, 0.8f, 0.8f};
  s.lights.push_back(d);
  Light p;
  p.type = LightType::point;
  p.position = {3.0f, 2.0f, 3.0f};
  p.color = {0.5f, 0.45f, 0.4f};
  s.lights.push_back(p);
  Light behind;  // toward the light = -view direction: H = L + V = 0 for the infinite viewer
  behind.direction = s.camera.position - s.camera.target;
  s.lights.push_back(behind);
  Material m = s.materials[0];
  m.shininess = 40.0f;
  s.materials.push_back(m);
  m.specular = glm::vec3(0.0f);
  m.shininess = 1.0f;
  s.materials.push_back(m);
  return s;
}

std::vector<glm::vec3> hard_points(const Scene& s) {
  const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  std::vector<glm::vec3> p = {{0, 0, 0}, s.camera.position, s.lights[1].position, {1e30f, 1e30f, 1e30f},
                              {-1e20f, 3e19f, 1e-30f}, {1e-40f, -1e-40f, 0.0f}, {nan, 0, 0}, {inf, 0, 0},
                              {0.5f, 1.0f, 3.999999f}, {-0.0f, -0.0f, -0.0f}};
  std::uint32_t seed = 7;
  const auto rnd = [&] { return float((seed = seed * 1664525u + 1013904223u) >> 8) / float(1 << 24) - 0.5f; };
  for (int i = 0; i < 2000; ++i) p.push_back({8 * rnd(), 8 * rnd(), 8 * rnd()});
  return p;
}

std::vector<glm::vec3> hard_normals() {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::vector<glm::vec3> n = {{0, 0, 0}, {0, 0, 1}, {0, 0, -1}, {nan, 0, 0}, {1e30f, 0, 0}, {0, 1e-40f, 0}};
  std::uint32_t seed = 99;
  const auto rnd = [&] { return float((seed = seed * 1664525u + 1013904223u) >> 8) / float(1 << 24) - 0.5f; };
  for (int i = 0; i < 2000; ++i) {
    const glm::vec3 v(rnd(), rnd(), rnd());
    n.push_back(glm::length(v) > 0.0f ? v / glm::length(v) : v);
  }
  return n;
}

TEST(VertexLightingLanes, EqualsShadeBitForBit) {
  for (const bool local : {true, false})
    for (const bool perspective : {true, false}) {
      const Scene s = lit_scene(local, perspective);
      const VertexLighting lighting(s);
      const std::vector<glm::vec3> p = hard_points(s), n = hard_normals();
      const glm::vec3 v = glm::normalize(s.camera.position - s.camera.target);
      std::size_t specular_lanes = 0;
      for (std::uint32_t material = 0; material < s.materials.size(); ++material)
        for (std::size_t i = 0; i + VertexLighting::kLanes <= p.size(); i += 3) {  // overlapping groups
          glm::vec3 lp[VertexLighting::kLanes], ln[VertexLighting::kLanes], out[VertexLighting::kLanes];
          for (int k = 0; k < VertexLighting::kLanes; ++k) {
            lp[k] = p[i + k];
            ln[k] = n[(i * 7 + k) % n.size()];
          }
          if (i % 5 == 0) ln[1] = v;  // N.H at its largest for the distant viewer
          lighting.shade_lanes(material, lp, ln, out);
          for (int k = 0; k < VertexLighting::kLanes; ++k) {
            const glm::vec3 want = lighting.shade(material, lp[k], ln[k]);
            for (int c = 0; c < 3; ++c)
              ASSERT_EQ(bits(out[k][c]), bits(want[c]))
                  << "local " << local << " material " << material << " point " << i + k << " channel " << c
                  << ": " << out[k][c] << " vs " << want[c];
            specular_lanes += want != lighting.shade(2, lp[k], ln[k]);  // material 2 has no specular
          }
        }
      EXPECT_GT(specular_lanes, 1000u);  // the specular branch was taken
    }
}

}  // namespace
}  // namespace parashade
