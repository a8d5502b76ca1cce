/* The counter unit (docs/units.md): two code interpolators from the span's ends toward each other, +dI
 * from S (left) and -dI from E (right): two intensities per clock; on an odd span the left one takes the
 * middle pixel. Its register at pixel i is S + i*dI for i < ceil(L/2), else E - (L-1-i)*dI. Golden model,
 * cost and error bound: host/units/counter.cpp. */
#ifndef PARASHADE_UNIT_COUNTER_H
#define PARASHADE_UNIT_COUNTER_H

#include "classic.h"

#define UNIT_COUNTER 1

/* Clocks for the pixels of a span of `length` >= 1 pixels. */
PS_INLINE ps_int counter_span_clocks(int lanes, ps_int length) { return (length + 1) / 2; }

#ifdef __OPENCL_VERSION__
INLINE uintV counter_register(const SpanRegisters* r, int c, intV i, int length) {
  const uintV from_left = classic_register(r, c, i, length);
  const uintV from_right = (uintV)(uint)r->end[c] - as_uintV((intV)(length - 1) - i) * (uint)r->step[c];
  return select(from_left, from_right, as_uintV(i >= (intV)((length + 1) / 2)));
}

#if defined(UNIT_KIND) && UNIT_KIND == UNIT_COUNTER /* the kernel's unit (unit_registers.h) */
#define UNIT_SPAN_CLOCKS counter_span_clocks
#define UNIT_REGISTER counter_register
#define UNIT_LOADS_END 1 /* the right interpolator starts from its own rounded E */
#endif
#endif

#endif
