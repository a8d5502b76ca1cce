/* Test kernel: how many triangles cover each pixel centre, ignoring depth, with the same tiles and
 * the same row_spans() as render_tiles.cl. The watertightness and coverage tests read it. */
#include "common.h"
#include "triangle_record.h"
#include "span.h"

#define TILE_VECTORS (TILE * SEGMENTS)

/* 1 in the lanes where `mask` (a comparison's -1) is set. Not -mask: LLVM turns that into a zext of the
 * comparisons' i1 lanes, which Oclgrind 21.10 widens to 255 (docs/pipeline.md). */
INLINE uintV ones(intV mask) { return select((uintV)0, (uintV)1, as_uintV(mask)); }

__kernel __attribute__((reqd_work_group_size(1, 1, 1)))
void coverage_count(__global const TriangleGeometry* tris, __global const uint* tile_start,
                    __global const uint* tile_tris, int tiles_x, __global uint* out_count) {
  const int tile = get_global_id(0);
  const int tile_x = (tile % tiles_x) * TILE, tile_y = (tile / tiles_x) * TILE;
  uintV count[TILE_VECTORS];
  for (int i = 0; i < TILE_VECTORS; ++i) count[i] = 0;
  const intV lane = LANE_INDEX;
  int span_lo[VEC], span_hi[VEC];
  for (uint k = tile_start[tile]; k < tile_start[tile + 1]; ++k) {
    __global const TriangleGeometry* t = &tris[tile_tris[k]];
    const int x0 = t->x0, y0 = t->y0;
    const int row_first = max(tile_y, y0), row_last = min(tile_y + TILE - 1, (int)t->y1);
    const int lo = max(tile_x, x0) - x0, hi = min(tile_x + TILE - 1, (int)t->x1) - x0;
    if (row_first > row_last || lo > hi) continue;
    if (t->flags & TRIANGLE_SMALL) { /* the same two paths as render_tiles.cl */
      for (int py = row_first; py <= row_last; ++py)
        for (int s = 0; s < SEGMENTS; ++s) {
          const intV rel = lane + (tile_x + s * VEC - x0);
          const intV inside = small_triangle_inside(t, rel, py - y0) & (rel >= lo) & (rel <= hi);
          count[(py - tile_y) * SEGMENTS + s] += ones(inside);
        }
      continue;
    }
    for (int block = row_first; block <= row_last; block += VEC) {
      intV lo_v, hi_v;
      row_spans(t, lane + (block - y0), &lo_v, &hi_v, lo, hi);
      vstoreV(lo_v, 0, span_lo);
      vstoreV(hi_v, 0, span_hi);
      for (int j = 0; j < min(VEC, row_last - block + 1); ++j) {
        const int py = block + j;
        for (int s = 0; s < SEGMENTS; ++s) {
          const intV rel = lane + (tile_x + s * VEC - x0);
          count[(py - tile_y) * SEGMENTS + s] += ones((rel >= span_lo[j]) & (rel <= span_hi[j]));
        }
      }
    }
  }
  const int pitch = tiles_x * TILE;
  for (int i = 0; i < TILE_VECTORS; ++i)
    vstoreV(count[i], 0, out_count + (size_t)(tile_y + i / SEGMENTS) * pitch + tile_x + (i % SEGMENTS) * VEC);
}
