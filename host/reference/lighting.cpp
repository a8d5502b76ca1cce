#include "parashade/lighting.hpp"

#include <cmath>

namespace parashade {

glm::dvec3 view_vector(const Scene& scene, glm::dvec3 p) {
  const Camera& c = scene.camera;
  if (scene.viewer_is_local()) {
    const glm::dvec3 v = glm::dvec3(c.position) - p;
    const double len = glm::length(v);
    if (len > 0.0) return v / len;
  }
  return glm::normalize(glm::dvec3(c.position) - glm::dvec3(c.target));
}

LightingTerms blinn_phong_terms(const Scene& scene, const Material& m, glm::dvec3 p, glm::dvec3 n) {
  LightingTerms t;
  t.ambient = 255.0 * glm::dvec3(m.ambient) * glm::dvec3(scene.ambient_light);
  const glm::dvec3 v = view_vector(scene, p);
  for (const Light& light : scene.lights) {
    glm::dvec3 l;
    if (light.type == LightType::directional) {
      l = -glm::normalize(glm::dvec3(light.direction));
    } else {
      const glm::dvec3 d = glm::dvec3(light.position) - p;
      const double len = glm::length(d);
      if (len == 0.0) continue;  // a light on the surface lights nothing at that point
      l = d / len;
    }
    const double n_dot_l = glm::dot(n, l);
    const glm::dvec3 il = 255.0 * glm::dvec3(light.color);
    if (n_dot_l > 0.0) t.diffuse += il * glm::dvec3(m.diffuse) * n_dot_l;
    const glm::dvec3 h_sum = l + v;
    const double h_len = glm::length(h_sum);
    if (h_len == 0.0) continue;  // light exactly opposite the viewer: no half vector
    const double n_dot_h = glm::dot(n, h_sum / h_len);
    // The specular term follows the sources: max(0, N.H)^n, independent of N.L.
    if (n_dot_h > 0.0) t.specular += il * glm::dvec3(m.specular) * std::pow(n_dot_h, double(m.shininess));
  }
  return t;
}

}  // namespace parashade
