// The planned frame (docs/planner.md): the planner's work lists for U modeled units, the units' depth
// pass (render_tiles.cl with PLAN_PASS=1: a work-item per unit, or units pulling batches from a
// counter; on one device or spread over its sub-devices), then the usual tile kernel as the resolve
// (PLAN_PASS=2), shading only each pixel's winner.
#include <algorithm>
#include <chrono>

#include "kernel_variant.hpp"
#include "parashade/errors.hpp"
#include "renderer_impl.hpp"
#include "tile_kernel_args.hpp"

namespace parashade {
namespace {

double event_span_ms(cl_ulong start, cl_ulong end) { return end > start ? double(end - start) * 1e-6 : 0.0; }

}  // namespace

// Units to sub-devices in contiguous blocks, in proportion to their compute units (unit u runs on the
// sub-device whose block holds u). dynamic: the batches too, in proportion to each one's units: a
// counter is shared only by the work-items of one device (the spec promises atomics on a buffer to the
// work-items of one device, not across devices), so each sub-device's units pull from their own range.
std::vector<UnitPassShare> Renderer::Impl::unit_pass_shares(const Plan& plan) const {
  const int units = plan.report.units, packets = plan.work.packets();
  if (unit_devices_.empty()) return {{device_.info().name, device_.info().compute_units, 0, units, 0, packets}};
  std::vector<int> cus;
  for (const Device* d : unit_devices_) cus.push_back(std::max(1, d->info().compute_units));
  const std::vector<int> unit_first = proportional_blocks(units, cus);
  std::vector<int> unit_count;
  for (std::size_t k = 0; k < cus.size(); ++k) unit_count.push_back(unit_first[k + 1] - unit_first[k]);
  const bool dynamic = plan.report.partition == Partition::dynamic;
  const std::vector<int> packet_first = dynamic ? proportional_blocks(packets, unit_count) : unit_first;
  std::vector<UnitPassShare> out;
  for (std::size_t k = 0; k < cus.size(); ++k)
    out.push_back({unit_devices_[k]->info().name, unit_devices_[k]->info().compute_units, unit_first[k], unit_count[k],
                   packet_first[k], packet_first[k + 1] - packet_first[k]});
  return out;
}

void Renderer::Impl::enqueue_unit_pass(cl::Kernel& resolve, const KernelVariant& variant, const TileKernelArgs& frame_args,
                                 const Plan& plan, const std::vector<UnitPassShare>& shares, std::size_t pixels,
                                 UnitPassEvents& events) {
  cl::CommandQueue& q = device_.queue();
  const WorkLists& w = plan.work;
  const std::size_t key_bytes = pixels * sizeof(cl_ulong);
  ensure(keys_, keys_cap_, key_bytes, CL_MEM_READ_WRITE);
  auto upload = [&](cl::Buffer& b, std::size_t& cap, const std::vector<std::uint32_t>& v) {
    ensure(b, cap, v.size() * sizeof(std::uint32_t), CL_MEM_READ_ONLY);
    if (!v.empty()) q.enqueueWriteBuffer(b, CL_FALSE, 0, v.size() * sizeof(std::uint32_t), v.data());
  };
  upload(plan_packets_, plan_packets_cap_, w.packet_first);
  upload(plan_vtiles_, plan_vtiles_cap_, w.vtile_tile);
  upload(plan_starts_, plan_starts_cap_, w.vtile_start);
  upload(plan_list_, plan_list_cap_, w.list);
  ensure(plan_counter_, plan_counter_cap_, sizeof(cl_int), CL_MEM_READ_WRITE);
  set_plan_pass_args(resolve, {&keys_, &plan_packets_, &plan_vtiles_, &plan_counter_, cl_int(w.packets())});

  KernelVariant unit_variant = variant;
  unit_variant.plan_pass = 1;
  unit_variant.plan_dynamic = plan.report.partition == Partition::dynamic;
  // The resolve kernel's arguments, with the plan's virtual tiles and lists in place of the bins, for
  // units [first_unit, first_unit + units) as work-items (global offset first_unit) that run packets up to
  // `end` (static: packet = unit; dynamic: pulled from `counter`, which starts at the share's first packet).
  TileKernelArgs unit_args = frame_args;
  unit_args.tile_start = &plan_starts_;
  unit_args.tile_list = &plan_list_;
  auto unit_kernel = [&](Device& d, cl::Buffer& keys, cl::Buffer& counter, int end) {
    cl::Kernel k(d.program(kernel_files(unit_variant), unit_variant.build_options()), "render_tiles");
    set_tile_kernel_args(k, unit_args);
    set_plan_pass_args(k, {&keys, &plan_packets_, &plan_vtiles_, &counter, cl_int(end)});
    return k;
  };
  events = UnitPassEvents{};
  if (unit_devices_.empty()) {
    // One work-item per modeled unit: U units run as U work-items whatever the device's cores.
    q.enqueueFillBuffer(keys_, ~cl_ulong(0), 0, key_bytes);
    q.enqueueFillBuffer(plan_counter_, cl_int(0), 0, sizeof(cl_int));
    cl::Kernel k = unit_kernel(device_, keys_, plan_counter_, w.packets());
    q.enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(std::size_t(plan.report.units)), cl::NDRange(1), nullptr,
                           &events.share.emplace_back());
    return;
  }

  // Sub-devices: each runs its block of units on its own queue, after the frame's uploads on the parent's
  // queue (a marker), into keys of its own (the first share with units into the resolve's keys), so
  // no two devices write one buffer at once; then the parent's queue waits for all of them and takes
  // the minimum of the keys, which is the same whatever order the units ran in.
  share_keys_.resize(shares.size());
  share_counters_.resize(shares.size());
  share_keys_cap_.resize(shares.size(), 0);
  share_counters_cap_.resize(shares.size(), 0);
  std::vector<cl::Event> uploaded(1);
  q.enqueueMarkerWithWaitList(nullptr, &uploaded[0]);
  q.flush();
  std::vector<cl::Buffer*> to_merge;
  bool first = true;
  for (std::size_t k = 0; k < shares.size(); ++k) {
    const UnitPassShare& s = shares[k];
    if (s.units == 0) continue;
    Device& d = *unit_devices_[k];
    cl::Buffer& keys = first ? keys_ : ensure(share_keys_[k], share_keys_cap_[k], key_bytes, CL_MEM_READ_WRITE);
    if (!first) to_merge.push_back(&keys);
    first = false;
    cl::Buffer& counter = ensure(share_counters_[k], share_counters_cap_[k], sizeof(cl_int), CL_MEM_READ_WRITE);
    cl::CommandQueue& sq = d.queue();
    sq.enqueueFillBuffer(keys, ~cl_ulong(0), 0, key_bytes, &uploaded);
    sq.enqueueFillBuffer(counter, cl_int(s.first_packet), 0, sizeof(cl_int));
    cl::Kernel kernel = unit_kernel(d, keys, counter, s.first_packet + s.packets);
    sq.enqueueNDRangeKernel(kernel, cl::NDRange(std::size_t(s.first_unit)), cl::NDRange(std::size_t(s.units)),
                            cl::NDRange(1), nullptr, &events.share.emplace_back());
    sq.flush();  // start now, concurrently with the other sub-devices
  }
  q.enqueueBarrierWithWaitList(&events.share);
  cl::Kernel merge(device_.program({"plan_merge.cl"}, ""), "plan_merge_keys");
  for (cl::Buffer* other : to_merge) {
    merge.setArg(0, keys_);
    merge.setArg(1, *other);
    merge.setArg(2, cl_uint(pixels));
    q.enqueueNDRangeKernel(merge, cl::NullRange, cl::NDRange(pixels), cl::NullRange, nullptr, &events.merge.emplace_back());
  }
}

void Renderer::Impl::unit_pass_times(const UnitPassEvents& events, FrameTimings& t) const {
  cl_ulong first = ~cl_ulong(0), last = 0;
  std::size_t e = 0;
  for (const UnitPassShare& s : frame_.stats.unit_pass) {
    if (s.units == 0) {
      t.unit_pass_share_ms.push_back(0.0);
      continue;
    }
    const cl_ulong start = events.share[e].getProfilingInfo<CL_PROFILING_COMMAND_START>();
    const cl_ulong end = events.share[e++].getProfilingInfo<CL_PROFILING_COMMAND_END>();
    first = std::min(first, start);
    last = std::max(last, end);
    t.unit_pass_share_ms.push_back(event_span_ms(start, end));
  }
  // PoCL's CPU devices stamp every queue's events from the host's one monotonic clock, so the span
  // across sub-devices is meaningful there.
  t.unit_pass_ms = event_span_ms(first, last);
  for (const cl::Event& m : events.merge)
    t.key_merge_ms += event_span_ms(m.getProfilingInfo<CL_PROFILING_COMMAND_START>(),
                                    m.getProfilingInfo<CL_PROFILING_COMMAND_END>());
}

std::vector<std::uint64_t> Renderer::Impl::plan_keys(const Scene& scene) {
  if (!options_.plan) throw UsageError("depth keys exist only in a planned frame (--cu)");
  std::vector<std::uint64_t> keys(std::size_t(scene.width) * scene.height);
  try {
    device_.queue().enqueueReadBuffer(keys_, CL_TRUE, 0, keys.size() * sizeof(cl_ulong), keys.data());
  } catch (const cl::Error&) {
    rethrow_cl_error("reading the depth keys on '" + device_.info().name + "'");
  }
  return keys;
}

}  // namespace parashade
