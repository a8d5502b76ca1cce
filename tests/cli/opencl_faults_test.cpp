// OpenCL faults a user meets without any bug in parashade: no OpenCL driver installed, a driver without
// devices. Exit 4 (device failure), a message that names the package to install, nothing written.
#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

#include "cli_fixture.hpp"

namespace parashade {
namespace {

using namespace testing_support;

using CliOpenClFaults = CliTest;

// The ICD loader finds no driver when its vendor directory is empty: as on a machine without PoCL.
TEST_F(CliOpenClFaults, NoPlatformNamesThePackageToInstall) {
  std::filesystem::create_directories(dir_.path() / "no-vendors");
  const ScopedEnv vendors("OCL_ICD_VENDORS", (dir_.path() / "no-vendors").string());
  const auto scene = input("ball.json", sphere_scene());
  EXPECT_TRUE(fails_with(render(scene), kDeviceFailure, {"no OpenCL platform", "pocl-opencl-icd"}));
  EXPECT_TRUE(nothing_written());
  EXPECT_TRUE(fails_with(run_parashade({"devices"}), kDeviceFailure, {"no OpenCL platform", "pocl-opencl-icd"}));
}

// PoCL with an unknown device type in POCL_DEVICES offers a platform without devices.
TEST_F(CliOpenClFaults, PlatformWithoutDevicesNamesThePackageToInstall) {
  const ScopedEnv devices("POCL_DEVICES", "no-such-device-type");
  const auto scene = input("ball.json", sphere_scene());
  const RunResult r = render(scene, {"--device", "0"});
  ASSERT_TRUE(r.exited()) << r;
  EXPECT_EQ(r.exit_code, kDeviceFailure) << r;
  EXPECT_NE(r.err.find("pocl-opencl-icd"), std::string::npos) << r;
  EXPECT_TRUE(nothing_written());
}

// A mesh whose triangle records need more than the device can allocate in one buffer: PoCL limited to
// 1 GB (POCL_MEMORY_LIMIT=1: at most 256 MiB per buffer) and a sphere of 8.4 M triangles (about 0.7 GB
// of records). The message gives the size asked for and the device's limit; nothing is written. The
// combined method takes the whole frame's records at once (Gouraud and Phong would stream them in bands
// of at most 16 MiB, FramePipeline::begin_frame, and render).
TEST_F(CliOpenClFaults, BufferBeyondTheDeviceLimitNamesTheSize) {
  const ScopedEnv limit("POCL_MEMORY_LIMIT", "1");
  const auto scene = input("huge.json", R"({"resolution": [64, 48], "camera": {"position": [0, 0, 4], "target": [0, 0, 0]},
    "objects": [{"shape": {"type": "sphere", "slices": 2048, "stacks": 2049}}]})");
  const RunResult r = run_parashade(render_args(scene, {"--method", "combined:2"}), {}, std::chrono::seconds(300));
  EXPECT_TRUE(fails_with(r, kDeviceFailure, {"a buffer of", "bytes exceeds the device's largest allocation (268435456 bytes)"}));
  EXPECT_TRUE(nothing_written());
}

}  // namespace
}  // namespace parashade
