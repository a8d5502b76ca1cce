/* The extra-triangulation unit (docs/units.md, "Sierpinski"; its records: sierpinski_leaf.h): the classic
 * code interpolator shades one of 4^D sub-triangles, and each other one, a copy, gets its intensities
 * through one adder: offset + I0(P - D), or offset - I0(C - P) for a point-reflected copy. A span's
 * registers are the shaded sub-triangle's span S0 + i*dI (walked from the copy's right pixel when
 * reflected) through the copy's adder. Its clocks are classic's for the shaded sub-triangle's spans; the
 * copies' adders emit their pixels in the same clock, so a copy's span costs none. Golden model and cost:
 * host/units/sierpinski.cpp; setup: host/units/sierpinski_setup.cpp. */
#ifndef PARASHADE_UNIT_SIERPINSKI_H
#define PARASHADE_UNIT_SIERPINSKI_H

#include "classic.h"
#include "../sierpinski_leaf.h"

#define UNIT_SIERPINSKI 4

#ifdef __OPENCL_VERSION__
/* The shaded sub-triangle's span starts at this copy's left pixel, or at its right one when reflected;
 * `end` holds the copy's adder constant. */
INLINE void sierpinski_load_span_registers(__global const FixedPlanes* p, __global const SierpinskiLeaf* leaf,
                                           int xl, int xr, int dy, SpanRegisters* r) {
  r->sign = leaf->sign;
  for (int c = 0; c < 3; ++c) {
    r->start[c] = load_register(plane_value(p->ref[c], p->ddx[c], p->ddy[c], r->sign > 0 ? xl : xr, dy), FRAC_BITS,
                                REG_BITS);
    r->step[c] = load_register(r->sign > 0 ? p->ddx[c] : (long)(0 - (ulong)p->ddx[c]), FRAC_BITS, REG_BITS);
    r->end[c] = load_register(leaf->offset[c], FRAC_BITS, REG_BITS);
  }
}

INLINE uintV sierpinski_register(const SpanRegisters* r, int c, intV i, int length) {
  const uintV shaded = (uintV)(uint)r->start[c] +
                       as_uintV(r->sign > 0 ? i : (intV)(length - 1) - i) * (uint)r->step[c];
  return r->sign > 0 ? (uintV)(uint)r->end[c] + shaded : (uintV)(uint)r->end[c] - shaded;
}

#if defined(UNIT_KIND) && UNIT_KIND == UNIT_SIERPINSKI /* the kernel's unit (unit_registers.h) */
#define UNIT_SPAN_CLOCKS classic_span_clocks
#define UNIT_SPAN_COSTS_CLOCKS(leaf) ((leaf)->shaded)
#define UNIT_LOAD_SPAN sierpinski_load_span_registers
#define UNIT_REGISTER sierpinski_register
#endif
#endif

#endif
