/* The walk of one triangle of a tile's list: its part of the tile, then the walk of its path (tile_paths.h):
 * the combined method's segment walk, the unit path, the stamps or the rows. */
#ifndef PARASHADE_TILE_WALK_H
#define PARASHADE_TILE_WALK_H

#include "depth_test.h"
#if COMBINED
#include "combined_walk.h"
#endif
#if UNIT_PATH
#include "tile_walk_unit.h"
#elif STAMPS
#include "tile_walk_stamps.h"
#else
#include "tile_walk_rows.h"
#endif

/* The tile's triangles are scattered in memory and their loads stall: the tile loop fetches the record and the
 * attributes (two lines each) PREFETCH_AHEAD triangles ahead. */
INLINE void prefetch_triangle(const FrameArgs* f, uint ti) {
  __global const char* const rec = (__global const char*)&f->tris[ti];
  __global const char* const att = (__global const char*)(f->attrs + (size_t)ti * ATTR_FLOATS);
  PREFETCH_LINE(rec);
  PREFETCH_LINE(rec + 64);
  PREFETCH_LINE(att);
  PREFETCH_LINE(att + 64);
}

/* Triangle ti in the tile whose top-left pixel is (tile_x, tile_y). */
INLINE void walk_triangle(const FrameArgs* f, uint ti, int tile_x, int tile_y, floatV* depth, colourV* cr,
                          colourV* cg, colourV* cb, TileCounts* counts DEFER_DECL) {
  __global const TriangleGeometry* t = &f->tris[ti];
  const int x0 = t->x0, y0 = t->y0;
  const int row_first = max(tile_y, y0), row_last = min(tile_y + TILE - 1, (int)t->y1);
  const int lo = max(tile_x, x0) - x0, hi = min(tile_x + TILE - 1, (int)t->x1) - x0;
  if (row_first > row_last || lo > hi) return;
  __global const float* attr = f->attrs + (size_t)ti * ATTR_FLOATS;
#if COMBINED
  /* Combined Gouraud/Phong (no unit path: the combinations table refuses it): by whole spans, segment ends
   * counted from each span's left pixel, shaded now even in a deferred tile (combined_walk.h; on the stamps a row
   * of stamp lanes at a time); narrow triangles, where it cannot save, by Phong per pixel below, and so are the
   * triangles the per-triangle choice gives to Gouraud (SHADE_PIXELS, SHADE_STAMP_PIXELS, method_combined.h). */
  if (combined_walks(t, attr)) {
    shade_triangle_combined(t, attr, tile_x, tile_y, row_first, row_last, lo, hi, depth, cr, cg, cb, f->lights,
                            f->materials, f->viewer DEFER_ARGS);
    return;
  }
#endif
#if UNIT_PATH
  walk_unit(f, ti, t, attr, tile_x, tile_y, row_first, row_last, lo, hi, depth, cr, cg, cb, counts);
#elif STAMPS
  walk_stamps(f, ti, t, attr, tile_x, tile_y, row_first, row_last, lo, hi, depth, cr, cg, cb DEFER_ARGS);
#else
  walk_rows(f, ti, t, attr, tile_x, tile_y, row_first, row_last, lo, hi, depth, cr, cg, cb, counts);
#endif
}

#endif
