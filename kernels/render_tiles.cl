/* Shades one frame. A work-item renders TILE x TILE screen tiles one after another (tiles
 * g, g + G, g + 2G, ... for work-item g of G: few work-items, because PoCL pays a fixed cost per
 * work-group, and interleaved tiles, so every work-item gets a share of the busy screen areas).
 * For each tile it walks the tile's triangle list in primitive order; for each triangle it finds the spans of all
 * its rows in the tile at once (row_spans, rows as vector lanes), then shades each row segment of VEC
 * pixels as vector lanes. Depth and colour of the tile stay in private memory and are written once,
 * so there is no read-modify-write of the frame and the result is deterministic.
 * The method (method_*.h, chosen by the host) supplies shade_pixels(). */
#include "common.h"
#include "triangle_record.h"
#include "span.h"

#define TILE_VECTORS (TILE * SEGMENTS)

/* One row segment of VEC pixels (columns rel from the triangle's x0, row dy from its y0; `inside` marks
 * covered lanes): depth test, shade, keep. */
INLINE void shade_segment(__global const TriangleGeometry* t, __global const float* attr, int dy, intV rel,
                          intV inside, int slot, floatV* depth, floatV* cr, floatV* cg, floatV* cb,
                          __constant float4* lights, __constant float4* materials, float4 viewer) {
  const floatV frel = convert_floatV(rel);
  const floatV z = (floatV)(t->z_ref + t->z_ddy * (float)dy) + t->z_ddx * frel;
  const intV pass = inside & isless(z, depth[slot]);
  if (!any(pass)) return;
  floatV sr, sg, sb;
  shade_pixels(attr, dy, frel, &sr, &sg, &sb, lights, materials, viewer);
  depth[slot] = select(depth[slot], z, pass);
  cr[slot] = select(cr[slot], sr, pass);
  cg[slot] = select(cg[slot], sg, pass);
  cb[slot] = select(cb[slot], sb, pass);
}

__kernel __attribute__((reqd_work_group_size(1, 1, 1)))
void render_tiles(__global const TriangleGeometry* tris, __global const float* attrs,
                  __global const uint* tile_start, __global const uint* tile_tris,
                  __constant float4* lights, __constant float4* materials, float4 viewer, float4 background,
                  int tiles_x, int num_tiles, int width, int height, __global uint* out_rgba,
                  __global float* out_float) {
  for (int tile = get_global_id(0); tile < num_tiles; tile += get_global_size(0)) {
  const int tile_x = (tile % tiles_x) * TILE, tile_y = (tile / tiles_x) * TILE;

  floatV depth[TILE_VECTORS], cr[TILE_VECTORS], cg[TILE_VECTORS], cb[TILE_VECTORS];
  for (int i = 0; i < TILE_VECTORS; ++i) {
    depth[i] = (floatV)INFINITY;
    cr[i] = (floatV)background.x;
    cg[i] = (floatV)background.y;
    cb[i] = (floatV)background.z;
  }
  const intV lane = LANE_INDEX;
  int span_lo[VEC], span_hi[VEC];

  const uint end = tile_start[tile + 1];
  for (uint k = tile_start[tile]; k < end; ++k) {
    const uint ti = tile_tris[k];
    __global const TriangleGeometry* t = &tris[ti];
    const int x0 = t->x0, y0 = t->y0;
    const int row_first = max(tile_y, y0), row_last = min(tile_y + TILE - 1, (int)t->y1);
    const int lo = max(tile_x, x0) - x0, hi = min(tile_x + TILE - 1, (int)t->x1) - x0;
    if (row_first > row_last || lo > hi) continue;
    __global const float* attr = attrs + (size_t)ti * ATTR_FLOATS;
    const int seg_first = (lo + x0 - tile_x) / VEC, seg_last = (hi + x0 - tile_x) / VEC;
    if (t->flags & TRIANGLE_SMALL) {
      /* Few rows: test each pixel's edge functions directly. */
      for (int py = row_first; py <= row_last; ++py) {
        const int dy = py - y0;
        for (int s = seg_first; s <= seg_last; ++s) {
          const intV rel = lane + (tile_x + s * VEC - x0);
          const intV inside = small_triangle_inside(t, rel, dy) & (rel >= lo) & (rel <= hi);
          shade_segment(t, attr, dy, rel, inside, (py - tile_y) * SEGMENTS + s, depth, cr, cg, cb, lights, materials,
                        viewer);
        }
      }
      continue;
    }
    for (int block = row_first; block <= row_last; block += VEC) {
      intV lo_v, hi_v;
      row_spans(t, lane + (block - y0), &lo_v, &hi_v, lo, hi);
      vstoreV(lo_v, 0, span_lo);
      vstoreV(hi_v, 0, span_hi);
      const int rows = min(VEC, row_last - block + 1);
      for (int j = 0; j < rows; ++j) {
        const int xl = span_lo[j], xr = span_hi[j];
        if (xl > xr) continue;
        const int py = block + j;
        for (int s = (xl + x0 - tile_x) / VEC; s <= (xr + x0 - tile_x) / VEC; ++s) {
          const intV rel = lane + (tile_x + s * VEC - x0);
          shade_segment(t, attr, py - y0, rel, (rel >= xl) & (rel <= xr), (py - tile_y) * SEGMENTS + s, depth, cr, cg,
                        cb, lights, materials, viewer);
        }
      }
    }
  }

  /* The frame is width x height exactly (no padding), so the host can use it without a copy. */
  for (int i = 0; i < TILE_VECTORS; ++i) {
    const int y = tile_y + i / SEGMENTS, x = tile_x + (i % SEGMENTS) * VEC;
    if (y >= height || x >= width) continue;
    const size_t at = (size_t)y * width + x;
    const uintV covered = convert_uintV(isless(depth[i], (floatV)INFINITY)) & 0xFF000000u;
    const uintV rgba = to_level(cr[i]) | (to_level(cg[i]) << 8) | (to_level(cb[i]) << 16) | covered;
    if (x + VEC <= width) {
      vstoreV(rgba, 0, out_rgba + at);
    } else {
      uint lanes[VEC];
      vstoreV(rgba, 0, lanes);
      for (int l = 0; l < width - x; ++l) out_rgba[at + l] = lanes[l];
    }
#if OUTPUT_FLOAT
    const size_t plane = (size_t)width * height;
    float fr[VEC], fg[VEC], fb[VEC];
    vstoreV(cr[i], 0, fr);
    vstoreV(cg[i], 0, fg);
    vstoreV(cb[i], 0, fb);
    for (int l = 0; l < min(VEC, width - x); ++l) {
      out_float[at + l] = fr[l];
      out_float[plane + at + l] = fg[l];
      out_float[2 * plane + at + l] = fb[l];
    }
#endif
  }
  }
}
