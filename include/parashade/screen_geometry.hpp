#pragma once
// The frame's geometry after the vertex stage, clipping, culling and snapping: what both the OpenCL
// path (through setup) and the exact reference rasterize.
//
// Screen coordinates (the sub-pixel format): signed 32-bit integers in 1/256 pixel (8 fraction bits),
// x to the right, y down. Pixel (i, j) has its centre at (256*i + 128, 256*j + 128). Pixel addresses
// are 12 bits (resolution <= 4096); vertex coordinates may lie in a guard band around the screen
// (|x_ndc|, |y_ndc| <= kGuardBand), i.e. within [-W, 2W] x [-H, 2H] pixels: 14 integer bits + sign.
// Triangles reaching beyond the guard band, or crossing the near or far plane, are clipped in clip
// space; new vertices interpolate every attribute linearly in clip space (perspective-correct).
//
// Coverage rule (pixel-centre sampling, top-left rule). Triangle vertices are ordered so that
// E01(V2) > 0, where the edge function of the edge Vi -> Vj is
//     E_ij(P) = (Xj - Xi) * (Py - Yi) - (Yj - Yi) * (Px - Xi)      (exact in 64-bit integers).
// A pixel centre P is covered when E_ij(P) >= bias_ij for the three edges, with bias 0 for a top edge
// (Yj == Yi and Xj > Xi) or a left edge (Yj < Yi), bias 1 otherwise. Shared edges are then covered
// exactly once. Zero-area triangles are dropped.
#include <algorithm>
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "parashade/kernels/constants.h"

namespace parashade {

constexpr int kSubpixelBits = SUBPIXEL_BITS;
constexpr int kSubpixel = 1 << kSubpixelBits;
constexpr float kGuardBand = 3.0f;

struct GeometryStats {
  std::uint64_t triangles_in = 0;        // scene triangles
  std::uint64_t culled_backface = 0;
  std::uint64_t zero_area = 0;           // after snapping
  std::uint64_t outside = 0;             // entirely outside the view volume
  std::uint64_t non_finite = 0;          // a vertex with NaN or Inf clip coordinates: dropped
  std::uint64_t clipped = 0;             // input triangles that needed clipping
  std::uint64_t triangles_out = 0;       // screen triangles (after clipping, culling)
};

// The vertex stage's working memory (geometry_stage.cpp), kept with the geometry so that a frame
// allocates nothing once the buffers have grown. A copy of the geometry starts without it.
struct GeometryScratch;
class GeometryScratchHolder {
 public:
  GeometryScratchHolder() = default;
  GeometryScratchHolder(const GeometryScratchHolder&) {}
  GeometryScratchHolder(GeometryScratchHolder&&) = default;
  GeometryScratchHolder& operator=(const GeometryScratchHolder&) { return *this; }
  GeometryScratchHolder& operator=(GeometryScratchHolder&&) = default;
  std::shared_ptr<GeometryScratch> ptr;
};

struct ScreenGeometry {
  int width = 0;
  int height = 0;
  // Per vertex: the scene's vertices (objects concatenated), then the vertices clipping made.
  std::vector<std::uint8_t> outcode;// clip planes the scene vertex is outside of (scene vertices only:
                                    // its size is their number)
  std::vector<glm::ivec2> xy;       // sub-pixel screen position (see above)
  std::vector<float> depth;         // window depth in [0, 1]; linear in screen space
  std::vector<float> inv_w;         // 1 / w_clip, for perspective-correct interpolation
  std::vector<glm::vec3> world;     // world-space position (flat, phong and the reference; else empty)
  std::vector<glm::vec3> normal;    // world-space normal: unit at scene vertices; at clip-made vertices the
                                    // (unnormalized) interpolation, so the normal field is unchanged
                                    // (phong and the reference; else empty)
  std::vector<glm::vec3> color;     // Gouraud: vertex Blinn–Phong in 8-bit levels, unclamped; else empty
  // Per screen triangle, in primitive order (the order of the scene's objects and faces).
  std::vector<glm::uvec3> triangles;   // vertex indices, ordered so that E01(V2) > 0
  std::vector<std::uint32_t> material; // index into Scene::materials
  std::vector<std::uint32_t> face;     // the scene face it comes from (objects' faces concatenated; a
                                       // clipped face's pieces share it): sort-last ranks' depth ties
  std::vector<glm::vec3> flat_color;   // Flat: the triangle's value in levels (centroid, face normal)
  GeometryStats stats;
  GeometryScratchHolder scratch;
};

// floor(a / b) for b > 0.
inline std::int64_t floor_div(std::int64_t a, std::int64_t b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

// The pixels whose centres may lie in the sub-pixel box [xmin, xmax] x [ymin, ymax], clamped to the
// screen: first and last column and row (empty when x0 > x1 or y0 > y1).
struct PixelBox {
  std::int64_t x0, y0, x1, y1;
};
inline PixelBox centre_box(std::int64_t xmin, std::int64_t xmax, std::int64_t ymin, std::int64_t ymax, int width,
                           int height) {
  const std::int64_t half = kSubpixel / 2;
  return {std::max<std::int64_t>(0, floor_div(xmin - half + kSubpixel - 1, kSubpixel)),
          std::max<std::int64_t>(0, floor_div(ymin - half + kSubpixel - 1, kSubpixel)),
          std::min<std::int64_t>(width - 1, floor_div(xmax - half, kSubpixel)),
          std::min<std::int64_t>(height - 1, floor_div(ymax - half, kSubpixel))};
}

// Bias of the edge Vi -> Vj under the top-left rule (see above).
inline int edge_bias(glm::ivec2 vi, glm::ivec2 vj) {
  const bool top = (vj.y == vi.y) && (vj.x > vi.x);
  const bool left = vj.y < vi.y;
  return (top || left) ? 0 : 1;
}

}  // namespace parashade
