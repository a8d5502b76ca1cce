// compute_vertex_normals and validate_mesh.
#include <gtest/gtest.h>

#include <cmath>

#include "mesh_checks.hpp"
#include "parashade/errors.hpp"
#include "parashade/mesh.hpp"

namespace parashade {
namespace {

using namespace testing_support;

TEST(VertexNormals, AreaWeighted) {
  // Vertex 0 is shared by a triangle of area 2 facing +z and one of area 0.5 facing +x.
  Mesh m;
  m.positions = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0, 1, 0}, {0, 0, -1}};
  m.triangles = {{0, 1, 2}, {0, 4, 3}};
  compute_vertex_normals(m);
  const glm::vec3 expected = glm::normalize(glm::vec3(0.5f, 0.0f, 2.0f));
  EXPECT_NEAR(glm::distance(m.normals[0], expected), 0.0f, 1e-6f);
  EXPECT_EQ(m.normals[1], glm::vec3(0, 0, 1));
  EXPECT_EQ(m.normals[4], glm::vec3(1, 0, 0));
}

TEST(VertexNormals, DegenerateFacesGiveNoNaN) {
  Mesh m;
  // A collinear triangle (0,1,2), a triangle with a repeated vertex (3,3,4), and a good one (0,5,6).
  m.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {5, 5, 5}, {6, 5, 5}, {0, 1, 0}, {0, 0, 1}};
  m.triangles = {{0, 1, 2}, {3, 3, 4}, {0, 5, 6}};
  compute_vertex_normals(m);
  EXPECT_EQ(bad_normals(m), 0u);
  EXPECT_EQ(m.normals[1], glm::vec3(0, 0, 1));  // only zero-area faces around it
  EXPECT_EQ(m.normals[3], glm::vec3(0, 0, 1));
  EXPECT_EQ(m.normals[0], glm::vec3(1, 0, 0));  // the zero-area face contributes nothing
}

TEST(VertexNormals, UnusedVertexAndOpposingFacesGiveTheDefault) {
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {9, 9, 9}};
  m.triangles = {{0, 1, 2}, {0, 2, 1}};  // the same triangle both ways: normals cancel
  compute_vertex_normals(m);
  EXPECT_EQ(bad_normals(m), 0u);
  for (const glm::vec3& n : m.normals) EXPECT_EQ(n, glm::vec3(0, 0, 1));
}

TEST(VertexNormals, NonFinitePositionsDoNotPoisonNeighbours) {
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {NAN, 0, 0}};
  m.triangles = {{0, 1, 2}, {0, 3, 1}};
  compute_vertex_normals(m);
  EXPECT_EQ(m.normals[0], glm::vec3(0, 0, 1));
  EXPECT_EQ(m.normals[3], glm::vec3(0, 0, 1));
}

Mesh one_triangle() {
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  m.triangles = {{0, 1, 2}};
  return m;
}

void expect_invalid(const Mesh& m, const std::string& fragment) {
  try {
    validate_mesh(m, "thing.obj");
    ADD_FAILURE() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("thing.obj"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(ValidateMesh, AcceptsAGoodMesh) { EXPECT_NO_THROW(validate_mesh(one_triangle(), "thing.obj")); }

TEST(ValidateMesh, RejectsWhatTheRendererCannotUse) {
  Mesh m = one_triangle();
  m.triangles[0].z = 3;
  expect_invalid(m, "refers to vertex 3");
  m = one_triangle();
  m.positions[1].y = INFINITY;
  expect_invalid(m, "vertex 1 has a non-finite coordinate");
  m = one_triangle();
  m.normals[2].x = NAN;
  expect_invalid(m, "vertex 2 has a non-finite normal");
  m = one_triangle();
  m.normals.pop_back();
  expect_invalid(m, "normals");
}

}  // namespace
}  // namespace parashade
