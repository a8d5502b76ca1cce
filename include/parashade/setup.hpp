#pragma once
// Triangle setup: screen triangles -> fixed-point edge functions, bounding boxes and attribute planes
// (the records of kernels/triangle_record.h). For Gouraud the x increment of each channel is the
// constant span increment dI_G of [Gouraud simplification], computed once per triangle with
// [Malovanyi 2019, parallel Gouraud] formula (2.16).
#include <cstddef>
#include <cstdint>

#include <glm/glm.hpp>

#include "parashade/method.hpp"
#include "parashade/screen_geometry.hpp"
#include "parashade/triangle_choice.hpp"
#include "parashade/kernels/fixed_point.h"
#include "parashade/kernels/triangle_record.h"

namespace parashade {

std::size_t attribute_floats(Method method);

struct SetupStats {
  std::uint64_t records = 0;          // screen triangles
  std::uint64_t without_pixels = 0;   // no pixel centre inside the bounding box (marked empty)
};

// Fills geometry[i] and attributes[i * attribute_floats(method) ...] for every screen triangle i.
// Triangles that cannot cover a pixel centre get an empty box (x0 > x1) and are skipped by binning.
// With `fixed` (Gouraud: the intensities; Phong: the normal components x NORMAL_REGISTER_LEVELS), also fills fixed[i] with the planes in setup's fixed-point format
// (kernels/fixed_point.h) for the fixed-point units.
// With `gouraud` (combined: triangle_choice.hpp), the triangles it gives to Gouraud get their colour
// planes (g.color needed) in the normal planes' slots.
SetupStats setup_triangles(const ScreenGeometry& g, Method method, TriangleGeometry* geometry, float* attributes,
                           FixedPlanes* fixed = nullptr, const TriangleShading* gouraud = nullptr);

// setup_triangles() for the records [first, last) only, on the calling thread; returns how many of them
// have no pixel centre. Record k is screen triangle k, or order[k] when `order` is given (a streamed
// band's triangles, frame_pipeline.hpp).
std::uint64_t setup_triangle_range(const ScreenGeometry& g, Method method, TriangleGeometry* geometry,
                                   float* attributes, FixedPlanes* fixed, const TriangleShading* gouraud,
                                   std::size_t first, std::size_t last, const std::uint32_t* order = nullptr);

// Copies a Gouraud record's depth plane, float attribute planes and (when both are given) fixed planes,
// re-anchored from `from`'s box corner to pixel (x0, y0); the planes themselves are unchanged. `to`'s
// other fields are left as they are.
void move_plane_anchor(const TriangleGeometry& from, const float* attr, const FixedPlanes* fixed, int x0, int y0,
                       TriangleGeometry& to, float* attr_to, FixedPlanes* fixed_to);

// A plane value or increment in levels into setup's PLANE_FRAC format, rounded to nearest. Magnitudes
// beyond kPlaneLimit levels saturate there: only slivers thinner than ~2^-14 pixel reach it, and
// 16 * kPlaneLimit still fits the 64-bit register (interleave:16:own forms 16*dI from it).
constexpr double kPlaneLimit = double(1 << 26);
std::int64_t to_plane_register(double levels);

// The constant span increment dI_G ([Malovanyi 2019, parallel Gouraud] formula (2.16)) for vertex values ia, ib, ic at screen
// positions a, b, c (pixels): [(Ic-Ia)*dy_BC - (Ic-Ib)*dy_AC] / [dx_AC*dy_BC - dx_BC*dy_AC].
double constant_span_increment(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, double ia, double ib, double ic);
// Formula (2.16) as setup evaluates it: the denominator depends only on the triangle, so its
// reciprocal is computed once and each channel costs a numerator and a product.
struct ConstantSpanIncrement {
  ConstantSpanIncrement(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c);
  double operator()(double ia, double ib, double ic) const {
    return ((ic - ia) * dy_bc - (ic - ib) * dy_ac) * inv_denominator;
  }
  double dy_bc, dy_ac, inv_denominator;
};
// The same increment by formula (2.15): along the longest span through the middle vertex B.
double constant_span_increment_longest_span(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, double ia, double ib,
                                            double ic);

}  // namespace parashade
