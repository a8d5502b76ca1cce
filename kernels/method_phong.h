/* Phong: normal (and position) interpolated linearly in screen space, normalized per pixel, and
 * Blinn–Phong per pixel with the scene's lights (blinn_phong.h). */
#define ATTR_FLOATS PHONG_ATTR_FLOATS

#include "blinn_phong.h"

INLINE floatV plane_row(__global const float* a, int slot, float fdy, floatV rel) {
  return (floatV)(a[slot] + a[slot + 6] * fdy) + a[slot + 3] * rel;
}

INLINE void shade_pixels(__global const float* a, int dy, floatV rel, floatV* r, floatV* g, floatV* b,
                         __constant float4* lights, __constant float4* materials, float4 viewer) {
  const float fdy = (float)dy;
  floatV nx = plane_row(a, 0, fdy, rel), ny = plane_row(a, 1, fdy, rel), nz = plane_row(a, 2, fdy, rel);
  const floatV len2 = nx * nx + ny * ny + nz * nz;
  /* A zero interpolated normal (opposite vertex normals) shades with ambient only, never NaN. */
  const floatV inv = safe_rsqrt(len2);
  nx *= inv;
  ny *= inv;
  nz *= inv;
#if NEED_POSITION
  const floatV px = plane_row(a, 9, fdy, rel), py = plane_row(a, 10, fdy, rel), pz = plane_row(a, 11, fdy, rel);
#else
  const floatV px = 0.0f, py = 0.0f, pz = 0.0f;
#endif
  blinn_phong(materials, (int)a[PHONG_MATERIAL_SLOT], lights, viewer, nx, ny, nz, px, py, pz, r, g, b);
}
