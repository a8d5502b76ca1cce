#include "weld.hpp"

#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace parashade::detail {

namespace {

struct CellHash {
  std::size_t operator()(const glm::i64vec3& c) const {
    const auto h = [](std::int64_t v) { return std::hash<std::int64_t>()(v); };
    return h(c.x) * 73856093u ^ h(c.y) * 19349663u ^ h(c.z) * 83492791u;
  }
};

}  // namespace

std::size_t weld_vertices(Mesh& mesh, float tolerance) {
  // A grid of cells one tolerance wide: a vertex's partner lies in its own cell or a neighbouring one.
  const double cell = tolerance;
  auto cell_of = [&](glm::vec3 p) { return glm::i64vec3(glm::floor(glm::dvec3(p) / cell)); };
  std::unordered_map<glm::i64vec3, std::vector<unsigned>, CellHash> grid;
  std::vector<unsigned> remap(mesh.positions.size());
  std::vector<glm::vec3> positions;
  std::vector<glm::dvec3> normal_sum;
  std::vector<glm::vec3> first_normal;  // for the (unlikely) case of members' normals cancelling out
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    const glm::vec3 p = mesh.positions[i];
    const glm::i64vec3 c = cell_of(p);
    unsigned found = ~0u;
    for (int dx = -1; dx <= 1 && found == ~0u; ++dx)
      for (int dy = -1; dy <= 1 && found == ~0u; ++dy)
        for (int dz = -1; dz <= 1 && found == ~0u; ++dz) {
          const auto it = grid.find(c + glm::i64vec3(dx, dy, dz));
          if (it == grid.end()) continue;
          for (const unsigned k : it->second) {
            const glm::vec3 d = glm::abs(positions[k] - p);
            if (d.x <= tolerance && d.y <= tolerance && d.z <= tolerance) {
              found = k;
              break;
            }
          }
        }
    if (found == ~0u) {
      found = static_cast<unsigned>(positions.size());
      positions.push_back(p);
      normal_sum.emplace_back(0.0);
      first_normal.push_back(mesh.normals[i]);
      grid[c].push_back(found);
    }
    remap[i] = found;
    normal_sum[found] += glm::dvec3(mesh.normals[i]);
  }

  std::vector<glm::vec3> normals(positions.size());
  for (std::size_t k = 0; k < positions.size(); ++k) {
    const double len = glm::length(normal_sum[k]);
    normals[k] = len > 1e-6 ? glm::vec3(normal_sum[k] / len) : first_normal[k];
  }
  std::vector<glm::uvec3> triangles;
  triangles.reserve(mesh.triangles.size());
  for (const glm::uvec3& t : mesh.triangles) {
    const glm::uvec3 w(remap[t.x], remap[t.y], remap[t.z]);
    if (w.x != w.y && w.y != w.z && w.z != w.x) triangles.push_back(w);
  }
  const std::size_t removed = mesh.triangles.size() - triangles.size();
  mesh.positions = std::move(positions);
  mesh.normals = std::move(normals);
  mesh.triangles = std::move(triangles);
  return removed;
}

}  // namespace parashade::detail
