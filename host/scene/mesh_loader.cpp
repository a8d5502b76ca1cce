// Mesh files through OpenMesh's readers, into the renderer's triangle list.

// OpenMesh's vectors are uninitialized by design (default constructor); GCC's inliner then reports
// its property containers as "maybe uninitialized" at a location in libstdc++, where no narrower
// suppression reaches. parashade reads only the values a reader wrote (normals: see CollectingImporter).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <new>
#include <string>
#include <vector>

#include <OpenMesh/Core/IO/IOManager.hh>
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/IO/importer/ImporterT.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>

#include "input_file.hpp"
#include "mesh_file_scan.hpp"
#include "off_reader.hpp"
#include "parashade/errors.hpp"
#include "parashade/mesh.hpp"

namespace parashade {

namespace {

using PolyMesh = OpenMesh::PolyMesh_ArrayKernelT<>;

// Sees every face and vertex normal the reader produces before OpenMesh's half-edge structure alters
// them. Faces keep the file's vertex indices: OpenMesh re-adds a non-manifold face on duplicated
// vertices, which would split its normals from its neighbours' (a renderer needs no manifold, only
// triangles). Normals are collected per face corner: a file may give one vertex several.
class CollectingImporter : public OpenMesh::IO::ImporterT<PolyMesh> {
 public:
  // detect_truncation: OpenMesh's PLY reader repeats the last face when the file ends early.
  CollectingImporter(PolyMesh& mesh, bool detect_truncation)
      : ImporterT(mesh), mesh_(mesh), detect_truncation_(detect_truncation) {}

  using ImporterT::set_normal;

  OpenMesh::FaceHandle add_face(const VHandles& corners) override {
    ++faces_seen;
    if (!error.empty()) return OpenMesh::FaceHandle();
    if (corners.size() < 3) {
      error = "a face has " + std::to_string(corners.size()) + " vertices (needs at least 3)";
      return OpenMesh::FaceHandle();
    }
    for (const OpenMesh::VertexHandle v : corners)
      if (!v.is_valid() || static_cast<std::size_t>(v.idx()) >= mesh_.n_vertices()) {
        error = "a face refers to vertex " + std::to_string(v.idx()) + " (the file has " +
                std::to_string(mesh_.n_vertices()) + ")";
        return OpenMesh::FaceHandle();
      }
    for (std::size_t i = 0; i < corners.size(); ++i)
      for (std::size_t j = i + 1; j < corners.size(); ++j)
        if (corners[i] == corners[j]) return OpenMesh::FaceHandle();  // OpenMesh would refuse it too; counted as dropped
    if (repeats_previous(corners)) {
      error = "face " + std::to_string(faces_seen) + " repeats the previous one: the file looks truncated";
      return OpenMesh::FaceHandle();
    }
    const std::size_t vertices_before = mesh_.n_vertices();
    const OpenMesh::FaceHandle face = ImporterT::add_face(corners);
    if (mesh_.n_vertices() != vertices_before) ++non_manifold_faces;
    polygon_start.push_back(polygon_corners.size());
    for (const OpenMesh::VertexHandle v : corners) polygon_corners.push_back(static_cast<unsigned>(v.idx()));
    return face;
  }

  using ImporterT::add_vertex;
  OpenMesh::VertexHandle add_vertex(const OpenMesh::Vec3f& p) override {
    ++vertices_added;
    return ImporterT::add_vertex(p);
  }
  OpenMesh::VertexHandle add_vertex(const OpenMesh::Vec3d& p) override {
    ++vertices_added;
    return ImporterT::add_vertex(p);
  }

  // OpenMesh's OBJ reader passes handles it never range-checked; ImporterT writes through them unchecked
  // (fuzzing finding F1: a heap overflow). Such a normal is an error, not a write.
  void set_normal(OpenMesh::VertexHandle v, const OpenMesh::Vec3f& n) override {
    if (!known(v)) return;
    collect_normal(v, glm::dvec3(n[0], n[1], n[2]));
    ImporterT::set_normal(v, n);
  }
  void set_normal(OpenMesh::VertexHandle v, const OpenMesh::Vec3d& n) override {
    if (!known(v)) return;
    collect_normal(v, glm::dvec3(n[0], n[1], n[2]));
    ImporterT::set_normal(v, n);
  }

  std::size_t faces_seen = 0;
  std::size_t vertices_added = 0;
  std::size_t non_manifold_faces = 0;
  std::string error;                         // the first malformed face; reported after reading
  std::vector<std::size_t> polygon_start;    // accepted faces, as offsets into polygon_corners
  std::vector<unsigned> polygon_corners;
  std::vector<glm::dvec3> normal_sum;        // per file vertex: sum of the unit normals given to it
  bool non_finite_normal = false;

 private:
  bool known(OpenMesh::VertexHandle v) {
    if (v.is_valid() && static_cast<std::size_t>(v.idx()) < mesh_.n_vertices()) return true;
    if (error.empty())
      error = "a normal is given to vertex " + std::to_string(v.idx()) + " (the reader has " +
              std::to_string(mesh_.n_vertices()) + ")";
    return false;
  }

  void collect_normal(OpenMesh::VertexHandle v, glm::dvec3 n) {
    if (!v.is_valid()) return;
    const auto i = static_cast<std::size_t>(v.idx());
    if (i >= normal_sum.size()) normal_sum.resize(i + 1, glm::dvec3(0.0));
    const double len = glm::length(n);
    if (!std::isfinite(len)) {
      non_finite_normal = true;
    } else if (len > 0.0) {
      normal_sum[i] += n / len;
    }
  }

  bool repeats_previous(const VHandles& corners) const {
    if (!detect_truncation_ || polygon_start.empty()) return false;
    const std::size_t last = polygon_start.back();
    if (polygon_corners.size() - last != corners.size()) return false;
    for (std::size_t k = 0; k < corners.size(); ++k)
      if (polygon_corners[last + k] != static_cast<unsigned>(corners[k].idx())) return false;
    return true;
  }

  PolyMesh& mesh_;
  bool detect_truncation_;
};

// OpenMesh reports to its own streams (omerr, omlog, omout); parashade reports through exceptions and
// stats, so they are muted while a file is read.
class QuietOpenMeshLogs {
 public:
  QuietOpenMeshLogs() : err_(omerr().is_enabled()), log_(omlog().is_enabled()), out_(omout().is_enabled()) {
    omerr().disable();
    omlog().disable();
    omout().disable();
  }
  ~QuietOpenMeshLogs() {
    if (err_) omerr().enable();
    if (log_) omlog().enable();
    if (out_) omout().enable();
  }
  QuietOpenMeshLogs(const QuietOpenMeshLogs&) = delete;
  QuietOpenMeshLogs& operator=(const QuietOpenMeshLogs&) = delete;

 private:
  bool err_, log_, out_;
};

std::string lower_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

void check_readable(const std::filesystem::path& path, const std::string& name) {
  std::error_code ec;
  detail::check_input_file(path, name, detail::kMaxMeshFileBytes, "mesh file");
  const std::string ext = lower_extension(path);
  if (ext != ".obj" && ext != ".off" && ext != ".ply" && ext != ".stl")
    throw InputError(name + ": unknown mesh format '" + ext + "' (expected .obj, .off, .ply or .stl)");
  if (!std::ifstream(path, std::ios::binary)) throw InputError(name + ": cannot open for reading");
  if (std::filesystem::file_size(path, ec) == 0) throw InputError(name + ": empty file");
}

}  // namespace

std::string mesh_load_warning(const std::string& name, const MeshLoadStats& stats) {
  std::string said;
  if (stats.non_manifold_faces > 0)
    said += std::to_string(stats.non_manifold_faces) + " non-manifold face" + (stats.non_manifold_faces == 1 ? "" : "s") + " kept";
  if (stats.faces_dropped > 0)
    said += (said.empty() ? "" : ", ") + std::to_string(stats.faces_dropped) + " face" +
            (stats.faces_dropped == 1 ? "" : "s") + " with a repeated vertex dropped";
  return said.empty() ? said : name + ": " + said;
}

Mesh load_mesh(const std::filesystem::path& path, MeshLoadStats* stats_out) {
  const std::string name = path.string();
  check_readable(path, name);
  const std::string ext = lower_extension(path);

  // Faces as the file has them (OBJ, OFF, STL), for the dropped count; PLY counts as its reader reports.
  std::size_t faces_in_file = 0;
  detail::ObjSummary obj;
  if (ext == ".obj") faces_in_file = (obj = detail::check_obj(path)).faces;
  if (ext == ".ply") detail::check_ply(path);
  if (ext == ".stl") faces_in_file = detail::count_stl_facets(path);
  // The counts against the memory limit before OpenMesh reads (PLY's and OFF's in their scans); an STL
  // facet's corners are shared by about six facets.
  if (ext == ".obj") detail::check_mesh_memory(name, obj.triangles, obj.vertices);
  if (ext == ".stl") detail::check_mesh_memory(name, faces_in_file, faces_in_file / 2);

  PolyMesh poly;
  poly.request_vertex_normals();
  CollectingImporter importer(poly, ext == ".ply");
  OpenMesh::IO::Options options = OpenMesh::IO::Options::VertexNormal;
  bool read_ok = false;
  try {
    if (ext == ".off") {
      faces_in_file = detail::read_off(path, importer);
      read_ok = true;
    } else {
      QuietOpenMeshLogs quiet;
      read_ok = OpenMesh::IO::IOManager().read(name, importer, options);
    }
  } catch (const std::bad_alloc&) {
    // The scans bound every count by the file's size, so this is a file too large for this machine.
    throw InputError(name + ": out of memory reading a file of " + std::to_string(std::filesystem::file_size(path)) +
                     " bytes (" + std::to_string(poly.n_vertices()) + " vertices and " +
                     std::to_string(importer.faces_seen) + " faces read so far)");
  }
  if (!read_ok) throw InputError(name + ": cannot parse as " + ext.substr(1) + " (OpenMesh's reader failed)");
  if (!importer.error.empty()) throw InputError(name + ": " + importer.error);
  if (ext == ".obj" && importer.vertices_added != obj.vertices)
    throw InputError(name + ": OpenMesh's reader found " + std::to_string(importer.vertices_added) +
                     " vertices where the file has " + std::to_string(obj.vertices) + " (a vertex line it cannot read)");
  if (importer.non_finite_normal) throw InputError(name + ": a vertex normal is not finite");

  MeshLoadStats stats;
  stats.faces_read = std::max(faces_in_file, importer.faces_seen);
  const std::size_t polygons = importer.polygon_start.size();
  stats.faces_dropped = stats.faces_read - polygons;
  stats.non_manifold_faces = importer.non_manifold_faces;
  if (polygons == 0) throw InputError(name + ": no faces");

  // Keep only the vertices faces use: the file's unused ones and OpenMesh's non-manifold duplicates go.
  Mesh mesh;
  std::vector<unsigned> remap(poly.n_vertices(), ~0u);
  std::vector<std::size_t> file_vertex;  // output vertex -> file vertex
  for (unsigned& corner : importer.polygon_corners) {
    if (remap[corner] == ~0u) {
      remap[corner] = static_cast<unsigned>(file_vertex.size());
      file_vertex.push_back(corner);
      const OpenMesh::Vec3f p = poly.point(OpenMesh::VertexHandle(static_cast<int>(corner)));
      if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
        throw InputError(name + ": vertex " + std::to_string(corner) + " has a non-finite coordinate");
      mesh.positions.emplace_back(p[0], p[1], p[2]);
    }
    corner = remap[corner];
  }

  // Fan triangulation: exact for the convex polygons mesh files hold in practice.
  for (std::size_t f = 0; f < polygons; ++f) {
    const std::size_t begin = importer.polygon_start[f];
    const std::size_t end = f + 1 < polygons ? importer.polygon_start[f + 1] : importer.polygon_corners.size();
    if (end - begin > 3) ++stats.polygons_triangulated;
    for (std::size_t k = begin + 1; k + 1 < end; ++k) {
      const glm::uvec3 t(importer.polygon_corners[begin], importer.polygon_corners[k], importer.polygon_corners[k + 1]);
      const glm::vec3 n = glm::cross(mesh.positions[t.y] - mesh.positions[t.x], mesh.positions[t.z] - mesh.positions[t.x]);
      if (n == glm::vec3(0.0f)) ++stats.degenerate_faces;
      mesh.triangles.push_back(t);
    }
  }

  // Normals from the file where it gives a usable one (the average when corners disagree); missing
  // or zero ones are recomputed from the faces. STL has only facet normals: OpenMesh gives none per vertex.
  compute_vertex_normals(mesh);
  if (options.check(OpenMesh::IO::Options::VertexNormal) && !importer.normal_sum.empty()) {
    stats.normals_from_file = true;
    for (std::size_t i = 0; i < file_vertex.size(); ++i) {
      const std::size_t v = file_vertex[i];
      const double len = v < importer.normal_sum.size() ? glm::length(importer.normal_sum[v]) : 0.0;
      if (len > 1e-6) {
        mesh.normals[i] = glm::vec3(importer.normal_sum[v] / len);
      } else {
        ++stats.normals_recomputed;
      }
    }
  }
  validate_mesh(mesh, name);
  if (stats_out) *stats_out = stats;
  return mesh;
}

}  // namespace parashade
