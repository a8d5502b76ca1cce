#pragma once
// Hand-built screen geometry for the reference tests: vertices in sub-pixel units, triangles put in
// the E01(V2) > 0 order the coverage rule expects.
#include <cstdint>
#include <glm/glm.hpp>
#include <utility>
#include <vector>

#include "parashade/reference.hpp"
#include "parashade/scene.hpp"
#include "parashade/screen_geometry.hpp"

namespace parashade::test_fixtures {

// Centre of pixel column/row i in sub-pixel units.
constexpr int centre(int i) { return kSubpixel * i + kSubpixel / 2; }

struct Vertex {
  glm::ivec2 xy{0};
  float depth = 0.5f;
  float inv_w = 1.0f;
  glm::vec3 world{0.0f};
  glm::vec3 normal{0.0f, 0.0f, 1.0f};
  glm::vec3 color{0.0f};
};

class GeometryBuilder {
 public:
  GeometryBuilder(int width, int height) {
    g_.width = width;
    g_.height = height;
  }

  std::uint32_t vertex(const Vertex& v) {
    g_.xy.push_back(v.xy);
    g_.depth.push_back(v.depth);
    g_.inv_w.push_back(v.inv_w);
    g_.world.push_back(v.world);
    g_.normal.push_back(v.normal);
    g_.color.push_back(v.color);
    return std::uint32_t(g_.xy.size() - 1);
  }
  std::uint32_t vertex(glm::ivec2 xy, float depth = 0.5f) {
    Vertex v;
    v.xy = xy;
    v.depth = depth;
    return vertex(v);
  }

  // Adds triangle (a, b, c), swapping b and c when needed so that E01(V2) > 0.
  void triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c, glm::vec3 flat_color = glm::vec3(0.0f),
                std::uint32_t material = 0) {
    const glm::ivec2 p0 = g_.xy[a], p1 = g_.xy[b], p2 = g_.xy[c];
    const std::int64_t area2 =
        std::int64_t(p1.x - p0.x) * (p2.y - p0.y) - std::int64_t(p1.y - p0.y) * (p2.x - p0.x);
    if (area2 < 0) std::swap(b, c);
    g_.triangles.emplace_back(a, b, c);
    g_.material.push_back(material);
    g_.flat_color.push_back(flat_color);
  }

  const ScreenGeometry& geometry() const { return g_; }

 private:
  ScreenGeometry g_;
};

// One material, one directional light, infinite viewer on +z.
inline Scene simple_scene() {
  Scene s;
  s.materials.resize(1);
  s.lights.resize(1);
  s.local_viewer = false;
  return s;
}

// How many triangles cover each pixel centre: each triangle rendered alone, coverage summed.
inline std::vector<int> coverage_counts(const Scene& scene, const ScreenGeometry& g) {
  std::vector<int> hits(std::size_t(g.width) * g.height, 0);
  for (std::size_t t = 0; t < g.triangles.size(); ++t) {
    ScreenGeometry one = g;
    one.triangles = {g.triangles[t]};
    one.material = {g.material[t]};
    one.flat_color = {g.flat_color[t]};
    const ReferenceImage r = render_reference(scene, one, Method::flat);
    for (std::size_t p = 0; p < hits.size(); ++p) hits[p] += r.covered[p];
  }
  return hits;
}

}  // namespace parashade::test_fixtures
