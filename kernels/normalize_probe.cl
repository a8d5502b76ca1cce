/* Test probe of normalize_span.h (tests/cl/normalize_golden_test.cpp): span k has end normals
 * ends[6k..6k+5] and `length` pixels; writes the kernel's normal of each pixel to out[3 (k length + i)]
 * (zero where the span falls back), and per span the sequential unit's steps to steps[k]. The pixels
 * go by runs of TILE, as the render kernel's tiles take them. */
#include "common.h"
#include "normalize_span.h"

__kernel void normalize_probe(__global const float* ends, int length, __global float* out, __global uint* steps) {
  const int k = get_global_id(0);
  SpanNormals s;
  span_normals_setup(&s, vload3(0, ends + 6 * k), vload3(1, ends + 6 * k));
  uint walked = 0;
  for (int run = 0; run < length; run += TILE) {
#if NORMALIZE_METHOD == 4
    walked += span_normals_walk(&s, length, run, min(run + TILE, length) - 1, run);
#endif
    for (int first = run; first < min(run + TILE, length); first += VEC) {
      floatV nx, ny, nz;
      span_pixel_normals(&s, LANE_INDEX + first, length, &nx, &ny, &nz);
      float x[VEC], y[VEC], z[VEC];
      vstoreV(nx, 0, x);
      vstoreV(ny, 0, y);
      vstoreV(nz, 0, z);
      for (int l = 0; l < VEC && first + l < length; ++l) {
        const size_t at = 3 * ((size_t)k * length + first + l);
        out[at] = s.fallback ? 0.0f : x[l];
        out[at + 1] = s.fallback ? 0.0f : y[l];
        out[at + 2] = s.fallback ? 0.0f : z[l];
      }
    }
  }
  steps[k] = walked;
}
