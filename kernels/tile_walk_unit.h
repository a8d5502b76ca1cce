/* The unit path's walk of one triangle in one tile (UNIT_PATH: Gouraud or Phong through a modeled unit,
 * unit_registers.h): every triangle by whole spans, since a unit's registers depend on where its span starts
 * and ends; a span's modeled clocks are counted by the tile that holds its left pixel, so each is counted once. */
#ifndef PARASHADE_TILE_WALK_UNIT_H
#define PARASHADE_TILE_WALK_UNIT_H

#include "unit_registers.h"
#if FIXED && !UNIT_REGISTER_COLOUR
#include "method_phong_units.h"
#endif

/* The whole spans of the triangle's rows block.. (rows of them), relative to its x0. */
INLINE void unit_block_spans(const FrameArgs* f, uint ti, __global const TriangleGeometry* t, int block, int rows,
                             int* span_lo, int* span_hi) {
  const int y0 = t->y0;
#if DDA_COVERAGE
  /* The sources' edge walk: the spans come from the host's row table. */
  for (int j = 0; j < rows; ++j) {
    const int at = 2 * (int)(f->dda_first[ti] + (uint)(block + j - y0));
    span_lo[j] = f->dda_rows[at];
    span_hi[j] = f->dda_rows[at + 1];
  }
#else
  const int x0 = t->x0;
  const intV lane = LANE_INDEX;
  intV lo_v, hi_v;
  if (t->flags & TRIANGLE_SMALL) row_spans_small(t, lane + (block - y0), &lo_v, &hi_v, 0, t->x1 - x0);
  else row_spans(t, lane + (block - y0), &lo_v, &hi_v, 0, t->x1 - x0);
  vstoreV(lo_v, 0, span_lo);
  vstoreV(hi_v, 0, span_hi);
#endif
}

/* The span xl..xr's pixels sl..sr in the tile, row py: depth test, the unit's registers, keep. */
INLINE void shade_unit_span(const FrameArgs* f, uint ti, __global const TriangleGeometry* t, __global const float* attr,
                            int tile_x, int tile_y, int py, int xl, int xr, int sl, int sr, floatV* depth, colourV* cr,
                            colourV* cg, colourV* cb) {
  const int x0 = t->x0, dy = py - t->y0, length = xr - xl + 1;
  const intV lane = LANE_INDEX;
#if FIXED
  SpanRegisters regs;
  load_span_registers(&f->fixed[ti], &f->leaves[ti], xl, xr, dy, &regs);
#endif
  for (int s = (sl + x0 - tile_x) / VEC; s <= (sr + x0 - tile_x) / VEC; ++s) {
    const intV rel = lane + (tile_x + s * VEC - x0);
    const floatV frel = convert_floatV(rel);
    const int slot = (py - tile_y) * SEGMENTS + s;
    const intV pass = depth_test(t, dy, frel, (rel >= sl) & (rel <= sr), &depth[slot] PLAN_ARGS(tile_x + s * VEC));
    if (!any_lanes(pass)) continue;
#if REGISTER_COLOUR
    const intV i = rel - xl;
    keep(pass, unit_register(&regs, 0, i, length), unit_register(&regs, 1, i, length),
         unit_register(&regs, 2, i, length), &cr[slot], &cg[slot], &cb[slot]);
#elif FIXED
    floatV sr_, sg_, sb_;
    shade_unit_normals(&regs, rel - xl, length, attr, dy, frel, &sr_, &sg_, &sb_, f->lights, f->materials, f->viewer);
    keep(pass, sr_, sg_, sb_, &cr[slot], &cg[slot], &cb[slot]);
#else
    floatV sr_, sg_, sb_;
    shade_pixels(attr, dy, frel, &sr_, &sg_, &sb_, f->lights, f->materials, f->viewer);
    keep(pass, sr_, sg_, sb_, &cr[slot], &cg[slot], &cb[slot]);
#endif
  }
}

/* The triangle's rows row_first..row_last and columns lo..hi (from its x0) that lie in the tile. */
INLINE void walk_unit(const FrameArgs* f, uint ti, __global const TriangleGeometry* t, __global const float* attr,
                      int tile_x, int tile_y, int row_first, int row_last, int lo, int hi, floatV* depth, colourV* cr,
                      colourV* cg, colourV* cb, TileCounts* counts) {
  const int x0 = t->x0;
  int span_lo[VEC], span_hi[VEC];
  for (int block = row_first; block <= row_last; block += VEC) {
    const int rows = min(VEC, row_last - block + 1);
    unit_block_spans(f, ti, t, block, rows, span_lo, span_hi);
    for (int j = 0; j < rows; ++j) {
      const int xl = span_lo[j], xr = span_hi[j];
      if (xl > xr) continue;
      const int length = xr - xl + 1;
      const int costs_clocks = unit_span_costs_clocks(&f->leaves[ti]);
      if (costs_clocks && xl + x0 >= tile_x && xl + x0 < tile_x + TILE) {
        counts->spans += 1;
        counts->span_pixels += (ulong)length;
        counts->clocks += (ulong)(SPAN_LOAD_CLOCKS + unit_span_clocks(length));
      }
      const int sl = max(xl, lo), sr = min(xr, hi);
      if (sl > sr) continue;
      shade_unit_span(f, ti, t, attr, tile_x, tile_y, block + j, xl, xr, sl, sr, depth, cr, cg, cb);
    }
  }
}

#endif
