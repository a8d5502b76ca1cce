#pragma once
// Sub-devices of one OpenCL device, named by `--device sub:NAME:N` (clCreateSubDevices with
// CL_DEVICE_PARTITION_EQUALLY: sub-devices of N compute units) or `sub:NAME:N1+N2+...`
// (CL_DEVICE_PARTITION_BY_COUNTS). Two uses: the bands of a frame split across devices (each sub-device
// in a context of its own, split_renderer.hpp), and the modeled units of --cu spread over the
// sub-devices (parent and sub-devices in one context, so that they share the frame's buffers:
// docs/planner.md).
#include <memory>
#include <string>
#include <vector>

#include "parashade/device.hpp"

namespace parashade {

// True for "sub:..." (a malformed one is refused by open_sub_devices with a UsageError).
bool is_sub_device_selector(const std::string& selector);

enum class SubDeviceContext {
  own,     // each sub-device its own context and queue (bands of a split frame)
  shared,  // parent and sub-devices in one context, each with its own queue (the units' depth pass)
};

struct SubDevices {
  std::unique_ptr<Device> parent;             // with `shared`, in the sub-devices' context
  std::vector<std::unique_ptr<Device>> subs;  // named "<parent> [sub-device i]", compute units as asked
};

// Throws UsageError for a malformed selector, DeviceError when the device is missing or cannot be
// partitioned that way (the OpenCL error named).
SubDevices open_sub_devices(const std::string& selector, SubDeviceContext context);

}  // namespace parashade
