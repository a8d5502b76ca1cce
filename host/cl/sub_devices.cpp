#include "parashade/sub_devices.hpp"

#include <algorithm>
#include <exception>

#include <CL/opencl.hpp>

#include "parashade/errors.hpp"

namespace parashade {

bool is_sub_device_selector(const std::string& selector) { return selector.rfind("sub:", 0) == 0; }

SubDevices open_sub_devices(const std::string& selector, SubDeviceContext context) {
  const std::size_t colon = selector.rfind(':');
  const std::string name = selector.substr(4, colon > 4 ? colon - 4 : 0);
  std::vector<int> counts;
  const std::string spec = colon > 4 ? selector.substr(colon + 1) : "";
  for (std::size_t from = 0; from <= spec.size();) {
    const std::size_t plus = std::min(spec.find('+', from), spec.size());
    int n = 0;
    try {
      std::size_t used = 0;
      n = std::stoi(spec.substr(from, plus - from), &used);
      if (used != plus - from) n = 0;
    } catch (const std::exception&) {
    }
    counts.push_back(n);
    from = plus + 1;
  }
  const bool bad = name.empty() || counts.empty() || std::any_of(counts.begin(), counts.end(), [](int n) { return n < 1; });
  if (!is_sub_device_selector(selector) || bad)
    throw UsageError("sub-device selector '" + selector +
                     "': expected sub:NAME:N (N compute units per sub-device) or sub:NAME:N1+N2+... (by counts)");
  SubDevices out;
  out.parent = open_device(name);
  const bool by_counts = counts.size() > 1;
  std::vector<cl_device_partition_property> props;
  if (by_counts) {
    props.push_back(CL_DEVICE_PARTITION_BY_COUNTS);
    for (int n : counts) props.push_back(cl_device_partition_property(n));
    props.push_back(CL_DEVICE_PARTITION_BY_COUNTS_LIST_END);
  } else {
    props = {CL_DEVICE_PARTITION_EQUALLY, cl_device_partition_property(counts[0])};
  }
  props.push_back(0);
  const DeviceInfo parent = out.parent->info();
  std::vector<cl::Device> subs;
  cl::Context shared;
  try {
    out.parent->device().createSubDevices(props.data(), &subs);
    if (context == SubDeviceContext::shared) {
      // A context may hold sub-devices next to their parent (OpenCL 1.2, clCreateContext); buffers of
      // one context can be used by all its devices, with events ordering the commands of their queues.
      std::vector<cl::Device> all{out.parent->device()};
      all.insert(all.end(), subs.begin(), subs.end());
      shared = cl::Context(all);
      out.parent = std::make_unique<Device>(out.parent->device(), parent, shared);
    }
  } catch (const cl::Error&) {
    rethrow_cl_error("partitioning '" + parent.name + "' into sub-devices of " + spec + " compute unit(s)");
  }
  for (std::size_t i = 0; i < subs.size(); ++i) {
    DeviceInfo info = parent;
    info.name += " [sub-device " + std::to_string(i) + "]";
    info.compute_units = by_counts ? counts[i] : counts[0];
    out.subs.push_back(context == SubDeviceContext::shared ? std::make_unique<Device>(subs[i], info, shared)
                                                           : std::make_unique<Device>(subs[i], info));
  }
  return out;
}

}  // namespace parashade
