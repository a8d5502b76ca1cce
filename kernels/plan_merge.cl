/* Units on sub-devices (docs/planner.md): each sub-device's units leave their least keys in a buffer
 * of their own; the parent takes the minimum into the resolve's keys. The minimum is commutative, so
 * the result is the key buffer one device's units would have left. */
#include "common.h"

__kernel void plan_merge_keys(__global ulong* keys, __global const ulong* other, uint n) {
  const size_t i = get_global_id(0);
  if (i < n) keys[i] = min(keys[i], other[i]);
}
