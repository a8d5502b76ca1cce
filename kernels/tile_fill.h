/* A tile's first triangles before its walk (TILE_FILL: the stamps of the plain frame, not the combined method):
 * those that miss the tile wholly are skipped, and when the next covers all of it, its depth and shading are
 * written to every stamp without the clear, the depth test or the spans; otherwise the tile is cleared and walked
 * as before. A covered tile that no later triangle meets is written straight to the frame (flat, Gouraud; Phong
 * fills a deferred tile's depth and winners only). The same operations per pixel as shade_stamp's on a cleared
 * tile, where every lane passes (a covered pixel's z is finite, below the clear's INFINITY), so the same values:
 * only the clear and the coverage work are saved, which is most of a large triangle's cost (the full-screen quad). */
#ifndef PARASHADE_TILE_FILL_H
#define PARASHADE_TILE_FILL_H

/* Whether some edge is negative over the whole rectangle (columns lo..hi, rows dy_lo..dy_hi from the triangle's
 * x0, y0): the triangle covers none of its pixels. rect_covered's counterpart (span.h). */
INLINE int rect_missed(__global const TriangleGeometry* t, int lo, int hi, int dy_lo, int dy_hi) {
  for (int e = 0; e < 3; ++e) {
    const long a = t->edge_a[e], b = t->edge_b[e];
    if ((long)t->edge_c[e] + max(a * lo, a * hi) + max(b * dy_lo, b * dy_hi) < 0) return 1;
  }
  return 0;
}

#define TILE_MISSED 0
#define TILE_COVERED 1
#define TILE_PARTLY 2

/* How triangle t meets the tile at (tile_x, tile_y). Covered needs the tile inside the triangle's box, which is
 * clamped to the screen, so a tile over the screen's edge is never covered. */
INLINE int tile_cover(__global const TriangleGeometry* t, int tile_x, int tile_y) {
  const int x0 = t->x0, y0 = t->y0, last_x = tile_x + TILE - 1, last_y = tile_y + TILE - 1;
  if (x0 > last_x || t->x1 < tile_x || y0 > last_y || t->y1 < tile_y) return TILE_MISSED;
  const int lo = tile_x - x0, hi = last_x - x0, dy_lo = tile_y - y0, dy_hi = last_y - y0;
  if (rect_missed(t, lo, hi, dy_lo, dy_hi)) return TILE_MISSED;
  const int boxed = x0 <= tile_x && t->x1 >= last_x && y0 <= tile_y && t->y1 >= last_y;
  return boxed && rect_covered(t, lo, hi, dy_lo, dy_hi) ? TILE_COVERED : TILE_PARTLY;
}

/* Triangle ti's depth and shading at every pixel of the tile; with DEFER_STAMPS (Phong, a deferred tile only) its
 * depth and ti as every pixel's winner, shaded after the walk: Phong's shading is not compiled here again, which
 * would cost its build time (24 lights: 18 -> 25 s cold on PoCL). */
INLINE void fill_tile(const FrameArgs* f, uint ti, int tile_x, int tile_y, floatV* depth, colourV* cr, colourV* cg,
                      colourV* cb DEFER_DECL) {
  __global const TriangleGeometry* t = &f->tris[ti];
  __global const float* attr = f->attrs + (size_t)ti * ATTR_FLOATS;
  for (int sy = 0; sy < TILE / STAMP; ++sy) {
    const floatV fdy = convert_floatV(STAMP_ROW + (tile_y + sy * STAMP - t->y0));
    for (int sx = 0; sx < STAMPS_X; ++sx) {
      const floatV frel = convert_floatV(STAMP_COLUMN + (tile_x + sx * STAMP - t->x0));
      const int slot = sy * STAMPS_X + sx;
      depth[slot] = depth_lanes(t, fdy, frel);
#if DEFER_STAMPS
      winner[slot] = (intV)(int)ti;
#else
      SHADE_STAMP_PIXELS(attr, fdy, frel, &cr[slot], &cg[slot], &cb[slot], f->lights, f->materials, f->viewer);
#endif
    }
  }
}

/* Whether every triangle of the tile's list from k on misses the tile. */
INLINE int rest_missed(const FrameArgs* f, uint k, uint end, int tile_x, int tile_y) {
  for (; k < end; ++k)
    if (tile_cover(&f->tris[f->tile_tris[k]], tile_x, tile_y) != TILE_MISSED) return 0;
  return 1;
}

#if !DEFER_STAMPS
/* A tile that triangle ti alone covers (flat, Gouraud): shaded and written straight to the frame a row segment at a time, without
 * the tile's arrays; each pixel's depth and colour as fill_tile's (the same planes at the same offsets), packed as
 * write_tile packs them. The tile lies inside the triangle's box, so inside the screen. */
INLINE void write_covered_tile(const FrameArgs* f, uint ti, int tile_x, int tile_y) {
  __global const TriangleGeometry* t = &f->tris[ti];
  __global const float* attr = f->attrs + (size_t)ti * ATTR_FLOATS;
  for (int row = 0; row < TILE; ++row) {
    const floatV fdy = convert_floatV((intV)(tile_y + row - t->y0));
    /* The row's segments are all shaded before any is stored: to the compiler a store to the frame might change
     * the planes, which it would then read again for every segment (a quarter of the quad's kernel). */
    uintV rgba[SEGMENTS];
#pragma unroll
    for (int s = 0; s < SEGMENTS; ++s) {
      const floatV frel = convert_floatV(LANE_INDEX + (tile_x + s * VEC - t->x0));
      const floatV z = depth_lanes(t, fdy, frel);
      floatV r, g, b;
      SHADE_STAMP_PIXELS(attr, fdy, frel, &r, &g, &b, f->lights, f->materials, f->viewer);
      rgba[s] = pixels_rgba(z, r, g, b);
    }
#pragma unroll
    for (int s = 0; s < SEGMENTS; ++s)
      write_frame_segment(rgba[s], f->out_rgba, tile_x + s * VEC, tile_y + row, f->width);
  }
}
#endif

/* The tile's list from `begin`: the triangles that miss it skipped; then the next, when it covers the tile, written
 * straight to the frame if no later one meets the tile (flat, Gouraud), else filled in (Phong: in a deferred tile);
 * else the tile cleared. Returns where the walk goes on; *done when the tile is written already (every triangle
 * missed it: the background). */
INLINE uint fill_or_clear(const FrameArgs* f, uint begin, uint end, int tile_x, int tile_y, floatV* depth,
                          colourV* cr, colourV* cg, colourV* cb, int* done DEFER_DECL) {
  uint k = begin;
  int cover = TILE_MISSED;
  while (k < end && (cover = tile_cover(&f->tris[f->tile_tris[k]], tile_x, tile_y)) == TILE_MISSED) ++k;
  *done = 1;
  if (k == end) {
    write_background_tile(f, tile_x, tile_y);
    return end;
  }
#if DEFER_STAMPS
  const int fills = cover == TILE_COVERED && deferred;
#else
  if (cover == TILE_COVERED && rest_missed(f, k + 1, end, tile_x, tile_y)) {
    write_covered_tile(f, f->tile_tris[k], tile_x, tile_y);
    return end;
  }
  const int fills = cover == TILE_COVERED;
#endif
  *done = 0;
  if (fills) {
    fill_tile(f, f->tile_tris[k], tile_x, tile_y, depth, cr, cg, cb DEFER_ARGS);
    return k + 1;
  }
  clear_tile(depth, cr, cg, cb, f->background DEFER_ARGS);
  return k;
}

#endif
