/* The depth test of one row segment of VEC pixels in each pass (PLAN_PASS, tile_paths.h), and keep(): the
 * colour of the lanes that passed. */
#ifndef PARASHADE_DEPTH_TEST_H
#define PARASHADE_DEPTH_TEST_H

#if PLAN_PASS
#pragma OPENCL EXTENSION cl_khr_int64_extended_atomics : enable
#include "plan_key.h"
/* The planned passes test against the frame's keys at pixel column px of the triangle ti's rows; f: the
 * walk's FrameArgs. */
#define PLAN_DECL , uint ti, int px, __global ulong* keys, int width
#define PLAN_ARGS(px_) , ti, (px_), f->keys, f->width
#else
#define PLAN_DECL
#define PLAN_ARGS(px_)
#endif

/* The triangle's depth at lanes of rows fdy and columns frel (from its y0 and x0): the stamps' walk, the tile fill
 * and a covered tile's straight write take it from here, so their values are the same bits. */
INLINE floatV depth_lanes(__global const TriangleGeometry* t, floatV fdy, floatV frel) {
  return (t->z_ref + t->z_ddy * fdy) + t->z_ddx * frel;
}

/* Columns rel from the triangle's x0, row dy from its y0; `inside` marks covered lanes: the lanes that pass,
 * their depth kept. */
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

#endif
