/* The lanes shape's walk of one triangle (render_lanes.cl): at each of the work-item's pixels, coverage, the depth
 * test and, where it passes, the triangle kept as the pixel's winner. Coverage is the record's exact rule
 * (triangle_record.h: the three edge functions >= 0 at the pixel centre, inside the box), which the vector shape's
 * span search (row_spans) and per-pixel tests (small triangles) settle exactly too; the depth is the vector
 * shape's plane in the same order, tested with the same strict <. So every pixel keeps the same triangle. */
#ifndef PARASHADE_LANES_WALK_H
#define PARASHADE_LANES_WALK_H

/* Edge functions at column rel and row dy (from x0, y0), inside the box: a small triangle's in 32 bits (exact
 * there, triangle_record.h), in the vector shape's order (row term, then the column's); a large one's in 64. */
INLINE int small_inside(__local const TriangleGeometry* t, int rel, int dy) {
  int inside = 1;
  for (int e = 0; e < 3; ++e) inside &= ((int)t->edge_c[e] + t->edge_b[e] * dy) + t->edge_a[e] * rel >= 0;
  return inside;
}

INLINE int large_inside(__local const TriangleGeometry* t, int rel, int dy) {
  int inside = 1;
  for (int e = 0; e < 3; ++e) inside &= (t->edge_c[e] + (long)t->edge_b[e] * dy) + (long)t->edge_a[e] * rel >= 0;
  return inside;
}

/* The work-item's pixels, the block whose top-left pixel is (bx, by) (from x0, y0), against triangle t (record ti),
 * whose box meets the tile in columns lo..hi and rows top..bottom (from x0, y0). `small` is a constant at each call,
 * so each test has a loop of its own. Outside the box the edges are evaluated at the nearest box pixel (a small
 * triangle's 32 bits hold only there) and not kept. */
INLINE void walk_lane_pixels(__local const TriangleGeometry* t, int ti, int small, int bx, int by, int lo, int hi,
                             int top, int bottom, float* depth, int* winner) {
  const float z_ref = t->z_ref, z_ddx = t->z_ddx, z_ddy = t->z_ddy;
  for (int p = 0; p < LANE_PIXELS; ++p) {
    const int rel = bx + BLOCK_X(p), dy = by + BLOCK_Y(p);
    const int cx = clamp(rel, lo, hi), cy = clamp(dy, top, bottom);
    const int covered = (rel == cx) & (dy == cy) & (small ? small_inside(t, cx, cy) : large_inside(t, cx, cy));
    const float z = (z_ref + z_ddy * (float)dy) + z_ddx * (float)rel;
    const int pass = covered & isless(z, depth[p]);
    depth[p] = pass ? z : depth[p];
    winner[p] = pass ? ti : winner[p];
  }
}

/* Triangle t (record ti) at the work-item's block, whose top-left pixel is (block_x, block_y) in the frame. */
INLINE void walk_lane_triangle(__local const TriangleGeometry* t, int ti, int tile_x, int tile_y, int block_x,
                               int block_y, float* depth, int* winner) {
  const int x0 = t->x0, y0 = t->y0;
  const int lo = max(tile_x, x0) - x0, hi = min(tile_x + TILE - 1, (int)t->x1) - x0;
  const int top = max(tile_y, y0) - y0, bottom = min(tile_y + TILE - 1, (int)t->y1) - y0;
  const int bx = block_x - x0, by = block_y - y0;
  /* The block misses the box (or the box the tile): nothing to test. */
  if (max(lo, bx) > min(hi, bx + BLOCK_W - 1) || max(top, by) > min(bottom, by + BLOCK_H - 1)) return;
  if (t->flags & TRIANGLE_SMALL) walk_lane_pixels(t, ti, 1, bx, by, lo, hi, top, bottom, depth, winner);
  else walk_lane_pixels(t, ti, 0, bx, by, lo, hi, top, bottom, depth, winner);
}

#endif
