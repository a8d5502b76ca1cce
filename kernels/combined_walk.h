/* The combined method's walk of one triangle in one tile (method_combined.h), included by
 * tile_walk.h after depth_test() and keep() (depth_test.h). Per block of VEC rows (rows as lanes):
 * 1. each row's whole span [xl, xr] (segment ends are counted from xl, so a span crossing tiles
 *    gives the same pixels in every tile) and its part [sl, sr] in the tile;
 * 2. rows with no pixel passing the depth test are dropped (occluded triangles cost no shading);
 * 3. the exact intensity at the segment ends the tile needs, one vector of rows per end column;
 * 4. per row: depth test and the linear interpolation between the two ends of each pixel's segment.
 * The same operations per pixel on the stamps as on row segments, so the same image; under DEFER_STAMPS a pixel
 * shaded here leaves no winner for the deferred tile's pass. */
#ifndef PARASHADE_COMBINED_WALK_H
#define PARASHADE_COMBINED_WALK_H

/* The walk's view of the tile: row r of the tile, its VEC pixels from column s * VEC. In the row layout that is
 * one vector of the tile's arrays; on the stamps (STAMPS) it is lane row r % STAMP of VEC / STAMP stamps side by
 * side, read and written four lanes at a time. (Walking the stamps themselves, each stamp's four rows
 * from their own segment ends, was slower than this view: sphere combined:auto kernel about 1.03-1.05x,
 * bench/README.md run AA.) */
#if STAMPS
INLINE floatV walk_load(const floatV* a, int r, int s) {
  const float* f = (const float*)(a + (r / STAMP) * STAMPS_X + s * (VEC / STAMP)) + (r % STAMP) * STAMP;
  return (floatV)(vload4(0, f), vload4(0, f + VEC), vload4(0, f + 2 * VEC), vload4(0, f + 3 * VEC));
}
INLINE void walk_store(floatV* a, int r, int s, floatV v) {
  float* f = (float*)(a + (r / STAMP) * STAMPS_X + s * (VEC / STAMP)) + (r % STAMP) * STAMP;
  vstore4(v.s0123, 0, f);
  vstore4(v.s4567, 0, f + VEC);
  vstore4(v.s89ab, 0, f + 2 * VEC);
  vstore4(v.scdef, 0, f + 3 * VEC);
}
#else
INLINE floatV walk_load(const floatV* a, int r, int s) { return a[r * SEGMENTS + s]; }
INLINE void walk_store(floatV* a, int r, int s, floatV v) { a[r * SEGMENTS + s] = v; }
#endif

/* 2. Visible rows of the block from row `block` (rows of them; their parts sl..sr in the tile, relative to x0):
 * a pixel in the tile passes the depth test (the test proper comes in step 4). Returns whether any row is. */
INLINE int visible_rows(__global const TriangleGeometry* t, int tile_x, int tile_y, int block, int rows,
                        const int* sl_, const int* sr_, const floatV* depth, int* visible_) {
  const int x0 = t->x0, y0 = t->y0;
  const intV lane = LANE_INDEX;
  int any_visible = 0;
  for (int j = 0; j < VEC; ++j) {
    int vis = 0;
    if (j < rows && sl_[j] <= sr_[j]) {
      const int py = block + j;
      for (int s = (sl_[j] + x0 - tile_x) / VEC; s <= (sr_[j] + x0 - tile_x) / VEC && !vis; ++s) {
        const intV rel = lane + (tile_x + s * VEC - x0);
        const floatV z = (floatV)(t->z_ref + t->z_ddy * (float)(py - y0)) + t->z_ddx * convert_floatV(rel);
        vis = any_lanes((rel >= sl_[j]) & (rel <= sr_[j]) & isless(z, walk_load(depth, py - tile_y, s)));
      }
    }
    visible_[j] = vis;
    any_visible |= vis;
  }
  return any_visible;
}

/* 4. Row py (lane j of its block; span from row_xl, its part row_sl..row_sr in the tile, segments of 2^kj pixels
 * from segment first): I = I_a + (I_b - I_a) * v / 2^K between the ends of each pixel's segment. */
INLINE void interpolate_row(__global const TriangleGeometry* t, int tile_x, int tile_y, int py, int j, int kj,
                            int row_xl, int row_sl, int row_sr, int first, const float* end_r, const float* end_g,
                            const float* end_b, floatV* depth, floatV* cr, floatV* cg, floatV* cb DEFER_DECL) {
  const int x0 = t->x0, y0 = t->y0;
  const intV lane = LANE_INDEX;
  const float step = 1.0f / (float)(1 << kj);
  for (int s = (row_sl + x0 - tile_x) / VEC; s <= (row_sr + x0 - tile_x) / VEC; ++s) {
    const intV rel = lane + (tile_x + s * VEC - x0);
    const int r = py - tile_y;
    floatV d = walk_load(depth, r, s);
    const intV pass = depth_test(t, py - y0, convert_floatV(rel), (rel >= row_sl) & (rel <= row_sr), &d);
    if (!any_lanes(pass)) continue;
    walk_store(depth, r, s, d);
    const intV i = rel - row_xl;
    const intV column = (i >> kj) - first;
    const floatV w = convert_floatV(i & ((1 << kj) - 1)) * step;
    /* The columns the chunk's covered lanes use (lanes are in increasing x). */
    const int c_lo = ((max(row_sl, tile_x + s * VEC - x0) - row_xl) >> kj) - first;
    const int c_hi = ((min(row_sr, tile_x + s * VEC + VEC - 1 - x0) - row_xl) >> kj) - first;
    floatV ar = 0.0f, ag = 0.0f, ab = 0.0f, br = 0.0f, bg = 0.0f, bb = 0.0f;
    for (int c = c_lo; c <= c_hi; ++c) {
      const intV here = column == c;
      ar = select(ar, (floatV)end_r[c * VEC + j], here);
      ag = select(ag, (floatV)end_g[c * VEC + j], here);
      ab = select(ab, (floatV)end_b[c * VEC + j], here);
      br = select(br, (floatV)end_r[(c + 1) * VEC + j], here);
      bg = select(bg, (floatV)end_g[(c + 1) * VEC + j], here);
      bb = select(bb, (floatV)end_b[(c + 1) * VEC + j], here);
    }
    floatV kr = walk_load(cr, r, s), kg = walk_load(cg, r, s), kb = walk_load(cb, r, s);
    keep(pass, ar + (br - ar) * w, ag + (bg - ag) * w, ab + (bb - ab) * w, &kr, &kg, &kb);
    walk_store(cr, r, s, kr);
    walk_store(cg, r, s, kg);
    walk_store(cb, r, s, kb);
#if DEFER_STAMPS
    if (deferred) { /* the winners (ints) through the same view: no earlier winner left at these pixels */
      const intV left = select(as_intV(walk_load((const floatV*)winner, r, s)), (intV)(-1), pass);
      walk_store((floatV*)winner, r, s, as_floatV(left));
    }
#endif
  }
}

INLINE void shade_triangle_combined(__global const TriangleGeometry* t, __global const float* attr, int tile_x,
                                    int tile_y, int row_first, int row_last, int lo, int hi, floatV* depth,
                                    floatV* cr, floatV* cg, floatV* cb, __constant float4* lights,
                                    __constant float4* materials, float4 viewer DEFER_DECL) {
  const int x0 = t->x0, y0 = t->y0;
  const intV lane = LANE_INDEX;
#if TRIANGLE_CHOICE
  const float psi_limit = attr[PHONG_PSI_SLOT];
#else
  const float psi_limit = materials[3 * (int)attr[PHONG_MATERIAL_SLOT] + 2].w;
#endif
  int xl_[VEC], xr_[VEC], sl_[VEC], sr_[VEC], k_[VEC], first_[VEC], visible_[VEC];
  float end_r[SEG_END_COLUMNS * VEC], end_g[SEG_END_COLUMNS * VEC], end_b[SEG_END_COLUMNS * VEC];
  for (int block = row_first; block <= row_last; block += VEC) {
    /* 1. The rows' whole spans and their parts in the tile. */
    const int rows = min(VEC, row_last - block + 1);
    const intV dy = lane + (block - y0);
    intV xl, xr;
    if (t->flags & TRIANGLE_SMALL) row_spans_small(t, dy, &xl, &xr, 0, t->x1 - x0);
    else row_spans(t, dy, &xl, &xr, 0, t->x1 - x0);
    const intV sl = max(xl, (intV)lo), sr = min(xr, (intV)hi);
    vstoreV(xl, 0, xl_);
    vstoreV(xr, 0, xr_);
    vstoreV(sl, 0, sl_);
    vstoreV(sr, 0, sr_);
    if (!visible_rows(t, tile_x, tile_y, block, rows, sl_, sr_, depth, visible_)) continue;

    /* 3. End columns: row j needs ends m = first_j .. last_j + 1 of its segments (m counted from xl). */
    const floatV fdy = convert_floatV(dy);
    const intV k = segment_log2(attr, fdy, xl, xr, psi_limit);
    const intV first = (sl - xl) >> k;
    vstoreV(k, 0, k_);
    vstoreV(first, 0, first_);
    int columns = 0;
    for (int j = 0; j < VEC; ++j)
      if (visible_[j]) columns = max(columns, ((sr_[j] - xl_[j]) >> k_[j]) - first_[j] + 2);
    for (int c = 0; c < columns; ++c) {
      const intV at = xl + ((first + c) << k);
      floatV r, g, b;
      shade_points(attr, fdy, convert_floatV(at), &r, &g, &b, lights, materials, viewer);
      vstoreV(r, 0, end_r + c * VEC);
      vstoreV(g, 0, end_g + c * VEC);
      vstoreV(b, 0, end_b + c * VEC);
    }

    for (int j = 0; j < rows; ++j)
      if (visible_[j])
        interpolate_row(t, tile_x, tile_y, block + j, j, k_[j], xl_[j], sl_[j], sr_[j], first_[j], end_r, end_g, end_b,
                        depth, cr, cg, cb DEFER_ARGS);
  }
}

#endif
