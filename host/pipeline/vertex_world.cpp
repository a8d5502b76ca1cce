#include "parashade/vertex_world.hpp"

#include "parashade/vertex_lanes.hpp"

namespace parashade {

glm::vec3 world_position(const glm::mat4& model, glm::vec3 p) { return glm::vec3(model * glm::vec4(p, 1.0f)); }

glm::vec3 unit_normal(const glm::mat3& normal_matrix, glm::vec3 n) {
  const glm::vec3 m = normal_matrix * n;
  const float len = glm::length(m);
  return len > 0.0f ? m / len : glm::vec3(0.0f, 0.0f, 1.0f);
}

namespace {

using namespace vertex_lanes;

// Whole groups of kLanes vertices; clones and the scalar tail outside them as transform_vertices
// (vertex_snap.cpp).
__attribute__((target_clones("arch=x86-64-v4", "avx2", "default")))
void world_and_normal_groups(const glm::mat4& model, const glm::mat3& normal_matrix, const glm::vec3* position,
                             const glm::vec3* normals, std::size_t groups, glm::vec3* world, glm::vec3* normal) {
  for (std::size_t i = 0; i < groups * kLanes; i += kLanes) {
    if (world) {
      const Vec3s p = load3(position + i);
      store3({transform(model, p, 0), transform(model, p, 1), transform(model, p, 2)}, world + i);
    }
    if (normal) {  // unit_normal: the scaled normal, or (0, 0, 1) where its length is 0
      const Vec3s n = transform(normal_matrix, load3(normals + i));
      const Floats len = length(n);
      store3(select3(len > splat(0.0f), divide(n, len), splat3({0.0f, 0.0f, 1.0f})), normal + i);
    }
  }
}

}  // namespace

void world_and_normals(const glm::mat4& model, const glm::mat3& normal_matrix, const glm::vec3* position,
                       const glm::vec3* normals, std::size_t count, glm::vec3* world, glm::vec3* normal) {
  const std::size_t groups = vertex_lanes::pay() ? count / vertex_lanes::kLanes : 0;
  if (groups) world_and_normal_groups(model, normal_matrix, position, normals, groups, world, normal);
  for (std::size_t i = groups * vertex_lanes::kLanes; i < count; ++i) {
    if (world) world[i] = world_position(model, position[i]);
    if (normal) normal[i] = unit_normal(normal_matrix, normals[i]);
  }
}

}  // namespace parashade
