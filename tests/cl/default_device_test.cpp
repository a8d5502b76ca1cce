// The default device (device.hpp, docs/environment.md): the real device with the most compute units; a
// simulator only when nothing else exists; PoCL's one-thread `basic` only when PoCL has no threaded
// device; among equals PoCL's threaded device, then platform and device name, whatever the order the ICD
// loader lists them in. Device lists written here as `parashade devices` shows them on this project's
// machines (names, platforms, compute units); no device is opened.
#include <algorithm>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "parashade/device.hpp"

namespace parashade {
namespace {

DeviceInfo device(const std::string& platform, const std::string& name, const std::string& type, int compute_units) {
  DeviceInfo d;
  d.platform = platform;
  d.name = name;
  d.type = type;
  d.compute_units = compute_units;
  return d;
}

const DeviceInfo kOclgrind = device("Oclgrind", "Oclgrind Simulator", "gpu", 1);
const DeviceInfo kPthread =
    device("Portable Computing Language", "pthread-skylake-avx512-Intel(R) Xeon(R) Processor", "cpu", 2);
const DeviceInfo kBasic = device("Portable Computing Language", "basic-skylake-avx512-Intel(R) Xeon(R) Processor", "cpu", 1);
const DeviceInfo kIntel = device("Intel(R) OpenCL", "Intel(R) Xeon(R) Processor", "cpu", 2);

// The name of the default device of `devices`, indexed as list_devices() indexes them.
std::string default_of(std::vector<DeviceInfo> devices) {
  for (std::size_t i = 0; i < devices.size(); ++i) devices[i].index = int(i);
  const int chosen = default_device(devices);
  if (chosen < 0 || chosen >= int(devices.size())) return "(none: " + std::to_string(chosen) + ")";
  EXPECT_EQ(devices[std::size_t(chosen)].index, chosen);
  return devices[std::size_t(chosen)].platform + " / " + devices[std::size_t(chosen)].name;
}

std::string named(const DeviceInfo& d) { return d.platform + " / " + d.name; }

TEST(DefaultDevice, NeverTheSimulatorWhenARealDeviceExists) {
  EXPECT_EQ(default_of({kOclgrind, kPthread}), named(kPthread));
  // Oclgrind says it is a GPU: its name, not its type, tells it apart. Even with more compute units.
  DeviceInfo big_simulator = kOclgrind;
  big_simulator.compute_units = 64;
  EXPECT_EQ(default_of({big_simulator, kBasic}), named(kBasic));
  EXPECT_TRUE(is_simulator(kOclgrind));
  EXPECT_FALSE(is_simulator(kPthread));
  EXPECT_FALSE(is_simulator(kIntel));
}

TEST(DefaultDevice, TheSimulatorWhenItIsTheOnlyDevice) { EXPECT_EQ(default_of({kOclgrind}), named(kOclgrind)); }

TEST(DefaultDevice, PthreadOverBasic) {
  EXPECT_EQ(default_of({kBasic, kPthread}), named(kPthread));  // POCL_DEVICES="basic pthread"
  EXPECT_EQ(default_of({kPthread, kBasic}), named(kPthread));
  // On one core both have one compute unit: still the threaded device; and PoCL 4's name for it.
  DeviceInfo one_core = kPthread;
  one_core.compute_units = 1;
  EXPECT_EQ(default_of({kBasic, one_core}), named(one_core));
  const DeviceInfo cpu = device("Portable Computing Language", "cpu-haswell-AMD EPYC 7B13", "cpu", 1);
  EXPECT_EQ(default_of({kBasic, cpu}), named(cpu));
  // basic alone is taken, and over the simulator.
  EXPECT_EQ(default_of({kOclgrind, kBasic}), named(kBasic));
}

TEST(DefaultDevice, MostComputeUnits) {
  DeviceInfo intel8 = kIntel;
  intel8.compute_units = 8;
  EXPECT_EQ(default_of({kOclgrind, kPthread, intel8}), named(intel8));
  const DeviceInfo gpu = device("NVIDIA CUDA", "NVIDIA A100", "gpu", 108);
  EXPECT_EQ(default_of({kPthread, gpu, kBasic}), named(gpu));
}

// Equal compute units: PoCL's pthread (the reference device), in whatever order the platforms come.
TEST(DefaultDevice, TiesGoToPoclPthreadThenByName) {
  std::vector<DeviceInfo> devices = {kOclgrind, kIntel, kPthread, kBasic};
  std::sort(devices.begin(), devices.end(), [](const DeviceInfo& a, const DeviceInfo& b) { return a.name < b.name; });
  do {
    EXPECT_EQ(default_of(devices), named(kPthread));
  } while (std::next_permutation(devices.begin(), devices.end(),
                                 [](const DeviceInfo& a, const DeviceInfo& b) { return a.name < b.name; }));
  // Two other devices of 4 units: the platform name decides, not the listing order.
  const DeviceInfo a = device("AMD Accelerated Parallel Processing", "gfx90c", "gpu", 4);
  const DeviceInfo b = device("Intel(R) OpenCL", "Intel(R) Core(TM) i5", "cpu", 4);
  EXPECT_EQ(default_of({a, b}), named(a));
  EXPECT_EQ(default_of({b, a}), named(a));
}

TEST(DefaultDevice, NoneOfAnEmptyList) { EXPECT_EQ(default_device({}), -1); }

TEST(DefaultDevice, NoteNamesTheDeviceAndHowToChoose) {
  EXPECT_EQ(default_device_note(kPthread),
            "device: pthread-skylake-avx512-Intel(R) Xeon(R) Processor (Portable Computing Language, 2 "
            "compute units; the default: --device to choose)");
  EXPECT_NE(default_device_note(kBasic).find("1 compute unit;"), std::string::npos);
}

}  // namespace
}  // namespace parashade
