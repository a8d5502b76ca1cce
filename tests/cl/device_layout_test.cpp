// The layout a device gets from its properties (device_layout.hpp, docs/pipeline.md "Defaults from the
// device"): on a CPU (PoCL's pthread, Intel's runtime) and on Oclgrind the vector shape, work-groups of one
// and one work-item a tile up to 256 per compute unit, as the renderer took before the rule (the measured
// choice for PoCL); on a GPU the lanes shape, 256 work-items a work-group within the tile's pixels and the
// device's largest work-group, and a work-item per tile for the vector shape. Devices written as `parashade
// devices` shows them; the GPU is made up (none is available here). No device is opened.
#include <string>

#include <gtest/gtest.h>

#include "parashade/device_layout.hpp"
#include "parashade/render_step.hpp"
#include "parashade/units.hpp"

namespace parashade {
namespace {

DeviceInfo device(const std::string& platform, const std::string& name, const std::string& type, int compute_units,
                  std::size_t max_work_group) {
  DeviceInfo d;
  d.platform = platform;
  d.name = name;
  d.type = type;
  d.compute_units = compute_units;
  d.max_work_group = max_work_group;
  return d;
}

const DeviceInfo kPthread =
    device("Portable Computing Language", "pthread-skylake-avx512-Intel(R) Xeon(R) Processor", "cpu", 2, 4096);
const DeviceInfo kIntel = device("Intel(R) OpenCL", "Intel(R) Xeon(R) Processor", "cpu", 2, 8192);
const DeviceInfo kOclgrind = device("Oclgrind", "Oclgrind Simulator", "gpu", 1, 1024);
const DeviceInfo kGpu = device("Some GPU platform", "Some GPU", "gpu", 100, 1024);

TEST(DeviceLayout, ACpuKeepsTheVectorShapeAndItsWorkItems) {
  for (const DeviceInfo& d : {kPthread, kIntel}) {
    SCOPED_TRACE(d.platform);
    EXPECT_FALSE(fills_lanes_with_work_items(d));
    EXPECT_EQ(device_kernel_shape(d), KernelShape::vector);
    EXPECT_EQ(device_work_group_size(d, KernelShape::vector, 64), 1);
    // 1920x1080: 510 tiles of 64 (one work-item each), 2040 of 32 (512: 256 for each of 2 compute units).
    EXPECT_EQ(device_work_items(d, 510), 510);
    EXPECT_EQ(device_work_items(d, 2040), 512);
    EXPECT_EQ(device_work_items(d, 0), 1);
  }
  DeviceInfo eight = kPthread;
  eight.compute_units = 8;
  EXPECT_EQ(device_work_items(eight, 8160), 2048);
}

TEST(DeviceLayout, TheSimulatorRunsAsACpu) {
  // Oclgrind says it is a GPU, but runs work-items one by one.
  EXPECT_FALSE(fills_lanes_with_work_items(kOclgrind));
  EXPECT_EQ(device_kernel_shape(kOclgrind), KernelShape::vector);
  EXPECT_EQ(device_work_items(kOclgrind, 2040), 256);
}

TEST(DeviceLayout, OnlyACpuPrefetchesWithTheCompilersIntrinsic) {
  // Intel's runtime compiles OpenCL's prefetch() as a call: the kernels prefetch by the intrinsic on a CPU
  // device (device.hpp), which Oclgrind refuses and a GPU's compiler need not know.
  for (const DeviceInfo& d : {kPthread, kIntel}) EXPECT_EQ(device_build_options(d), " -D CPU_DEVICE=1") << d.platform;
  for (const DeviceInfo& d : {kOclgrind, kGpu}) EXPECT_EQ(device_build_options(d), "") << d.platform;
}

TEST(DeviceLayout, AGpuTakesTheLanesShape) {
  EXPECT_TRUE(fills_lanes_with_work_items(kGpu));
  EXPECT_EQ(device_kernel_shape(kGpu), KernelShape::lanes);
  EXPECT_EQ(device_work_group_size(kGpu, KernelShape::lanes, 32), 256);
  EXPECT_EQ(device_work_group_size(kGpu, KernelShape::lanes, 16), 256);
  EXPECT_EQ(device_work_group_size(kGpu, KernelShape::vector, 32), 1);
  // A smaller largest work-group: the largest power of two within it.
  DeviceInfo small = kGpu;
  small.max_work_group = 192;
  EXPECT_EQ(device_work_group_size(small, KernelShape::lanes, 32), 128);
  // The vector shape there (a frame the lanes shape cannot take): a work-item per tile, the machine is wide.
  EXPECT_EQ(device_work_items(kGpu, 2040), 2040);
  DeviceInfo accelerator = kGpu;
  accelerator.type = "accelerator";
  EXPECT_EQ(device_kernel_shape(accelerator), KernelShape::lanes);
}

// What resolve_render takes without --kernel-shape (device_shape_for): the device's own shape where the table
// of combinations allows it; a frame the lanes shape cannot take keeps the vector shape, and says why, in the
// note and in the shape's source (the layout line and the report's layout.sources), which then is not the
// device's properties.
TEST(DeviceLayout, AGpuKeepsTheVectorShapeForAFrameTheLanesShapeRefuses) {
  RenderOptions plain;
  DeviceShape taken = device_shape_for(kGpu, plain, DeviceMode::one);
  EXPECT_EQ(taken.shape, KernelShape::lanes);
  EXPECT_EQ(taken.refused, "");
  EXPECT_EQ(taken.source, "device properties");
  taken = device_shape_for(kPthread, plain, DeviceMode::one);
  EXPECT_EQ(taken.shape, KernelShape::vector);
  EXPECT_EQ(taken.refused, "");
  EXPECT_EQ(taken.source, "device properties");
  RenderOptions fixed;
  fixed.units = parse_units("counter");
  fixed.arith = parse_arith("fixed:12.12");
  taken = device_shape_for(kGpu, fixed, DeviceMode::one);
  EXPECT_EQ(taken.shape, KernelShape::vector);
  EXPECT_NE(taken.refused.find("the vector kernel shape on Some GPU, whose own is lanes"), std::string::npos)
      << taken.refused;
  EXPECT_EQ(taken.source.rfind("option (the device's lanes refused: ", 0), 0u) << taken.source;
  EXPECT_NE(taken.source.find("units"), std::string::npos) << taken.source;  // the table's reason
  EXPECT_EQ(taken.source.back(), ')') << taken.source;
}

// The lanes shape's default work-group, one rule (frame_config.hpp's shape_work_group_size): what the options
// resolve it to is what a device without a limit gets, at every tile size, before a tile is chosen (0) too.
TEST(DeviceLayout, TheOptionsAndTheDeviceTakeOneDefaultWorkGroup) {
  DeviceInfo unlimited = kGpu;
  unlimited.max_work_group = 0;  // not reported: no limit
  for (KernelShape shape : {KernelShape::vector, KernelShape::lanes})
    for (int tile : {0, 8, 16, 32, 64}) {
      RenderOptions o;
      o.kernel_shape = shape;
      o.tile_size = tile;
      o.work_group_size = 0;
      EXPECT_EQ(o.group_size(), device_work_group_size(unlimited, shape, tile))
          << kernel_shape_name(shape) << " tile " << tile;
      EXPECT_GE(o.group_size(), 1) << kernel_shape_name(shape) << " tile " << tile;
    }
  EXPECT_EQ(shape_work_group_size(KernelShape::lanes, 64), 256);
  EXPECT_EQ(shape_work_group_size(KernelShape::lanes, 8), 64);  // within the tile's pixels
}

}  // namespace
}  // namespace parashade
