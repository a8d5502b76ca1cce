// `render --device A,B` / `--device all`: one frame split across PoCL's pthread and basic devices
// (POCL_DEVICES="pthread basic", chosen by name: PoCL orders devices its own way) is the same image as
// one device's. A device made to fail (PARASHADE_FAIL_DEVICE, device.hpp) ends the run naming it, or
// with --keep-going is dropped with a warning naming it.
#include <fstream>
#include <iterator>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "cli_fixture.hpp"

namespace parashade {
namespace {

using namespace testing_support;

std::string bytes_of(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

class SplitDevices : public CliTest {
 protected:
  const ScopedEnv devices_{"POCL_DEVICES", "pthread basic"};
};

TEST_F(SplitDevices, TwoDevicesGiveTheSingleDeviceImage) {
  const auto scene = input("ball.json", sphere_scene());
  ASSERT_TRUE(succeeds(render(scene, {"--device", "pthread", "--no-tuned", "--size", "200x150"})));
  const std::string single = bytes_of(image());
  // sub:pthread:1 = the pthread device cut into sub-devices of one compute unit (clCreateSubDevices).
  for (const char* list : {"pthread,basic", "basic,pthread", "all", "sub:pthread:1", "sub:pthread:1+1"}) {
    const RunResult r = render(scene, {"--device", list, "--size", "200x150"});
    ASSERT_TRUE(succeeds(r)) << list;
    EXPECT_EQ(bytes_of(image()), single) << "split over " << list << " differs from the pthread device's image";
    const nlohmann::json rep = read_report();
    ASSERT_EQ(field(rep, "/devices").size(), 2u) << list;
    int rows = 0;
    for (const auto& d : rep["devices"]) rows += d["tile_rows"].get<int>();
    EXPECT_EQ(rows, (150 + 15) / 16) << "the bands cover every tile row once";
  }
}

TEST_F(SplitDevices, BadListsAreNamed) {
  const auto scene = input("ball.json", sphere_scene());
  EXPECT_TRUE(fails_with(render(scene, {"--device", "pthread,pthread"}), kUsage, {"twice"}));
  EXPECT_TRUE(fails_with(render(scene, {"--device", "pthread,nosuchdevice"}), kDeviceFailure, {"nosuchdevice"}));
  EXPECT_TRUE(fails_with(render(scene, {"--device", "sub:pthread:1+x"}), kUsage, {"sub:pthread:1+x"}));
  EXPECT_TRUE(fails_with(render(scene, {"--device", "sub:pthread:0"}), kUsage, {"sub:pthread:0"}));
  EXPECT_TRUE(fails_with(render(scene, {"--device", "pthread", "--keep-going"}), kUsage, {"--keep-going", "one device"}));
  EXPECT_TRUE(nothing_written());
}

// PARASHADE_FAIL_DEVICE=basic: every kernel build on the basic device fails (#error in common.h).
TEST_F(SplitDevices, AFailingDeviceEndsTheRunNamingIt) {
  const auto scene = input("ball.json", sphere_scene());
  const ScopedEnv fail("PARASHADE_FAIL_DEVICE", "basic");
  const RunResult r = render(scene, {"--device", "pthread,basic"});
  EXPECT_TRUE(fails_with(r, kDeviceFailure, {"device 'basic-", "CL_BUILD_PROGRAM_FAILURE", "PARASHADE_FAIL_DEVICE"}));
  EXPECT_TRUE(nothing_written());
}

TEST_F(SplitDevices, KeepGoingDropsTheFailingDeviceAndSaysSo) {
  const auto scene = input("ball.json", sphere_scene());
  ASSERT_TRUE(succeeds(render(scene, {"--device", "pthread", "--no-tuned", "--size", "200x150"})));
  const std::string single = bytes_of(image());
  // The basic device of a list, and one sub-device of two (its name ends in "[sub-device 1]").
  for (const auto& [list, failing] : {std::pair<std::string, std::string>{"pthread,basic", "basic"},
                                      {"sub:pthread:1", "sub-device 1"}}) {
    const ScopedEnv fail("PARASHADE_FAIL_DEVICE", failing);
    const RunResult r = render(scene, {"--device", list, "--keep-going", "--size", "200x150"});
    ASSERT_TRUE(succeeds(r)) << list;
    EXPECT_NE(r.err.find("warning: device '"), std::string::npos) << r;
    EXPECT_NE(r.err.find(failing), std::string::npos) << "the warning names the dropped device" << r;
    EXPECT_NE(r.err.find("continuing on the others"), std::string::npos) << r;
    EXPECT_EQ(bytes_of(image()), single) << list << " without " << failing << " differs from the pthread device's image";
    const nlohmann::json rep = read_report();
    int failed = 0, rows = 0;
    for (const auto& d : rep["devices"]) {
      failed += d["failed"].get<bool>();
      rows += d["tile_rows"].get<int>();
      if (d["failed"].get<bool>()) {
        EXPECT_NE(d["device"].get<std::string>().find(failing), std::string::npos) << d.dump();
        EXPECT_NE(d["error"].get<std::string>().find("PARASHADE_FAIL_DEVICE"), std::string::npos) << d.dump();
        EXPECT_EQ(d["tile_rows"], 0) << d.dump();
      }
    }
    EXPECT_EQ(failed, 1) << rep.dump(2);
    EXPECT_EQ(rows, (150 + 15) / 16) << "the device left covers every tile row";
  }
}

}  // namespace
}  // namespace parashade
