/* Per-span unit normals for Phong without a per-pixel normalization ([Dembitsky 2025, software/hardware rendering] ch. 2; the host library
 * host/phong/normalization.cpp is the reference, docs/phong-methods.md the measured errors). Chosen by
 * -D NORMALIZE_METHOD: 1 slerp, 2 quadratic N(t) = G t^2 + P t + Q through the exact mid normal
 * h (Na + Nb), with NORMALIZE_MID: 0 exact h, 1 quadratic fit, 2 the source's cubic, 3 cubic fit
 * (fits for r = Na.Nb in [0, 1]; below 0, h is exact); 3 dichotomy (normalize_dichotomy.h, per lane);
 * 4 the recurrence (normalize_recurrence.h, a sequential unit whose normals for a run of pixels are
 * kept in a row of TILE columns that the lanes then read). The span's end normals are the
 * interpolated normals at its first and last pixel, normalized once per span. Lanes evaluate their
 * pixel's t directly (Horner) instead of by forward differences: the lanes of a vector are parallel.
 * Fallback (counted by the caller): ends with no direction or nearly opposite (1 + r < 1e-6): the
 * exact per-pixel normalization. */
#ifndef PARASHADE_NORMALIZE_SPAN_H
#define PARASHADE_NORMALIZE_SPAN_H

#ifndef NORMALIZE_MID
#define NORMALIZE_MID 0
#endif

#if NORMALIZE_METHOD == 3
#include "normalize_dichotomy.h"
#elif NORMALIZE_METHOD == 4
#include "normalize_recurrence.h"
#endif

typedef struct {
  float3 a, b;     /* unit end normals */
#if NORMALIZE_METHOD == 1
  float theta, inv_sin;
#elif NORMALIZE_METHOD == 2
  float3 g, p;     /* G and P (Q = a) */
#elif NORMALIZE_METHOD == 4
  float x[TILE], y[TILE], z[TILE]; /* the recurrence's normals of a run of pixels, by column */
  int column0;     /* the pixel (0-based in the span) at column 0 */
#endif
  int fallback;    /* 1: shade with the exact per-pixel normal */
} SpanNormals;

#if NORMALIZE_METHOD == 2
INLINE float span_mid_scale(float r) {
#if NORMALIZE_MID == 1
  if (r >= 0.0f) return 0.705190045f + r * (-0.31033697f + r * 0.107063661f);
#elif NORMALIZE_MID == 2
  if (r >= 0.0f) return 0.707f + r * (-0.341f + r * (0.193f + r * -0.059f));
#elif NORMALIZE_MID == 3
  if (r >= 0.0f) return 0.706818541f + r * (-0.342553233f + r * (0.196821778f + r * -0.0613753257f));
#endif
  return rsqrt(2.0f * (1.0f + r));
}
#endif

INLINE void span_normals_setup(SpanNormals* s, float3 na, float3 nb) {
  const float la = dot(na, na), lb = dot(nb, nb);
  s->fallback = !(la > 0.0f) || !(lb > 0.0f);
  s->a = s->fallback ? (float3)(0.0f) : na * rsqrt(la);
  s->b = s->fallback ? (float3)(0.0f) : nb * rsqrt(lb);
  const float r = clamp(dot(s->a, s->b), -1.0f, 1.0f);
  s->fallback |= 1.0f + r < 1e-6f;
#if NORMALIZE_METHOD == 1
  s->theta = acos(r);
  s->inv_sin = s->theta < 1e-3f ? 0.0f : 1.0f / sin(s->theta);
#elif NORMALIZE_METHOD == 2
  const float h = span_mid_scale(r);
  const float3 sum = s->a + s->b;
  s->g = sum * (2.0f * (1.0f - 2.0f * h));
  s->p = sum * (4.0f * h - 3.0f) + 2.0f * s->b;
#endif
}

#if NORMALIZE_METHOD == 4
/* The sequential unit's run: pixels first..last (0-based, of a span of `length`) into the row from
 * column first - column0; the rest of the row's vectors it touches are zeroed (lanes outside the run are
 * masked, but stay finite). Returns the unit's steps. */
INLINE uint span_normals_walk(SpanNormals* s, int length, int first, int last, int column0) {
  s->column0 = column0;
  if (s->fallback || first > last) return 0u;
  const int c0 = first - column0, c1 = last - column0;
  for (int c = c0 / VEC * VEC; c < (c1 / VEC + 1) * VEC; ++c)
    if (c < c0 || c > c1) s->x[c] = s->y[c] = s->z[c] = 0.0f;
  return recurrence_walk(s->a, s->b, length, first, last, s->x + c0, s->y + c0, s->z + c0);
}
#endif

#if NORMALIZE_METHOD <= 2
/* The normal at parameter t in [0, 1] of the span, one pixel per lane. */
INLINE void span_normal_at(const SpanNormals* s, floatV t, floatV* nx, floatV* ny, floatV* nz) {
#if NORMALIZE_METHOD == 1
  floatV wa, wb;
  if (s->inv_sin == 0.0f) { /* theta -> 0: sin(w theta)/sin(theta) -> w */
    wa = 1.0f - t;
    wb = t;
  } else {
    wa = sin((1.0f - t) * s->theta) * s->inv_sin;
    wb = sin(t * s->theta) * s->inv_sin;
  }
  *nx = wa * s->a.x + wb * s->b.x;
  *ny = wa * s->a.y + wb * s->b.y;
  *nz = wa * s->a.z + wb * s->b.z;
#else
  *nx = (s->g.x * t + s->p.x) * t + s->a.x;
  *ny = (s->g.y * t + s->p.y) * t + s->a.y;
  *nz = (s->g.z * t + s->p.z) * t + s->a.z;
#endif
}
#endif

/* The normals of pixels i (0-based in a span of `length`), one per lane; for the recurrence, the
 * walked row's (span_normals_walk) VEC pixels from pixel i.s0. */
INLINE void span_pixel_normals(const SpanNormals* s, intV i, int length, floatV* nx, floatV* ny, floatV* nz) {
#if NORMALIZE_METHOD == 3
  dichotomy_normals(s->a, s->b, i, length, nx, ny, nz);
#elif NORMALIZE_METHOD == 4
  const int c = i.s0 - s->column0;
  *nx = vloadV(0, s->x + c);
  *ny = vloadV(0, s->y + c);
  *nz = vloadV(0, s->z + c);
#else
  const floatV t = length > 1 ? convert_floatV(i) * (1.0f / (float)(length - 1)) : (floatV)0.0f;
  span_normal_at(s, t, nx, ny, nz);
#endif
}

#endif
