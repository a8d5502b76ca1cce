/* The span registers of a modeled shading unit (UNIT_KIND, UNIT_LANES, UNIT_OWN_STEP from the host):
 * Gouraud's intensities, or Phong's normal components (method_phong_units.h).
 *
 * FIXED = 1: span registers in I.F fixed point (REG_BITS = I + F, FRAC_BITS = F; kernels/fixed_point.h).
 * Each span's registers are loaded from setup's planes (S at the left pixel, E at the right one, dI,
 * and an own-rounded M*dI), then every pixel gets the value the unit's interpolator holds for it.
 * The golden models (host/units/<unit>.cpp) step the registers clock by clock; here each pixel's value
 * is the closed form of the same additions (kernels/units/<unit>.h), which in modular W-bit arithmetic
 * is bit-identical (z additions of a rounded increment are one multiplication by z).
 * FIXED = 0: the method's float planes (the units' ideal, identical for every unit); the units then
 * differ only in modeled clocks.
 *
 * The header of the unit UNIT_KIND names defines UNIT_SPAN_CLOCKS (its clocks per span, the host's
 * cost model too) and, where it differs from the defaults below, UNIT_REGISTER (its closed form;
 * default classic's S + i*dI), UNIT_LOADS_END (it needs E), UNIT_LOAD_SPAN (its own load) or
 * UNIT_SPAN_COSTS_CLOCKS(leaf) (0 for a span that costs no clock). */
#include "fixed_point.h"
#include "sierpinski_leaf.h"
#include "span_division.h"
#include "span_registers.h"
#include "unit_cost.h"

#ifndef UNIT_SPAN_COSTS_CLOCKS
#define UNIT_SPAN_COSTS_CLOCKS(leaf) 1
#endif
#ifndef UNIT_REGISTER
#define UNIT_REGISTER classic_register
#endif

/* Clocks for the pixels of a span of `length` pixels (each span adds SPAN_LOAD_CLOCKS). */
INLINE int unit_span_clocks(int length) { return UNIT_SPAN_CLOCKS(UNIT_LANES, length); }

/* 1 when this record's span costs clocks, 0 for one the unit copies in the same clock. */
INLINE int unit_span_costs_clocks(__global const SierpinskiLeaf* leaf) { return UNIT_SPAN_COSTS_CLOCKS(leaf); }

#if FIXED
/* S at the span's left pixel, dI (the plane's, or a division per span of E - S), E where the unit or the
 * division needs it, and interleave:M:own's M*dI rounded on its own. */
INLINE void load_plane_span_registers(__global const FixedPlanes* p, __global const SierpinskiLeaf* leaf, int xl,
                                      int xr, int dy, SpanRegisters* r) {
  for (int c = 0; c < 3; ++c) {
    r->start[c] = load_register(plane_value(p->ref[c], p->ddx[c], p->ddy[c], xl, dy), FRAC_BITS, REG_BITS);
#if UNIT_LOADS_END || SPAN_DIV != DIV_CONSTANT
    r->end[c] = load_register(plane_value(p->ref[c], p->ddx[c], p->ddy[c], xr, dy), FRAC_BITS, REG_BITS);
#endif
#if SPAN_DIV == DIV_CONSTANT
    r->step[c] = load_register(p->ddx[c], FRAC_BITS, REG_BITS);
#else
    r->step[c] = xr > xl ? saturate_register(span_quotient((long)r->end[c] - (long)r->start[c], xr - xl, SPAN_DIV,
                                                           DIV_BITS, DIV_NEAREST), REG_BITS)
                         : 0;
#endif
#if UNIT_OWN_STEP
    r->lane_step[c] = load_register((long)((ulong)p->ddx[c] * (ulong)UNIT_LANES), FRAC_BITS, REG_BITS);
#endif
  }
}
#ifndef UNIT_LOAD_SPAN
#define UNIT_LOAD_SPAN load_plane_span_registers
#endif

/* The registers of the span [xl, xr] of row dy, per channel, as the unit loads them. */
INLINE void load_span_registers(__global const FixedPlanes* p, __global const SierpinskiLeaf* leaf, int xl, int xr,
                                int dy, SpanRegisters* r) {
  UNIT_LOAD_SPAN(p, leaf, xl, xr, dy, r);
}

/* The register value at pixel offsets i (from the span's left pixel) of a span of `length` pixels,
 * wrapped to REG_BITS. Unsigned arithmetic: the wrap-around of the hardware adders. */
INLINE intV unit_register(const SpanRegisters* r, int c, intV i, int length) {
  const uintV v = UNIT_REGISTER(r, c, i, length);
  return as_intV(v << (32 - REG_BITS)) >> (32 - REG_BITS);
}

/* The register's 8-bit level: round to nearest (ties up), saturate (register_level on lanes). The bounds
 * are vectors: Oclgrind 21.10 reads lanes 1..15 of scalar bounds of an integer clamp/min/max from past
 * the scalar (garbage levels; docs/pipeline.md, "What a kernel may assume of a device"). */
INLINE uintV register_levels(intV v) {
  return as_uintV(clamp((v >> FRAC_BITS) + ((v >> (FRAC_BITS - 1)) & 1), (intV)0, (intV)255));
}
#endif
