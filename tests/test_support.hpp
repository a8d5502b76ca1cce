#pragma once
// Helpers shared by the test programs.
#include <cstddef>
#include <cstdlib>
#include <memory>
#include <vector>
#include <filesystem>
#include <optional>
#include <string>

#include "parashade/scene.hpp"

namespace parashade::testing_support {

// A perspective camera (fov in degrees) looking from `position` at `target`.
inline void set_perspective(Camera& c, glm::vec3 position, glm::vec3 target, float fov_degrees, float near_plane,
                            float far_plane) {
  c.projection = Projection::perspective;
  c.position = position;
  c.target = target;
  c.fov_y_degrees = fov_degrees;
  c.near_plane = near_plane;
  c.far_plane = far_plane;
}

// The real meshes' folder, PARASHADE_MESH_DIR (README); nullopt (and the test skips) when unset or absent.
inline std::optional<std::filesystem::path> mesh_dir() {
  const char* dir = std::getenv("PARASHADE_MESH_DIR");
  if (!dir || !*dir || !std::filesystem::is_directory(dir)) return std::nullopt;
  return std::filesystem::path(dir);
}

#define PARASHADE_REQUIRE_MESH_DIR(var)                                                        \
  const auto var##_opt = ::parashade::testing_support::mesh_dir();                             \
  if (!var##_opt) GTEST_SKIP() << "PARASHADE_MESH_DIR is not set (or not a directory): skipping";\
  const std::filesystem::path var = *var##_opt

// Orthographic camera looking down -z, 1 world unit = 1 pixel, world (x, y) at pixel (x + W/2, H/2 - y).
inline Scene ortho_scene(int width, int height) {
  Scene s;
  s.width = width;
  s.height = height;
  s.camera.projection = Projection::orthographic;
  s.camera.position = {0.0f, 0.0f, 10.0f};
  s.camera.target = {0.0f, 0.0f, 0.0f};
  s.camera.ortho_height = float(height);
  s.camera.near_plane = 1.0f;
  s.camera.far_plane = 20.0f;
  Light l;
  l.direction = glm::normalize(glm::vec3(-0.2f, -0.3f, -1.0f));
  s.lights.push_back(l);
  Material m;
  m.ambient = glm::vec3(0.1f);
  m.diffuse = glm::vec3(0.6f, 0.5f, 0.4f);
  m.specular = glm::vec3(0.3f);
  m.shininess = 10.0f;
  s.materials.push_back(m);
  return s;
}

inline void add_mesh(Scene& s, std::vector<glm::vec3> positions, std::vector<glm::uvec3> triangles,
              std::vector<glm::vec3> normals = {}) {
  auto mesh = std::make_shared<Mesh>();
  mesh->positions = std::move(positions);
  mesh->triangles = std::move(triangles);
  if (normals.empty()) normals.assign(mesh->positions.size(), glm::vec3(0.0f, 0.0f, 1.0f));
  mesh->normals = std::move(normals);
  Object o;
  o.mesh = mesh;
  s.objects.push_back(o);
}

inline std::filesystem::path source_dir() { return PARASHADE_SOURCE_DIR; }

// Sets an environment variable for this process and the children it starts, and restores it afterwards.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const std::string& value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old, had_ = true;
    ::setenv(name, value.c_str(), 1);
  }
  // Removes the variable instead (env -i's environment has no PATH).
  ScopedEnv(const char* name, std::nullptr_t) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old, had_ = true;
    ::unsetenv(name);
  }
  ~ScopedEnv() {
    if (had_) {
      ::setenv(name_, old_.c_str(), 1);
    } else {
      ::unsetenv(name_);
    }
  }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;

 private:
  const char* name_;
  std::string old_;
  bool had_ = false;
};

}  // namespace parashade::testing_support
