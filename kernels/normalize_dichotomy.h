/* Dichotomy ([Dembitsky 2025, software/hardware rendering] ch. 2): unit normals by binary bisection inside segments of 2^K pixels whose end
 * normals are exact. It follows the host library's float rule step for step (dichotomy_span in
 * host/phong/normalization.cpp), including the last, shorter segment: bisected between the span's real
 * ends, three levels finer than it needs when its length is no power of two, each pixel taking the
 * nearest dyadic point; with NORMALIZE_EXTRAPOLATE the source's rule (2^K long, far end extrapolated).
 * Bisection: N_mid = (N_lo + N_hi) s(u), u = 2 cos(phi) of the angle bisected, s ~ 1/sqrt(2 + u) by
 * NORMALIZE_BISECTOR: 0 exact, 1 the source's linear, 2 the source's quadratic, 3 linear fit,
 * 4 quadratic fit (fits for u in [sqrt 2, 2]; a wider first step is taken exactly); the next level's
 * u is sqrt(2 + u). Vectorized: each lane computes its own segment's ends and descends the levels
 * toward its own pixel (left or right half by where its dyadic point lies), so no lane waits for
 * another; the price is the ends and up to K + 3 levels per pixel. */
#ifndef PARASHADE_NORMALIZE_DICHOTOMY_H
#define PARASHADE_NORMALIZE_DICHOTOMY_H

#ifndef NORMALIZE_BISECTOR
#define NORMALIZE_BISECTOR 0
#endif
#ifndef NORMALIZE_SEGMENT_LOG2
#define NORMALIZE_SEGMENT_LOG2 4
#endif
#ifndef NORMALIZE_EXTRAPOLATE
#define NORMALIZE_EXTRAPOLATE 0
#endif
#define DICHOTOMY_SEGMENT (1 << NORMALIZE_SEGMENT_LOG2)
/* Below this 1 + cos between a segment's ends, the host takes the segment's pixels exactly. */
#define DICHOTOMY_OPPOSITE (2.0f * 1e-6f)

INLINE floatV bisector_scale(floatV u) {
#if NORMALIZE_BISECTOR == 1
  return 0.64f + u * -0.07f;
#elif NORMALIZE_BISECTOR == 2
  return 0.681f + u * (-0.119f + u * 0.014f);
#elif NORMALIZE_BISECTOR == 3
  return 0.640040939f + u * -0.0703261419f;
#elif NORMALIZE_BISECTOR == 4
  return 0.680849766f + u * (-0.118921801f + u * 0.0142534992f);
#else
  return rsqrt(2.0f + u);
#endif
}

/* normalize(a + (b - a) w) per lane, and where it has no length, zero and *zero set: the host's
 * exact_normal (same operations, same order). */
INLINE void lerp_unit(float3 a, float3 b, floatV w, floatV* x, floatV* y, floatV* z, intV* zero) {
  *x = a.x + (b.x - a.x) * w;
  *y = a.y + (b.y - a.y) * w;
  *z = a.z + (b.z - a.z) * w;
  const floatV len2 = *x * *x + *y * *y + *z * *z;
  *zero = !isgreater(len2, 0.0f) | !isfinite(len2);
  const floatV len = select(sqrt(len2), (floatV)1.0f, *zero);
  *x = select(*x / len, (floatV)0.0f, *zero);
  *y = select(*y / len, (floatV)0.0f, *zero);
  *z = select(*z / len, (floatV)0.0f, *zero);
}

/* The normal of pixel p (0 .. length-1 of the span from unit a to unit b), one pixel per lane. */
INLINE void dichotomy_normals(float3 a, float3 b, intV pixel, int length, floatV* nx, floatV* ny, floatV* nz) {
  const int last = length - 1;
  const float denom = length > 1 ? (float)last : 1.0f;
  /* Integer clamp/min/max take vector bounds: Oclgrind 21.10 reads garbage for the lanes of scalar ones. */
  const intV p = clamp(pixel, (intV)0, (intV)max(last, 0)); /* lanes outside the span (masked later) stay inside it */
  /* Pixel p >= 1 is pixel i = 1 .. 2^K of the segment from pixel `start`; pixel 0 is a itself. */
  const intV start = ((max(p, (intV)1) - 1) >> NORMALIZE_SEGMENT_LOG2) << NORMALIZE_SEGMENT_LOG2;
  const intV i = p - start;
#if NORMALIZE_EXTRAPOLATE
  const intV whole = (intV)(-1);
#else
  const intV whole = start + DICHOTOMY_SEGMENT <= last;
#endif
  const intV steps = select(max(last - start, (intV)1), (intV)DICHOTOMY_SEGMENT, whole); /* pixels to the segment's end */
  /* Dyadic points: 2^K for a whole segment, else the next power of two >= steps, times 8 unless exact. */
  /* steps is a power of two when 2^ceil(log2 steps) equals it; (steps & (steps - 1)) == 0 is the same test,
   * but LLVM turns it into llvm.ctpop, which Oclgrind 21.10 cannot run (docs/pipeline.md). */
  const intV ceil_log2 = 32 - clz(steps - 1);
  const intV levels = ceil_log2 + select((intV)3, (intV)0, ((intV)1 << ceil_log2) == steps);
  const intV n = select((intV)1 << levels, (intV)DICHOTOMY_SEGMENT, whole);
  /* Pixel i sits at i/steps of the segment: dyadic point i n / steps, or the nearest one. */
  intV j = i;
  /* !all(whole), not any(!whole): LLVM makes !whole an xor of the comparison's i1 lanes with true, which
   * Oclgrind 21.10 sign-extends to 1 instead of -1 (docs/pipeline.md). */
  if (!all(whole)) j = select((2 * i * n + steps) / (2 * steps), i, whole);

  floatV ax, ay, az, bx, by, bz;
  intV zero_a, zero_b;
  lerp_unit(a, b, convert_floatV(start) / denom, &ax, &ay, &az, &zero_a);
  lerp_unit(a, b, convert_floatV(start + steps) / denom, &bx, &by, &bz, &zero_b);
  const floatV cos_ab = clamp(ax * bx + ay * by + az * bz, -1.0f, 1.0f);
  const intV fallback = zero_a | zero_b | isless(1.0f + cos_ab, (floatV)DICHOTOMY_OPPOSITE);

  floatV u = 2.0f * cos_ab;
  intV lo = 0, hi = n;
  for (int level = 0; level < NORMALIZE_SEGMENT_LOG2 + 3; ++level) {
    const intV active = (hi - lo >= 2) & (j != lo) & (j != hi);
    if (!any(active)) break;
    const floatV sx = ax + bx, sy = ay + by, sz = az + bz;
    floatV scale = bisector_scale(u);
    floatV mx = sx * scale, my = sy * scale, mz = sz * scale;
#if NORMALIZE_BISECTOR
    if (level == 0) { /* outside the polynomials' range (phi > 45 degrees): this step exactly */
      const intV wide = isless(u, 1.41421356f);
      const floatV root = sqrt(2.0f + u);
      mx = select(mx, sx / root, wide);
      my = select(my, sy / root, wide);
      mz = select(mz, sz / root, wide);
    }
#endif
    u = sqrt(max(0.0f, 2.0f + u)); /* 2 cos(phi/2) = sqrt(2 + 2 cos phi) */
    const intV mid = (lo + hi) >> 1;
    const intV left = active & (j <= mid), right = active & (j > mid);
    bx = select(bx, mx, left);
    by = select(by, my, left);
    bz = select(bz, mz, left);
    hi = select(hi, mid, left);
    ax = select(ax, mx, right);
    ay = select(ay, my, right);
    az = select(az, mz, right);
    lo = select(lo, mid, right);
  }
  const intV at_lo = j == lo;
  *nx = select(bx, ax, at_lo);
  *ny = select(by, ay, at_lo);
  *nz = select(bz, az, at_lo);

  /* A segment with opposite or zero ends takes its pixels exactly; pixel 0 is the span's start. */
  if (any(fallback)) {
    floatV ex, ey, ez;
    intV zero_p;
    lerp_unit(a, b, convert_floatV(p) / denom, &ex, &ey, &ez, &zero_p);
    *nx = select(*nx, ex, fallback);
    *ny = select(*ny, ey, fallback);
    *nz = select(*nz, ez, fallback);
  }
  const intV first = p == 0;
  *nx = select(*nx, (floatV)a.x, first);
  *ny = select(*ny, (floatV)a.y, first);
  *nz = select(*nz, (floatV)a.z, first);
}

#endif
