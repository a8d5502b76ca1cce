/* max(0, x)^n on lanes without PoCL's lane-by-lane library calls, for the specular models (the exact
 * cos^n and the 7n/16 variant). Included by specular_models.h, which blinn_phong.h includes: one way. */
#ifndef PARASHADE_POSITIVE_POWER_H
#define PARASHADE_POSITIVE_POWER_H

/* log2(x) for x > 0; -inf below FLT_MIN. PoCL 3.1 calls a scalar log2 lane by lane (20% of a Phong
 * frame); this is x = m 2^e with m in [sqrt(1/2), sqrt(2)) and log2(m) = (2/ln 2) atanh(s),
 * s = (m-1)/(m+1), |s| <= 0.172, by its series to s^9 (truncation < 2e-9): absolute error a few
 * 1e-8, well inside the bound of docs/error-bounds.md. */
INLINE floatV log2_positive(floatV x) {
  const intV bits = as_intV(x);
  intV e = (bits >> 23) - 127;
  floatV m = as_floatV((bits & 0x007FFFFF) | 0x3F800000);
  const intV high = LANE_MASK(isgreater(m, (floatV)1.41421356f)); /* -1 where true */
  m = select(m, m * 0.5f, high);
  e -= high;
  const floatV s = (m - 1.0f) / (m + 1.0f), s2 = s * s;
  const floatV series =
      s * (2.88539008f + s2 * (0.961796694f + s2 * (0.577078016f + s2 * (0.412198583f + s2 * 0.320598898f))));
  return select(convert_floatV(e) + series, (floatV)(-INFINITY), isless(x, (floatV)FLT_MIN));
}

/* max(0,x)^n for a whole n in [1, 65536], by squaring: the lobe's usual exponents are whole, and the logarithm's
 * division and exp2 made the power the longest part of a Phong stamp's chain of dependent instructions (bench/
 * README.md run DI). n = 40: five squarings and one product instead of about forty instructions. Each product
 * rounds once, so the relative error is below (n - 1) u (u = 2^-24), inside the bound of docs/error-bounds.md. */
INLINE floatV whole_power(floatV x, uint n) { /* n >= 1: positive_power checks it */
  floatV p = x;
  for (; (n & 1u) == 0u; n >>= 1) p *= p;
  floatV r = p;
  for (n >>= 1; n != 0u; n >>= 1) {
    p *= p;
    if (n & 1u) r *= p;
  }
  return r;
}

INLINE floatV positive_power(floatV x, float n) {
  /* max(0,x)^n for n > 0; log2 of 0 is -inf and exp2(-inf) = 0. -D POWER_BY_LOGARITHM keeps exp2(n log2 x) for
   * whole n too (bench_kernel_ab's A/B). */
  const floatV base = fmax(x, (floatV)0.0f);
#ifndef POWER_BY_LOGARITHM
  if (n >= 1.0f && n <= 65536.0f && n == floor(n)) return whole_power(base, (uint)n);
#endif
  return exp2(n * log2_positive(base));
}

#endif
