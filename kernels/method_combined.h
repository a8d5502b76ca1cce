/* Combined Gouraud/Phong on digital segments ([Romanyuk & Romanyuk, combined shading], docs/combined.md): each span is cut into
 * segments of 2^K pixels starting at its left pixel; Blinn–Phong is exact (method_phong.h's
 * normalized interpolated normal) at the segment ends and linear inside, I_v = I_a + (I_b - I_a) v/2^K.
 * The last, shorter segment is treated as 2^K long (its far end extrapolated past the span) and
 * stopped at the span's end, as in the sources: no division per segment.
 * SEG_AUTO = 0: K = SEG_K for every span. SEG_AUTO = 1: K per span, the largest K <= SEG_K_MAX whose
 * relative normal change |dN/dx| 2^K / min|N| stays below the material's limit (materials[3m+2].w,
 * from the error budget on the host: combined.hpp).
 * render_tiles.cl walks triangles by whole spans for this method (combined_walk.h). */
#define COMBINED 1
#include "method_phong.h"
#ifndef HIGHLIGHT_TEST
#define HIGHLIGHT_TEST 0
#endif

/* TRIANGLE_CHOICE = 1: the host chose per triangle (triangle_choice.hpp) in PHONG_METHOD_SLOT: 0 Phong per
 * pixel, 1 Gouraud (its colour planes in slots 0..8, Gouraud's layout), 2 segments; combined:auto takes
 * the triangle's limit on the normal change from PHONG_PSI_SLOT. */
#ifndef TRIANGLE_CHOICE
#define TRIANGLE_CHOICE 0
#endif
INLINE bool shaded_by_gouraud(__global const float* a) { return TRIANGLE_CHOICE && a[PHONG_METHOD_SLOT] == 1.0f; }

#ifndef SEG_AUTO
#define SEG_AUTO 0
#endif
#ifndef SEG_K
#define SEG_K 2
#endif
#ifndef SEG_K_MAX
#define SEG_K_MAX 6
#endif
/* Segment-end columns a row may need in a tile: at most ((TILE - 1) >> K) + 3 for the smallest K. */
#if SEG_AUTO
#define SEG_K_MIN 0
#else
#define SEG_K_MIN SEG_K
#endif
#define SEG_END_COLUMNS (((TILE - 1) >> SEG_K_MIN) + 3)

/* Per triangle: segments (combined_walk.h) or Phong per pixel. A triangle whose box is narrower than
 * COMBINED_MIN_WIDTH pixels has spans too short to share segment ends (its ends would be nearly all its
 * pixels), so it goes the per-pixel way: the same result as combined:0, without the walk's overhead. */
#ifndef COMBINED_MIN_WIDTH
#define COMBINED_MIN_WIDTH 0
#endif
INLINE bool combined_walks(__global const TriangleGeometry* t, __global const float* a) {
#if TRIANGLE_CHOICE
  return a[PHONG_METHOD_SLOT] == 2.0f;
#else
  return t->x1 - t->x0 + 1 >= COMBINED_MIN_WIDTH;
#endif
}

/* Exact Blinn–Phong at one point per lane (row dy, column rel relative to the record's corner): method_phong.h's
 * per-pixel shading, so segment ends equal Phong's pixels bit for bit; under HIGHLIGHT_TEST with the triangle's
 * specular mask (the branch keeps the all-lights case free of per-light tests). */
INLINE void shade_points(__global const float* a, floatV fdy, floatV rel, floatV* r, floatV* g, floatV* b,
                         __constant float4* lights, __constant float4* materials, float4 viewer) {
#if HIGHLIGHT_TEST
  const int needed = (int)a[PHONG_HIGHLIGHT_SLOT];
  if (needed != (1 << NUM_LIGHTS) - 1) {
    shade_pixels_masked(a, fdy, rel, needed, r, g, b, lights, materials, viewer);
    return;
  }
#endif
  shade_pixels_at(a, fdy, rel, r, g, b, lights, materials, viewer);
}

/* Per pixel (narrow triangles, those given to Gouraud, and every triangle on the stamps): Gouraud's planes, or
 * Phong with the triangle's specular mask (shade_points: the same operations as method_phong.h's shade_pixels). */
INLINE void shade_points_chosen(__global const float* a, floatV fdy, floatV rel, floatV* r, floatV* g, floatV* b,
                                __constant float4* lights, __constant float4* materials, float4 viewer) {
  if (shaded_by_gouraud(a)) {
    *r = plane_row(a, 0, fdy, rel);
    *g = plane_row(a, 1, fdy, rel);
    *b = plane_row(a, 2, fdy, rel);
    return;
  }
  shade_points(a, fdy, rel, r, g, b, lights, materials, viewer);
}

#if TRIANGLE_CHOICE || HIGHLIGHT_TEST
INLINE void shade_pixels_combined(__global const float* a, int dy, floatV rel, floatV* r, floatV* g, floatV* b,
                                  __constant float4* lights, __constant float4* materials, float4 viewer) {
  shade_points_chosen(a, (floatV)(float)dy, rel, r, g, b, lights, materials, viewer);
}
#define SHADE_PIXELS shade_pixels_combined
#endif

/* K per span (rows as lanes): the largest K <= SEG_K_MAX with |D| 2^K <= psi_limit * min|N|, min|N|
 * the smallest unnormalized normal length over [xl, xr + 2^SEG_K_MAX] (the last segment reaches past
 * the span). |N(x)|^2 is a quadratic in x: its minimum is at x* = -(R.D)/|D|^2, clamped. */
INLINE intV segment_log2(__global const float* a, floatV fdy, intV xl, intV xr, float psi_limit) {
#if SEG_AUTO
  const floatV rx = (floatV)a[0] + a[6] * fdy, ry = (floatV)a[1] + a[7] * fdy, rz = (floatV)a[2] + a[8] * fdy;
  const float dx = a[3], dy = a[4], dz = a[5];
  const float d2 = dx * dx + dy * dy + dz * dz;
  if (!(d2 > 0.0f)) return (intV)SEG_K_MAX; /* constant normal along rows: any segment is exact */
  const floatV x = clamp(-(rx * dx + ry * dy + rz * dz) / d2, convert_floatV(xl),
                         convert_floatV(xr + (1 << SEG_K_MAX)));
  const floatV mx = rx + dx * x, my = ry + dy * x, mz = rz + dz * x;
  const floatV allowed = psi_limit * sqrt(mx * mx + my * my + mz * mz); /* largest |D| * length */
  const float d = sqrt(d2);
  intV k = (intV)0;
  for (int j = 1; j <= SEG_K_MAX; ++j) k -= LANE_MASK(isless(d * (float)(1 << j), allowed)); /* -1 where true */
  return k;
#else
  return (intV)SEG_K;
#endif
}
