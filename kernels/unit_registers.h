/* The span registers of a modeled shading unit (UNIT_KIND, UNIT_LANES, UNIT_OWN_STEP from the host):
 * Gouraud's intensities, or Phong's normal components (method_phong_units.h).
 *
 * FIXED = 1: span registers in I.F fixed point (REG_BITS = I + F, FRAC_BITS = F; kernels/fixed_point.h).
 * Each span's registers are loaded from setup's planes (S at the left pixel, E at the right one, dI,
 * and an own-rounded M*dI), then every pixel gets the value the unit's interpolator holds for it.
 * The golden models (host/core/golden_units.cpp) step the registers clock by clock; here each
 * pixel's value is the closed form of the same additions, which in modular W-bit arithmetic is
 * bit-identical (z additions of a rounded increment are one multiplication by z):
 *   classic, segment:P, interleave:M   S + i*dI                     (multiples of the rounded dI)
 *   interleave:M:own                   S + (i mod M)*dI + (i div M)*[M*dI]
 *   counter                            S + i*dI for i < ceil(L/2), else E - (L-1-i)*dI
 *   sierpinski:D (sierpinski_leaf.h)   offset + (S0 + i*dI), or offset - (S0 + (L-1-i)*dI) for a reflected copy,
 *                                      S0 the shaded sub-triangle's span start
 * FIXED = 0: the method's float planes (the units' ideal, identical for every unit); the units then
 * differ only in modeled clocks. */
#include "fixed_point.h"
#include "unit_cost.h"
#include "sierpinski_leaf.h"
#include "span_division.h"

#if FIXED
/* The registers of the current span, per channel (end: counter's right start, or the sierpinski copy's
 * adder constant; lane_step: interleave:M:own only; sign: sierpinski only). */
typedef struct {
  int start[3], end[3], step[3], lane_step[3];
  int sign;
} SpanRegisters;

INLINE void load_span_registers(__global const FixedPlanes* p, __global const SierpinskiLeaf* leaf, int xl, int xr,
                                int dy, SpanRegisters* r) {
#if UNIT_KIND == UNIT_SIERPINSKI
  r->sign = leaf->sign;
  for (int c = 0; c < 3; ++c) {
    r->start[c] = load_register(plane_value(p->ref[c], p->ddx[c], p->ddy[c], r->sign > 0 ? xl : xr, dy), FRAC_BITS,
                                REG_BITS);
    r->step[c] = load_register(r->sign > 0 ? p->ddx[c] : (long)(0 - (ulong)p->ddx[c]), FRAC_BITS, REG_BITS);
    r->end[c] = load_register(leaf->offset[c], FRAC_BITS, REG_BITS);
  }
#else
  for (int c = 0; c < 3; ++c) {
    r->start[c] = load_register(plane_value(p->ref[c], p->ddx[c], p->ddy[c], xl, dy), FRAC_BITS, REG_BITS);
#if UNIT_KIND == UNIT_COUNTER || SPAN_DIV != DIV_CONSTANT
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
#endif
}

/* The register value at pixel offsets i (from the span's left pixel) of a span of `length` pixels,
 * wrapped to REG_BITS. Unsigned arithmetic: the wrap-around of the hardware adders. */
INLINE intV unit_register(const SpanRegisters* r, int c, intV i, int length) {
  const uintV ui = as_uintV(i);
#if UNIT_KIND == UNIT_COUNTER
  const uintV from_left = (uintV)(uint)r->start[c] + ui * (uint)r->step[c];
  const uintV from_right = (uintV)(uint)r->end[c] - as_uintV((intV)(length - 1) - i) * (uint)r->step[c];
  const uintV v = select(from_left, from_right, as_uintV(i >= (intV)((length + 1) / 2)));
#elif UNIT_KIND == UNIT_SIERPINSKI
  const uintV shaded = (uintV)(uint)r->start[c] +
                       as_uintV(r->sign > 0 ? i : (intV)(length - 1) - i) * (uint)r->step[c];
  const uintV v = r->sign > 0 ? (uintV)(uint)r->end[c] + shaded : (uintV)(uint)r->end[c] - shaded;
#elif UNIT_KIND == UNIT_INTERLEAVE && UNIT_OWN_STEP
  /* i < 2^13 and the fraction of (i + 1/2)/M is >= 1/32 away from an integer: the float quotient is exact. */
  const intV q = convert_intV((convert_floatV(i) + 0.5f) * (1.0f / UNIT_LANES));
  const uintV v = (uintV)(uint)r->start[c] + as_uintV(i - q * UNIT_LANES) * (uint)r->step[c] +
                  as_uintV(q) * (uint)r->lane_step[c];
#else
  const uintV v = (uintV)(uint)r->start[c] + ui * (uint)r->step[c];
#endif
  return as_intV(v << (32 - REG_BITS)) >> (32 - REG_BITS);
}

/* The register's 8-bit level: round to nearest (ties up), saturate (register_level on lanes). The bounds
 * are vectors: Oclgrind 21.10 reads lanes 1..15 of scalar bounds of an integer clamp/min/max from past
 * the scalar (garbage levels; docs/pipeline.md, "What a kernel may assume of a device"). */
INLINE uintV register_levels(intV v) {
  return as_uintV(clamp((v >> FRAC_BITS) + ((v >> (FRAC_BITS - 1)) & 1), (intV)0, (intV)255));
}
#endif
