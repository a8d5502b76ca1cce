// Procedural sphere, torus, box and cylinder. Rings of vertices are shared around the seam (no texture
// coordinates to split them), so the smooth shapes are closed on shared vertices; flat faces get their
// own vertices so that each carries its face normal.
#include <cmath>
#include <string>

#include "parashade/errors.hpp"
#include "parashade/shapes.hpp"

namespace parashade {

namespace {

constexpr double kPi = 3.14159265358979323846;

class MeshBuilder {
 public:
  unsigned vertex(glm::dvec3 p, glm::dvec3 n) {
    mesh_.positions.emplace_back(p);
    mesh_.normals.emplace_back(glm::normalize(n));
    return static_cast<unsigned>(mesh_.positions.size() - 1);
  }
  void triangle(unsigned a, unsigned b, unsigned c) { mesh_.triangles.emplace_back(a, b, c); }
  Mesh take() { return std::move(mesh_); }

 private:
  Mesh mesh_;
};

void require(bool ok, const char* shape, const std::string& what) {
  if (!ok) throw InputError(std::string(shape) + ": " + what);
}

}  // namespace

Mesh make_sphere(int slices, int stacks) {
  require(slices >= 3, "sphere", "slices must be at least 3");
  require(stacks >= 2, "sphere", "stacks must be at least 2");
  MeshBuilder b;
  // Poles on the y axis; ring j at polar angle pi*j/stacks; slice i at azimuth 2*pi*i/slices from +z
  // toward +x. On the unit sphere the position is its own normal.
  const unsigned north = b.vertex({0, 1, 0}, {0, 1, 0});
  for (int j = 1; j < stacks; ++j) {
    const double theta = kPi * j / stacks;
    for (int i = 0; i < slices; ++i) {
      const double phi = 2.0 * kPi * i / slices;
      const glm::dvec3 p(std::sin(theta) * std::sin(phi), std::cos(theta), std::sin(theta) * std::cos(phi));
      b.vertex(p, p);
    }
  }
  const unsigned south = b.vertex({0, -1, 0}, {0, -1, 0});
  auto ring = [&](int j, int i) { return 1u + unsigned((j - 1) * slices + (i % slices)); };
  for (int i = 0; i < slices; ++i) b.triangle(north, ring(1, i), ring(1, i + 1));
  for (int j = 1; j + 1 < stacks; ++j)
    for (int i = 0; i < slices; ++i) {
      // Seen from outside, i runs right and j runs down: (upper left, lower left, lower right) is CCW.
      b.triangle(ring(j, i), ring(j + 1, i), ring(j + 1, i + 1));
      b.triangle(ring(j, i), ring(j + 1, i + 1), ring(j, i + 1));
    }
  for (int i = 0; i < slices; ++i) b.triangle(ring(stacks - 1, i), south, ring(stacks - 1, i + 1));
  return b.take();
}

Mesh make_torus(float major_radius, float minor_radius, int major_segments, int minor_segments) {
  require(std::isfinite(major_radius) && std::isfinite(minor_radius) && minor_radius > 0.0f &&
              minor_radius < major_radius,
          "torus", "needs 0 < minor_radius < major_radius (else the tube meets itself)");
  require(major_segments >= 3 && minor_segments >= 3, "torus", "segments must be at least 3");
  MeshBuilder b;
  for (int i = 0; i < major_segments; ++i) {
    const double phi = 2.0 * kPi * i / major_segments;
    const glm::dvec3 radial(std::sin(phi), 0.0, std::cos(phi));
    for (int j = 0; j < minor_segments; ++j) {
      const double theta = 2.0 * kPi * j / minor_segments;
      const glm::dvec3 n = std::cos(theta) * radial + glm::dvec3(0.0, std::sin(theta), 0.0);
      b.vertex(double(major_radius) * radial + double(minor_radius) * n, n);
    }
  }
  auto at = [&](int i, int j) { return unsigned((i % major_segments) * minor_segments + (j % minor_segments)); };
  for (int i = 0; i < major_segments; ++i)
    for (int j = 0; j < minor_segments; ++j) {
      // On the outer equator, i runs right and j runs up as seen from outside.
      b.triangle(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      b.triangle(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  return b.take();
}

Mesh make_box(glm::vec3 size) {
  require(std::isfinite(size.x) && std::isfinite(size.y) && std::isfinite(size.z) && size.x > 0.0f &&
              size.y > 0.0f && size.z > 0.0f,
          "box", "every size must be positive");
  const glm::dvec3 half = 0.5 * glm::dvec3(size);
  // Each face: normal n and in-plane axes u, v with u x v = n, so corners in (u, v) order are CCW.
  const glm::dvec3 x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
  const glm::dvec3 faces[6][3] = {{x, y, z}, {-x, z, y}, {y, z, x}, {-y, x, z}, {z, x, y}, {-z, y, x}};
  MeshBuilder b;
  for (const auto& f : faces) {
    const glm::dvec3 n = f[0], u = f[1], v = f[2];
    const unsigned c0 = b.vertex(half * (n - u - v), n);
    const unsigned c1 = b.vertex(half * (n + u - v), n);
    const unsigned c2 = b.vertex(half * (n + u + v), n);
    const unsigned c3 = b.vertex(half * (n - u + v), n);
    b.triangle(c0, c1, c2);
    b.triangle(c0, c2, c3);
  }
  return b.take();
}

Mesh make_cylinder(float radius, float height, int segments, bool caps) {
  require(std::isfinite(radius) && std::isfinite(height) && radius > 0.0f && height > 0.0f, "cylinder",
          "radius and height must be positive");
  require(segments >= 3, "cylinder", "segments must be at least 3");
  MeshBuilder b;
  const double r = radius, top = 0.5 * height, bottom = -0.5 * height;
  auto radial = [&](int i) {
    const double phi = 2.0 * kPi * (i % segments) / segments;
    return glm::dvec3(std::sin(phi), 0.0, std::cos(phi));
  };
  // Side: a top and a bottom ring with radial normals (smooth); caps get their own rings (flat).
  for (int i = 0; i < segments; ++i) b.vertex(r * radial(i) + glm::dvec3(0, top, 0), radial(i));
  for (int i = 0; i < segments; ++i) b.vertex(r * radial(i) + glm::dvec3(0, bottom, 0), radial(i));
  auto upper = [&](int i) { return unsigned(i % segments); };
  auto lower = [&](int i) { return unsigned(segments + i % segments); };
  for (int i = 0; i < segments; ++i) {
    b.triangle(upper(i), lower(i), lower(i + 1));
    b.triangle(upper(i), lower(i + 1), upper(i + 1));
  }
  if (caps) {
    const glm::dvec3 up(0, 1, 0);
    const unsigned top_centre = b.vertex({0, top, 0}, up);
    for (int i = 0; i < segments; ++i) b.vertex(r * radial(i) + glm::dvec3(0, top, 0), up);
    const unsigned bottom_centre = b.vertex({0, bottom, 0}, -up);
    for (int i = 0; i < segments; ++i) b.vertex(r * radial(i) + glm::dvec3(0, bottom, 0), -up);
    for (int i = 0; i < segments; ++i) {
      b.triangle(top_centre, top_centre + 1 + (i % segments), top_centre + 1 + ((i + 1) % segments));
      b.triangle(bottom_centre, bottom_centre + 1 + ((i + 1) % segments), bottom_centre + 1 + (i % segments));
    }
  }
  return b.take();
}

}  // namespace parashade
