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

// PoCL's two CPU devices (POCL_DEVICES, as determinism_test does): the variable picks the one the default
// is not; --device picks the default again, and without the variable the default renders.
TEST_F(CliDeviceEnvironment, ChoosesTheDeviceWhenDeviceIsAbsent) {
  const ScopedEnv devices("POCL_DEVICES", "pthread basic");
  const RunResult listing = run_parashade({"devices", "--report", report().string()});
  ASSERT_TRUE(succeeds(listing));
  const nlohmann::json listed = read_report(), list = field(listed, "/devices");
  if (!list.is_array() || list.size() != 2) GTEST_SKIP() << "PoCL does not offer two devices:" << listing;
  ASSERT_TRUE(field(listed, "/default_device").is_number_integer()) << listed.dump(1);
  const int chosen = field(listed, "/default_device").get<int>(), other = 1 - chosen;
  const nlohmann::json by_default = list[chosen]["name"], by_variable = list[other]["name"];
  {
    const ScopedEnv choice("PARASHADE_DEVICE", std::to_string(other));
    ASSERT_TRUE(succeeds(render_without_device()));
    EXPECT_EQ(field(read_report(), "/device/name"), by_variable);
    ASSERT_TRUE(succeeds(run_parashade(render_args(scene_, {"--device", std::to_string(chosen)}))));
    EXPECT_EQ(field(read_report(), "/device/name"), by_default) << "--device must win over PARASHADE_DEVICE";
  }
  ASSERT_TRUE(succeeds(render_without_device()));
  EXPECT_EQ(field(read_report(), "/device/name"), by_default) << "without the variable the default renders";
}

// Without --device and PARASHADE_DEVICE: PoCL's pthread device even when `basic` is listed first (the rule
// of device.hpp's default_device; before, the first device rendered). Said on stderr, not under -q;
// `devices` marks it in the table and the report.
TEST_F(CliDeviceEnvironment, TheDefaultIsPthreadNotTheFirstDevice) {
  const ScopedEnv devices("POCL_DEVICES", "basic pthread");
  const ScopedEnv no_choice("PARASHADE_DEVICE", nullptr);
  const RunResult listing = run_parashade({"devices", "--report", report().string()});
  ASSERT_TRUE(succeeds(listing));
  const nlohmann::json devices_report = read_report();
  const nlohmann::json list = field(devices_report, "/devices");
  if (!list.is_array() || list.size() != 2 || list[0].value("name", "").rfind("basic-", 0) != 0)
    GTEST_SKIP() << "PoCL does not list basic, then pthread:" << listing;
  const std::string pthread = list[1].value("name", "");
  ASSERT_EQ(pthread.rfind("pthread-", 0), 0u) << listing;
  EXPECT_EQ(field(devices_report, "/default_device"), 1) << listing;
  EXPECT_NE(listing.out.find("1: " + pthread + "  (the default)\n"), std::string::npos) << listing;
  EXPECT_EQ(listing.out.find("0: " + list[0].value("name", "") + "  (the default)"), std::string::npos) << listing;

  const std::vector<std::string> args = {"render", scene_.string(), "-o", image().string(), "--report",
                                         report().string(), "--frames", "1", "--warmup", "0", "--no-error"};
  const RunResult r = run_parashade(args);
  ASSERT_TRUE(succeeds(r));
  EXPECT_EQ(field(read_report(), "/device/name"), pthread) << r;
  EXPECT_NE(r.err.find("parashade: note: device: " + pthread + " (Portable Computing Language, " +
                       std::to_string(list[1].value("compute_units", 0)) + " compute unit"),
            std::string::npos)
      << r;
  EXPECT_NE(r.err.find("; the default: --device to choose)\n"), std::string::npos) << r;
  std::vector<std::string> quiet = args;
  quiet.push_back("-q");
  const RunResult q = run_parashade(quiet);
  ASSERT_TRUE(succeeds(q));
  EXPECT_EQ(q.err.find("parashade: note: device:"), std::string::npos) << q;
  // A device named (by --device or the variable) is not the default: no such line.
  std::vector<std::string> named = args;
  named.insert(named.end(), {"--device", "basic"});
  const RunResult n = run_parashade(named);
  ASSERT_TRUE(succeeds(n));
  EXPECT_EQ(n.err.find("parashade: note: device:"), std::string::npos) << n;
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
