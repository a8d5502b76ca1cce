/* The deferred tile's shading (DEFER_STAMPS, Phong and combined:0): after a walk that kept per pixel only the
 * triangle that passed its depth test last (winner, tile_state.h), each pixel is shaded once by that triangle:
 * what the walk would have kept, without shading the pixels overwritten later or a stamp's uncovered lanes once
 * per triangle. */
#ifndef PARASHADE_DEFERRED_SHADE_H
#define PARASHADE_DEFERRED_SHADE_H

#if COMBINED
#define SPECULAR_NEEDED(attr) (HIGHLIGHT_TEST ? (int)(attr)[PHONG_HIGHLIGHT_SLOT] : -1)
#else
#define SPECULAR_NEEDED(attr) (-1)
#endif
#define DEFER_PLANE_FLOATS 18 /* the normal and position planes: slots 0..17 */

/* Triangle id's pixels of the stamp whose top-left pixel is (x, y), from its planes as the walk would shade
 * them, kept in the lanes `mine`. */
INLINE void shade_winner_lanes(const FrameArgs* f, int id, intV mine, int x, int y, floatV* cr, floatV* cg,
                               floatV* cb) {
  __global const TriangleGeometry* t = &f->tris[id];
  floatV sr, sg, sb;
  SHADE_STAMP_PIXELS(f->attrs + (size_t)id * ATTR_FLOATS, convert_floatV(STAMP_ROW + (y - t->y0)),
                     convert_floatV(STAMP_COLUMN + (x - t->x0)), &sr, &sg, &sb, f->lights, f->materials, f->viewer);
  keep(mine, sr, sg, sb, cr, cg, cb);
}

/* A stamp's winners (lanes `won` have one), once each, in the order their first lanes come: the lowest lane not
 * yet taken, then all its winner's lanes taken (one pass per winner, no scan of lanes by lanes). */
INLINE int list_winners(const FrameArgs* f, intV winner, intV won, int* winners) {
  int ids[VEC];
  vstoreV(winner, 0, ids);
  int count = 0;
  for (uint todo = lane_bits(won); todo != 0;) {
    const int id = ids[31 - clz(todo & (0u - todo))];
    winners[count++] = id;
    /* Its records are read after the list is complete: their loads (often misses on small triangles) start now. */
    PREFETCH_LINE(f->attrs + (size_t)id * ATTR_FLOATS);
    PREFETCH_LINE(f->attrs + (size_t)id * ATTR_FLOATS + PHONG_MATERIAL_SLOT);
    PREFETCH_LINE(&f->tris[id].y0);
    todo &= ~lane_bits(winner == (intV)id);
  }
  return count;
}

/* The deferred tile's pixels, a stamp at a time, each by its winner. A stamp of one winner is shaded from its
 * planes, as the walk would. A stamp whose pixels have several winners of one material is shaded once with each
 * lane's planes and specular mask gathered from its own triangle (lanes without a winner repeat a covered
 * lane's and are not kept); otherwise each winner shades its own lanes from its planes. */
INLINE void shade_winners(const FrameArgs* f, const intV* winner, int tile_x, int tile_y, floatV* cr, floatV* cg,
                          floatV* cb) {
  for (int i = 0; i < TILE_VECTORS; ++i) {
    const int only = max_lane(winner[i]);
    if (only < 0) continue; /* no winner: every lane -1 */
    const intV won = ~winner[i]; /* sign bits: the lanes with a winner */
    const int x = tile_x + (i % STAMPS_X) * STAMP, y = tile_y + (i / STAMPS_X) * STAMP;
    /* Winners are 0..only, so a lane with another winner than `only` has winner - only < 0 and winner >= 0. */
    if (!any_lanes(won & (winner[i] - only))) {
      /* One triangle won every lane that has a winner (inside and along the edges of large triangles, most
       * stamps): shaded without listing the winners. */
      shade_winner_lanes(f, only, won, x, y, &cr[i], &cg[i], &cb[i]);
      continue;
    }
    int winners[VEC];
    const int count = list_winners(f, winner[i], won, winners);
    /* Each lane's planes from its own winner: a stamp has a few winners, so each one's record is read once and
     * blended into the lanes it won (lanes without a winner keep the first one's). Copying every lane's record
     * into a lane-major array instead compiled to a scatter per lane. */
    const int first = winners[0];
    __global const float* a = f->attrs + (size_t)first * ATTR_FLOATS;
    const int material = (int)a[PHONG_MATERIAL_SLOT];
    int needed = SPECULAR_NEEDED(a); /* the lanes' specular masks and their union */
    intV lane_needed = (intV)needed;
    floatV p[DEFER_PLANE_FLOATS];
#pragma unroll
    for (int k = 0; k < DEFER_PLANE_FLOATS; ++k) p[k] = (floatV)a[k];
    intV dy = STAMP_ROW + (y - f->tris[first].y0), rel = STAMP_COLUMN + (x - f->tris[first].x0);
    int materials_differ = 0;
    for (int w = 1; w < count; ++w) {
      const int id = winners[w];
      a = f->attrs + (size_t)id * ATTR_FLOATS;
      materials_differ |= (int)a[PHONG_MATERIAL_SLOT] != material;
      const intV mine = winner[i] == id;
      needed |= SPECULAR_NEEDED(a);
      lane_needed = select(lane_needed, (intV)SPECULAR_NEEDED(a), mine);
#pragma unroll
      for (int k = 0; k < DEFER_PLANE_FLOATS; ++k) p[k] = select(p[k], (floatV)a[k], mine);
      dy = select(dy, STAMP_ROW + (y - f->tris[id].y0), mine);
      rel = select(rel, STAMP_COLUMN + (x - f->tris[id].x0), mine);
    }
    if (!materials_differ) {
      floatV sr, sg, sb;
      shade_pixels_lanes(p, material, needed, lane_needed, convert_floatV(dy), convert_floatV(rel), &sr, &sg, &sb,
                         f->lights, f->materials, f->viewer);
      keep(won, sr, sg, sb, &cr[i], &cg[i], &cb[i]);
      continue;
    }
    for (int w = 0; w < count; ++w) /* each winner over its own lanes */
      shade_winner_lanes(f, winners[w], winner[i] == winners[w], x, y, &cr[i], &cg[i], &cb[i]);
  }
}

#endif
