#pragma once
// Blinn–Phong in double precision, written from the formula ([Dembitsky 2025, software/hardware rendering] §4.1). Used by the vertex stage for
// Gouraud vertex values and by the exact reference; the kernels have their own implementation.
#include <glm/glm.hpp>

#include "parashade/scene.hpp"

namespace parashade {

struct LightingTerms {
  glm::dvec3 ambient{0.0}, diffuse{0.0}, specular{0.0};
  glm::dvec3 total() const { return ambient + diffuse + specular; }
};

// Terms at world position p with unit normal n, in 8-bit levels (x255), unclamped.
LightingTerms blinn_phong_terms(const Scene& scene, const Material& m, glm::dvec3 p, glm::dvec3 n);
inline glm::dvec3 blinn_phong(const Scene& scene, const Material& m, glm::dvec3 p, glm::dvec3 n) {
  return blinn_phong_terms(scene, m, p, n).total();
}
// Unit vector from p toward the viewer (local viewer) or the constant view direction (infinite viewer).
glm::dvec3 view_vector(const Scene& scene, glm::dvec3 p);

}  // namespace parashade
