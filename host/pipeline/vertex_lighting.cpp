#include "parashade/vertex_lighting.hpp"

#include <cmath>

namespace parashade {

VertexLighting::VertexLighting(const Scene& scene)
    : eye_(scene.camera.position),
      view_dir_(glm::normalize(scene.camera.position - scene.camera.target)),
      local_viewer_(scene.local_viewer && scene.camera.projection == Projection::perspective) {
  for (const Light& l : scene.lights) {
    const bool directional = l.type == LightType::directional;
    lights_.push_back({directional, directional ? -glm::normalize(l.direction) : l.position, 255.0f * l.color});
  }
  for (const Material& m : scene.materials)
    materials_.push_back({255.0f * m.ambient * scene.ambient_light, m.diffuse, m.specular, m.shininess});
}

glm::vec3 VertexLighting::shade(std::uint32_t material, glm::vec3 p, glm::vec3 n) const {
  const PreparedMaterial& m = materials_[material];
  glm::vec3 out = m.ambient_term;
  glm::vec3 v = view_dir_;
  if (local_viewer_) {
    const glm::vec3 d = eye_ - p;
    const float len = glm::length(d);
    if (len > 0.0f) v = d / len;
  }
  for (const PreparedLight& light : lights_) {
    glm::vec3 l = light.l_or_position;
    if (!light.directional) {
      const glm::vec3 d = l - p;
      const float len = glm::length(d);
      if (len == 0.0f) continue;
      l = d / len;
    }
    const float n_dot_l = glm::dot(n, l);
    if (n_dot_l > 0.0f) out += light.intensity * m.diffuse * n_dot_l;
    const glm::vec3 h = l + v;
    const float h_len = glm::length(h);
    if (h_len == 0.0f) continue;
    const float n_dot_h = glm::dot(n, h) / h_len;
    if (n_dot_h > 0.0f) out += light.intensity * m.specular * std::pow(n_dot_h, m.shininess);
  }
  return out;
}

}  // namespace parashade
