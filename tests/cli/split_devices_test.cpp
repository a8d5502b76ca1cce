// `render --device A,B` / `--device all`: one frame split across PoCL's pthread and basic devices
// (POCL_DEVICES="pthread basic", chosen by name: PoCL orders devices its own way) is the same image as
// one device's.
#include <cstdlib>
#include <fstream>
#include <iterator>

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
  void SetUp() override {
    const char* old = std::getenv("POCL_DEVICES");
    if (old) saved_ = old;
    had_ = old != nullptr;
    ::setenv("POCL_DEVICES", "pthread basic", 1);
  }
  void TearDown() override {
    if (had_) ::setenv("POCL_DEVICES", saved_.c_str(), 1);
    else ::unsetenv("POCL_DEVICES");
  }
  std::string saved_;
  bool had_ = false;
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
  EXPECT_TRUE(nothing_written());
}

}  // namespace
}  // namespace parashade
