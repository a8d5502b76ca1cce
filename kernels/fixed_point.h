/* The register model of the fixed-point shading units, one definition shared by the host (C++: setup,
 * golden models, tests) and the kernels (OpenCL C). docs/units.md explains each choice.
 *
 * Setup's plane registers (the "software" side and the line interpolators): per channel a value at the
 * centre of the triangle's box corner pixel (x0, y0) and its x and y increments, signed 64-bit with
 * PLANE_FRAC = 32 fraction bits, rounded to nearest from double precision. Evaluated with modular
 * 64-bit arithmetic, so a value is exact whenever it fits, and at covered pixels it always does
 * (it lies between vertex values).
 *
 * Span registers (the code interpolators of a unit): I.F two's complement, W = I + F <= 32 bits,
 * F >= 1. Loading a register from a plane value (span start S, span end E, the span increment dI,
 * an own-quantized multiple M*dI) rounds to nearest, ties up, and saturates to W bits. Adders wrap
 * modulo 2^W like hardware adders. The output level rounds to nearest, ties up, then saturates to
 * [0, 255].
 *
 * Phong through a unit: the registers hold the interpolated normal's components scaled by
 * NORMAL_REGISTER_LEVELS, so a unit normal spans the same +-255 range as an intensity and one I.F
 * format describes both; the shading after the registers is float. */
#ifndef PARASHADE_FIXED_POINT_H
#define PARASHADE_FIXED_POINT_H

#include "triangle_record.h"

#ifdef __OPENCL_VERSION__
typedef ulong ps_ulong;
typedef uint ps_uint;
#define PS_INLINE inline __attribute__((always_inline))
#else
typedef std::uint64_t ps_ulong;
typedef std::uint32_t ps_uint;
#define PS_INLINE inline
#endif

#define PLANE_FRAC 32
#define NORMAL_REGISTER_LEVELS 255

/* Gouraud planes of one triangle in setup's format, indexed like TriangleGeometry. */
typedef struct {
  ps_long ref[3]; /* r, g, b at the box corner pixel centre (x0 + 1/2, y0 + 1/2) */
  ps_long ddx[3]; /* the constant span increment dI_G ([Malovanyi 2019, parallel Gouraud] formula (2.16)) */
  ps_long ddy[3];
} FixedPlanes;

/* Plane value at pixel (x0 + dx, y0 + dy), PLANE_FRAC fraction bits, modulo 2^64. */
PS_INLINE ps_long plane_value(ps_long ref, ps_long ddx, ps_long ddy, ps_int dx, ps_int dy) {
  return (ps_long)((ps_ulong)ref + (ps_ulong)ddx * (ps_ulong)(ps_long)dx + (ps_ulong)ddy * (ps_ulong)(ps_long)dy);
}

/* A value in register units saturated to `width` bits. */
PS_INLINE ps_int saturate_register(ps_long r, int width) {
  const ps_long hi = ((ps_long)1 << (width - 1)) - 1, lo = -hi - 1;
  return (ps_int)(r < lo ? lo : (r > hi ? hi : r));
}

/* A plane value into a span register of `width` bits with `frac` fraction bits (1 <= frac < PLANE_FRAC):
 * round to nearest (ties up), saturate. */
PS_INLINE ps_int load_register(ps_long v, int frac, int width) {
  const int shift = PLANE_FRAC - frac;
  return saturate_register((v >> shift) + ((v >> (shift - 1)) & 1), width);
}

/* Two's complement wrap-around to `width` bits (an adder's carry out of the register is lost). */
PS_INLINE ps_int wrap_register(ps_uint v, int width) {
  return (ps_int)(v << (32 - width)) >> (32 - width);
}

/* The 8-bit output level of a register: round to nearest (ties up), saturate to [0, 255]. */
PS_INLINE ps_int register_level(ps_int v, int frac) {
  const ps_int r = (v >> frac) + ((v >> (frac - 1)) & 1);
  return r < 0 ? 0 : (r > 255 ? 255 : r);
}

#endif
