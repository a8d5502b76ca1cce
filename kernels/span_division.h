/* The span increment by a division per span (--div exact | shiftadd:N), instead of the constant
 * increment dI_G once per triangle ([Gouraud simplification] vs [Romanyuk & Obidnyk 2011, faster shading]): dI = (E - S) / k from the span's end registers,
 * k = L - 1 pixels between them. Shared by host and kernels; the golden models use the independent
 * host implementation (host/units/shift_add_division.cpp) so that the tests compare two of them.
 *   exact:     round to nearest, ties up: floor((2 (E - S) + k) / 2k)
 *   shiftadd:  1/k as n binary digits m / 2^n (rounded to nearest as the source's Table 1, or truncated),
 *              the quotient as the shift register and accumulating adder form it: the sum of (E - S)
 *              shifted right by j (arithmetic, dropping bits) for every digit i_j = 1. */
#ifndef PARASHADE_SPAN_DIVISION_H
#define PARASHADE_SPAN_DIVISION_H

#include "fixed_point.h"

#define DIV_CONSTANT 0
#define DIV_EXACT 1
#define DIV_SHIFT_ADD 2

PS_INLINE ps_long floor_quotient(ps_long a, ps_long b) { /* b > 0 */
  return a >= 0 ? a / b : -((-a + b - 1) / b);
}

/* (difference) / k for k >= 1 in the given mode; bits = n digits, nearest = 1 for rounded digits. */
PS_INLINE ps_long span_quotient(ps_long difference, ps_int k, int mode, int bits, int nearest) {
  if (mode == DIV_EXACT) return floor_quotient(2 * difference + k, 2 * (ps_long)k);
  const ps_ulong one = (ps_ulong)1 << bits, kk = (ps_ulong)k;
  const ps_ulong m = nearest ? (2 * one + kk) / (2 * kk) : one / kk;
  ps_long sum = 0;
  for (int j = 0; j <= bits; ++j)
    if ((m >> (bits - j)) & 1) sum += difference >> j;
  return sum;
}

#endif
