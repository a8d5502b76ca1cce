// `render --device A,B`: one frame split across PoCL's pthread and basic devices
// (POCL_DEVICES="pthread basic", chosen by name: PoCL orders devices its own way) is the same image as
// one device's. A device made to fail (PARASHADE_FAIL_DEVICE, device.hpp) ends the run naming it, or
// with --keep-going is dropped with a warning naming it. With --cu, sub:NAME:N runs the units' depth
// pass on the sub-devices instead of bands (docs/planner.md).
#include <fstream>
#include <iterator>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "cli_fixture.hpp"
#include "parashade/kernels/constants.h"

namespace parashade {
namespace {

using namespace testing_support;

class SplitDevices : public CliTest {
 protected:
  const ScopedEnv devices_{"POCL_DEVICES", "pthread basic"};
};

TEST_F(SplitDevices, TwoDevicesGiveTheSingleDeviceImage) {
  const auto scene = input("ball.json", sphere_scene());
  ASSERT_TRUE(succeeds(render(scene, {"--device", "pthread", "--no-tuned", "--size", "200x150"})));
  const std::string single = bytes_of(image());
  // sub:pthread:1 = the pthread device cut into sub-devices of one compute unit (clCreateSubDevices).
  // (`all` leaves `basic` out beside `pthread`: tests/devices.)
  for (const char* list : {"pthread,basic", "basic,pthread", "sub:pthread:1", "sub:pthread:1+1"}) {
    const RunResult r = render(scene, {"--device", list, "--size", "200x150"});
    ASSERT_TRUE(succeeds(r)) << list;
    EXPECT_EQ(bytes_of(image()), single) << "split over " << list << " differs from the pthread device's image";
    const nlohmann::json rep = read_report();
    ASSERT_EQ(field(rep, "/devices").size(), 2u) << list;
    int rows = 0;
    for (const auto& d : rep["devices"]) rows += d["tile_rows"].get<int>();
    EXPECT_EQ(rows, (150 + TILE_DEFAULT - 1) / TILE_DEFAULT) << "the bands cover every tile row once";
  }
}

TEST_F(SplitDevices, BadListsAreNamed) {
  const auto scene = input("ball.json", sphere_scene());
  EXPECT_TRUE(fails_with(render(scene, {"--device", "pthread,pthread"}), kUsage, {"--device", "twice"}));
  EXPECT_TRUE(fails_with(render(scene, {"--device", "pthread,nosuchdevice"}), kDeviceFailure, {"nosuchdevice"}));
  EXPECT_TRUE(fails_with(render(scene, {"--device", "sub:pthread:1+x"}), kUsage, {"--device", "sub:pthread:1+x"}));
  EXPECT_TRUE(fails_with(render(scene, {"--device", "sub:pthread:0"}), kUsage, {"--device", "sub:pthread:0"}));
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
    EXPECT_EQ(rows, (150 + TILE_DEFAULT - 1) / TILE_DEFAULT) << "the device left covers every tile row";
  }
}

// PoCL's pthread device's compute units (0 when it is not offered).
int pthread_compute_units() {
  const RunResult r = run_parashade({"devices", "--json"});
  const nlohmann::json list = nlohmann::json::parse(r.out, nullptr, false);
  if (!list.is_array()) return 0;
  for (const auto& d : list)
    if (d.value("name", "").find("pthread") != std::string::npos) return d.value("compute_units", 0);
  return 0;
}

// --cu with --device sub:NAME:N: the units' depth pass spread over the sub-devices (not bands): the same
// image, and the report says which sub-device ran which units, with its pass time.
TEST_F(SplitDevices, UnitsOnSubDevicesKeepTheImageAndReportWhichRanWhat) {
  if (const int cu = pthread_compute_units(); cu < 2)
    GTEST_SKIP() << "the pthread device offers " << cu << " compute unit(s); two sub-devices need 2";
  const auto scene = input("ball.json", sphere_scene());
  ASSERT_TRUE(succeeds(render(scene, {"--device", "pthread", "--no-tuned", "--size", "200x150"})));
  const std::string single = bytes_of(image());
  const RunResult items = render(scene, {"--device", "pthread", "--cu", "3", "--size", "200x150"});
  ASSERT_TRUE(succeeds(items));
  EXPECT_EQ(field(read_report(), "/plan/mapping/kind"), "work-items");
  EXPECT_EQ(field(read_report(), "/plan/mapping/shares/0/units"), 3);
  EXPECT_NE(items.out.find("units as 3 work-items"), std::string::npos) << items;
  for (const char* list : {"sub:pthread:1", "sub:pthread:1+1"})
    for (const char* partition : {"lpt", "dynamic"}) {
      SCOPED_TRACE(std::string(list) + " " + partition);
      const RunResult r = render(scene, {"--device", list, "--cu", "3", "--partition", partition, "--size", "200x150"});
      ASSERT_TRUE(succeeds(r));
      EXPECT_EQ(bytes_of(image()), single) << "the units on " << list << " change the image";
      EXPECT_NE(r.out.find("units on 2 sub-devices"), std::string::npos) << r;
      const nlohmann::json m = field(read_report(), "/plan/mapping");
      EXPECT_EQ(field(m, "/kind"), "sub-devices");
      ASSERT_EQ(field(m, "/shares").size(), 2u) << m.dump(2);
      // 3 units over two sub-devices of one compute unit: units 0-1 and 2.
      EXPECT_EQ(field(m, "/shares/0/first_unit"), 0);
      EXPECT_EQ(field(m, "/shares/0/units"), 2);
      EXPECT_EQ(field(m, "/shares/1/first_unit"), 2);
      EXPECT_EQ(field(m, "/shares/1/units"), 1);
      EXPECT_NE(field(m, "/shares/1/device").get<std::string>().find("[sub-device 1]"), std::string::npos);
      for (const auto& share : m["shares"]) EXPECT_GT(share["pass_ms"].get<double>(), 0.0) << share.dump();
      EXPECT_TRUE(field(m, "/key_merge_ms").is_number());
    }
}

TEST_F(SplitDevices, UnitsRefuseADeviceListAndKeepGoing) {
  const auto scene = input("ball.json", sphere_scene());
  EXPECT_TRUE(fails_with(render(scene, {"--device", "pthread,basic", "--cu", "2"}), kUsage, {"--cu", "sub:NAME:N"}));
  EXPECT_TRUE(fails_with(render(scene, {"--device", "sub:pthread:1", "--cu", "2", "--keep-going"}), kUsage,
                         {"--keep-going", "no fallback"}));
  EXPECT_TRUE(nothing_written());
}

TEST_F(SplitDevices, AFailingSubDeviceEndsTheUnitsPassNamingIt) {
  if (const int cu = pthread_compute_units(); cu < 2)
    GTEST_SKIP() << "the pthread device offers " << cu << " compute unit(s); two sub-devices need 2";
  const auto scene = input("ball.json", sphere_scene());
  const ScopedEnv fail("PARASHADE_FAIL_DEVICE", "sub-device 1");
  EXPECT_TRUE(fails_with(render(scene, {"--device", "sub:pthread:1", "--cu", "2"}), kDeviceFailure,
                         {"[sub-device 1]", "CL_BUILD_PROGRAM_FAILURE"}));
  EXPECT_TRUE(nothing_written());
}

}  // namespace
}  // namespace parashade
