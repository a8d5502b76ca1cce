/* The classic unit (docs/units.md): one code interpolator stepping S, S + dI, S + 2dI, ...: one intensity
 * per clock. Its register at pixel i of a span is S + i*dI: in W-bit modular arithmetic, i additions of the
 * rounded dI are one multiplication. Golden model, cost and error bound: host/units/classic.cpp. */
#ifndef PARASHADE_UNIT_CLASSIC_H
#define PARASHADE_UNIT_CLASSIC_H

#include "../fixed_point.h"
#include "../span_registers.h"

#define UNIT_CLASSIC 0

/* Clocks for the pixels of a span of `length` >= 1 pixels. */
PS_INLINE ps_int classic_span_clocks(int lanes, ps_int length) { return length; }

#ifdef __OPENCL_VERSION__
/* S + i*dI modulo 2^32: the register of every unit whose multiples of dI are copies of the rounded one
 * (interleave:M, segment:P), so unit_registers.h's default. */
INLINE uintV classic_register(const SpanRegisters* r, int c, intV i, int length) {
  return (uintV)(uint)r->start[c] + as_uintV(i) * (uint)r->step[c];
}

#if defined(UNIT_KIND) && UNIT_KIND == UNIT_CLASSIC /* the kernel's unit (unit_registers.h) */
#define UNIT_SPAN_CLOCKS classic_span_clocks
#endif
#endif

#endif
