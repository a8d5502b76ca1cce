/* The lanes shape's shading and write-out (render_lanes.cl): after the walk, each of the work-item's pixels shaded
 * once by its winner (the triangle that passed its depth test last, what the vector shape's walk keeps) with the
 * method's shading at that pixel (method_*.h at a lane width of 1: the same operations as the vector shape's
 * lanes), or the background; then its RGBA8 and, with OUTPUT_FLOAT, its float values written. */
#ifndef PARASHADE_LANES_SHADE_H
#define PARASHADE_LANES_SHADE_H

#if COMBINED
#include "lanes_segments.h"
#endif

/* Winner w's colour at frame pixel (px, py). */
INLINE void shade_lane_pixel(const FrameArgs* f, int w, int px, int py, float* r, float* g, float* b) {
  __global const TriangleGeometry* t = &f->tris[w];
  __global const float* a = f->attrs + (size_t)w * ATTR_FLOATS;
  const int dy = py - t->y0, rel = px - t->x0;
#if COMBINED
  /* The combined method: a triangle its walk shades by segments (combined_walks) takes its segment's ends; the
   * others Gouraud's planes or Phong, by its choice (shade_points_chosen, as on the stamps). */
  if (combined_walks(t, a)) {
    shade_segment_pixel(t, a, dy, rel, r, g, b, f->lights, f->materials, f->viewer);
    return;
  }
  shade_points_chosen(a, (float)dy, (float)rel, r, g, b, f->lights, f->materials, f->viewer);
#else
  shade_pixels_at(a, (float)dy, (float)rel, r, g, b, f->lights, f->materials, f->viewer);
#endif
}

/* The work-item's pixels, the block whose top-left pixel is (block_x, block_y) in the frame, those inside the frame. */
INLINE void write_lane_pixels(const FrameArgs* f, int block_x, int block_y, const int* winner) {
  const size_t plane = (size_t)f->width * f->height;
  /* Not unrolled: a block of 64 pixels' unrolled shading took PoCL a minute to compile. */
  for (int p = 0; p < LANE_PIXELS; ++p) {
    const int px = block_x + BLOCK_X(p), py = block_y + BLOCK_Y(p);
    if (px >= f->width || py >= f->height) continue;
    float r = f->background.x, g = f->background.y, b = f->background.z;
    const int w = winner[p];
    if (w >= 0) shade_lane_pixel(f, w, px, py, &r, &g, &b);
    const size_t at = (size_t)py * f->width + px;
    f->out_rgba[at] = to_level(r) | (to_level(g) << 8) | (to_level(b) << 16) | (w >= 0 ? 0xFF000000u : 0u);
#if OUTPUT_FLOAT
    f->out_float[at] = r;
    f->out_float[plane + at] = g;
    f->out_float[2 * plane + at] = b;
#endif
  }
}

#endif
