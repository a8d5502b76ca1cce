#pragma once
// A triangle mesh as the renderer consumes it: positions, one unit normal per position, index triples.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace parashade {

struct Mesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;  // same size as positions; unit length, never NaN
  std::vector<glm::uvec3> triangles;
};

// What loading found and did, so callers can report it.
struct MeshLoadStats {
  std::size_t faces_read = 0;               // faces in the file (any polygon size)
  std::size_t polygons_triangulated = 0;    // faces with more than 3 vertices, fanned into triangles
  std::size_t degenerate_faces = 0;         // zero-area triangles kept (they cover no pixel)
  std::size_t faces_dropped = 0;            // faces with a repeated vertex (OpenMesh refuses them)
  std::size_t non_manifold_faces = 0;       // kept on the file's vertices (OpenMesh would split them off)
  std::size_t normals_recomputed = 0;       // file gave normals, but none or a zero one for these vertices
  bool normals_from_file = false;           // otherwise area-weighted face normals
};

// Reads OBJ, OFF, PLY or STL through OpenMesh; polygons are fan-triangulated. Throws InputError naming
// the file: missing, unreadable, unknown extension, malformed (an OBJ is checked line by line; a face
// with fewer than 3 vertices or an index out of range), no faces, non-finite coordinates or normals.
// Vertices no face uses are left out. Normals come from the file when it has them (a vertex given
// several gets their average); vertices it gives none or a zero one get area-weighted face normals.
// STL files carry only facet normals, so their vertex normals are always computed.
Mesh load_mesh(const std::filesystem::path& path, MeshLoadStats* stats = nullptr);

// What a user should hear about a mesh that loaded: "<name>: N non-manifold faces kept, M faces with a
// repeated vertex dropped"; empty when there is nothing to say. Non-manifold meshes are accepted (a
// renderer needs triangles, not a manifold), with this warning and the count.
std::string mesh_load_warning(const std::string& name, const MeshLoadStats& stats);

// Vertex normal = normalized sum of the area-weighted normals of the faces around it. A zero-area face
// contributes nothing; a vertex with no face of non-zero area gets (0, 0, 1). Never produces NaN.
void compute_vertex_normals(Mesh& mesh);

// Throws InputError(what + reason) when an index is out of range or a coordinate/normal is not finite.
void validate_mesh(const Mesh& mesh, const std::string& what);

}  // namespace parashade
