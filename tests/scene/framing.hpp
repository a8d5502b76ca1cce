#pragma once
// Where a scene's geometry lands in its frame, with the camera's own projection (GLM's conventions).
#include <algorithm>
#include <cstddef>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "parashade/scene.hpp"

namespace parashade::testing_support {

struct Framing {
  std::size_t vertices = 0;
  std::size_t outside = 0;         // beyond the frame's edges or the near/far planes
  glm::vec2 lo{1e9f}, hi{-1e9f};   // projected bounding box in NDC ([-1, 1] is the frame)
  float height_fraction() const { return std::max(0.0f, (hi.y - lo.y) / 2.0f); }
  float width_fraction() const { return std::max(0.0f, (hi.x - lo.x) / 2.0f); }
};

inline glm::mat4 projection(const Scene& s) {
  const Camera& c = s.camera;
  const float aspect = float(s.width) / float(s.height);
  if (c.projection == Projection::perspective)
    return glm::perspective(glm::radians(c.fov_y_degrees), aspect, c.near_plane, c.far_plane);
  const float h = 0.5f * c.ortho_height;
  return glm::ortho(-h * aspect, h * aspect, -h, h, c.near_plane, c.far_plane);
}

inline Framing framing(const Scene& s) {
  const glm::mat4 view_projection = projection(s) * glm::lookAt(s.camera.position, s.camera.target, s.camera.up);
  Framing f;
  for (const Object& o : s.objects) {
    const glm::mat4 m = view_projection * o.model;
    for (const glm::vec3& p : o.mesh->positions) {
      const glm::vec4 clip = m * glm::vec4(p, 1.0f);
      ++f.vertices;
      if (!(clip.w > 0.0f)) {
        ++f.outside;
        continue;
      }
      const glm::vec3 ndc = glm::vec3(clip) / clip.w;
      if (std::abs(ndc.x) > 1.0f || std::abs(ndc.y) > 1.0f || std::abs(ndc.z) > 1.0f) ++f.outside;
      f.lo = glm::min(f.lo, glm::vec2(ndc));
      f.hi = glm::max(f.hi, glm::vec2(ndc));
    }
  }
  return f;
}

}  // namespace parashade::testing_support
