// load_mesh on small files written for the test: each format, normals, counts, and malformed input.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <tuple>
#include <vector>

#include "mesh_checks.hpp"
#include "parashade/errors.hpp"
#include "parashade/mesh.hpp"
#include "temp_dir.hpp"

namespace parashade {
namespace {

using namespace testing_support;

// A tetrahedron with outward counter-clockwise faces, in each format.
const char* kTetraObj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
const char* kTetraOff = "OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
const char* kTetraPly =
    "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 4\nproperty list uchar int vertex_indices\nend_header\n"
    "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
const glm::vec3 kTetra[4] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
const int kTetraFaces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};

std::string tetra_stl_text() {
  std::string s = "solid tetra\n";
  for (const auto& f : kTetraFaces) {
    s += "facet normal 0 0 0\nouter loop\n";
    for (int k : f) {
      const glm::vec3 p = kTetra[k];
      s += "vertex " + std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + "\n";
    }
    s += "endloop\nendfacet\n";
  }
  return s + "endsolid tetra\n";
}

std::string tetra_stl_binary() {
  std::string s(80, ' ');
  const std::uint32_t count = 4;
  s.append(reinterpret_cast<const char*>(&count), 4);
  for (const auto& f : kTetraFaces) {
    std::vector<float> v(3, 0.0f);  // facet normal, ignored
    for (int k : f) v.insert(v.end(), {kTetra[k].x, kTetra[k].y, kTetra[k].z});
    s.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(float));
    s.append(2, '\0');  // attribute byte count
  }
  return s;
}

void expect_tetrahedron(const Mesh& m, const MeshLoadStats& stats) {
  EXPECT_EQ(m.triangles.size(), 4u);
  EXPECT_EQ(m.positions.size(), 4u);
  EXPECT_TRUE(closed(edge_report(m)));
  EXPECT_EQ(bad_normals(m), 0u);
  const glm::vec3 c = centroid(m);
  for (std::size_t i = 0; i < m.positions.size(); ++i) EXPECT_GT(glm::dot(m.normals[i], m.positions[i] - c), 0.0f);
  EXPECT_EQ(stats.faces_read, 4u);
  EXPECT_EQ(stats.faces_dropped, 0u);
  EXPECT_EQ(stats.degenerate_faces, 0u);
  EXPECT_FALSE(stats.normals_from_file);
}

struct FormatCase {
  const char* name;
  std::string text;
};

void PrintTo(const FormatCase& c, std::ostream* os) { *os << c.name; }

class EachFormat : public ::testing::TestWithParam<FormatCase> {};

TEST_P(EachFormat, LoadsATetrahedron) {
  TempDir dir;
  MeshLoadStats stats;
  const Mesh m = load_mesh(dir.write(GetParam().name, GetParam().text), &stats);
  expect_tetrahedron(m, stats);
}

INSTANTIATE_TEST_SUITE_P(Formats, EachFormat,
                         ::testing::Values(FormatCase{"tetra.obj", kTetraObj}, FormatCase{"tetra.off", kTetraOff},
                                           FormatCase{"tetra.ply", kTetraPly},
                                           FormatCase{"tetra.stl", tetra_stl_text()},
                                           FormatCase{"binary.stl", tetra_stl_binary()},
                                           FormatCase{"UPPER.OBJ", kTetraObj}),
                         [](const auto& info) {
                           std::string n = info.param.name;
                           for (char& c : n)
                             if (c == '.') c = '_';
                           return n;
                         });

TEST(LoadMesh, QuadsAreFanned) {
  TempDir dir;
  const std::string cube =
      "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
      "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 3 4 8 7\nf 2 3 7 6\nf 1 5 8 4\n";
  MeshLoadStats stats;
  const Mesh m = load_mesh(dir.write("cube.obj", cube), &stats);
  EXPECT_EQ(m.triangles.size(), 12u);
  EXPECT_EQ(stats.faces_read, 6u);
  EXPECT_EQ(stats.polygons_triangulated, 6u);
  EXPECT_TRUE(closed(edge_report(m)));
  for (std::size_t i = 0; i < m.positions.size(); ++i) EXPECT_GT(glm::dot(m.normals[i], m.positions[i]), 0.0f);
}

TEST(LoadMesh, NormalsFromTheFileAreNormalized) {
  TempDir dir;
  const std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 2\nvn 0.6 0 0.8\nf 1//1 2//2 3//1\n";
  MeshLoadStats stats;
  const Mesh m = load_mesh(dir.write("n.obj", obj), &stats);
  EXPECT_TRUE(stats.normals_from_file);
  EXPECT_EQ(stats.normals_recomputed, 0u);
  EXPECT_EQ(m.normals[0], glm::vec3(0, 0, 1));
  EXPECT_NEAR(glm::distance(m.normals[1], glm::vec3(0.6f, 0.0f, 0.8f)), 0.0f, 1e-6f);
}

TEST(LoadMesh, ZeroAndMissingFileNormalsAreRecomputedAndCounted) {
  TempDir dir;
  // Vertex 1 gets a zero normal, vertex 4 none at all; the faces face +z.
  const std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvn 0 0 1\nvn 0 0 0\n"
                          "f 1//1 2//2 3//1\nf 2//1 4 3//1\n";
  MeshLoadStats stats;
  const Mesh m = load_mesh(dir.write("zero.obj", obj), &stats);
  EXPECT_TRUE(stats.normals_from_file);
  EXPECT_EQ(stats.normals_recomputed, 1u);  // vertex 4; vertex 2 also got (0,0,1) from the second face
  EXPECT_EQ(bad_normals(m), 0u);
  for (const glm::vec3& n : m.normals) EXPECT_EQ(n, glm::vec3(0, 0, 1));
}

TEST(LoadMesh, OnlyAZeroFileNormalIsRecomputed) {
  TempDir dir;
  const std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nvn 0 0 0\nf 1//1 2//2 3//1\n";
  MeshLoadStats stats;
  const Mesh m = load_mesh(dir.write("zero.obj", obj), &stats);
  EXPECT_EQ(stats.normals_recomputed, 1u);
  EXPECT_EQ(m.normals[1], glm::vec3(0, 0, 1));
}

TEST(LoadMesh, DisagreeingFileNormalsAreAveraged) {
  TempDir dir;
  // Flat-shaded export: vertex 1 is given -z by one face and -y by the other.
  const std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvn 0 0 -1\nvn 0 -1 0\n"
                          "f 1//1 3//1 2//1\nf 1//2 2//2 4//2\n";
  const Mesh m = load_mesh(dir.write("flat.obj", obj));
  EXPECT_NEAR(glm::distance(m.normals[0], glm::normalize(glm::vec3(0, -1, -1))), 0.0f, 1e-6f);
}

TEST(LoadMesh, UnusedVerticesAreLeftOut) {
  TempDir dir;
  const Mesh m = load_mesh(dir.write("extra.obj", "v 9 9 9\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 2 3 4\n"));
  ASSERT_EQ(m.positions.size(), 3u);
  EXPECT_EQ(m.positions[0], glm::vec3(0, 0, 0));
}

TEST(LoadMesh, NonManifoldFacesKeepTheirVertices) {
  TempDir dir;
  // Three triangles on the edge 1-2: OpenMesh re-adds the third on copies of its vertices.
  const std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 0 -1 0\nf 1 2 3\nf 2 1 4\nf 1 2 5\n";
  MeshLoadStats stats;
  const Mesh m = load_mesh(dir.write("fin.obj", obj), &stats);
  EXPECT_EQ(m.triangles.size(), 3u);
  EXPECT_EQ(m.positions.size(), 5u);
  EXPECT_EQ(stats.non_manifold_faces, 1u);
  EXPECT_EQ(stats.faces_dropped, 0u);
}

TEST(LoadMesh, FacesWithARepeatedVertexAreDroppedAndCounted) {
  TempDir dir;
  MeshLoadStats stats;
  load_mesh(dir.write("rep.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 1\n"), &stats);
  EXPECT_EQ(stats.faces_read, 2u);
  EXPECT_EQ(stats.faces_dropped, 1u);

  // In STL coincident corners merge, so a needle facet has a repeated vertex.
  std::string stl = tetra_stl_text();
  stl.insert(stl.rfind("endsolid"), "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                                    "vertex 1 0 0\nendloop\nendfacet\n");
  const Mesh m = load_mesh(dir.write("needle.stl", stl), &stats);
  EXPECT_EQ(m.triangles.size(), 4u);
  EXPECT_EQ(stats.faces_read, 5u);
  EXPECT_EQ(stats.faces_dropped, 1u);
}

TEST(LoadMesh, ZeroAreaFacesAreKeptCountedAndHaveFiniteNormals) {
  TempDir dir;
  MeshLoadStats stats;
  const Mesh m = load_mesh(dir.write("line.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n"), &stats);
  EXPECT_EQ(m.triangles.size(), 1u);
  EXPECT_EQ(stats.degenerate_faces, 1u);
  EXPECT_EQ(bad_normals(m), 0u);
}

// Every refusal names the file (and, for text formats, the line) and says what is wrong.
struct BadFile {
  const char* name;
  const char* text;
  const char* says;
};

void PrintTo(const BadFile& c, std::ostream* os) { *os << c.name; }

class MalformedFile : public ::testing::TestWithParam<BadFile> {};

TEST_P(MalformedFile, ThrowsInputErrorNamingTheFile) {
  TempDir dir;
  const std::filesystem::path p = dir.write(GetParam().name, GetParam().text);
  try {
    load_mesh(p);
    ADD_FAILURE() << "loaded";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(p.string()), std::string::npos) << message;
    EXPECT_NE(message.find(GetParam().says), std::string::npos) << message;
  }
}

const char* kPlyHeader =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 2\nproperty list uchar int vertex_indices\nend_header\n";

INSTANTIATE_TEST_SUITE_P(
    Files, MalformedFile,
    ::testing::Values(BadFile{"bad_index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n", ":4: vertex index 9 out of range"},
                      BadFile{"negative_index.obj", "v 0 0 0\nv 1 0 0\nf 1 2 -3\n", ":3: vertex index -3"},
                      // Fuzzing finding F7: negating the most negative index was undefined behaviour.
                      BadFile{"min_index.obj", "v 0 0 0\nv 1 0 0\nf 1 2 -9223372036854775808\n",
                              ":3: vertex index -9223372036854775808 reaches before"},
                      BadFile{"zero_index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", ":4: vertex index 0"},
                      BadFile{"bad_normal_index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//2\n",
                              ":5: normal index 2 out of range"},
                      BadFile{"truncated.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nv 0.5 0.", ":5: vertex needs 3"},
                      BadFile{"two_vertices.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n", ":4: face has 2 vertices"},
                      BadFile{"nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n", ":2: vertex has a non-finite"},
                      BadFile{"inf_normal.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn inf 0 0\nf 1//1 2//1 3//1\n",
                              ":4: normal has a non-finite"},
                      BadFile{"word.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 two 3\n", "cannot read 'two'"},
                      BadFile{"no_faces.obj", "v 0 0 0\nv 1 0 0\n", "no faces"},
                      BadFile{"text.obj", "this is not a mesh\n", "no faces"},
                      BadFile{"empty.obj", "", "empty file"},
                      BadFile{"bad_index.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n", ":6: vertex index 7"},
                      BadFile{"truncated.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "ends after 1 of 2 faces"},
                      BadFile{"nan.off", "OFF\n3 1 0\n0 nan 0\n1 0 0\n0 1 0\n3 0 1 2\n", ":3: vertex has a non-finite"},
                      BadFile{"two_vertices.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n", "face has 2 vertices"},
                      BadFile{"not.off", "hello\n", "no OFF header"},
                      BadFile{"not.ply", "hello\n", ":1: no 'ply' magic line"},
                      BadFile{"text.stl", "hello\n", "no faces"},
                      BadFile{"mesh.xyz", "v 0 0 0\n", "unknown mesh format '.xyz'"}),
    [](const auto& info) {
      std::string n = info.param.name;
      for (char& c : n)
        if (c == '.') c = '_';
      return n;
    });

TEST(LoadMeshPly, MalformedFacesAreRefused) {
  TempDir dir;
  for (const auto& [name, faces, says] :
       {std::make_tuple("bad_index.ply", "3 0 1 2\n3 0 1 9\n", "refers to vertex 9"),
        std::make_tuple("truncated.ply", "3 0 1 2\n", "face record 1: the file ends early"),
        std::make_tuple("two_vertices.ply", "3 0 1 2\n2 0 1\n", "a face has 2 vertices")}) {
    const std::filesystem::path p = dir.write(name, std::string(kPlyHeader) + "0 0 0\n1 0 0\n0 1 0\n" + faces);
    try {
      load_mesh(p);
      ADD_FAILURE() << name << " loaded";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(p.string()), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
    }
  }
}

TEST(LoadMesh, MissingFileAndDirectoryAreRefused) {
  TempDir dir;
  const std::filesystem::path missing = dir.path() / "missing.obj";
  try {
    load_mesh(missing);
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(missing.string() + ": no such file"), std::string::npos) << e.what();
  }
  std::filesystem::create_directories(dir.path() / "folder.obj");
  EXPECT_THROW(load_mesh(dir.path() / "folder.obj"), InputError);
}

}  // namespace
}  // namespace parashade
