#pragma once
// Geometric checks on meshes shared by the scene tests.
#include <cmath>
#include <cstddef>
#include <algorithm>
#include <map>
#include <tuple>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "parashade/mesh.hpp"

namespace parashade::testing_support {

// How the directed edges of a mesh pair up. Closed and consistently oriented: every undirected edge is
// used exactly once in each direction (boundary, overused and same_direction all zero).
struct EdgeReport {
  std::size_t edges = 0;           // undirected
  std::size_t boundary = 0;        // used by one triangle only
  std::size_t same_direction = 0;  // a directed edge used more than once: inconsistent winding
  std::size_t overused = 0;        // more than two triangles on one edge
};

// by_position: vertices at the same position count as one (shapes that duplicate vertices for flat
// normals are closed only in that sense).
inline EdgeReport edge_report(const Mesh& mesh, bool by_position = false) {
  std::vector<unsigned> id(mesh.positions.size());
  std::map<std::tuple<float, float, float>, unsigned> first;
  for (std::size_t i = 0; i < id.size(); ++i) {
    const glm::vec3 p = mesh.positions[i];
    id[i] = by_position ? first.emplace(std::make_tuple(p.x, p.y, p.z), unsigned(i)).first->second : unsigned(i);
  }
  // Per undirected edge (low, high): how often it is used low->high and high->low.
  std::map<std::pair<unsigned, unsigned>, std::pair<int, int>> uses;
  for (const glm::uvec3& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const unsigned a = id[t[k]], b = id[t[(k + 1) % 3]];
      auto& u = uses[{std::min(a, b), std::max(a, b)}];
      ++(a < b ? u.first : u.second);
    }
  EdgeReport r;
  r.edges = uses.size();
  for (const auto& [edge, u] : uses) {
    const int total = u.first + u.second;
    if (total == 1) ++r.boundary;
    if (total > 2) ++r.overused;
    if (u.first > 1 || u.second > 1) ++r.same_direction;
  }
  return r;
}

inline bool closed(const EdgeReport& r) { return r.boundary == 0 && r.same_direction == 0 && r.overused == 0; }

inline glm::vec3 face_normal(const Mesh& m, const glm::uvec3& t) {
  return glm::cross(m.positions[t.y] - m.positions[t.x], m.positions[t.z] - m.positions[t.x]);
}

inline bool finite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Normals that are finite and of unit length (within float rounding).
inline std::size_t bad_normals(const Mesh& m) {
  std::size_t bad = 0;
  for (const glm::vec3& n : m.normals)
    if (!finite(n) || std::abs(glm::length(n) - 1.0f) > 1e-4f) ++bad;
  return bad + (m.normals.size() == m.positions.size() ? 0 : 1);
}

// Triangles whose winding disagrees with a corner's vertex normal (face normal . vertex normal <= 0).
inline std::size_t winding_disagreements(const Mesh& m) {
  std::size_t bad = 0;
  for (const glm::uvec3& t : m.triangles) {
    const glm::vec3 n = face_normal(m, t);
    for (int k = 0; k < 3; ++k)
      if (glm::dot(n, m.normals[t[k]]) <= 0.0f) {
        ++bad;
        break;
      }
  }
  return bad;
}

inline std::size_t zero_area_triangles(const Mesh& m) {
  std::size_t n = 0;
  for (const glm::uvec3& t : m.triangles)
    if (glm::length(face_normal(m, t)) == 0.0f) ++n;
  return n;
}

inline glm::vec3 centroid(const Mesh& m) {
  glm::dvec3 sum(0.0);
  for (const glm::vec3& p : m.positions) sum += glm::dvec3(p);
  return glm::vec3(sum / double(m.positions.size()));
}

}  // namespace parashade::testing_support
