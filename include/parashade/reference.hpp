#pragma once
// The exact reference: double precision, plain C++, sharing no shading code with the kernels.
// It rasterizes the same screen triangles with the same coverage rule (see screen_geometry.hpp),
// resolves visibility with a depth test in double (ties: the earlier triangle wins), and gives per
// covered pixel two values in 8-bit levels, clamped to [0, 255]:
//   ideal — the method's own ideal: flat: the triangle's value; gouraud: screen-space barycentric
//           interpolation of the vertex values at the pixel centre; phong: screen-space barycentric
//           interpolation of normal and position, normalized normal, Blinn–Phong per pixel;
//   exact — exact Phong: perspective-correct position and normal, per-pixel L and V, Blinn–Phong.
// Barycentrics come from the exact integer edge values at the pixel centre (b_k = E_k / area2). An
// interpolated normal of zero length is replaced by the world-space face normal turned toward the
// viewer (never NaN). Uncovered pixels hold the background (x255) in both. Needs world and normal per
// vertex (and color for gouraud, flat_color for flat); throws std::invalid_argument on inconsistent
// geometry or a triangle not ordered E01(V2) > 0. Deterministic for any host thread count. It also lists the
// pixels whose front surface float depth cannot settle (depth_ties), with the other surface's values there.
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "parashade/image.hpp"
#include "parashade/method.hpp"
#include "parashade/scene.hpp"
#include "parashade/screen_geometry.hpp"

namespace parashade {

struct ReferenceImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> covered;   // 1 where some triangle covers the pixel centre
  std::vector<std::int32_t> triangle;  // visible screen triangle, -1 where none
  std::vector<glm::dvec3> ideal;       // method's own ideal (levels, clamped)
  std::vector<glm::dvec3> exact;       // exact Phong (levels, clamped)
  // Where float depth cannot tell the front surface: another triangle covers the pixel within the float depth
  // planes' rounding (docs/error-bounds.md's bound, twice over) of the visible one's depth — interpenetrating or
  // nearly coplanar surfaces. A renderer in float may keep either there. Per such (pixel, other triangle): the
  // other triangle's ideal and exact values at the pixel. Sorted by pixel, then triangle.
  struct DepthTie {
    std::size_t pixel;
    std::int32_t triangle;
    glm::dvec3 ideal, exact;
  };
  std::vector<DepthTie> depth_ties;
};

ReferenceImage render_reference(const Scene& scene, const ScreenGeometry& geometry, Method method);

// 1 at each pixel of depth_ties where `image` shows another surface than the reference's visible one (its
// value nearer that surface's ideal than the visible one's, largest channel), else 0; empty when the
// reference has no ties. The image's own method must be the reference's. Such pixels are not shading error:
// compare_to_reference counts them apart (front_surface_mismatch).
std::vector<std::uint8_t> front_surface_flips(const RenderedImage& image, const ReferenceImage& ref);

}  // namespace parashade
