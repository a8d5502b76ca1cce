#include "shading_tables.hpp"

#include <algorithm>

namespace parashade {

std::vector<cl_float4> light_table(const Scene& s) {
  std::vector<cl_float4> out;
  for (const Light& l : s.lights) {
    const bool point = l.type == LightType::point;
    const glm::vec3 v = point ? l.position : -glm::normalize(l.direction);
    out.push_back({{v.x, v.y, v.z, point ? 1.0f : 0.0f}});
    out.push_back({{255.0f * l.color.r, 255.0f * l.color.g, 255.0f * l.color.b, 0.0f}});
  }
  if (out.empty()) out.push_back({{0, 0, 0, 0}});
  return out;
}

cl_float4 viewer_value(const Scene& s, bool local_viewer) {
  const glm::vec3 v = local_viewer ? s.camera.position : glm::normalize(s.camera.position - s.camera.target);
  return {{v.x, v.y, v.z, 0.0f}};
}

std::vector<cl_float4> material_table(const Scene& s, const SpecularModel& spec) {
  std::vector<cl_float4> out;
  for (const Material& m : s.materials) {
    const glm::vec3 a = 255.0f * m.ambient * s.ambient_light;
    out.push_back({{a.x, a.y, a.z, m.shininess}});
    const double scale = spec.kind == SpecularKind::cosk_taylor ? taylor_scale(m.shininess, spec.k)
                         : spec.kind == SpecularKind::cosk_lobe ? lobe_scale(m.shininess, spec.k)
                                                                : 0.0;
    out.push_back({{m.diffuse.r, m.diffuse.g, m.diffuse.b, float(scale)}});
    out.push_back({{m.specular.r, m.specular.g, m.specular.b, 0.0f}});
  }
  if (out.empty()) out.push_back({{0, 0, 0, 1}});
  return out;
}

void set_combined_limits(const Scene& s, const CombinedConfig& c, std::vector<cl_float4>& materials) {
  // The specular terms --highlight-test drops are charged to the budget first (dropped_specular_levels).
  const double budget = combined_shading_budget(c);
  const double segments =
      c.highlight_test ? std::max(0.0, budget - dropped_specular_levels(c, budget, s.lights.size()) * double(s.lights.size()))
                       : budget;
  for (std::size_t m = 0; m < s.materials.size() && 3 * m + 2 < materials.size(); ++m)
    materials[3 * m + 2].s[3] =
        c.automatic && c.rule == TriangleRule::none ? float(psi_limit(s, s.materials[m], segments)) : 0.0f;
}

}  // namespace parashade
