/* The row walk of one triangle in one tile (no unit, no stamps: the planned passes, per-span normalization,
 * --float, or stamps turned off): the spans of VEC rows at once (row_spans, rows as lanes), then each row
 * segment of VEC pixels as vector lanes. */
#ifndef PARASHADE_TILE_WALK_ROWS_H
#define PARASHADE_TILE_WALK_ROWS_H

/* The per-pixel shading of the plain path: the method's, or the combined method's choice per triangle. */
#ifndef SHADE_PIXELS
#define SHADE_PIXELS shade_pixels
#endif

#if SHADE_SPAN
/* Per-span normalization (method_phong.h): a span's setup, once per span and tile, for the tile's pixels
 * first..last of it; counted in the tile's counters. */
#define SPAN_SETUP(attr, dy, xl, xr, first, last) \
  SpanNormals span_n; \
  counts->span_steps += span_setup(&span_n, attr, dy, xl, xr, first, last, tile_x - x0); \
  counts->span_setups += 1; \
  counts->span_fallbacks += span_n.fallback;
#define SPAN_ARGS , &span_n, span_xl, span_xr
#else
#define SPAN_SETUP(attr, dy, xl, xr, first, last)
#define SPAN_ARGS
#endif

/* One row segment of VEC pixels from frame column px: depth test, shade, keep. */
INLINE void shade_segment(const FrameArgs* f, uint ti, __global const TriangleGeometry* t, __global const float* attr,
                          int dy, intV rel, intV inside, int px, int slot, floatV* depth, floatV* cr, floatV* cg,
                          floatV* cb
#if SHADE_SPAN
                          , const SpanNormals* span_ptr, int xl, int xr
#endif
                          ) {
  const floatV frel = convert_floatV(rel);
  const intV pass = depth_test(t, dy, frel, inside, &depth[slot] PLAN_ARGS(px));
  if (!any_lanes(pass)) return;
  floatV sr, sg, sb;
#if SHADE_SPAN
  shade_pixels_span(attr, dy, frel, span_ptr, xl, xr, &sr, &sg, &sb, f->lights, f->materials, f->viewer);
#else
  SHADE_PIXELS(attr, dy, frel, &sr, &sg, &sb, f->lights, f->materials, f->viewer);
#endif
  keep(pass, sr, sg, sb, &cr[slot], &cg[slot], &cb[slot]);
}

/* A small triangle (few rows): each pixel's edge functions tested directly. */
INLINE void walk_rows_small(const FrameArgs* f, uint ti, __global const TriangleGeometry* t, __global const float* attr,
                            int tile_x, int tile_y, int row_first, int row_last, int lo, int hi, floatV* depth,
                            floatV* cr, floatV* cg, floatV* cb, TileCounts* counts) {
  const int x0 = t->x0, y0 = t->y0;
  const intV lane = LANE_INDEX;
  const int seg_first = (lo + x0 - tile_x) / VEC, seg_last = (hi + x0 - tile_x) / VEC;
  for (int py = row_first; py <= row_last; ++py) {
    const int dy = py - y0;
#if SHADE_SPAN
    intV sl_v, sr_v;
    row_spans_small(t, (intV)dy, &sl_v, &sr_v, 0, t->x1 - x0);
    const int span_xl = sl_v.s0, span_xr = sr_v.s0;
    if (span_xl > span_xr) continue;
    SPAN_SETUP(attr, dy, span_xl, span_xr, max(span_xl, lo), min(span_xr, hi))
#endif
    for (int s = seg_first; s <= seg_last; ++s) {
      const intV rel = lane + (tile_x + s * VEC - x0);
      const intV inside = small_triangle_inside(t, rel, dy) & (rel >= lo) & (rel <= hi);
      shade_segment(f, ti, t, attr, dy, rel, inside, tile_x + s * VEC, (py - tile_y) * SEGMENTS + s, depth, cr, cg, cb
                    SPAN_ARGS);
    }
  }
}

/* The triangle's rows row_first..row_last and columns lo..hi (from its x0) that lie in the tile. */
INLINE void walk_rows(const FrameArgs* f, uint ti, __global const TriangleGeometry* t, __global const float* attr,
                      int tile_x, int tile_y, int row_first, int row_last, int lo, int hi, floatV* depth, floatV* cr,
                      floatV* cg, floatV* cb, TileCounts* counts) {
  if (t->flags & TRIANGLE_SMALL) {
    walk_rows_small(f, ti, t, attr, tile_x, tile_y, row_first, row_last, lo, hi, depth, cr, cg, cb, counts);
    return;
  }
  const int x0 = t->x0, y0 = t->y0;
  const intV lane = LANE_INDEX;
  int span_lo[VEC], span_hi[VEC];
  for (int block = row_first; block <= row_last; block += VEC) {
    intV lo_v, hi_v;
#if SHADE_SPAN
    row_spans(t, lane + (block - y0), &lo_v, &hi_v, 0, t->x1 - x0); /* whole spans: their ends matter */
#else
    /* A block the triangle covers whole (large triangles' inner tiles) needs no span search. */
    if (rect_covered(t, lo, hi, block - y0, min(block + VEC - 1, row_last) - y0)) {
      lo_v = (intV)lo;
      hi_v = (intV)hi;
    } else {
      row_spans(t, lane + (block - y0), &lo_v, &hi_v, lo, hi);
    }
#endif
    vstoreV(lo_v, 0, span_lo);
    vstoreV(hi_v, 0, span_hi);
    const int rows = min(VEC, row_last - block + 1);
    for (int j = 0; j < rows; ++j) {
#if SHADE_SPAN
      const int span_xl = span_lo[j], span_xr = span_hi[j];
      const int xl = max(span_xl, lo), xr = min(span_xr, hi);
#else
      const int xl = span_lo[j], xr = span_hi[j];
#endif
      if (xl > xr) continue;
      const int py = block + j;
      SPAN_SETUP(attr, py - y0, span_xl, span_xr, xl, xr)
      for (int s = (xl + x0 - tile_x) / VEC; s <= (xr + x0 - tile_x) / VEC; ++s) {
        const intV rel = lane + (tile_x + s * VEC - x0);
        shade_segment(f, ti, t, attr, py - y0, rel, (rel >= xl) & (rel <= xr), tile_x + s * VEC,
                      (py - tile_y) * SEGMENTS + s, depth, cr, cg, cb SPAN_ARGS);
      }
    }
  }
}

#endif
