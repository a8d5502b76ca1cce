#pragma once
// World positions and unit normals of vertices, the vertex stage's inputs to lighting: the scalar
// definitions (world_position, unit_normal) and a version that computes many at once in vector lanes with
// the same bits (a test checks).
#include <cstddef>

#include <glm/glm.hpp>

namespace parashade {

// vec3(model * (p, 1)) with glm's float product.
glm::vec3 world_position(const glm::mat4& model, glm::vec3 p);
// normal_matrix * n scaled to unit length; (0, 0, 1) when that is zero.
glm::vec3 unit_normal(const glm::mat3& normal_matrix, glm::vec3 n);

// world[i] = world_position(model, position[i]) and normal[i] = unit_normal(normal_matrix, normals[i]) for
// i in [0, count); either output may be null (not computed).
void world_and_normals(const glm::mat4& model, const glm::mat3& normal_matrix, const glm::vec3* position,
                       const glm::vec3* normals, std::size_t count, glm::vec3* world, glm::vec3* normal);

}  // namespace parashade
