/* Phong: normal (and position) interpolated linearly in screen space, normalized per pixel, and
 * Blinn–Phong per pixel with the scene's lights (blinn_phong.h). */
#define ATTR_FLOATS PHONG_ATTR_FLOATS

#include "blinn_phong.h"

/* A plane at the lanes' row offsets fdy and column offsets rel. The rows of a row segment are one value
 * (a splat, which the compiler folds back to scalar arithmetic); a stamp's lanes lie on four rows. */
INLINE floatV plane_row(__global const float* a, int slot, floatV fdy, floatV rel) {
  return (a[slot] + a[slot + 6] * fdy) + a[slot + 3] * rel;
}

/* Blinn–Phong with a unit normal per lane, the specular term for the lights in `needed` (blinn_phong_masked;
 * -1: every light); the world position from its planes only when a point light or a local viewer needs it. */
INLINE void shade_unit_normal(__global const float* a, floatV fdy, floatV rel, int needed, floatV nx, floatV ny,
                              floatV nz, floatV* r, floatV* g, floatV* b, __constant float4* lights,
                              __constant float4* materials, float4 viewer) {
#if NEED_POSITION
  const floatV px = plane_row(a, 9, fdy, rel), py = plane_row(a, 10, fdy, rel), pz = plane_row(a, 11, fdy, rel);
#else
  const floatV px = 0.0f, py = 0.0f, pz = 0.0f;
#endif
  blinn_phong_masked(materials, (int)a[PHONG_MATERIAL_SLOT], lights, viewer, needed, (intV)(-1), nx, ny, nz, px, py,
                     pz, r, g, b);
}

/* Phong at the lanes' pixels, the specular term for the lights in `needed` (the combined method's highlight
 * test; -1: every light). */
INLINE void shade_pixels_masked(__global const float* a, floatV fdy, floatV rel, int needed, floatV* r, floatV* g,
                                floatV* b, __constant float4* lights, __constant float4* materials, float4 viewer) {
  floatV nx = plane_row(a, 0, fdy, rel), ny = plane_row(a, 1, fdy, rel), nz = plane_row(a, 2, fdy, rel);
  /* A zero interpolated normal (opposite vertex normals) shades with ambient only, never NaN. */
  normalize_lanes(&nx, &ny, &nz);
  shade_unit_normal(a, fdy, rel, needed, nx, ny, nz, r, g, b, lights, materials, viewer);
}

INLINE void shade_pixels_at(__global const float* a, floatV fdy, floatV rel, floatV* r, floatV* g, floatV* b,
                            __constant float4* lights, __constant float4* materials, float4 viewer) {
  shade_pixels_masked(a, fdy, rel, -1, r, g, b, lights, materials, viewer);
}

/* shade_pixels_masked with each lane's own planes (p[k]: coefficient k of the lane's triangle, slots 0..17) and
 * specular mask (lane_needed; needed their union), one material: the deferred stamps of render_tiles.cl, where a
 * stamp's pixels come from different triangles. The same operations in the same order, so the same values as
 * shade_pixels_masked on each lane's triangle. */
INLINE floatV plane_lanes(const floatV* p, int slot, floatV fdy, floatV rel) {
  return (p[slot] + p[slot + 6] * fdy) + p[slot + 3] * rel;
}

INLINE void shade_pixels_lanes(const floatV* p, int material, int needed, intV lane_needed, floatV fdy, floatV rel,
                               floatV* r, floatV* g, floatV* b, __constant float4* lights, __constant float4* materials,
                               float4 viewer) {
  floatV nx = plane_lanes(p, 0, fdy, rel), ny = plane_lanes(p, 1, fdy, rel), nz = plane_lanes(p, 2, fdy, rel);
  normalize_lanes(&nx, &ny, &nz);
#if NEED_POSITION
  const floatV px = plane_lanes(p, 9, fdy, rel), py = plane_lanes(p, 10, fdy, rel), pz = plane_lanes(p, 11, fdy, rel);
#else
  const floatV px = 0.0f, py = 0.0f, pz = 0.0f;
#endif
  blinn_phong_masked(materials, material, lights, viewer, needed, lane_needed, nx, ny, nz, px, py, pz, r, g, b);
}

INLINE void shade_pixels(__global const float* a, int dy, floatV rel, floatV* r, floatV* g, floatV* b,
                         __constant float4* lights, __constant float4* materials, float4 viewer) {
  shade_pixels_at(a, (floatV)(float)dy, rel, r, g, b, lights, materials, viewer);
}

#if NORMALIZE_METHOD
/* Per-span normalization (normalize_span.h): the span's end normals from the planes at its first
 * and last pixel xl, xr (relative to x0); the rest of the shading is unchanged. SHADE_SPAN tells
 * render_tiles.cl to pass whole spans. */
#include "normalize_span.h"
#define SHADE_SPAN 1

INLINE float3 plane_normal_at(__global const float* a, float fdy, float x) {
  return (float3)(a[0] + a[6] * fdy + a[3] * x, a[1] + a[7] * fdy + a[4] * x, a[2] + a[8] * fdy + a[5] * x);
}

/* The span's setup in one tile, which shades its pixels first..last (relative to x0; the tile's
 * column 0 at column0): for the recurrence, the sequential unit's run over them. Returns the unit's
 * steps (0 for the per-lane methods). */
INLINE uint span_setup(SpanNormals* s, __global const float* a, int dy, int xl, int xr, int first, int last,
                       int column0) {
  const float fdy = (float)dy;
  span_normals_setup(s, plane_normal_at(a, fdy, (float)xl), plane_normal_at(a, fdy, (float)xr));
#if NORMALIZE_METHOD == 4
  return span_normals_walk(s, xr - xl + 1, first - xl, last - xl, column0 - xl);
#else
  return 0u;
#endif
}

INLINE void shade_pixels_span(__global const float* a, int dy, floatV rel, const SpanNormals* s, int xl, int xr,
                              floatV* r, floatV* g, floatV* b, __constant float4* lights, __constant float4* materials,
                              float4 viewer) {
  if (s->fallback) {
    shade_pixels(a, dy, rel, r, g, b, lights, materials, viewer);
    return;
  }
  floatV nx, ny, nz;
  span_pixel_normals(s, convert_intV(rel) - xl, xr - xl + 1, &nx, &ny, &nz);
  shade_unit_normal(a, (floatV)(float)dy, rel, -1, nx, ny, nz, r, g, b, lights, materials, viewer);
}
#endif
