/* The combined method's segments at one pixel (the lanes shape; combined_walk.h walks them a row of spans at a
 * time): the row's whole span [xl, xr] (segments count from xl), the segment length 2^K of the row, the exact
 * Blinn-Phong at the two ends of the pixel's segment and the linear step between them, each as combined_walk.h
 * computes it for that row and pixel, so the same value. */
#ifndef PARASHADE_LANES_SEGMENTS_H
#define PARASHADE_LANES_SEGMENTS_H

INLINE void shade_segment_pixel(__global const TriangleGeometry* t, __global const float* a, int dy, int rel, float* r,
                                float* g, float* b, __constant float4* lights, __constant float4* materials,
                                float4 viewer) {
#if TRIANGLE_CHOICE
  const float psi_limit = a[PHONG_PSI_SLOT];
#else
  const float psi_limit = materials[3 * (int)a[PHONG_MATERIAL_SLOT] + 2].w;
#endif
  int xl, xr;
  if (t->flags & TRIANGLE_SMALL) row_spans_small(t, dy, &xl, &xr, 0, t->x1 - t->x0);
  else row_spans(t, dy, &xl, &xr, 0, t->x1 - t->x0);
  const float fdy = (float)dy;
  const int k = segment_log2(a, fdy, xl, xr, psi_limit);
  const int i = rel - xl, start = xl + ((i >> k) << k);
  float ar, ag, ab, br, bg, bb;
  shade_points(a, fdy, (float)start, &ar, &ag, &ab, lights, materials, viewer);
  shade_points(a, fdy, (float)(start + (1 << k)), &br, &bg, &bb, lights, materials, viewer);
  const float w = (float)(i & ((1 << k) - 1)) * (1.0f / (float)(1 << k));
  *r = ar + (br - ar) * w;
  *g = ag + (bg - ag) * w;
  *b = ab + (bb - ab) * w;
}

#endif
