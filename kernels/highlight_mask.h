/* The highlight-presence unit (SEEDS §8): Blinn–Phong as blinn_phong.h, but the specular term only for the
 * lights in `needed` (a per-triangle bit mask from the host's highlight test, highlight.hpp); the others
 * add their diffuse term only. The mask is the same for the whole triangle, so the branch is uniform. */
#ifndef PARASHADE_HIGHLIGHT_MASK_H
#define PARASHADE_HIGHLIGHT_MASK_H

INLINE void blinn_phong_masked(__constant float4* materials, int m, __constant float4* lights, float4 viewer, int needed,
                               floatV nx, floatV ny, floatV nz, floatV px, floatV py, floatV pz, floatV* r, floatV* g,
                               floatV* b) {
  const float4 amb = materials[3 * m], kd = materials[3 * m + 1], ks = materials[3 * m + 2];
  floatV cr = (floatV)amb.x, cg = (floatV)amb.y, cb = (floatV)amb.z;
#if LOCAL_VIEWER
  floatV vx = viewer.x - px, vy = viewer.y - py, vz = viewer.z - pz;
  {
    const floatV inv = safe_rsqrt(vx * vx + vy * vy + vz * vz);
    vx *= inv;
    vy *= inv;
    vz *= inv;
  }
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
      const floatV inv = safe_rsqrt(lx * lx + ly * ly + lz * lz);
      lx *= inv;
      ly *= inv;
      lz *= inv;
    } else {
      lx = l4.x;
      ly = l4.y;
      lz = l4.z;
    }
    const floatV n_dot_l = fmax(nx * lx + ny * ly + nz * lz, (floatV)0.0f);
    floatV sr = kd.x * n_dot_l, sg = kd.y * n_dot_l, sb = kd.z * n_dot_l;
    if (needed & (1 << i)) {
      const floatV hx = lx + vx, hy = ly + vy, hz = lz + vz;
      const floatV n_dot_h = (nx * hx + ny * hy + nz * hz) * safe_rsqrt(hx * hx + hy * hy + hz * hz);
      const floatV spec = positive_power(n_dot_h, amb.w);
      sr += ks.x * spec;
      sg += ks.y * spec;
      sb += ks.z * spec;
    }
    cr += il.x * sr;
    cg += il.y * sg;
    cb += il.z * sb;
  }
  *r = cr;
  *g = cg;
  *b = cb;
}

#endif
