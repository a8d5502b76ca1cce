#pragma once
// The benchmark scenes by name, at a chosen resolution: sphere_8k / sphere_131k / sphere_2m
// (scenes/sphere.json re-tessellated: 64x65, 256x257, 1024x1025 slices x stacks), fullscreen_quad (two
// triangles covering the whole screen: pixel throughput with the fewest triangles), and the scene files
// teapot, robot, bunny, fandisk (the last two need PARASHADE_MESH_DIR). Cached: the meshes are shared
// between resolutions.
#include <map>
#include <memory>
#include <string>
#include <utility>

#include "parashade/scene.hpp"
#include "parashade/shapes.hpp"

namespace parashade::bench {

inline std::string source_path(const std::string& relative) {
  return std::string(PARASHADE_SOURCE_DIR) + "/" + relative;
}

inline bool needs_mesh_dir(const std::string& name) { return name == "bunny" || name == "fandisk"; }

inline Scene fullscreen_quad_scene() {
  Scene s = load_scene(source_path("scenes/sphere.json"));  // its lights, material and background
  s.name = "fullscreen_quad";
  s.camera.projection = Projection::orthographic;
  s.camera.position = {0.0f, 0.0f, 2.0f};
  s.camera.target = {0.0f, 0.0f, 0.0f};
  s.camera.up = {0.0f, 1.0f, 0.0f};
  s.camera.ortho_height = 2.0f;
  auto mesh = std::make_shared<Mesh>();
  const float w = 4.0f, h = 1.5f;  // beyond the view volume of any aspect up to 8:3, inside the guard band
  mesh->positions = {{-w, -h, 0.0f}, {w, -h, 0.0f}, {w, h, 0.0f}, {-w, h, 0.0f}};
  mesh->normals = {{-0.3f, -0.3f, 0.9f}, {0.3f, -0.3f, 0.9f}, {0.3f, 0.3f, 0.9f}, {-0.3f, 0.3f, 0.9f}};
  for (auto& n : mesh->normals) n = glm::normalize(n);
  mesh->triangles = {{0, 1, 2}, {0, 2, 3}};
  s.objects.resize(1);
  s.objects[0].mesh = mesh;
  s.objects[0].model = glm::mat4(1.0f);
  s.cull_backfaces = true;
  return s;
}

inline Scene sphere_scene(int slices, int stacks) {
  Scene s = load_scene(source_path("scenes/sphere.json"));
  s.objects.at(0).mesh = std::make_shared<Mesh>(make_sphere(slices, stacks));
  s.name = "sphere_" + std::to_string(2 * slices * (stacks - 1));
  return s;
}

// The scene at width x height (the camera keeps its vertical field of view). Throws InputError.
inline const Scene& scene_named(const std::string& name, int width, int height) {
  static std::map<std::string, Scene> base;
  static std::map<std::string, Scene> sized;
  const std::string key = name + "@" + std::to_string(width) + "x" + std::to_string(height);
  if (auto it = sized.find(key); it != sized.end()) return it->second;
  auto b = base.find(name);
  if (b == base.end()) {
    Scene s;
    if (name == "sphere_8k") s = sphere_scene(64, 65);
    else if (name == "sphere_131k") s = sphere_scene(256, 257);
    else if (name == "sphere_2m") s = sphere_scene(1024, 1025);
    else if (name == "fullscreen_quad") s = fullscreen_quad_scene();
    else s = load_scene(source_path("scenes/" + name + ".json"));
    s.name = name;  // the benchmark's name for it (sphere_8k, not sphere_8192)
    b = base.emplace(name, std::move(s)).first;
  }
  Scene s = b->second;  // meshes are shared pointers: no copy of the geometry
  check_resolution(width, height, "benchmark resolution");
  s.width = width;
  s.height = height;
  return sized.emplace(key, std::move(s)).first->second;
}

}  // namespace parashade::bench
