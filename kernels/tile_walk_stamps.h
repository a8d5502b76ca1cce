/* The stamp walk of one triangle in one tile (STAMPS, stamp_layout.h): the values per pixel are the row walk's
 * (tile_walk_rows.h), so the image is the same; a small triangle's few pixels fill more of the lanes it shades. */
#ifndef PARASHADE_TILE_WALK_STAMPS_H
#define PARASHADE_TILE_WALK_STAMPS_H

/* A stamp's pixels of one triangle: the method's, or the combined method's choice per triangle (Phong with the
 * triangle's specular mask under HIGHLIGHT_TEST, or Gouraud's planes where its triangle choice says so). */
#if COMBINED
#define SHADE_STAMP_PIXELS shade_points_chosen
#else
#define SHADE_STAMP_PIXELS shade_pixels_at
#endif

/* Whether a deferred tile still shades the triangle in the walk: those that cost less than deferring them (the
 * combined method's Gouraud triangles: three planes). A function, not a constant macro: a constant operand of &&
 * is a warning (an error under PARASHADE_KERNEL_WERROR). */
INLINE bool shaded_in_walk(__global const float* attr) {
#if COMBINED
  return shaded_by_gouraud(attr);
#else
  return false;
#endif
}

/* One stamp: columns rel (from the triangle's x0) and rows dy (from its y0) per lane, `outside` negative in the
 * lanes the triangle does not cover; depth test, shade, keep. The same operations per pixel as shade_segment's, so
 * the same values. The masks are sign bits, as select() and any_lanes() read them: a covered lane passes where
 * z - depth is negative, which is z < depth for finite z (a covered pixel's), the depth infinite or not (equal
 * values give +0). On AVX2, ANDing a compare's 16-lane mask packed it to bytes and back. */
INLINE void shade_stamp(const FrameArgs* f, uint ti, __global const TriangleGeometry* t, __global const float* attr,
                        intV dy, intV rel, intV outside, int slot, floatV* depth, floatV* cr, floatV* cg, floatV* cb
                        DEFER_DECL) {
  const floatV frel = convert_floatV(rel), fdy = convert_floatV(dy);
  const floatV z = depth_lanes(t, fdy, frel);
  const intV pass = ~outside & as_intV(z - depth[slot]);
#if DEFER_STAMPS
  if (deferred && !shaded_in_walk(attr)) { /* two selects: cheaper than asking whether any lane passed */
    depth[slot] = select(depth[slot], z, pass);
    winner[slot] = select(winner[slot], (intV)(int)ti, pass);
    return;
  }
#endif
  if (!SHADE_EVERY_LANE && !shaded_in_walk(attr) && !any_lanes(pass)) return;
  depth[slot] = select(depth[slot], z, pass);
  floatV sr, sg, sb;
  SHADE_STAMP_PIXELS(attr, fdy, frel, &sr, &sg, &sb, f->lights, f->materials, f->viewer);
  keep(pass, sr, sg, sb, &cr[slot], &cg[slot], &cb[slot]);
#if DEFER_STAMPS
  if (deferred) winner[slot] = select(winner[slot], (intV)(-1), pass); /* shaded: no earlier winner left there */
#endif
}

/* A small triangle (few pixels): every stamp of its box, each pixel's edge functions directly. */
INLINE void walk_stamps_small(const FrameArgs* f, uint ti, __global const TriangleGeometry* t,
                              __global const float* attr, int tile_x, int tile_y, int row_first, int row_last, int lo,
                              int hi, floatV* depth, floatV* cr, floatV* cg, floatV* cb DEFER_DECL) {
  const int x0 = t->x0, y0 = t->y0;
  const int sy_first = (row_first - tile_y) / STAMP, sy_last = (row_last - tile_y) / STAMP;
  const int sx_first = (lo + x0 - tile_x) / STAMP, sx_last = (hi + x0 - tile_x) / STAMP;
  for (int sy = sy_first; sy <= sy_last; ++sy) {
    const intV dy = STAMP_ROW + (tile_y + sy * STAMP - y0);
    /* Each bound as a difference that is >= 0 inside (pixel offsets: no overflow), so the lane's tests are
     * one sign test of their OR: on AVX2 each separate 16-lane compare was packed to bytes and back. */
    const intV rows = (dy - (row_first - y0)) | ((row_last - y0) - dy);
    const intV r0 = small_edge_row(t, 0, dy), r1 = small_edge_row(t, 1, dy), r2 = small_edge_row(t, 2, dy);
    for (int sx = sx_first; sx <= sx_last; ++sx) {
      const intV rel = STAMP_COLUMN + (tile_x + sx * STAMP - x0);
      /* Outside where any edge or bound is negative: the sign bit of their OR. */
      const intV outside = (r0 + t->edge_a[0] * rel) | (r1 + t->edge_a[1] * rel) | (r2 + t->edge_a[2] * rel) | rows |
                           (rel - lo) | (hi - rel);
      shade_stamp(f, ti, t, attr, dy, rel, outside, sy * STAMPS_X + sx, depth, cr, cg, cb DEFER_ARGS);
    }
  }
}

/* The triangle's rows row_first..row_last and columns lo..hi (from its x0) that lie in the tile: the spans of the
 * tile's rows, VEC rows at a time, then each stamp's lanes from its four rows. */
INLINE void walk_stamps(const FrameArgs* f, uint ti, __global const TriangleGeometry* t, __global const float* attr,
                        int tile_x, int tile_y, int row_first, int row_last, int lo, int hi, floatV* depth, floatV* cr,
                        floatV* cg, floatV* cb DEFER_DECL) {
  if (t->flags & TRIANGLE_SMALL) {
    walk_stamps_small(f, ti, t, attr, tile_x, tile_y, row_first, row_last, lo, hi, depth, cr, cg, cb DEFER_ARGS);
    return;
  }
  const int x0 = t->x0, y0 = t->y0;
  const intV lane = LANE_INDEX;
  const int sy_first = (row_first - tile_y) / STAMP, sy_last = (row_last - tile_y) / STAMP;
  int span_lo[TILE + VEC], span_hi[TILE + VEC]; /* per row of the tile (and VEC - 1 past it) */
  for (int block = row_first; block <= row_last; block += VEC) {
    intV lo_v = (intV)lo, hi_v = (intV)hi; /* a block the triangle covers whole needs no span search */
    if (!rect_covered(t, lo, hi, block - y0, min(block + VEC - 1, row_last) - y0))
      row_spans(t, lane + (block - y0), &lo_v, &hi_v, lo, hi);
    vstoreV(lo_v, 0, span_lo + (block - tile_y));
    vstoreV(hi_v, 0, span_hi + (block - tile_y));
  }
  for (int sy = sy_first; sy <= sy_last; ++sy) {
    const int r = sy * STAMP;
    /* Rows of the stamp outside the triangle's are empty. */
    int l[STAMP], h[STAMP], left = hi + 1, right = lo - 1;
    for (int j = 0; j < STAMP; ++j) {
      const int py = tile_y + r + j;
      const int in = py >= row_first && py <= row_last;
      l[j] = in ? span_lo[r + j] : 1;
      h[j] = in ? span_hi[r + j] : 0;
      if (l[j] <= h[j]) {
        left = min(left, l[j]);
        right = max(right, h[j]);
      }
    }
    if (left > right) continue;
    const intV lo_s = (intV)(l[0], l[0], l[0], l[0], l[1], l[1], l[1], l[1], l[2], l[2], l[2], l[2], l[3], l[3], l[3], l[3]);
    const intV hi_s = (intV)(h[0], h[0], h[0], h[0], h[1], h[1], h[1], h[1], h[2], h[2], h[2], h[2], h[3], h[3], h[3], h[3]);
    const intV dy = STAMP_ROW + (tile_y + r - y0);
    for (int sx = (left + x0 - tile_x) / STAMP; sx <= (right + x0 - tile_x) / STAMP; ++sx) {
      const intV rel = STAMP_COLUMN + (tile_x + sx * STAMP - x0);
      shade_stamp(f, ti, t, attr, dy, rel, (rel - lo_s) | (hi_s - rel), sy * STAMPS_X + sx, depth, cr, cg, cb
                  DEFER_ARGS);
    }
  }
}

#endif
