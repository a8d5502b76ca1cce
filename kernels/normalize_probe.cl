/* Test probe of normalize_span.h (tests/cl/normalize_golden_test.cpp): span k has end normals
 * ends[6k..6k+5] and `length` pixels; writes the kernel's normal of each pixel to out[3 (k length + i)]. */
#include "common.h"
#include "normalize_span.h"

__kernel void normalize_probe(__global const float* ends, int length, __global float* out) {
  const int k = get_global_id(0);
  const float3 na = vload3(0, ends + 6 * k), nb = vload3(1, ends + 6 * k);
  const SpanNormals s = span_normals_setup(na, nb);
  const intV lane = LANE_INDEX;
  for (int first = 0; first < length; first += VEC) {
    const intV i = lane + first;
    const floatV t = length > 1 ? convert_floatV(i) * (1.0f / (float)(length - 1)) : (floatV)0.0f;
    floatV nx, ny, nz;
    span_normal_at(&s, t, &nx, &ny, &nz);
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
