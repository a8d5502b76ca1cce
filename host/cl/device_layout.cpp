// The layout a device gets from its properties (device_layout.hpp, docs/pipeline.md "Defaults from the device").
#include "parashade/device_layout.hpp"

#include <algorithm>

#include "parashade/kernels/constants.h"

namespace parashade {

bool fills_lanes_with_work_items(const DeviceInfo& d) {
  return (d.type == "gpu" || d.type == "accelerator") && !is_simulator(d);
}

KernelShape device_kernel_shape(const DeviceInfo& d) {
  return fills_lanes_with_work_items(d) ? KernelShape::lanes : KernelShape::vector;
}

int device_work_group_size(const DeviceInfo& d, KernelShape shape, int tile) {
  int n = shape_work_group_size(shape, tile);
  // The largest power of two within the device's work-group (0: not reported, no limit).
  while (d.max_work_group > 0 && std::size_t(n) > d.max_work_group && n > 1) n /= 2;
  return n;
}

int device_work_items(const DeviceInfo& d, int tiles) {
  const int n = std::max(1, tiles);
  if (fills_lanes_with_work_items(d)) return n;
  return std::min(n, kCpuWorkItemsPerComputeUnit * std::max(1, d.compute_units));
}

}  // namespace parashade
