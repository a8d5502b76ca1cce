#pragma once
// The kernel layout a device gets when neither the command line nor a tuned entry of the tune cache for
// that device chooses it (docs/pipeline.md "Defaults from the device"): the kernel's shape, its work-group
// and its work-items from the device's properties. resolve_render (render_step.hpp) applies them and says
// where each setting came from (LayoutSources).
#include <string>

#include "parashade/device.hpp"
#include "parashade/frame_config.hpp"

namespace parashade {

// The vector shape's work-items per compute unit on a CPU (at most one per tile): each walks interleaved
// tiles. PoCL 3.1's pthread device hands a thread about half the remaining work-groups at a time (at most 32
// times its thread count; get_wg_index_range in its scheduler), so a few work-groups split the frame almost
// statically and one core idles while the other finishes the busy tiles; 256 per compute unit leave it
// chunks of an eighth of a 1080 frame or less. Against 16 per compute unit on 64-pixel tiles (2 compute
// units, frames alternating in one process): 1920x1080 frames 1.00-1.10x faster, 3840x2160 1.02-1.30x
// (bench/README.md run AC). One work-group per 16-pixel tile is slower again: PoCL pays a fixed cost per
// work-group. A property of the CPU runtime's scheduler, which OpenCL does not report, so a measured constant.
constexpr int kCpuWorkItemsPerComputeUnit = 256;

// Whether `d` runs many work-items in lockstep lanes (a GPU or an accelerator that is not a simulator):
// such a device makes its vectors from work-items. A CPU's compute unit is a thread that a work-item's own
// 16-lane vectors fill; a simulator (Oclgrind, which says it is a GPU) runs work-items one by one.
bool fills_lanes_with_work_items(const DeviceInfo& d);

// The kernel shape for `d`: lanes where the device fills its lanes with work-items, else vector.
KernelShape device_kernel_shape(const DeviceInfo& d);

// The work-group size for `shape` on `d` with tiles of `tile` pixels: vector 1 (a work-item walks tiles of
// its own); lanes LANES_WORK_GROUP_DEFAULT within the tile's pixels (shape_work_group_size) and the device's
// largest work-group.
int device_work_group_size(const DeviceInfo& d, KernelShape shape, int tile);

// The vector shape's work-items for a frame of `tiles` tiles on `d` (before rounding up to whole
// work-groups): one a tile where the device fills lanes with work-items; elsewhere one a tile up to
// kCpuWorkItemsPerComputeUnit per compute unit.
int device_work_items(const DeviceInfo& d, int tiles);

// Where a render's layout settings came from: kFromOption (the command line or the library's caller),
// kFromTuneCache (the tuned entry of this device), kFromDevice (the rules above) or kFromFrame (the tile,
// tile_choice.hpp: by the frame).
constexpr const char* kFromOption = "option";
constexpr const char* kFromTuneCache = "tune cache";
constexpr const char* kFromDevice = "device properties";
constexpr const char* kFromFrame = "frame";
struct LayoutSources {
  std::string kernel_shape = kFromOption, work_group_size = kFromOption, work_items = kFromOption, tile = kFromOption;
};

}  // namespace parashade
