/* Shades one frame. A work-item renders TILE x TILE screen tiles one after another (tiles
 * g, g + G, g + 2G, ... for work-item g of G: few work-items, because PoCL pays a fixed cost per
 * work-group, and interleaved tiles, so every work-item gets a share of the busy screen areas).
 * A tile (render_tile) is cleared (tile_state.h) or filled by a first triangle that covers it (tile_fill.h), its
 * triangle list walked in primitive order (tile_walk.h: the
 * unit path, the stamps or the rows, each finding the spans of all a triangle's rows in the tile at once, rows as
 * vector lanes, then shading VEC pixels at a time as vector lanes), a deferred tile shaded after its walk
 * (deferred_shade.h), and the tile written once (tile_write.h). The method (method_*.h, chosen by the host)
 * supplies shade_pixels(); which of these passes a build has follows from the host's -D options by the rules
 * in tile_paths.h. */
#include "common.h"
#include "triangle_record.h"
#include "span.h"
#include "fixed_point.h"
#include "sierpinski_leaf.h"
#include "tile_paths.h"
#include "stamp_layout.h"
#include "frame_args.h"
#include "tile_state.h"
#include "tile_walk.h"
#if DEFER_STAMPS
#include "deferred_shade.h"
#endif
#include "tile_write.h"
#if TILE_FILL
#include "tile_fill.h"
#endif

/* One tile: cleared (or filled by a first triangle that covers it, tile_fill.h), its triangles walked in
 * primitive order, a deferred tile shaded after its walk, then written; in the units' depth pass (PLAN_PASS 1)
 * a virtual tile, whose walk only offers depth keys. */
INLINE void render_tile(const FrameArgs* f, int tile, uint begin, uint end) {
  const int tile_x = (tile % f->tiles_x) * TILE, tile_y = (tile / f->tiles_x) * TILE;
#if PLAIN_FRAME
  if (begin == end) {
    write_background_tile(f, tile_x, tile_y);
    return;
  }
#endif
  floatV depth[TILE_ARRAY];
  colourV cr[TILE_ARRAY], cg[TILE_ARRAY], cb[TILE_ARRAY];
#if DEFER_STAMPS
  intV winner[TILE_ARRAY];
  const int deferred = (int)(end - begin) >= DEFER_MIN_TRIANGLES;
#endif
#if TILE_FILL
  int done;
  const uint first = fill_or_clear(f, begin, end, tile_x, tile_y, depth, cr, cg, cb, &done DEFER_ARGS);
  if (done) return;
#else
  const uint first = begin;
  clear_tile(depth, cr, cg, cb, f->background DEFER_ARGS);
#endif
  TileCounts counts = {0, 0, 0};
  for (uint k = first; k < end; ++k) {
    const uint ti = f->tile_tris[k];
    if (k + PREFETCH_AHEAD < end) prefetch_triangle(f, f->tile_tris[k + PREFETCH_AHEAD]);
    walk_triangle(f, ti, tile_x, tile_y, depth, cr, cg, cb, &counts DEFER_ARGS);
  }
#if DEFER_STAMPS
  if (deferred) shade_winners(f, winner, tile_x, tile_y, cr, cg, cb);
#endif
#if WRITES_FRAME
  write_tile(f, tile_x, tile_y, depth, cr, cg, cb);
#endif
#if COUNTS_TILE
  write_tile_counts(f, tile, &counts);
#endif
}

#if PLAN_PASS == 1
/* The units' depth pass: work-item = modeled unit, walking its packet (static) or packets pulled from the
 * shared counter (dynamic). tile_start and tile_tris are the plan's virtual tiles (a unit's triangles of one
 * screen tile) and their lists here. */
INLINE void units_depth_pass(const FrameArgs* f, __global const uint* tile_start, __global const uint* packet_first,
                             __global const uint* vtile_tile, volatile __global int* packet_counter, int num_packets) {
#if PLAN_DYNAMIC
  for (int packet = atomic_inc(packet_counter); packet < num_packets; packet = atomic_inc(packet_counter))
#else
  for (int packet = get_global_id(0); packet < num_packets; packet += get_global_size(0))
#endif
    for (uint v = packet_first[packet]; v < packet_first[packet + 1]; ++v)
      render_tile(f, vtile_tile[v], tile_start[v], tile_start[v + 1]);
}
#endif

/* Work-items per work-group (--work-group-size; 1 unless given): each still walks its own interleaved tiles. */
#ifndef WORK_GROUP_SIZE
#define WORK_GROUP_SIZE 1
#endif

__kernel __attribute__((reqd_work_group_size(WORK_GROUP_SIZE, 1, 1)))
void render_tiles(RENDER_TILES_PARAMS) {
  const FrameArgs f = FRAME_ARGS_OF_PARAMS;
#if PLAN_PASS == 1
  units_depth_pass(&f, tile_start, packet_first, vtile_tile, packet_counter, num_packets);
#else
  for (int tile = get_global_id(0); tile < num_tiles; tile += get_global_size(0))
    render_tile(&f, tile, tile_start[tile], tile_start[tile + 1]);
#endif
  FRAME_STORES_DONE();
}
