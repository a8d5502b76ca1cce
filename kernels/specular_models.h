/* Lower-degree specular models ([Dembitsky 2025, software/hardware rendering] ch. 3, host/phong/specular_models.cpp, docs/phong-methods.md), chosen by
 * -D SPECULAR_MODEL: 0 exact cos^n, 1 cos^k(a alpha) (a from the Taylor or the lobe rule: the host puts
 * a in the material's diffuse .w), 3 (1 + (n/2)(cos-1))^2, 4 (1 + (7n/16)(cos-1))^SPECULAR_P. SPECULAR_K = k.
 * Unused models are not compiled. */
#ifndef PARASHADE_SPECULAR_MODELS_H
#define PARASHADE_SPECULAR_MODELS_H

#include "positive_power.h"

#ifndef SPECULAR_MODEL
#define SPECULAR_MODEL 0
#endif

#if SPECULAR_MODEL == 1
/* acos(c) for c in [0, 1] as sqrt(1 - c) times a cubic (Abramowitz & Stegun 4.4.45, |error| <= 6.7e-5),
 * and cos(x) for x in [0, pi/2] by its series to x^8 (|error| < 3e-6): no lane-by-lane library calls. */
INLINE floatV acos_unit(floatV c) {
  return sqrt(fmax(1.0f - c, (floatV)0.0f)) * (1.5707288f + c * (-0.2121144f + c * (0.0742610f + c * -0.0187293f)));
}
INLINE floatV cos_quarter(floatV x) {
  const floatV x2 = x * x;
  return 1.0f + x2 * (-0.5f + x2 * (1.0f / 24.0f + x2 * (-1.0f / 720.0f + x2 * (1.0f / 40320.0f))));
}
#endif

/* The specular factor for cos(alpha) = n_dot_h (any sign), exponent n, model scale a. */
INLINE floatV specular_term(floatV n_dot_h, float n, float a) {
#if SPECULAR_MODEL == 0
  return positive_power(n_dot_h, n);
#elif SPECULAR_MODEL == 1
  const floatV c = clamp(n_dot_h, 0.0f, 1.0f);
  const floatV x = a * acos_unit(c);
  const floatV base = select(cos_quarter(x), (floatV)0.0f, isgreaterequal(x, (floatV)1.57079633f) | isless(n_dot_h, (floatV)0.0f));
#if SPECULAR_K == 4
  return (base * base) * (base * base);
#else
  return base * base;
#endif
#else
#if SPECULAR_MODEL == 3
  const floatV t = fmax(1.0f + (0.5f * n) * (n_dot_h - 1.0f), (floatV)0.0f);
#else
  const floatV t = fmax(1.0f + (0.4375f * n) * (n_dot_h - 1.0f), (floatV)0.0f);
#endif
  const floatV s = select(t, (floatV)0.0f, isless(n_dot_h, (floatV)0.0f)); /* N.H <= 0: no highlight */
#if SPECULAR_MODEL == 4 && !SPECULAR_P_IS_2
  return positive_power(s, SPECULAR_P);
#else
  return s * s;
#endif
#endif
}

#endif
