#pragma once
// A scene: camera, resolution, lights, Blinn–Phong materials and objects (meshes with transforms).
// Colours and intensities are in [0,1]; the renderer works in 8-bit levels (x255).
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "parashade/mesh.hpp"
#include "parashade/kernels/constants.h"

namespace parashade {

enum class Projection { perspective, orthographic };

struct Camera {
  Projection projection = Projection::perspective;
  glm::vec3 position{0.0f, 0.0f, 5.0f};
  glm::vec3 target{0.0f, 0.0f, 0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float fov_y_degrees = 40.0f;   // perspective: vertical field of view
  float ortho_height = 2.0f;     // orthographic: height of the view volume in world units
  float near_plane = 0.1f;
  float far_plane = 100.0f;
};

enum class LightType { directional, point };

struct Light {
  LightType type = LightType::directional;
  glm::vec3 direction{0.0f, 0.0f, -1.0f};  // directional: the direction light travels (L = -direction)
  glm::vec3 position{0.0f};                // point: position (no attenuation, as in the sources)
  glm::vec3 color{1.0f};                   // colour x intensity = I_l per channel
};

// Blinn–Phong per channel c: I_c = ambient_c*I_a,c + sum_l I_l,c*(diffuse_c*max(0,N.L) + specular_c*max(0,N.H)^n)
struct Material {
  std::string name;
  glm::vec3 ambient{0.1f};   // k_a times the surface colour
  glm::vec3 diffuse{0.7f};   // k_d times the surface colour
  glm::vec3 specular{0.5f};  // k_s times the specular colour
  float shininess = 32.0f;   // exponent n > 0
};

struct Object {
  std::string name;
  std::shared_ptr<const Mesh> mesh;
  glm::mat4 model{1.0f};     // object to world
  std::uint32_t material = 0;
};

struct Scene {
  std::string name;
  std::filesystem::path source;   // the file it came from, if any
  int width = 1920;
  int height = 1080;
  glm::vec3 background{0.0f};
  glm::vec3 ambient_light{1.0f};  // I_a per channel
  Camera camera;
  std::vector<Light> lights;
  std::vector<Material> materials;
  std::vector<Object> objects;
  bool cull_backfaces = false;
  bool local_viewer = true;       // false: V is the constant view direction (infinite viewer)
  std::vector<std::string> warnings;  // what loading accepted but the user should hear (mesh_load_warning)

  std::size_t triangle_count() const;
  // V varies with the point: a local viewer, and only under a perspective camera (an orthographic one
  // looks along one direction).
  bool viewer_is_local() const { return local_viewer && camera.projection == Projection::perspective; }
};

// Largest resolution the 12-bit screen addresses of the sources allow (kernels/constants.h).
constexpr int kMaxResolution = MAX_RESOLUTION;

// Loads a JSON scene (see scenes/README.md), or a bare mesh file (.obj .off .ply .stl) framed by a
// default camera and lit by a default light. Throws InputError naming the file, key or value at fault.
Scene load_scene(const std::filesystem::path& path);
// The mesh's bounding sphere seen from +z and slightly above (fov 40), one white directional light from
// the upper left behind the camera, a grey material with a highlight (n = 32), 1920x1080, no culling.
Scene scene_for_mesh(const std::filesystem::path& mesh_path);
// Throws InputError unless 1 <= width, height <= kMaxResolution.
void check_resolution(int width, int height, const std::string& what);
// --size WIDTHxHEIGHT (nullopt when absent). Only the syntax (UsageError), so that a usage error is reported
// before the scene is read; the limit is check_resolution's, with the scene's own resolution.
std::optional<std::pair<int, int>> parse_size(const std::string& size);

}  // namespace parashade
