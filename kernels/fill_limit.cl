/* The device's fill limit: every pixel of an RGBA8 frame written once, one work-item per 16 pixels,
 * nothing computed. No renderer can write a frame faster on this device; bench_frame reports it as
 * the ceiling beside the real frames. */
#include "common.h"

__kernel void fill_limit(__global uint* out, uint value, int vectors) {
  const int i = get_global_id(0);
  if (i < vectors) vstoreV((uintV)value, i, out);
}
