/* The spherical-angular recurrence ([Dembitsky 2025, software/hardware rendering] ch. 2) as a sequential unit: N(t+1) = 2 cos(dtheta) N(t) - N(t-1),
 * or with NORMALIZE_DIFFERENCE N(t+1) = N(t) + D(t), D(t) = D(t-1) - k N(t), k = 4 sin^2(dtheta/2);
 * dtheta = theta/(m-1), theta = arccos(a.b) by NORMALIZE_ARCCOS (0 exact, 1 the source's table 3.1 as
 * printed, 2 our refit); the unit loads pixels jR and jR+1 from slerp with that theta (NORMALIZE_REANCHOR
 * R; 0: pixels 0 and 1 only). It follows the host library's float rule step for step (recurrence_span
 * in host/phong/normalization.cpp). Every pixel needs the two before it, so this is a scalar loop, not
 * lanes: to produce a run of pixels the unit steps from the last anchor at or before the run's first
 * pixel (the span's first pixel without re-anchoring), and every step counts as the method's cost. */
#ifndef PARASHADE_NORMALIZE_RECURRENCE_H
#define PARASHADE_NORMALIZE_RECURRENCE_H

#ifndef NORMALIZE_ARCCOS
#define NORMALIZE_ARCCOS 0
#endif
#ifndef NORMALIZE_REANCHOR
#define NORMALIZE_REANCHOR 0
#endif
#ifndef NORMALIZE_DIFFERENCE
#define NORMALIZE_DIFFERENCE 0
#endif

/* arccos(x): exact, or the table's quadratics on |x| (odd symmetry below 0). */
INLINE float recurrence_arccos(float x) {
#if NORMALIZE_ARCCOS == 0
  return acos(x);
#else
  const float a = fabs(x);
  float v;
#if NORMALIZE_ARCCOS == 1 /* table 3.1 as printed, C + B x + A x^2 */
  if (a <= 0.5f) v = 1.57f + a * (-0.972f + a * -0.144f);
  else if (a <= 0.75f) v = 1.439f + a * (-0.447f + a * -0.677f);
  else if (a <= 0.9f) v = 0.454f + a * (2.154f + a * -2.397f);
  else if (a <= 0.96f) v = -5.529f + a * (15.47f + a * -9.806f);
  else v = -33.838f + a * (74.547f + a * -40.535f);
#else /* relative-error minimax refit; the last interval sqrt(1 - x) q(x) */
  if (a <= 0.5f) v = 1.56967418f + a * (-0.966445134f + a * -0.154023842f);
  else if (a <= 0.75f) v = 1.42897092f + a * (-0.412448371f + a * -0.704801676f);
  else if (a <= 0.9f) v = 0.351904584f + a * (2.4039881f + a * -2.54792052f);
  else if (a <= 0.96f) v = -6.04446671f + a * (16.5781328f + a * -10.4018351f);
  else v = (1.55905524f + a * (-0.17183946f + a * 0.0269977955f)) * sqrt(1.0f - a);
#endif
  v = max(0.0f, v);
  return x < 0.0f ? M_PI_F - v : v;
#endif
}

/* sin(s x) / sin(x) for x in [0, pi), finite as x -> 0 (its limit s, by the series there). */
INLINE float anchor_sin_ratio(float s, float x) {
  if (x < 1e-4f) return s * (1.0f - (s * s - 1.0f) * x * x / 6.0f);
  return sin(s * x) / sin(x);
}

/* What the unit loads at an anchor: slerp at pixel i of `length` with the unit's theta. */
INLINE float3 recurrence_anchor(float3 a, float3 b, float theta, int i, int length) {
  const float w = length > 1 ? (float)i / (float)(length - 1) : 0.0f;
  return a * anchor_sin_ratio(1.0f - w, theta) + b * anchor_sin_ratio(w, theta);
}

/* Pixels first..last (0-based) of the span from unit a to unit b into x, y, z [0 .. last-first];
 * returns the steps taken. */
INLINE uint recurrence_walk(float3 a, float3 b, int length, int first, int last, float* x, float* y, float* z) {
  const float theta = recurrence_arccos(clamp(a.x * b.x + a.y * b.y + a.z * b.z, -1.0f, 1.0f));
  const float step = length > 2 ? theta / (float)(length - 1) : 0.0f;
#if NORMALIZE_DIFFERENCE
  const float s = sin(step / 2.0f), k = 4.0f * s * s; /* 2 - 2 cos(step) without cancellation */
#else
  const float two_cos = 2.0f * cos(step);
#endif
  const int every = NORMALIZE_REANCHOR > 1 ? NORMALIZE_REANCHOR : length;
  const int from = first / every * every;
  float3 prev = (float3)(0.0f), prev2 = (float3)(0.0f);
#if NORMALIZE_DIFFERENCE
  float3 d = (float3)(0.0f);
#endif
  for (int i = from, at = 0; i <= last; ++i, at = at + 1 == every ? 0 : at + 1) {
    float3 n;
    if (at <= 1) {
      n = recurrence_anchor(a, b, theta, i, length);
#if NORMALIZE_DIFFERENCE
      if (at == 1) d = n - prev;
#endif
    } else {
#if NORMALIZE_DIFFERENCE
      d -= prev * k;
      n = prev + d;
#else
      n = prev * two_cos - prev2;
#endif
    }
    prev2 = prev;
    prev = n;
    if (i >= first) {
      x[i - first] = n.x;
      y[i - first] = n.y;
      z[i - first] = n.z;
    }
  }
  return first <= last ? (uint)(last - from + 1) : 0u;
}

#endif
