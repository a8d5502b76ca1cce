#pragma once
// Blinn–Phong in single precision for the vertex stage (Gouraud vertex values, flat triangle values).
// The same formula as lighting.hpp, prepared once per frame so the per-vertex work is small, with x^n from
// vertex_power.hpp (both paths, so the lanes keep shade()'s bits); a test checks it against the
// double-precision version.
#include <vector>

#include <glm/glm.hpp>

#include "parashade/scene.hpp"

namespace parashade {

class VertexLighting {
 public:
  explicit VertexLighting(const Scene& scene);
  // Levels (x255), unclamped. n must be unit length (a zero normal gives ambient only).
  glm::vec3 shade(std::uint32_t material, glm::vec3 p, glm::vec3 n) const;
  // shade() of kLanes vertices at once, as vectors of kLanes floats: lane for lane the same IEEE single
  // operations in the same order (no contraction), so the same bits as kLanes calls of shade().
  static constexpr int kLanes = 8;
  void shade_lanes(std::uint32_t material, const glm::vec3* p, const glm::vec3* n, glm::vec3* out) const;

 private:
  struct PreparedLight {
    bool directional;
    glm::vec3 l_or_position;  // directional: unit vector toward the light; point: position
    glm::vec3 intensity;      // levels
  };
  struct PreparedMaterial {
    glm::vec3 ambient_term;   // ambient x I_a x 255
    glm::vec3 diffuse, specular;
    float shininess;
  };
  std::vector<PreparedLight> lights_;
  std::vector<PreparedMaterial> materials_;
  glm::vec3 eye_;
  glm::vec3 view_dir_;        // toward the viewer, for the infinite viewer
  bool local_viewer_;
};

}  // namespace parashade
