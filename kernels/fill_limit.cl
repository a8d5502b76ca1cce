/* The device's fill limit: every pixel of an RGBA8 frame written once, one work-item per 16 pixels,
 * nothing computed. No renderer can write a frame faster on this device; bench_frame reports it as
 * the ceiling beside the real frames. */
#include "common.h"

__kernel void fill_limit(__global uint* out, uint value, int vectors) {
  const int i = get_global_id(0);
  if (i < vectors) vstoreV((uintV)value, i, out);
}

/* The Gouraud floor: every pixel's colour from one plane per channel and its depth from a plane, tested
 * against the cleared depth, packed and written as the frame kernel does (to_level, store_frame_row):
 * the least per-pixel work of a frame whose one triangle covers the screen, with no coverage test, no
 * triangle loop and no tile. Few work-items, each writing every G-th row, as the frame kernel's; `width`
 * a multiple of VEC. */
__kernel void plane_fill_limit(__global uint* out, float4 ref, float4 ddx, float4 ddy, int width, int height) {
  for (int y = get_global_id(0); y < height; y += get_global_size(0)) {
    const float fy = (float)y;
    for (int x = 0; x < width; x += VEC) {
      const floatV fx = convert_floatV(LANE_INDEX + x);
      const floatV z = (floatV)(ref.w + ddy.w * fy) + ddx.w * fx;
      const uintV covered = convert_uintV(isless(z, (floatV)INFINITY)) & 0xFF000000u;
      const floatV r = (floatV)(ref.x + ddy.x * fy) + ddx.x * fx;
      const floatV g = (floatV)(ref.y + ddy.y * fy) + ddx.y * fx;
      const floatV b = (floatV)(ref.z + ddy.z * fy) + ddx.z * fx;
      store_frame_row(to_level(r) | (to_level(g) << 8) | (to_level(b) << 16) | covered, out + (size_t)y * width + x);
    }
  }
  FRAME_STORES_DONE();
}
