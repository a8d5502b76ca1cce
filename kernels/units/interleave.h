/* The interleave:M unit (docs/units.md; interleave:2 is the even/odd unit): M code interpolators,
 * interpolator j starts at S + j*dI and steps by M*dI: M intensities per clock. M*dI is shifted and added
 * copies of the rounded dI (the sources' RG3), so the registers hold classic's S + i*dI; with :own
 * (UNIT_OWN_STEP) M*dI is rounded from setup's plane on its own (lane_step) and pixel i = qM + j holds
 * S + j*dI + q*[M*dI]. Golden model, cost and error bound: host/units/interleave.cpp. */
#ifndef PARASHADE_UNIT_INTERLEAVE_H
#define PARASHADE_UNIT_INTERLEAVE_H

#include "../fixed_point.h"
#include "../span_registers.h"

#define UNIT_INTERLEAVE 2

/* Clocks for the pixels of a span of `length` >= 1 pixels, `lanes` = M. */
PS_INLINE ps_int interleave_span_clocks(int lanes, ps_int length) { return (length + lanes - 1) / lanes; }

#ifdef __OPENCL_VERSION__
#if defined(UNIT_KIND) && UNIT_KIND == UNIT_INTERLEAVE /* the kernel's unit (unit_registers.h) */
#define UNIT_SPAN_CLOCKS interleave_span_clocks
#if UNIT_OWN_STEP
#define UNIT_REGISTER interleave_own_step_register
/* S + (i mod M)*dI + (i div M)*[M*dI], M = UNIT_LANES. */
INLINE uintV interleave_own_step_register(const SpanRegisters* r, int c, intV i, int length) {
  /* i < 2^13 and the fraction of (i + 1/2)/M is >= 1/32 away from an integer: the float quotient is exact. */
  const intV q = convert_intV((convert_floatV(i) + 0.5f) * (1.0f / UNIT_LANES));
  return (uintV)(uint)r->start[c] + as_uintV(i - q * UNIT_LANES) * (uint)r->step[c] +
         as_uintV(q) * (uint)r->lane_step[c];
}
#endif
#endif
#endif

#endif
