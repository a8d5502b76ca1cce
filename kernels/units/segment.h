/* The segment:P unit (docs/units.md): P outputs per clock, base + i*dI from precomputed multiples of the
 * rounded dI (even ones wired shifts, odd ones one adder), the base stepping by P*dI: its registers hold
 * classic's S + i*dI (unit_registers.h's default). Golden model, adder count, cost and error bound:
 * host/units/segment.cpp. */
#ifndef PARASHADE_UNIT_SEGMENT_H
#define PARASHADE_UNIT_SEGMENT_H

#include "../fixed_point.h"

#define UNIT_SEGMENT 3

/* Clocks for the pixels of a span of `length` >= 1 pixels, `lanes` = P. */
PS_INLINE ps_int segment_span_clocks(int lanes, ps_int length) { return (length + lanes - 1) / lanes; }

#if defined(UNIT_KIND) && UNIT_KIND == UNIT_SEGMENT /* the kernel's unit (unit_registers.h) */
#define UNIT_SPAN_CLOCKS segment_span_clocks
#endif

#endif
