/* The write-out of a tile, once after its walk: 8-bit RGBA (alpha 255 where a triangle covers the pixel), the
 * float image (OUTPUT_FLOAT) and the tile's counters. The frame is width x height exactly (no padding), so the
 * host can use it without a copy: segments past the right edge are cut, rows past the bottom skipped. */
#ifndef PARASHADE_TILE_WRITE_H
#define PARASHADE_TILE_WRITE_H

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

/* The background as VEC uncovered RGBA8 pixels. */
INLINE uintV background_rgba(float4 bg) {
  return to_level((floatV)bg.x) | (to_level((floatV)bg.y) << 8) | (to_level((floatV)bg.z) << 16);
}

/* A tile without triangles (the plain frame's): the background, uncovered, written directly without the
 * tile's private arrays. */
INLINE void write_background_tile(const FrameArgs* f, int tile_x, int tile_y) {
  const uintV rgba = background_rgba(f->background);
  for (int i = 0; i < TILE_VECTORS; ++i) {
    const int y = tile_y + i / SEGMENTS, x = tile_x + (i % SEGMENTS) * VEC;
    if (y >= f->height || x >= f->width) continue;
    write_frame_segment(rgba, f->out_rgba, x, y, f->width);
  }
}

/* VEC pixels (a row segment or a stamp) as RGBA8. */
INLINE uintV pixels_rgba(floatV depth, colourV r, colourV g, colourV b) {
  const uintV covered = convert_uintV(isless(depth, (floatV)INFINITY)) & 0xFF000000u;
#if REGISTER_COLOUR
  return register_levels(r) | (register_levels(g) << 8) | (register_levels(b) << 16) | covered;
#else
  return to_level(r) | (to_level(g) << 8) | (to_level(b) << 16) | covered;
#endif
}

#if STAMPS
/* Each stamp row of the tile through a private line buffer, so the frame is still written VEC pixels of a row
 * at a time. */
INLINE void write_tile(const FrameArgs* f, int tile_x, int tile_y, const floatV* depth, const colourV* cr,
                       const colourV* cg, const colourV* cb) {
#if CLEARS_DEPTH_ONLY
  const uintV background = background_rgba(f->background); /* uncovered pixels' colour was never written */
#endif
  for (int sy = 0; sy < STAMPS_X; ++sy) {
    uint lines[STAMP][TILE];
    for (int sx = 0; sx < STAMPS_X; ++sx) {
      const int i = sy * STAMPS_X + sx;
#if CLEARS_DEPTH_ONLY
      const uintV rgba = select(background, pixels_rgba(depth[i], cr[i], cg[i], cb[i]),
                                as_uintV(LANE_MASK(isless(depth[i], (floatV)INFINITY))));
#else
      const uintV rgba = pixels_rgba(depth[i], cr[i], cg[i], cb[i]);
#endif
      vstore4(rgba.s0123, 0, &lines[0][sx * STAMP]);
      vstore4(rgba.s4567, 0, &lines[1][sx * STAMP]);
      vstore4(rgba.s89ab, 0, &lines[2][sx * STAMP]);
      vstore4(rgba.scdef, 0, &lines[3][sx * STAMP]);
    }
    for (int j = 0; j < STAMP; ++j) {
      const int y = tile_y + sy * STAMP + j;
      if (y >= f->height) break;
      for (int seg = 0; seg < SEGMENTS; ++seg) {
        const int x = tile_x + seg * VEC;
        if (x >= f->width) break;
        write_frame_segment(vloadV(0, &lines[j][seg * VEC]), f->out_rgba, x, y, f->width);
      }
    }
  }
}
#else
#if OUTPUT_FLOAT
/* The float image's VEC pixels from (x, y) on: three planes of width x height, unclamped. */
INLINE void write_float_segment(const FrameArgs* f, int x, int y, colourV r, colourV g, colourV b) {
  const size_t at = (size_t)y * f->width + x;
  const size_t plane = (size_t)f->width * f->height;
  float fr[VEC], fg[VEC], fb[VEC];
#if REGISTER_COLOUR
  /* The float image holds the register values in levels (exact while REG_BITS <= 24). */
  vstoreV(convert_floatV(r) * (1.0f / (1 << FRAC_BITS)), 0, fr);
  vstoreV(convert_floatV(g) * (1.0f / (1 << FRAC_BITS)), 0, fg);
  vstoreV(convert_floatV(b) * (1.0f / (1 << FRAC_BITS)), 0, fb);
#else
  vstoreV(r, 0, fr);
  vstoreV(g, 0, fg);
  vstoreV(b, 0, fb);
#endif
  for (int l = 0; l < min(VEC, f->width - x); ++l) {
    f->out_float[at + l] = fr[l];
    f->out_float[plane + at + l] = fg[l];
    f->out_float[2 * plane + at + l] = fb[l];
  }
}
#endif

/* The tile's row segments. */
INLINE void write_tile(const FrameArgs* f, int tile_x, int tile_y, const floatV* depth, const colourV* cr,
                       const colourV* cg, const colourV* cb) {
  for (int i = 0; i < TILE_VECTORS; ++i) {
    const int y = tile_y + i / SEGMENTS, x = tile_x + (i % SEGMENTS) * VEC;
    if (y >= f->height || x >= f->width) continue;
    write_frame_segment(pixels_rgba(depth[i], cr[i], cg[i], cb[i]), f->out_rgba, x, y, f->width);
#if OUTPUT_FLOAT
    write_float_segment(f, x, y, cr[i], cg[i], cb[i]);
#endif
  }
}
#endif

INLINE void write_tile_counts(const FrameArgs* f, int tile, const TileCounts* counts) {
#if UNIT_PATH
  f->tile_counters[3 * tile] = counts->spans;
  f->tile_counters[3 * tile + 1] = counts->span_pixels;
  f->tile_counters[3 * tile + 2] = counts->clocks;
#else
  f->tile_counters[3 * tile] = counts->span_setups;
  f->tile_counters[3 * tile + 1] = counts->span_fallbacks;
  f->tile_counters[3 * tile + 2] = counts->span_steps;
#endif
}

#endif
