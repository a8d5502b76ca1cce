#pragma once
// Eight vertices as GCC/Clang generic vectors, for the vertex stage's lanes (vertex_snap.cpp,
// vertex_world.cpp, vertex_lighting.cpp): +, -, *, / are the IEEE operations lane by lane, comparisons give
// lanes of all ones (true) or zero, casts between the types keep the bits. The files that include it are
// built without FMA contraction, so each lane repeats the scalar code's bits. Internal to those files: the
// vectors never cross a library interface.
#include <cmath>

#include <glm/glm.hpp>

namespace parashade::vertex_lanes {

constexpr int kLanes = 8;
typedef float Floats __attribute__((vector_size(4 * kLanes)));
typedef double Doubles __attribute__((vector_size(8 * kLanes)));
typedef int Mask __attribute__((vector_size(4 * kLanes)));

struct Vec3s {
  Floats x, y, z;
};

// Whether the lanes pay on this machine: with AVX2 or better. Their baseline x86-64 (SSE2) build was slower
// than the scalar loop (sphere_2m's vertex stage 1.16-1.23x), so without AVX2 the callers run the scalar
// definitions: the same bits.
inline bool pay() {
  static const bool avx2 = __builtin_cpu_supports("avx2");
  return avx2;
}

#define PARASHADE_LANE inline __attribute__((always_inline))
PARASHADE_LANE Floats splat(float v) {
  Floats r;
  for (int k = 0; k < kLanes; ++k) r[k] = v;
  return r;
}
PARASHADE_LANE Floats sqrt_lanes(Floats v) {  // correctly rounded lane by lane, as std::sqrt(float)
  for (int k = 0; k < kLanes; ++k) v[k] = std::sqrt(v[k]);
  return v;
}
PARASHADE_LANE Floats select(Mask m, Floats yes, Floats no) { return Floats((m & Mask(yes)) | (~m & Mask(no))); }
// glm::dot of vec3: (x*x' + y*y') + z*z'; glm::length = sqrt(dot(a, a)).
PARASHADE_LANE Floats dot(const Vec3s& a, const Vec3s& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
PARASHADE_LANE Floats length(const Vec3s& a) { return sqrt_lanes(dot(a, a)); }
PARASHADE_LANE Vec3s minus(const Vec3s& a, const Vec3s& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
PARASHADE_LANE Vec3s plus(const Vec3s& a, const Vec3s& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
PARASHADE_LANE Vec3s divide(const Vec3s& a, Floats d) { return {a.x / d, a.y / d, a.z / d}; }
PARASHADE_LANE Vec3s splat3(glm::vec3 v) { return {splat(v.x), splat(v.y), splat(v.z)}; }
PARASHADE_LANE Vec3s select3(Mask m, const Vec3s& yes, const Vec3s& no) {
  return {select(m, yes.x, no.x), select(m, yes.y, no.y), select(m, yes.z, no.z)};
}
// v[0..kLanes) as lanes, and back.
PARASHADE_LANE Vec3s load3(const glm::vec3* v) {
  Vec3s r;
  for (int k = 0; k < kLanes; ++k) r.x[k] = v[k].x, r.y[k] = v[k].y, r.z[k] = v[k].z;
  return r;
}
PARASHADE_LANE void store3(const Vec3s& a, glm::vec3* v) {
  for (int k = 0; k < kLanes; ++k) v[k] = {a.x[k], a.y[k], a.z[k]};
}
// Component j of glm's m * vec4(p, 1): (m[0][j] * x + m[1][j] * y) + (m[2][j] * z + m[3][j] * 1).
PARASHADE_LANE Floats transform(const glm::mat4& m, const Vec3s& p, int j) {
  return (splat(m[0][j]) * p.x + splat(m[1][j]) * p.y) + (splat(m[2][j]) * p.z + splat(m[3][j]));
}
// glm's mat3 * vec3: component j is (m[0][j] * x + m[1][j] * y) + m[2][j] * z.
PARASHADE_LANE Vec3s transform(const glm::mat3& m, const Vec3s& v) {
  Floats r[3];
  for (int j = 0; j < 3; ++j) r[j] = splat(m[0][j]) * v.x + splat(m[1][j]) * v.y + splat(m[2][j]) * v.z;
  return {r[0], r[1], r[2]};
}
#undef PARASHADE_LANE

}  // namespace parashade::vertex_lanes
