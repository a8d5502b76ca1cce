// The exact reference (reference.hpp): its own rasterizer, written from the coverage rule of
// screen_geometry.hpp, and its own interpolation, in double precision. It shares only edge_bias and
// the Blinn–Phong formula (lighting.hpp) with the rest of the project, on purpose: a
// reference that reused the renderer's code would agree with the renderer's mistakes.
//
// Two passes. Visibility: the screen is cut into bands of rows; each band, owned by one thread,
// visits its triangles in primitive order and keeps per pixel the nearest depth (nearer by more than the rounding of coplanar depths, so the
// earlier triangle wins ties). Shading: each pixel shades only its visible triangle. Every pixel is
// computed by exactly one thread in a fixed order, so the result does not depend on the thread count.
#include "parashade/reference.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <string>

#include "parashade/lighting.hpp"
#include "parashade/parallel.hpp"

namespace parashade {
namespace {

using i64 = std::int64_t;

constexpr int kBandRows = 8;  // rows per unit of parallel work in the visibility pass

// Centre of pixel column/row i in sub-pixel units.
i64 centre(int i) { return i64(kSubpixel) * i + kSubpixel / 2; }

i64 floor_div(i64 a, i64 b) { return a / b - ((a % b != 0) && ((a < 0) != (b < 0))); }

// Smallest i with centre(i) >= lo, largest i with centre(i) <= hi.
i64 first_centre_at_or_after(i64 lo) { return -floor_div(-(lo - kSubpixel / 2), kSubpixel); }
i64 last_centre_at_or_before(i64 hi) { return floor_div(hi - kSubpixel / 2, kSubpixel); }

// E_ij(P) = (Xj - Xi) * (Py - Yi) - (Yj - Yi) * (Px - Xi), exactly as screen_geometry.hpp states it.
i64 edge_function(glm::ivec2 vi, glm::ivec2 vj, i64 px, i64 py) {
  return i64(vj.x - vi.x) * (py - vi.y) - i64(vj.y - vi.y) * (px - vi.x);
}

// One screen triangle ready to rasterize. Edge k is the edge opposite vertex k, so that its edge
// function, divided by area2, is the barycentric weight of vertex k.
struct Triangle {
  glm::ivec2 v[3];
  int bias[3];
  i64 area2 = 0;        // E01(V2) > 0; 0 marks a triangle to skip
  int x0 = 0, x1 = -1;  // pixel bounding box, clamped to the screen (empty when x0 > x1)
  int y0 = 0, y1 = -1;
  double depth_slack = 0.0;  // how far a float depth plane of it may be off at a covered pixel (depth_slack())
};

constexpr int kEdgeFrom[3] = {1, 2, 0};
constexpr int kEdgeTo[3] = {2, 0, 1};

// How far the kernels' depth at a pixel of the triangle may be from the exact plane's: their plane is stored
// in float (value at the box corner, two increments) and evaluated in float, within
// 8u (max|z_v| + |dz/dx| w + |dz/dy| h) of the plane (docs/error-bounds.md, the Gouraud bound applied to depth;
// w, h the box in pixels). Twice that, for the record's move to a tile or band corner and as a margin.
double depth_slack(const Triangle& tri, const ScreenGeometry& g, const glm::uvec3& idx) {
  const double z[3] = {double(g.depth[idx.x]), double(g.depth[idx.y]), double(g.depth[idx.z])};
  double dzdx = 0.0, dzdy = 0.0, largest = 0.0;
  for (int k = 0; k < 3; ++k) {  // z = sum_k z_k E_k / area2, E_k the edge function opposite vertex k
    const glm::ivec2 a = tri.v[kEdgeFrom[k]], b = tri.v[kEdgeTo[k]];
    dzdx -= z[k] * double(b.y - a.y);
    dzdy += z[k] * double(b.x - a.x);
    largest = std::max(largest, std::abs(z[k]));
  }
  const double per_pixel = double(kSubpixel) / double(tri.area2);
  const double w = double(std::max({tri.v[0].x, tri.v[1].x, tri.v[2].x}) - std::min({tri.v[0].x, tri.v[1].x, tri.v[2].x}));
  const double h = double(std::max({tri.v[0].y, tri.v[1].y, tri.v[2].y}) - std::min({tri.v[0].y, tri.v[1].y, tri.v[2].y}));
  const double span = std::abs(dzdx * per_pixel) * (w / kSubpixel + 1.0) + std::abs(dzdy * per_pixel) * (h / kSubpixel + 1.0);
  return 16.0 * 0x1p-24 * (largest + span);
}

Triangle setup_triangle(const ScreenGeometry& g, std::size_t t) {
  Triangle tri;
  const glm::uvec3 idx = g.triangles[t];
  for (int k = 0; k < 3; ++k) tri.v[k] = g.xy[idx[k]];
  for (int k = 0; k < 3; ++k) tri.bias[k] = edge_bias(tri.v[kEdgeFrom[k]], tri.v[kEdgeTo[k]]);
  tri.area2 = edge_function(tri.v[0], tri.v[1], tri.v[2].x, tri.v[2].y);
  if (tri.area2 < 0) {
    throw std::invalid_argument("render_reference: screen triangle " + std::to_string(t) +
                                " is not ordered so that E01(V2) > 0");
  }
  if (tri.area2 == 0) return tri;  // zero-area: covers nothing (the geometry stage should drop it)
  const i64 min_x = std::min({tri.v[0].x, tri.v[1].x, tri.v[2].x});
  const i64 max_x = std::max({tri.v[0].x, tri.v[1].x, tri.v[2].x});
  const i64 min_y = std::min({tri.v[0].y, tri.v[1].y, tri.v[2].y});
  const i64 max_y = std::max({tri.v[0].y, tri.v[1].y, tri.v[2].y});
  tri.x0 = int(std::max<i64>(0, first_centre_at_or_after(min_x)));
  tri.x1 = int(std::min<i64>(g.width - 1, last_centre_at_or_before(max_x)));
  tri.y0 = int(std::max<i64>(0, first_centre_at_or_after(min_y)));
  tri.y1 = int(std::min<i64>(g.height - 1, last_centre_at_or_before(max_y)));
  tri.depth_slack = depth_slack(tri, g, idx);
  return tri;
}

// Edge values at the centre of pixel (x, y); true when the centre is covered (E_k >= bias_k).
bool edges_at(const Triangle& tri, int x, int y, i64 e[3]) {
  const i64 px = centre(x), py = centre(y);
  bool inside = true;
  for (int k = 0; k < 3; ++k) {
    e[k] = edge_function(tri.v[kEdgeFrom[k]], tri.v[kEdgeTo[k]], px, py);
    inside = inside && e[k] >= tri.bias[k];
  }
  return inside;
}

void check_geometry(const Scene& scene, const ScreenGeometry& g, Method method) {
  auto fail = [](const std::string& what) { throw std::invalid_argument("render_reference: " + what); };
  if (g.width < 1 || g.height < 1) fail("empty screen");
  const std::size_t nv = g.xy.size();
  // The guard band keeps the vertices of screen triangles within 14 integer bits + sign; 2^24 leaves
  // the int64 edge functions far from overflow. (Scene vertices that clipping cut away may lie
  // anywhere; no triangle uses them.)
  constexpr int kCoordLimit = 1 << 24;
  if (g.depth.size() != nv || g.inv_w.size() != nv) fail("per-vertex depth or 1/w missing");
  if (g.world.size() != nv || g.normal.size() != nv) fail("exact shading needs world positions and normals");
  if (method == Method::gouraud && g.color.size() != nv) fail("gouraud needs a colour per vertex");
  const std::size_t nt = g.triangles.size();
  if (g.material.size() != nt) fail("a material per triangle is needed");
  if (method == Method::flat && g.flat_color.size() != nt) fail("flat needs a colour per triangle");
  for (std::size_t t = 0; t < nt; ++t) {
    const glm::uvec3 idx = g.triangles[t];
    if (idx.x >= nv || idx.y >= nv || idx.z >= nv)
      fail("triangle " + std::to_string(t) + " indexes no vertex");
    for (int k = 0; k < 3; ++k)
      if (std::abs(i64(g.xy[idx[k]].x)) > kCoordLimit || std::abs(i64(g.xy[idx[k]].y)) > kCoordLimit)
        fail("triangle " + std::to_string(t) + " has a vertex far outside the guard band");
    if (g.material[t] >= scene.materials.size()) fail("triangle " + std::to_string(t) + " has no material");
  }
}

glm::dvec3 clamp_levels(glm::dvec3 c) { return glm::clamp(c, glm::dvec3(0.0), glm::dvec3(255.0)); }

// Unit normal for shading. An interpolated normal can vanish (opposite vertex normals); then the
// world-space face normal, turned toward the viewer (the pixel is visible, so its surface faces the
// viewer), stands in for it; the view vector if the face itself is degenerate. Never NaN.
glm::dvec3 shading_normal(const Scene& scene, glm::dvec3 n, glm::dvec3 p, const glm::dvec3 w[3]) {
  const double len = glm::length(n);
  if (len > 1e-12) return n / len;
  const glm::dvec3 v = view_vector(scene, p);
  glm::dvec3 face = glm::cross(w[1] - w[0], w[2] - w[0]);
  const double face_len = glm::length(face);
  if (!(face_len > 0.0)) return v;
  face /= face_len;
  return glm::dot(face, v) < 0.0 ? -face : face;
}

template <class T>
T weighted(const double b[3], const T& a0, const T& a1, const T& a2) {
  return b[0] * a0 + b[1] * a1 + b[2] * a2;
}

// Triangle t's depth at pixel (x, y), which it covers with the edge values e: window depth, linear in screen
// space, interpolated with screen-space barycentrics. Vertex depths are floats (~6e-8 apart at 1); rounding
// of the double sum is ~1e-16.
double depth_at(const ScreenGeometry& g, const Triangle& tri, std::size_t t, const i64 e[3]) {
  const glm::uvec3 idx = g.triangles[t];
  const double area2 = double(tri.area2);
  const double b[3] = {double(e[0]) / area2, double(e[1]) / area2, double(e[2]) / area2};
  return weighted(b, double(g.depth[idx.x]), double(g.depth[idx.y]), double(g.depth[idx.z]));
}

// The screen cut into bands of kBandRows rows, each with the triangles whose boxes touch it, in primitive
// order; every band is one unit of parallel work, so each pixel is written by one thread in a fixed order.
struct Bands {
  Bands(const std::vector<Triangle>& tris, int height) : rows(height), triangles((height + kBandRows - 1) / kBandRows) {
    for (std::size_t t = 0; t < tris.size(); ++t) {
      const Triangle& tri = tris[t];
      if (tri.area2 == 0 || tri.x0 > tri.x1 || tri.y0 > tri.y1) continue;
      for (int b = tri.y0 / kBandRows; b <= tri.y1 / kBandRows; ++b) triangles[std::size_t(b)].push_back(std::uint32_t(t));
    }
  }
  // f(t, x, y, e) for every pixel (x, y) each triangle t covers, band by band in parallel.
  template <typename F>
  void each_covered(const std::vector<Triangle>& tris, const F& f) const {
    parallel_for(triangles.size(), [&](std::size_t band) {
      const int band_y0 = int(band) * kBandRows, band_y1 = std::min(rows - 1, band_y0 + kBandRows - 1);
      for (const std::uint32_t t : triangles[band]) {
        const Triangle& tri = tris[t];
        for (int y = std::max(tri.y0, band_y0); y <= std::min(tri.y1, band_y1); ++y)
          for (int x = tri.x0; x <= tri.x1; ++x) {
            i64 e[3];
            if (edges_at(tri, x, y, e)) f(t, x, y, e, band);
          }
      }
    });
  }
  int rows;
  std::vector<std::vector<std::uint32_t>> triangles;
};

// Triangle t's two values at pixel (x, y), which it covers: the method's ideal and exact Phong (clamped).
struct PixelValues {
  glm::dvec3 ideal, exact;
};
PixelValues shade_at(const Scene& scene, const ScreenGeometry& g, Method method, const Triangle& tri, std::size_t t,
                     int x, int y) {
  const glm::uvec3 idx = g.triangles[t];
  const Material& material = scene.materials[g.material[t]];
  i64 e[3];
  edges_at(tri, x, y, e);
  const double area2 = double(tri.area2);
  const double b[3] = {double(e[0]) / area2, double(e[1]) / area2, double(e[2]) / area2};
  const glm::dvec3 w[3] = {glm::dvec3(g.world[idx.x]), glm::dvec3(g.world[idx.y]), glm::dvec3(g.world[idx.z])};
  const glm::dvec3 n[3] = {glm::dvec3(g.normal[idx.x]), glm::dvec3(g.normal[idx.y]), glm::dvec3(g.normal[idx.z])};
  glm::dvec3 ideal;
  switch (method) {
    case Method::flat:
      ideal = glm::dvec3(g.flat_color[t]);
      break;
    case Method::gouraud:
      ideal = weighted(b, glm::dvec3(g.color[idx.x]), glm::dvec3(g.color[idx.y]), glm::dvec3(g.color[idx.z]));
      break;
    case Method::phong:
    case Method::combined: {  // its ideal is Phong: the error shown is the method's own
      const glm::dvec3 pos = weighted(b, w[0], w[1], w[2]);
      ideal = blinn_phong(scene, material, pos, shading_normal(scene, weighted(b, n[0], n[1], n[2]), pos, w));
      break;
    }
  }
  // Exact: perspective-correct weights b_k / w_k, normalized (screen-space ones if 1/w is unusable).
  double pc[3] = {b[0] * g.inv_w[idx.x], b[1] * g.inv_w[idx.y], b[2] * g.inv_w[idx.z]};
  const double sum = pc[0] + pc[1] + pc[2];
  if (sum > 0.0 && std::isfinite(sum)) {
    for (double& c : pc) c /= sum;
  } else {
    std::copy(b, b + 3, pc);
  }
  const glm::dvec3 pos = weighted(pc, w[0], w[1], w[2]);
  const glm::dvec3 exact = blinn_phong(scene, material, pos, shading_normal(scene, weighted(pc, n[0], n[1], n[2]), pos, w));
  return {clamp_levels(ideal), clamp_levels(exact)};
}

// The other triangles at pixels where float depth cannot tell them from the visible one: covering the pixel
// within the two triangles' depth slack of the visible depth (a tie the reference broke by less than the
// kernels' rounding). Sorted by pixel, then triangle.
std::vector<ReferenceImage::DepthTie> depth_ties(const ScreenGeometry& g, const std::vector<Triangle>& tris,
                                                 const Bands& bands, const std::vector<double>& depth,
                                                 const std::vector<std::int32_t>& visible) {
  std::vector<std::vector<ReferenceImage::DepthTie>> per_band(bands.triangles.size());
  const std::size_t width = std::size_t(g.width);
  bands.each_covered(tris, [&](std::uint32_t t, int x, int y, const i64 e[3], std::size_t band) {
    const std::size_t p = std::size_t(y) * width + std::size_t(x);
    const std::int32_t front = visible[p];
    if (front == std::int32_t(t)) return;
    const double slack = tris[t].depth_slack + tris[std::size_t(front)].depth_slack;
    if (std::abs(depth_at(g, tris[t], t, e) - depth[p]) <= slack) per_band[band].push_back({p, std::int32_t(t), {}, {}});
  });
  std::vector<ReferenceImage::DepthTie> ties;
  for (const auto& b : per_band) ties.insert(ties.end(), b.begin(), b.end());
  std::sort(ties.begin(), ties.end(), [](const auto& a, const auto& b) {
    return a.pixel != b.pixel ? a.pixel < b.pixel : a.triangle < b.triangle;
  });
  return ties;
}

}  // namespace

ReferenceImage render_reference(const Scene& scene, const ScreenGeometry& g, Method method) {
  check_geometry(scene, g, method);
  const int width = g.width, height = g.height;
  const std::size_t pixels = std::size_t(width) * std::size_t(height);
  std::vector<Triangle> tris(g.triangles.size());
  for (std::size_t t = 0; t < tris.size(); ++t) tris[t] = setup_triangle(g, t);  // serial: may throw
  const Bands bands(tris, height);

  ReferenceImage out;
  out.width = width;
  out.height = height;
  out.covered.assign(pixels, 0);
  out.triangle.assign(pixels, -1);
  const glm::dvec3 background = 255.0 * glm::dvec3(scene.background);
  out.ideal.assign(pixels, background);
  out.exact.assign(pixels, background);

  // Visibility. Exactly coplanar triangles give the same depth up to the rounding of the barycentric sum: a
  // later triangle must be nearer by more than that to win (ties: the earlier triangle).
  constexpr double kDepthTie = 1e-12;
  std::vector<double> depth(pixels, std::numeric_limits<double>::infinity());
  bands.each_covered(tris, [&](std::uint32_t t, int x, int y, const i64 e[3], std::size_t) {
    const std::size_t p = std::size_t(y) * std::size_t(width) + std::size_t(x);
    const double z = depth_at(g, tris[t], t, e);
    if (z < depth[p] - kDepthTie) {
      depth[p] = z;
      out.triangle[p] = std::int32_t(t);
    }
  });
  out.depth_ties = depth_ties(g, tris, bands, depth, out.triangle);

  // Shading: the visible triangle of each pixel, and the tied ones where float depth may have kept them.
  parallel_for(std::size_t(height), [&](std::size_t row) {
    for (int x = 0; x < width; ++x) {
      const std::size_t p = row * std::size_t(width) + std::size_t(x);
      const std::int32_t t = out.triangle[p];
      if (t < 0) continue;
      const PixelValues v = shade_at(scene, g, method, tris[std::size_t(t)], std::size_t(t), x, int(row));
      out.covered[p] = 1;
      out.ideal[p] = v.ideal;
      out.exact[p] = v.exact;
    }
  });
  parallel_for_ranges(out.depth_ties.size(), 256, [&](std::size_t first, std::size_t last) {
    for (std::size_t i = first; i < last; ++i) {
      ReferenceImage::DepthTie& tie = out.depth_ties[i];
      const int x = int(tie.pixel % std::size_t(width)), y = int(tie.pixel / std::size_t(width));
      const PixelValues v = shade_at(scene, g, method, tris[std::size_t(tie.triangle)], std::size_t(tie.triangle), x, y);
      tie.ideal = v.ideal;
      tie.exact = v.exact;
    }
  });
  return out;
}

}  // namespace parashade
