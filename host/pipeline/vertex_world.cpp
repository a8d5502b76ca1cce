#include "parashade/vertex_world.hpp"

#include <cmath>
#include <cstring>

#include "parashade/vertex_snap.hpp"  // vertex_lanes_pay

namespace parashade {

glm::vec3 world_position(const glm::mat4& model, glm::vec3 p) { return glm::vec3(model * glm::vec4(p, 1.0f)); }

glm::vec3 unit_normal(const glm::mat3& normal_matrix, glm::vec3 n) {
  const glm::vec3 m = normal_matrix * n;
  const float len = glm::length(m);
  return len > 0.0f ? m / len : glm::vec3(0.0f, 0.0f, 1.0f);
}

namespace {

// kLanes vertices as vectors (GCC/Clang vector extensions: the IEEE operations lane by lane; the file is
// built without contraction into fused multiply-adds, so each lane repeats the scalar functions' bits).
constexpr int kLanes = 8;
typedef float Floats __attribute__((vector_size(4 * kLanes)));
typedef int Ints __attribute__((vector_size(4 * kLanes)));
#define PARASHADE_LANE inline __attribute__((always_inline))

PARASHADE_LANE Floats splat(float v) {
  Floats r;
  for (int k = 0; k < kLanes; ++k) r[k] = v;
  return r;
}

// Lanes j = 0, 1, 2 of kLanes vec3s from `v` (structure of arrays), and back.
PARASHADE_LANE void load(const glm::vec3* v, Floats (&out)[3]) {
  float c[3][kLanes];
  for (int k = 0; k < kLanes; ++k)
    for (int j = 0; j < 3; ++j) c[j][k] = v[k][j];
  std::memcpy(out, c, sizeof out);
}
PARASHADE_LANE void store(const Floats (&in)[3], glm::vec3* v) {
  for (int k = 0; k < kLanes; ++k) v[k] = {in[0][k], in[1][k], in[2][k]};
}

PARASHADE_LANE void world_lanes(const glm::mat4& m, const glm::vec3* position, glm::vec3* world) {
  Floats p[3], w[3];
  load(position, p);
  // glm's mat4 * vec4: (m[0] * x + m[1] * y) + (m[2] * z + m[3] * w), w = 1.
  for (int j = 0; j < 3; ++j)
    w[j] = (splat(m[0][j]) * p[0] + splat(m[1][j]) * p[1]) + (splat(m[2][j]) * p[2] + splat(m[3][j]));
  store(w, world);
}

PARASHADE_LANE void normal_lanes(const glm::mat3& m, const glm::vec3* normals, glm::vec3* normal) {
  Floats n[3], r[3];
  load(normals, n);
  // glm's mat3 * vec3: m[0][j] * x + m[1][j] * y + m[2][j] * z; length = sqrt((x*x + y*y) + z*z).
  for (int j = 0; j < 3; ++j) r[j] = splat(m[0][j]) * n[0] + splat(m[1][j]) * n[1] + splat(m[2][j]) * n[2];
  Floats len = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
  for (int k = 0; k < kLanes; ++k) len[k] = std::sqrt(len[k]);
  const Ints positive = len > splat(0.0f);
  const Floats fallback[3] = {splat(0.0f), splat(0.0f), splat(1.0f)};
  for (int j = 0; j < 3; ++j) r[j] = Floats((positive & Ints(r[j] / len)) | (~positive & Ints(fallback[j])));
  store(r, normal);
}

// Whole groups of kLanes vertices; clones and the scalar tail outside them as transform_vertices
// (vertex_snap.cpp).
__attribute__((target_clones("arch=x86-64-v4", "avx2", "default")))
void world_and_normal_groups(const glm::mat4& model, const glm::mat3& normal_matrix, const glm::vec3* position,
                             const glm::vec3* normals, std::size_t groups, glm::vec3* world, glm::vec3* normal) {
  for (std::size_t i = 0; i < groups * kLanes; i += kLanes) {
    if (world) world_lanes(model, position + i, world + i);
    if (normal) normal_lanes(normal_matrix, normals + i, normal + i);
  }
}

}  // namespace

void world_and_normals(const glm::mat4& model, const glm::mat3& normal_matrix, const glm::vec3* position,
                       const glm::vec3* normals, std::size_t count, glm::vec3* world, glm::vec3* normal) {
  const std::size_t groups = vertex_lanes_pay() ? count / kLanes : 0;
  if (groups) world_and_normal_groups(model, normal_matrix, position, normals, groups, world, normal);
  for (std::size_t i = groups * kLanes; i < count; ++i) {
    if (world) world[i] = world_position(model, position[i]);
    if (normal) normal[i] = unit_normal(normal_matrix, normals[i]);
  }
}

}  // namespace parashade
