// PARASHADE_DEVICE is --device's default in every command that opens a device, as for the benchmarks
// (docs/environment.md): it picks the device when --device is absent, --device wins over it, and a value
// that names no device fails as --device would, with a message naming the variable.
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "cli_fixture.hpp"

namespace parashade {
namespace {

using namespace testing_support;

class CliDeviceEnvironment : public CliTest {
 protected:
  std::filesystem::path scene_ = input("ball.json", sphere_scene());

  // render without --device: only the environment or the default picks the device.
  RunResult render_without_device() const {
    return run_parashade({"render", scene_.string(), "-o", image().string(), "--report", report().string(),
                          "--frames", "1", "--warmup", "0", "-q", "--no-error"});
  }
};

// PoCL's two CPU devices (POCL_DEVICES, as determinism_test does): the variable picks the second one,
// which the default (the first) is not; --device picks the first again.
TEST_F(CliDeviceEnvironment, ChoosesTheDeviceWhenDeviceIsAbsent) {
  const ScopedEnv devices("POCL_DEVICES", "pthread basic");
  const RunResult listing = run_parashade({"devices", "--json"});
  ASSERT_TRUE(succeeds(listing));
  const nlohmann::json list = nlohmann::json::parse(listing.out, nullptr, /*allow_exceptions=*/false);
  if (!list.is_array() || list.size() < 2) GTEST_SKIP() << "PoCL does not offer two devices:" << listing;
  const nlohmann::json first = list[0]["name"], second = list[1]["name"];
  {
    const ScopedEnv choice("PARASHADE_DEVICE", "1");
    ASSERT_TRUE(succeeds(render_without_device()));
    EXPECT_EQ(field(read_report(), "/device/name"), second);
    ASSERT_TRUE(succeeds(run_parashade(render_args(scene_, {"--device", "0"}))));
    EXPECT_EQ(field(read_report(), "/device/name"), first) << "--device must win over PARASHADE_DEVICE";
  }
  ASSERT_TRUE(succeeds(render_without_device()));
  EXPECT_EQ(field(read_report(), "/device/name"), first) << "without the variable the first device renders";
}

// A value that names no device: exit 4 as for --device, and the message says where the value came from,
// since the command line does not show it. For every command that opens a device.
TEST_F(CliDeviceEnvironment, BadValueNamesTheVariable) {
  const ScopedEnv choice("PARASHADE_DEVICE", "nonexistent-device");
  const std::string cache = (out_dir() / "tune.json").string();
  const std::vector<std::pair<std::string, std::vector<std::string>>> runs = {
      {"render", {"render", scene_.string(), "-o", image().string(), "-q", "--no-error"}},
      {"tune", {"tune", scene_.string(), "--budget-runs", "1", "--frames", "1", "--cache", cache}},
      {"scaling", {"scaling", scene_.string(), "--units", "classic", "--frames", "1", "--warmup", "1", "-q"}},
  };
  for (const auto& [command, args] : runs) {
    SCOPED_TRACE(command);
    const RunResult r = run_parashade(args);
    EXPECT_TRUE(fails_with(r, kDeviceFailure, {"PARASHADE_DEVICE", "nonexistent-device"}));
    EXPECT_TRUE(nothing_written());
  }
}

}  // namespace
}  // namespace parashade
