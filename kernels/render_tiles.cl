/* Shades one frame. A work-item renders TILE x TILE screen tiles one after another (tiles
 * g, g + G, g + 2G, ... for work-item g of G: few work-items, because PoCL pays a fixed cost per
 * work-group, and interleaved tiles, so every work-item gets a share of the busy screen areas).
 * For each tile it walks the tile's triangle list in primitive order; for each triangle it finds the spans of all
 * its rows in the tile at once (row_spans, rows as vector lanes), then shades each row segment of VEC
 * pixels as vector lanes. Depth and colour of the tile stay in private memory and are written once,
 * so there is no read-modify-write of the frame and the result is deterministic.
 * The method (method_*.h, chosen by the host) supplies shade_pixels().
 * UNIT_PATH = 1 (Gouraud or Phong through a modeled unit, unit_registers.h): every triangle is walked by
 * whole spans, each span's registers come from its full extent, and the tile that holds a span's
 * left pixel counts its modeled clocks into tile_counters (spans, pixels, clocks per tile).
 * STAMPS = 1 (the plain path only: no unit, combined method, per-span normalization or plan): the tile's
 * pixels are 4x4 stamps instead of 1xVEC row segments (lane l: row l / 4, column l % 4), so a small
 * triangle's few pixels fill more of the lanes it shades; the values per pixel are the same. */
#include "common.h"
#include "triangle_record.h"
#include "span.h"
#include "fixed_point.h"
#include "sierpinski_leaf.h"
#if UNIT_PATH
#include "unit_registers.h"
#if FIXED && !UNIT_REGISTER_COLOUR
#include "method_phong_units.h"
#endif
#endif
/* Gouraud's fixed-point unit keeps its registers as the colour until the output rounds them, in int
 * vectors: their bits as floats would be denormals and NaNs, which a device may flush or quieten
 * (Oclgrind's select() sets the quiet bit of a signalling NaN; docs/pipeline.md). */
#define REGISTER_COLOUR (UNIT_PATH && FIXED && UNIT_REGISTER_COLOUR)
#if REGISTER_COLOUR
typedef intV colourV;
#else
typedef floatV colourV;
#endif
#ifndef COMBINED
#define COMBINED 0
#endif

#define TILE_VECTORS (TILE * SEGMENTS)
#ifndef STAMPS
#define STAMPS 0
#endif
/* The combined method on the stamps: per pixel (Phong with the triangle's specular mask under HIGHLIGHT_TEST, or
 * where the per-triangle choice says so Gouraud's planes) in stamps, and its segment walk (combined_walk.h) by rows
 * of stamp lanes. */
#if STAMPS && (PLAN_PASS || UNIT_PATH || SHADE_SPAN || OUTPUT_FLOAT)
#error "STAMPS: the plain path only"
#endif
/* Stamps: STAMP x STAMP pixels, STAMPS_X of them across a tile (TILE_VECTORS in all, as row segments). */
#define STAMP 4
#define STAMPS_X (TILE / STAMP)
#define STAMP_ROW ((intV)(0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3))
#define STAMP_COLUMN ((intV)(0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3))
/* Triangles ahead whose record and attributes the tile loop prefetches. */
#ifndef PREFETCH_AHEAD
#define PREFETCH_AHEAD 4
#endif

/* PLAN_PASS (docs/planner.md): 0 the plain frame; 1 the modeled units' depth pass, each unit walking its
 * own work lists and keeping per pixel the least key (depth, primitive index) by an atomic minimum;
 * 2 the resolve, which shades at each pixel only the triangle whose key won. The least key is what
 * the plain frame's in-order strict depth test keeps, whatever the order the units ran in. */
#ifndef PLAN_PASS
#define PLAN_PASS 0
#endif
#if PLAN_PASS
#pragma OPENCL EXTENSION cl_khr_int64_extended_atomics : enable
#define PLAN_DECL , uint ti, int px, __global ulong* keys, int width
#define PLAN_ARGS(px_) , ti, (px_), keys, width
#include "plan_key.h"
#else
#define PLAN_DECL
#define PLAN_ARGS(px_)
#endif

/* Depth test of one row segment of VEC pixels (columns rel from the triangle's x0, row dy from its y0;
 * `inside` marks covered lanes): the lanes that pass, their depth kept. */
INLINE intV depth_test(__global const TriangleGeometry* t, int dy, floatV frel, intV inside, floatV* depth PLAN_DECL) {
  const floatV z = (floatV)(t->z_ref + t->z_ddy * (float)dy) + t->z_ddx * frel;
#if PLAN_PASS == 1
  /* Within one unit's list (primitive order) only a strictly nearer pixel can still win. */
  const intV nearer = inside & isless(z, *depth);
  *depth = select(*depth, z, nearer);
  plan_offer_keys(z, nearer, ti, keys + (size_t)(t->y0 + dy) * width + px);
  return (intV)0;
#else
#if PLAN_PASS == 2
  const intV pass = inside & plan_won(ti, keys + (size_t)(t->y0 + dy) * width + px, inside);
#else
  const intV pass = inside & isless(z, *depth);
#endif
  *depth = select(*depth, z, pass);
  return pass;
#endif
}

INLINE void keep(intV pass, colourV sr, colourV sg, colourV sb, colourV* cr, colourV* cg, colourV* cb) {
  *cr = select(*cr, sr, pass);
  *cg = select(*cg, sg, pass);
  *cb = select(*cb, sb, pass);
}

#if SHADE_SPAN
/* Per-span normalization (method_phong.h): a span's setup, once per span and tile, for the tile's
 * pixels first..last of it; its end normals, the fallback count and a sequential unit's steps (spans,
 * fallbacks, steps) go to tile_counters. */
#define SPAN_SETUP(attr, dy, xl, xr, first, last) \
  SpanNormals span_n; \
  span_steps += span_setup(&span_n, attr, dy, xl, xr, first, last, tile_x - x0); \
  span_setups += 1; \
  span_fallbacks += span_n.fallback;
#define SPAN_ARGS , &span_n, span_xl, span_xr
#else
#define SPAN_SETUP(attr, dy, xl, xr, first, last)
#define SPAN_ARGS
#endif
/* The per-pixel shading of the plain path: the method's, or the combined method's choice per triangle. */
#ifndef SHADE_PIXELS
#define SHADE_PIXELS shade_pixels
#endif

#if !UNIT_PATH
/* One row segment of VEC pixels: depth test, shade, keep. */
INLINE void shade_segment(__global const TriangleGeometry* t, __global const float* attr, int dy, intV rel,
                          intV inside, int slot, floatV* depth, floatV* cr, floatV* cg, floatV* cb,
                          __constant float4* lights, __constant float4* materials, float4 viewer PLAN_DECL
#if SHADE_SPAN
                          , const SpanNormals* span_ptr, int xl, int xr
#endif
                          ) {
  const floatV frel = convert_floatV(rel);
  const intV pass = depth_test(t, dy, frel, inside, &depth[slot] PLAN_ARGS(px));
  if (!any_lanes(pass)) return;
  floatV sr, sg, sb;
#if SHADE_SPAN
  shade_pixels_span(attr, dy, frel, span_ptr, xl, xr, &sr, &sg, &sb, lights, materials, viewer);
#else
  SHADE_PIXELS(attr, dy, frel, &sr, &sg, &sb, lights, materials, viewer);
#endif
  keep(pass, sr, sg, sb, &cr[slot], &cg[slot], &cb[slot]);
}
#endif

#ifndef SHADE_EVERY_LANE
#define SHADE_EVERY_LANE 0
#endif
#ifndef DEFER_STAMPS
#define DEFER_STAMPS 0
#endif
#if DEFER_STAMPS
/* Deferred stamps (Phong): in a tile of at least DEFER_MIN_TRIANGLES triangles the walk only keeps, per pixel,
 * the record of the triangle that passed its depth test last (winner), and each pixel is shaded once after
 * the walk by that triangle: what the walk would have kept, without shading the pixels overwritten later or
 * a stamp's uncovered lanes once per triangle. */
#define DEFER_DECL , uint ti, intV* winner, int deferred
#define DEFER_ARGS , ti, winner, deferred
#else
#define DEFER_DECL
#define DEFER_ARGS
#endif

#if COMBINED
#include "combined_walk.h"
#endif

#if STAMPS
/* A stamp's pixels of one triangle; a deferred tile still shades in the walk the triangles that cost less than
 * deferring them (the combined method's Gouraud triangles: three planes). */
#if COMBINED
#define SHADE_STAMP_PIXELS shade_points_chosen
#define SPECULAR_NEEDED(attr) (HIGHLIGHT_TEST ? (int)(attr)[PHONG_HIGHLIGHT_SLOT] : -1)
#else
#define SHADE_STAMP_PIXELS shade_pixels_at
#define SPECULAR_NEEDED(attr) (-1)
#endif
/* A function, not a constant macro: a constant operand of && is a warning (an error under PARASHADE_KERNEL_WERROR). */
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
INLINE void shade_stamp(__global const TriangleGeometry* t, __global const float* attr, intV dy, intV rel, intV outside,
                        int slot, floatV* depth, floatV* cr, floatV* cg, floatV* cb, __constant float4* lights,
                        __constant float4* materials, float4 viewer DEFER_DECL) {
  const floatV frel = convert_floatV(rel), fdy = convert_floatV(dy);
  const floatV z = (t->z_ref + t->z_ddy * fdy) + t->z_ddx * frel;
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
  SHADE_STAMP_PIXELS(attr, fdy, frel, &sr, &sg, &sb, lights, materials, viewer);
  keep(pass, sr, sg, sb, &cr[slot], &cg[slot], &cb[slot]);
#if DEFER_STAMPS
  if (deferred) winner[slot] = select(winner[slot], (intV)(-1), pass); /* shaded: no earlier winner left there */
#endif
}

#if DEFER_STAMPS
/* The deferred tile's pixels, a stamp at a time, each by its winner. A stamp of one winner is shaded from its
 * planes, as the walk would. A stamp whose pixels have several winners of one material is shaded once with each
 * lane's planes and specular mask gathered from its own triangle (lanes without a winner repeat a covered
 * lane's and are not kept); otherwise each winner shades its own lanes from its planes. */
#define DEFER_PLANE_FLOATS 18 /* the normal and position planes: slots 0..17 */
INLINE void shade_winners(const intV* winner, floatV* cr, floatV* cg, floatV* cb, __global const TriangleGeometry* tris,
                          __global const float* attrs, int tile_x, int tile_y, __constant float4* lights,
                          __constant float4* materials, float4 viewer) {
  for (int i = 0; i < TILE_VECTORS; ++i) {
    const int only = max_lane(winner[i]);
    if (only < 0) continue; /* no winner: every lane -1 */
    const intV won = ~winner[i]; /* sign bits: the lanes with a winner */
    const int x = tile_x + (i % STAMPS_X) * STAMP, y = tile_y + (i / STAMPS_X) * STAMP;
    floatV sr, sg, sb;
    /* Winners are 0..only, so a lane with another winner than `only` has winner - only < 0 and winner >= 0. */
    if (!any_lanes(won & (winner[i] - only))) {
      /* One triangle won every lane that has a winner (inside and along the edges of large triangles, most
       * stamps): shade it as the scan below would, without the scan. */
      __global const TriangleGeometry* t = &tris[only];
      SHADE_STAMP_PIXELS(attrs + (size_t)only * ATTR_FLOATS, convert_floatV(STAMP_ROW + (y - t->y0)),
                         convert_floatV(STAMP_COLUMN + (x - t->x0)), &sr, &sg, &sb, lights, materials, viewer);
      keep(won, sr, sg, sb, &cr[i], &cg[i], &cb[i]);
      continue;
    }
    int ids[VEC];
    vstoreV(winner[i], 0, ids);
    /* The stamp's winners (two or more here), once each, in the order their first lanes come: the lowest lane
     * not yet taken, then all its winner's lanes taken (one pass per winner, no scan of lanes by lanes). */
    int winners[VEC], count = 0;
    for (uint todo = lane_bits(won); todo != 0;) {
      const int id = ids[31 - clz(todo & (0u - todo))];
      winners[count++] = id;
      /* Its records are read below, after the list is complete: their loads (often misses on small
       * triangles) start now. */
      PREFETCH_LINE(attrs + (size_t)id * ATTR_FLOATS);
      PREFETCH_LINE(attrs + (size_t)id * ATTR_FLOATS + PHONG_MATERIAL_SLOT);
      PREFETCH_LINE(&tris[id].y0);
      todo &= ~lane_bits(winner[i] == (intV)id);
    }
    const int first = winners[0];
    /* Each lane's planes from its own winner: a stamp has a few winners, so each one's record is read
     * once and blended into the lanes it won (lanes without a winner keep the first one's). Copying
     * every lane's record into a lane-major array instead compiled to a scatter per lane. */
    __global const float* a = attrs + (size_t)first * ATTR_FLOATS;
    const int material = (int)a[PHONG_MATERIAL_SLOT];
    int needed = SPECULAR_NEEDED(a); /* the lanes' specular masks and their union */
    intV lane_needed = (intV)needed;
    floatV p[DEFER_PLANE_FLOATS];
#pragma unroll
    for (int k = 0; k < DEFER_PLANE_FLOATS; ++k) p[k] = (floatV)a[k];
    intV dy = STAMP_ROW + (y - tris[first].y0), rel = STAMP_COLUMN + (x - tris[first].x0);
    int materials_differ = 0;
    for (int w = 1; w < count; ++w) {
      const int id = winners[w];
      a = attrs + (size_t)id * ATTR_FLOATS;
      materials_differ |= (int)a[PHONG_MATERIAL_SLOT] != material;
      const intV mine = winner[i] == id;
      needed |= SPECULAR_NEEDED(a);
      lane_needed = select(lane_needed, (intV)SPECULAR_NEEDED(a), mine);
#pragma unroll
      for (int k = 0; k < DEFER_PLANE_FLOATS; ++k) p[k] = select(p[k], (floatV)a[k], mine);
      dy = select(dy, STAMP_ROW + (y - tris[id].y0), mine);
      rel = select(rel, STAMP_COLUMN + (x - tris[id].x0), mine);
    }
    if (!materials_differ) {
      shade_pixels_lanes(p, material, needed, lane_needed, convert_floatV(dy), convert_floatV(rel), &sr, &sg, &sb,
                         lights, materials, viewer);
      keep(won, sr, sg, sb, &cr[i], &cg[i], &cb[i]);
      continue;
    }
    for (int w = 0; w < count; ++w) { /* each winner over its own lanes */
      const int id = winners[w];
      const intV mine = winner[i] == id;
      __global const TriangleGeometry* t = &tris[id];
      SHADE_STAMP_PIXELS(attrs + (size_t)id * ATTR_FLOATS, convert_floatV(STAMP_ROW + (y - t->y0)),
                         convert_floatV(STAMP_COLUMN + (x - t->x0)), &sr, &sg, &sb, lights, materials, viewer);
      keep(mine, sr, sg, sb, &cr[i], &cg[i], &cb[i]);
    }
  }
}
#endif

#endif

/* VEC pixels of the frame from (x, y) on, those left of the frame's right edge. */
INLINE void write_frame_segment(uintV rgba, __global uint* out_rgba, int x, int y, int width) {
  const size_t at = (size_t)y * width + x;
  if (x + VEC <= width) {
    store_frame_row(rgba, out_rgba + at);
  } else {
    uint lanes[VEC];
    vstoreV(rgba, 0, lanes);
    for (int l = 0; l < width - x; ++l) out_rgba[at + l] = lanes[l];
  }
}

__kernel __attribute__((reqd_work_group_size(1, 1, 1)))
void render_tiles(__global const TriangleGeometry* tris, __global const float* attrs,
                  __global const uint* tile_start, __global const uint* tile_tris,
                  __constant float4* lights, __constant float4* materials, float4 viewer, float4 background,
                  int tiles_x, int num_tiles, int width, int height, __global uint* out_rgba,
                  __global float* out_float, __global const FixedPlanes* fixed, __global ulong* tile_counters,
                  __global const SierpinskiLeaf* leaves, __global const uint* dda_first,
                  __global const int* dda_rows
#if PLAN_PASS
                  , __global ulong* keys, __global const uint* packet_first, __global const uint* vtile_tile,
                  volatile __global int* packet_counter, int num_packets
#endif
                  ) {
#if PLAN_PASS == 1
  /* Work-item = modeled unit: its packet (static), or packets pulled from the shared counter (dynamic).
   * tile_start / tile_tris are the plan's virtual tiles and lists here. */
#if PLAN_DYNAMIC
  for (int packet = atomic_inc(packet_counter); packet < num_packets; packet = atomic_inc(packet_counter))
#else
  for (int packet = get_global_id(0); packet < num_packets; packet += get_global_size(0))
#endif
  for (uint v = packet_first[packet]; v < packet_first[packet + 1]; ++v) {
  const int tile = vtile_tile[v];
  const uint begin = tile_start[v], end = tile_start[v + 1];
#else
  for (int tile = get_global_id(0); tile < num_tiles; tile += get_global_size(0)) {
  const uint begin = tile_start[tile], end = tile_start[tile + 1];
#endif
  const int tile_x = (tile % tiles_x) * TILE, tile_y = (tile / tiles_x) * TILE;
#if PLAN_PASS == 0 && !UNIT_PATH && !SHADE_SPAN && !OUTPUT_FLOAT
  if (begin == end) {
    /* No triangle: the background (uncovered) written directly, without the tile's private arrays. */
    const uintV rgba = to_level((floatV)background.x) | (to_level((floatV)background.y) << 8) |
                       (to_level((floatV)background.z) << 16);
    for (int i = 0; i < TILE_VECTORS; ++i) {
      const int y = tile_y + i / SEGMENTS, x = tile_x + (i % SEGMENTS) * VEC;
      if (y >= height || x >= width) continue;
      const size_t at = (size_t)y * width + x;
      if (x + VEC <= width) {
        store_frame_row(rgba, out_rgba + at);
      } else {
        for (int l = 0; l < width - x; ++l) out_rgba[at + l] = rgba.s0;
      }
    }
    continue;
  }
#endif

  floatV depth[TILE_VECTORS];
  colourV cr[TILE_VECTORS], cg[TILE_VECTORS], cb[TILE_VECTORS];
#if DEFER_STAMPS
  intV winner[TILE_VECTORS];
  const int deferred = (int)(end - begin) >= DEFER_MIN_TRIANGLES;
#endif
  for (int i = 0; i < TILE_VECTORS; ++i) {
    depth[i] = (floatV)INFINITY;
#if DEFER_STAMPS
    winner[i] = (intV)(-1);
#endif
#if REGISTER_COLOUR
    /* Colour holds span registers: the background as a register value. */
    cr[i] = (intV)(int)(background.x * (1 << FRAC_BITS));
    cg[i] = (intV)(int)(background.y * (1 << FRAC_BITS));
    cb[i] = (intV)(int)(background.z * (1 << FRAC_BITS));
#else
    cr[i] = (floatV)background.x;
    cg[i] = (floatV)background.y;
    cb[i] = (floatV)background.z;
#endif
  }
#if UNIT_PATH
  ulong spans = 0, span_pixels = 0, clocks = 0;
#endif
#if SHADE_SPAN
  ulong span_setups = 0, span_fallbacks = 0, span_steps = 0;
#endif
  const intV lane = LANE_INDEX;
#if STAMPS
  int span_lo[TILE + VEC], span_hi[TILE + VEC]; /* per row of the tile (and VEC - 1 past it) */
#else
  int span_lo[VEC], span_hi[VEC];
#endif

  for (uint k = begin; k < end; ++k) {
    const uint ti = tile_tris[k];
    /* The tile's triangles are scattered in memory and their loads stall: fetch the record and the
     * attributes (two lines each) PREFETCH_AHEAD triangles ahead. */
    if (k + PREFETCH_AHEAD < end) {
      const uint tn = tile_tris[k + PREFETCH_AHEAD];
      __global const char* const rec = (__global const char*)&tris[tn];
      __global const char* const att = (__global const char*)(attrs + (size_t)tn * ATTR_FLOATS);
      PREFETCH_LINE(rec);
      PREFETCH_LINE(rec + 64);
      PREFETCH_LINE(att);
      PREFETCH_LINE(att + 64);
    }
    __global const TriangleGeometry* t = &tris[ti];
    const int x0 = t->x0, y0 = t->y0;
    const int row_first = max(tile_y, y0), row_last = min(tile_y + TILE - 1, (int)t->y1);
    const int lo = max(tile_x, x0) - x0, hi = min(tile_x + TILE - 1, (int)t->x1) - x0;
    if (row_first > row_last || lo > hi) continue;
    __global const float* attr = attrs + (size_t)ti * ATTR_FLOATS;
#if COMBINED
    /* Combined Gouraud/Phong (no unit path: the combinations table refuses it): by whole spans, segment ends
     * counted from each span's left pixel, shaded now even in a deferred tile (combined_walk.h; on the stamps a row
     * of stamp lanes at a time); narrow triangles, where it cannot save, by Phong per pixel below, and so are the
     * triangles the per-triangle choice gives to Gouraud (SHADE_PIXELS, SHADE_STAMP_PIXELS, method_combined.h). */
    if (combined_walks(t, attr)) {
      shade_triangle_combined(t, attr, tile_x, tile_y, row_first, row_last, lo, hi, depth, cr, cg, cb, lights, materials,
                              viewer DEFER_ARGS);
      continue;
    }
#endif
#if UNIT_PATH
    /* Every triangle by whole spans: a unit's registers depend on where its span starts and ends. A span
     * is counted (modeled clocks) by the tile that holds its left pixel, so each is counted once. */
    for (int block = row_first; block <= row_last; block += VEC) {
      const int rows = min(VEC, row_last - block + 1);
#if DDA_COVERAGE
      /* The sources' edge walk: the spans come from the host's row table. */
      for (int j = 0; j < rows; ++j) {
        const int at = 2 * (int)(dda_first[ti] + (uint)(block + j - y0));
        span_lo[j] = dda_rows[at];
        span_hi[j] = dda_rows[at + 1];
      }
#else
      intV lo_v, hi_v;
      if (t->flags & TRIANGLE_SMALL) row_spans_small(t, lane + (block - y0), &lo_v, &hi_v, 0, t->x1 - x0);
      else row_spans(t, lane + (block - y0), &lo_v, &hi_v, 0, t->x1 - x0);
      vstoreV(lo_v, 0, span_lo);
      vstoreV(hi_v, 0, span_hi);
#endif
      for (int j = 0; j < rows; ++j) {
        const int xl = span_lo[j], xr = span_hi[j];
        if (xl > xr) continue;
        const int length = xr - xl + 1;
        const int costs_clocks = unit_span_costs_clocks(&leaves[ti]);
        if (costs_clocks && xl + x0 >= tile_x && xl + x0 < tile_x + TILE) {
          spans += 1;
          span_pixels += (ulong)length;
          clocks += (ulong)(SPAN_LOAD_CLOCKS + unit_span_clocks(length));
        }
        const int sl = max(xl, lo), sr = min(xr, hi);
        if (sl > sr) continue;
        const int py = block + j, dy = py - y0;
#if FIXED
        SpanRegisters regs;
        load_span_registers(&fixed[ti], &leaves[ti], xl, xr, dy, &regs);
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
          shade_unit_normals(&regs, rel - xl, length, attr, dy, frel, &sr_, &sg_, &sb_, lights, materials, viewer);
          keep(pass, sr_, sg_, sb_, &cr[slot], &cg[slot], &cb[slot]);
#else
          floatV sr_, sg_, sb_;
          shade_pixels(attr, dy, frel, &sr_, &sg_, &sb_, lights, materials, viewer);
          keep(pass, sr_, sg_, sb_, &cr[slot], &cg[slot], &cb[slot]);
#endif
        }
      }
    }
#elif STAMPS
    {
      const int sy_first = (row_first - tile_y) / STAMP, sy_last = (row_last - tile_y) / STAMP;
      if (t->flags & TRIANGLE_SMALL) {
        /* Few pixels: every stamp of the box, each pixel's edge functions directly. */
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
            shade_stamp(t, attr, dy, rel, outside, sy * STAMPS_X + sx, depth, cr, cg, cb, lights, materials, viewer
                        DEFER_ARGS);
          }
        }
        continue;
      }
      /* The spans of the tile's rows, VEC rows at a time, then each stamp's lanes from its four rows. */
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
          shade_stamp(t, attr, dy, rel, (rel - lo_s) | (hi_s - rel), sy * STAMPS_X + sx, depth, cr, cg, cb, lights,
                      materials, viewer DEFER_ARGS);
        }
      }
    }
#else
    const int seg_first = (lo + x0 - tile_x) / VEC, seg_last = (hi + x0 - tile_x) / VEC;
    if (t->flags & TRIANGLE_SMALL) {
      /* Few rows: test each pixel's edge functions directly. */
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
          shade_segment(t, attr, dy, rel, inside, (py - tile_y) * SEGMENTS + s, depth, cr, cg, cb, lights, materials,
                        viewer PLAN_ARGS(tile_x + s * VEC) SPAN_ARGS);
        }
      }
      continue;
    }
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
          shade_segment(t, attr, py - y0, rel, (rel >= xl) & (rel <= xr), (py - tile_y) * SEGMENTS + s, depth, cr, cg,
                        cb, lights, materials, viewer PLAN_ARGS(tile_x + s * VEC) SPAN_ARGS);
        }
      }
    }
#endif
  }

#if DEFER_STAMPS
  if (deferred) shade_winners(winner, cr, cg, cb, tris, attrs, tile_x, tile_y, lights, materials, viewer);
#endif
#if STAMPS
  /* Each stamp row of the tile through a private line buffer, so the frame is still written VEC pixels
   * of a row at a time. */
  for (int sy = 0; sy < STAMPS_X; ++sy) {
    uint lines[STAMP][TILE];
    for (int sx = 0; sx < STAMPS_X; ++sx) {
      const int i = sy * STAMPS_X + sx;
      const uintV covered = convert_uintV(isless(depth[i], (floatV)INFINITY)) & 0xFF000000u;
      const uintV rgba = to_level(cr[i]) | (to_level(cg[i]) << 8) | (to_level(cb[i]) << 16) | covered;
      vstore4(rgba.s0123, 0, &lines[0][sx * STAMP]);
      vstore4(rgba.s4567, 0, &lines[1][sx * STAMP]);
      vstore4(rgba.s89ab, 0, &lines[2][sx * STAMP]);
      vstore4(rgba.scdef, 0, &lines[3][sx * STAMP]);
    }
    for (int j = 0; j < STAMP; ++j) {
      const int y = tile_y + sy * STAMP + j;
      if (y >= height) break;
      for (int seg = 0; seg < SEGMENTS; ++seg) {
        const int x = tile_x + seg * VEC;
        if (x >= width) break;
        write_frame_segment(vloadV(0, &lines[j][seg * VEC]), out_rgba, x, y, width);
      }
    }
  }
#elif PLAN_PASS != 1
  /* The frame is width x height exactly (no padding), so the host can use it without a copy. */
  for (int i = 0; i < TILE_VECTORS; ++i) {
    const int y = tile_y + i / SEGMENTS, x = tile_x + (i % SEGMENTS) * VEC;
    if (y >= height || x >= width) continue;
    const uintV covered = convert_uintV(isless(depth[i], (floatV)INFINITY)) & 0xFF000000u;
#if REGISTER_COLOUR
    const uintV rgba = register_levels(cr[i]) | (register_levels(cg[i]) << 8) | (register_levels(cb[i]) << 16) | covered;
#else
    const uintV rgba = to_level(cr[i]) | (to_level(cg[i]) << 8) | (to_level(cb[i]) << 16) | covered;
#endif
    write_frame_segment(rgba, out_rgba, x, y, width);
#if OUTPUT_FLOAT
    const size_t at = (size_t)y * width + x;
    const size_t plane = (size_t)width * height;
    float fr[VEC], fg[VEC], fb[VEC];
#if REGISTER_COLOUR
    /* The float image holds the register values in levels (exact while REG_BITS <= 24). */
    vstoreV(convert_floatV(cr[i]) * (1.0f / (1 << FRAC_BITS)), 0, fr);
    vstoreV(convert_floatV(cg[i]) * (1.0f / (1 << FRAC_BITS)), 0, fg);
    vstoreV(convert_floatV(cb[i]) * (1.0f / (1 << FRAC_BITS)), 0, fb);
#else
    vstoreV(cr[i], 0, fr);
    vstoreV(cg[i], 0, fg);
    vstoreV(cb[i], 0, fb);
#endif
    for (int l = 0; l < min(VEC, width - x); ++l) {
      out_float[at + l] = fr[l];
      out_float[plane + at + l] = fg[l];
      out_float[2 * plane + at + l] = fb[l];
    }
#endif
  }
#endif
#if SHADE_SPAN && PLAN_PASS != 1
  tile_counters[3 * tile] = span_setups;
  tile_counters[3 * tile + 1] = span_fallbacks;
  tile_counters[3 * tile + 2] = span_steps;
#endif
#if UNIT_PATH && PLAN_PASS != 1
  tile_counters[3 * tile] = spans;
  tile_counters[3 * tile + 1] = span_pixels;
  tile_counters[3 * tile + 2] = clocks;
#endif
  }
  FRAME_STORES_DONE();
}
