/* Blinn–Phong per pixel ([Dembitsky 2025, software/hardware rendering] §4.1): I = ambient + sum_l I_l*(k_d*max(0,N.L) + k_s*max(0,N.H)^n).
 * Lights: two float4 each — (direction toward the light | position, 0 | 1), (I_l x 255, 0).
 * Materials: three float4 each — (ambient x I_a x 255, n), (diffuse, 0), (specular, 0).
 * Specialized per scene: NUM_LIGHTS, POINT_LIGHTS (bit mask), LOCAL_VIEWER. viewer = eye position
 * (local viewer) or the unit vector toward the viewer. */
#ifndef PARASHADE_BLINN_PHONG_H
#define PARASHADE_BLINN_PHONG_H

#include "specular_models.h"

/* The specular term only for the lights in `needed` (a bit mask; the highlight-presence unit of [Dembitsky 2025, software/hardware rendering] ch. 3,
 * highlight.hpp, clears the lights no highlight can reach in a triangle): the others add their diffuse
 * term only. The mask is uniform over a triangle, so the branch is too; with every bit set (blinn_phong
 * below) the compiler removes it. `lane_needed` narrows it per lane (lanes of different triangles: a lane
 * without light i's bit adds a zero specular term, which leaves its sum the same bits as no term); all bits
 * set where the lanes share one mask, and the select folds away. */
INLINE void blinn_phong_masked(__constant float4* materials, int m, __constant float4* lights, float4 viewer, int needed,
                               intV lane_needed, floatV nx, floatV ny, floatV nz, floatV px, floatV py, floatV pz,
                               floatV* r, floatV* g, floatV* b) {
  const float4 amb = materials[3 * m], kd = materials[3 * m + 1], ks = materials[3 * m + 2];
  floatV cr = (floatV)amb.x, cg = (floatV)amb.y, cb = (floatV)amb.z;
#if LOCAL_VIEWER
  floatV vx = viewer.x - px, vy = viewer.y - py, vz = viewer.z - pz;
  normalize_lanes(&vx, &vy, &vz);
#else
  const floatV vx = viewer.x, vy = viewer.y, vz = viewer.z;
#endif
#pragma unroll
  for (int i = 0; i < NUM_LIGHTS; ++i) {
    const float4 l4 = lights[2 * i], il = lights[2 * i + 1];
    floatV lx, ly, lz;
    if (POINT_LIGHTS & (1 << i)) {
      lx = l4.x - px;
      ly = l4.y - py;
      lz = l4.z - pz;
      normalize_lanes(&lx, &ly, &lz);
    } else {
      lx = l4.x;
      ly = l4.y;
      lz = l4.z;
    }
    const floatV n_dot_l = fmax(nx * lx + ny * ly + nz * lz, (floatV)0.0f);
    if (needed & (1 << i)) {
      floatV hx = lx + vx, hy = ly + vy, hz = lz + vz;
      const floatV h_inv = safe_rsqrt(hx * hx + hy * hy + hz * hz);
      const floatV n_dot_h = (nx * hx + ny * hy + nz * hz) * h_inv;
      const floatV spec = select((floatV)0.0f, specular_term(n_dot_h, amb.w, kd.w), /* specular_models.h */
                                 (lane_needed & (1 << i)) != 0);
      cr += il.x * (kd.x * n_dot_l + ks.x * spec);
      cg += il.y * (kd.y * n_dot_l + ks.y * spec);
      cb += il.z * (kd.z * n_dot_l + ks.z * spec);
    } else {
      cr += il.x * (kd.x * n_dot_l);
      cg += il.y * (kd.y * n_dot_l);
      cb += il.z * (kd.z * n_dot_l);
    }
  }
  *r = cr;
  *g = cg;
  *b = cb;
}

INLINE void blinn_phong(__constant float4* materials, int m, __constant float4* lights, float4 viewer,
                        floatV nx, floatV ny, floatV nz, floatV px, floatV py, floatV pz,
                        floatV* r, floatV* g, floatV* b) {
  blinn_phong_masked(materials, m, lights, viewer, -1, (intV)(-1), nx, ny, nz, px, py, pz, r, g, b);
}

#endif
