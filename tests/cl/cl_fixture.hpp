#pragma once
// Shared by the OpenCL tests: one device for the whole program (PARASHADE_TEST_DEVICE selects it,
// default the first), and scenes built in code with a pixel-aligned orthographic camera.
#include <cstdlib>
#include <memory>
#include <random>

#include <gtest/gtest.h>

#include "parashade/device.hpp"
#include "parashade/renderer.hpp"
#include "parashade/scene.hpp"
#include "parashade/shapes.hpp"
#include "test_support.hpp"

namespace parashade::testing_support {

// Never destroyed: releasing OpenCL objects from a static destructor runs after the main thread's
// thread_local objects are gone, and Oclgrind 21.10's runtime keeps its API call stack in one (its
// clReleaseProgram then writes to freed memory and the program aborts at exit, valgrind shows it).
inline Device& test_device() {
  static Device* device = [] {
    const char* sel = std::getenv("PARASHADE_TEST_DEVICE");
    return open_device(sel ? sel : "").release();
  }();
  return *device;
}

// `method` on screen tiles of `tile` pixels, with the float read-back or not.
inline RenderOptions render_options(Method method, bool float_output, int tile) {
  RenderOptions o;
  o.method = method;
  o.float_output = float_output;
  o.tile_size = tile;
  return o;
}

// Orthographic camera on +z looking down -z, 1 world unit = 1 pixel, world (x, y) at screen
// (x + W/2, H/2 - y); one directional light, one material.
inline Scene pixel_scene(int width, int height) {
  Scene s = ortho_scene(width, height);  // test_support.hpp: the same camera and material
  s.name = "test";
  s.background = {0.0f, 0.0f, 0.0f};
  s.ambient_light = {1.0f, 1.0f, 1.0f};
  s.lights[0].direction = glm::normalize(glm::vec3(-0.3f, -0.4f, -1.0f));
  s.lights[0].color = {1.0f, 0.9f, 0.8f};
  s.materials[0].shininess = 20.0f;
  return s;
}

// `count` random triangles inside the screen (one object), random depths in the view volume and
// random unit normals facing the viewer, so vertex colours vary strongly.
inline std::shared_ptr<Mesh> random_triangles(int count, int width, int height, float max_size, std::mt19937& rng) {
  auto mesh = std::make_shared<Mesh>();
  std::uniform_real_distribution<float> ux(-0.5f * width, 0.5f * width), uy(-0.5f * height, 0.5f * height);
  std::uniform_real_distribution<float> ud(-max_size, max_size), uz(-5.0f, 5.0f), un(-1.0f, 1.0f);
  for (int t = 0; t < count; ++t) {
    const glm::vec2 c(ux(rng), uy(rng));
    for (int k = 0; k < 3; ++k) {
      mesh->positions.push_back({c.x + ud(rng), c.y + ud(rng), uz(rng)});
      glm::vec3 n(un(rng), un(rng), 1.0f + std::abs(un(rng)));
      mesh->normals.push_back(glm::normalize(n));
    }
    mesh->triangles.push_back({3 * t, 3 * t + 1, 3 * t + 2});
  }
  return mesh;
}

inline void add_object(Scene& s, std::shared_ptr<const Mesh> mesh, glm::mat4 model = glm::mat4(1.0f)) {
  Object o;
  o.name = "object" + std::to_string(s.objects.size());
  o.mesh = std::move(mesh);
  o.model = model;
  s.objects.push_back(o);
}

// Three small-triangle spheres (48x24) overlapping in depth in a 301x203 frame: triangles of different
// objects compete per pixel, so a walk that changes their order within a tile changes the image.
inline Scene overlapping_spheres_scene() {
  Scene s = pixel_scene(301, 203);
  for (int k = 0; k < 3; ++k) {
    auto mesh = std::make_shared<Mesh>(make_sphere(48, 24));
    for (auto& p : mesh->positions) p = p * glm::vec3(90.0f, 90.0f, 4.0f) + glm::vec3(40.0f * float(k) - 40.0f, 10.0f * float(k), -2.0f * float(k));
    add_object(s, mesh);
  }
  return s;
}

}  // namespace parashade::testing_support
