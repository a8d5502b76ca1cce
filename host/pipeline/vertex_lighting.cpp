#include "parashade/vertex_lighting.hpp"

#include <cmath>

#include "parashade/vertex_lanes.hpp"
#include "parashade/vertex_power.hpp"

namespace parashade {

VertexLighting::VertexLighting(const Scene& scene)
    : eye_(scene.camera.position),
      view_dir_(glm::normalize(scene.camera.position - scene.camera.target)),
      local_viewer_(scene.viewer_is_local()) {
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
    if (n_dot_h > 0.0f) out += light.intensity * m.specular * vertex_lanes::power(n_dot_h, m.shininess);
  }
  return out;
}

namespace {

using namespace vertex_lanes;
static_assert(VertexLighting::kLanes == vertex_lanes::kLanes, "the vertex stage's lanes");

// out + (i * k) * s where m holds (glm: light.intensity * m.diffuse * n_dot_l, added to out).
inline __attribute__((always_inline)) void add_where(Mask m, Vec3s& out, glm::vec3 ik, Floats s) {
  out.x = select(m, out.x + splat(ik.x) * s, out.x);
  out.y = select(m, out.y + splat(ik.y) * s, out.y);
  out.z = select(m, out.z + splat(ik.z) * s, out.z);
}

}  // namespace

// shade() with its branches as lane masks: a lane adds a term exactly when shade() would.
// Two builds chosen at load time: AVX2's 8-float registers hold the lanes whole (no FMA either way: the
// same bits).
__attribute__((target_clones("avx2", "default"))) void VertexLighting::shade_lanes(std::uint32_t material,
                                                                                 const glm::vec3* p_in,
                                                                                 const glm::vec3* n_in,
                                                                                 glm::vec3* out_colour) const {
  const PreparedMaterial& m = materials_[material];
  const Vec3s p = load3(p_in), n = load3(n_in);
  const Floats zero = splat(0.0f);
  Vec3s out = splat3(m.ambient_term);
  Vec3s v = splat3(view_dir_);
  if (local_viewer_) {
    const Vec3s d = minus(splat3(eye_), p);
    const Floats len = length(d);
    v = select3(len > zero, divide(d, len), v);
  }
  for (const PreparedLight& light : lights_) {
    Vec3s l = splat3(light.l_or_position);
    Mask lit = zero == zero;  // all lanes
    if (!light.directional) {
      const Vec3s d = minus(l, p);
      const Floats len = length(d);
      lit = len != zero;
      l = divide(d, len);
    }
    const Floats n_dot_l = dot(n, l);
    add_where(lit & (n_dot_l > zero), out, light.intensity * m.diffuse, n_dot_l);
    const Vec3s h = plus(l, v);
    const Floats h_len = length(h);
    lit &= h_len != zero;
    const Floats n_dot_h = dot(n, h) / h_len;
    const Mask specular = lit & (n_dot_h > zero);
    add_where(specular, out, light.intensity * m.specular, power(n_dot_h, m.shininess));  // other lanes unspecified
  }
  store3(out, out_colour);
}

}  // namespace parashade