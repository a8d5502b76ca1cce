// Mesh invariants shared by the loader and the procedural shapes: vertex normals and validation.
#include <cmath>
#include <string>

#include "parashade/errors.hpp"
#include "parashade/mesh.hpp"

namespace parashade {

namespace {

bool finite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

void compute_vertex_normals(Mesh& mesh) {
  // Accumulate in double: a vertex of a fine scan sums many small, nearly cancelling contributions.
  std::vector<glm::dvec3> sum(mesh.positions.size(), glm::dvec3(0.0));
  for (const glm::uvec3& t : mesh.triangles) {
    const glm::dvec3 a(mesh.positions[t.x]), b(mesh.positions[t.y]), c(mesh.positions[t.z]);
    // The unnormalized cross product is twice the area times the unit normal: area weighting for free.
    const glm::dvec3 n = glm::cross(b - a, c - a);
    if (!std::isfinite(n.x) || !std::isfinite(n.y) || !std::isfinite(n.z)) continue;
    sum[t.x] += n;
    sum[t.y] += n;
    sum[t.z] += n;
  }
  mesh.normals.resize(mesh.positions.size());
  for (std::size_t i = 0; i < sum.size(); ++i) {
    const double len = glm::length(sum[i]);
    mesh.normals[i] = (len > 0.0 && std::isfinite(len)) ? glm::vec3(sum[i] / len) : glm::vec3(0.0f, 0.0f, 1.0f);
  }
}

void validate_mesh(const Mesh& mesh, const std::string& what) {
  const std::size_t n = mesh.positions.size();
  if (mesh.normals.size() != n)
    throw InputError(what + ": " + std::to_string(n) + " positions but " + std::to_string(mesh.normals.size()) +
                     " normals");
  for (std::size_t i = 0; i < n; ++i) {
    if (!finite(mesh.positions[i]))
      throw InputError(what + ": vertex " + std::to_string(i) + " has a non-finite coordinate");
    if (!finite(mesh.normals[i]))
      throw InputError(what + ": vertex " + std::to_string(i) + " has a non-finite normal");
  }
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    const glm::uvec3& t = mesh.triangles[i];
    for (int k = 0; k < 3; ++k)
      if (t[k] >= n)
        throw InputError(what + ": triangle " + std::to_string(i) + " refers to vertex " + std::to_string(t[k]) +
                         " of " + std::to_string(n));
  }
}

}  // namespace parashade
