/* The modeled clocks of the shading units (docs/units.md), shared by the host (cost model, golden-model
 * tests, planning) and the kernels (which count the spans they shade). */
#ifndef PARASHADE_UNIT_COST_H
#define PARASHADE_UNIT_COST_H

#include "fixed_point.h"

#define UNIT_CLASSIC 0
#define UNIT_COUNTER 1
#define UNIT_INTERLEAVE 2
#define UNIT_SEGMENT 3
#define UNIT_SIERPINSKI 4

/* Clocks to load a span's registers (the edge step of the line interpolators and the loads run in
 * parallel: one clock), before the span's pixels. */
#define SPAN_LOAD_CLOCKS 1

/* Clocks a unit needs for the pixels of one span of `length` >= 1 pixels: it produces `lanes`
 * intensities per clock (classic 1, counter 2, interleave M, segment P). The extra-triangulation unit
 * shades only the spans of one of its 4^D sub-triangles, one pixel per clock, and its adders emit the
 * copies in the same clock: its spans are classic ones, and the copies' spans cost nothing. */
PS_INLINE ps_int span_clocks(int kind, int lanes, ps_int length) {
  if (kind == UNIT_CLASSIC || kind == UNIT_SIERPINSKI) return length;
  if (kind == UNIT_COUNTER) return (length + 1) / 2;
  return (length + lanes - 1) / lanes;
}

#endif
