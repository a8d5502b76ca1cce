/* Spans of a triangle on VEC consecutive pixel rows at once (one row per lane): the exact range of
 * covered pixel centres (the coverage rule of screen_geometry.hpp). Per edge, the crossing is
 * estimated in float, q = -E_row / a, and settled by exact 64-bit evaluation of the edge function at
 * the candidate and its neighbour. |q| <= 4097 within a window and the estimate's relative error is
 * below 2^-22 (2^-21 with a division of 2.5 ulp, OpenCL's least for float), so it is off by less than
 * 0.002 pixel and one correction step each way is enough. */
#ifndef PARASHADE_SPAN_H
#define PARASHADE_SPAN_H

#include "triangle_record.h"

#if KERNEL_SHAPE == KERNEL_SHAPE_LANES
typedef long longV; /* one row (the lanes shape's pixel) */
#define convert_longV convert_long
#else
typedef long16 longV;
#define convert_longV convert_long16
#endif

/* 1/a, the seed of the span search, computed here rather than stored in the record: the records are what
 * setup writes and the kernel reads per triangle, and only the span search of larger triangles needs it. */
INLINE float edge_reciprocal(long a) { return a != 0 ? 1.0f / (float)a : 0.0f; }

/* The span search of row_spans for one edge, in vector type T (long or int lanes): r holds E at x = x0 on
 * each row, a the x increment; narrows [lo_v, hi_v]. */
#define SETTLE_SPAN_EDGE(T, convert_T, r, a, inv_a, lo_v, hi_v)                                      \
  do {                                                                                               \
    if ((a) == 0) {                                                                                  \
      hi_v = select(hi_v, lo_v - 1, convert_intV((r) < 0));                                          \
      break;                                                                                         \
    }                                                                                                \
    const floatV q = -convert_floatV(r) * (inv_a);                                                   \
    if ((a) > 0) { /* covered for x >= boundary */                                                   \
      intV c = convert_intV(ceil(clamp(q, convert_floatV(lo_v), convert_floatV(hi_v + 1))));         \
      const T cl = convert_T(c);                                                                     \
      c = select(c, c - 1, (c > lo_v) & convert_intV((r) + (a) * (cl - 1) >= 0));                    \
      c = select(c, c + 1, (c <= hi_v) & convert_intV((r) + (a) * cl < 0));                          \
      lo_v = max(lo_v, c);                                                                           \
    } else { /* covered for x <= boundary */                                                         \
      intV c = convert_intV(floor(clamp(q, convert_floatV(lo_v - 1), convert_floatV(hi_v))));        \
      const T cl = convert_T(c);                                                                     \
      c = select(c, c + 1, (c < hi_v) & convert_intV((r) + (a) * (cl + 1) >= 0));                    \
      c = select(c, c - 1, (c >= lo_v) & convert_intV((r) + (a) * cl < 0));                          \
      hi_v = min(hi_v, c);                                                                           \
    }                                                                                                \
  } while (0)

/* Row dy (per lane, relative to the record's y0): covered pixels [*lo, *hi] (relative to x0) within
 * the window [lo, hi] given on entry; empty where *lo > *hi. */
INLINE void row_spans(__global const TriangleGeometry* t, intV dy, intV* lo_out, intV* hi_out, int lo, int hi) {
  intV lo_v = (intV)lo, hi_v = (intV)hi;
  const longV dyl = convert_longV(dy);
  for (int e = 0; e < 3; ++e) {
    const long a = t->edge_a[e];
    const longV r = (longV)t->edge_c[e] + dyl * (long)t->edge_b[e]; /* E at x = x0 on each row */
    SETTLE_SPAN_EDGE(longV, convert_longV, r, a, edge_reciprocal(a), lo_v, hi_v);
  }
  *lo_out = lo_v;
  *hi_out = hi_v;
}

/* Whether the triangle covers every pixel centre of columns lo..hi and rows dy_lo..dy_hi (relative to x0,
 * y0): each edge function is linear, so its least value over the rectangle is at a corner. Where it
 * holds, row_spans over the rectangle with the window [lo, hi] gives [lo, hi] on every row. */
INLINE int rect_covered(__global const TriangleGeometry* t, int lo, int hi, int dy_lo, int dy_hi) {
  for (int e = 0; e < 3; ++e) {
    const long a = t->edge_a[e], b = t->edge_b[e];
    if ((long)t->edge_c[e] + min(a * lo, a * hi) + min(b * dy_lo, b * dy_hi) < 0) return 0;
  }
  return 1;
}

/* A small triangle's (TRIANGLE_SMALL) edge function e at column x0 of rows dy (its row term), in 32 bits: exact over
 * its box and the 16 pixels beyond (triangle_record.h). */
INLINE intV small_edge_row(__global const TriangleGeometry* t, int e, intV dy) {
  return (intV)(int)t->edge_c[e] + t->edge_b[e] * dy;
}

/* The same for a small triangle (TRIANGLE_SMALL) in 32-bit lanes: its edge values stay below 2^30 over
 * its box and 16 pixels beyond, which is all the search evaluates, so the spans are identical. */
INLINE void row_spans_small(__global const TriangleGeometry* t, intV dy, intV* lo_out, intV* hi_out, int lo, int hi) {
  intV lo_v = (intV)lo, hi_v = (intV)hi;
  for (int e = 0; e < 3; ++e) {
    const int a = t->edge_a[e];
    const intV r = small_edge_row(t, e, dy);
    SETTLE_SPAN_EDGE(intV, convert_intV, r, a, edge_reciprocal(a), lo_v, hi_v);
  }
  *lo_out = lo_v;
  *hi_out = hi_v;
}

/* Small triangles (TRIANGLE_SMALL): which of the VEC pixels at columns rel (relative to x0) of row dy
 * are covered, from the edge functions evaluated exactly in 32 bits (triangle_record.h). Cheaper than
 * row_spans when a triangle meets only a few rows of a tile. -1 where covered. */
INLINE intV small_triangle_inside(__global const TriangleGeometry* t, intV rel, int dy) {
  intV inside = (intV)(-1);
  for (int e = 0; e < 3; ++e) {
    const int row = (int)t->edge_c[e] + t->edge_b[e] * dy;
    inside &= ((intV)row + t->edge_a[e] * rel) >= 0;
  }
  return inside;
}

#endif
