// `parashade devices` and --device: the listing is valid JSON with at least one device (the tests run
// with PoCL), the table shows the same devices, and a device that is not there is exit 4 with the
// available ones listed.
#include <unistd.h>

#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "cli_fixture.hpp"

namespace parashade {
namespace {

using namespace testing_support;

// devices --report: the versioned report's "devices".
nlohmann::json device_list() {
  // Not a TempDir: a test's fixture holds one of the same name, which a second one would remove.
  static int serial = 0;
  const std::filesystem::path file = std::filesystem::temp_directory_path() /
                                     ("parashade_devices_" + std::to_string(::getpid()) + "_" + std::to_string(serial++) + ".json");
  const RunResult r = run_parashade({"devices", "--report", file.string()});
  EXPECT_TRUE(succeeds(r));
  nlohmann::json report;
  {
    std::ifstream in(file);
    report = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  }
  std::error_code ignored;
  std::filesystem::remove(file, ignored);
  EXPECT_EQ(report.value("schema", ""), "parashade.devices/2") << r;
  const nlohmann::json list = report.is_object() ? report.value("devices", nlohmann::json()) : nlohmann::json();
  EXPECT_TRUE(list.is_array()) << "devices --report has no \"devices\" array:" << r;
  return list.is_array() ? list : nlohmann::json::array();
}

// The deprecated --json still prints the bare array, with a warning naming --report on stderr.
TEST(CliDevices, DeprecatedJsonFlagWarnsAndPrintsTheArray) {
  const RunResult r = run_parashade({"devices", "--json"});
  ASSERT_TRUE(succeeds(r));
  const nlohmann::json list = nlohmann::json::parse(r.out, nullptr, /*allow_exceptions=*/false);
  EXPECT_TRUE(list.is_array()) << r;
  EXPECT_EQ(list, device_list());
  EXPECT_NE(r.err.find("deprecated"), std::string::npos) << r;
  EXPECT_NE(r.err.find("--report"), std::string::npos) << r;
}

TEST(CliDevices, JsonListsDevicesWithComputeUnits) {
  const nlohmann::json list = device_list();
  ASSERT_GE(list.size(), 1u) << "no OpenCL device (is PoCL installed?)";
  for (std::size_t i = 0; i < list.size(); ++i) {
    const nlohmann::json& d = list[i];
    SCOPED_TRACE(d.dump());
    EXPECT_EQ(d.value("index", -1), int(i));
    EXPECT_FALSE(d.value("name", "").empty());
    EXPECT_FALSE(d.value("platform", "").empty());
    EXPECT_GT(d.value("compute_units", 0), 0);
  }
}

TEST(CliDevices, TableShowsTheSameDevices) {
  const nlohmann::json list = device_list();
  const RunResult r = run_parashade({"devices"});
  ASSERT_TRUE(succeeds(r));
  for (const nlohmann::json& d : list) EXPECT_NE(r.out.find(d.value("name", "?")), std::string::npos) << r;
}

class CliDeviceChoice : public CliTest {
 protected:
  std::filesystem::path scene_ = input("ball.json", sphere_scene());
};

TEST_F(CliDeviceChoice, UnknownNameListsTheDevices) {
  const nlohmann::json list = device_list();
  const RunResult r = render(scene_, {"--device", "nonexistent-name"});
  EXPECT_TRUE(fails_with(r, kDeviceFailure, {"nonexistent-name"}));
  for (const nlohmann::json& d : list) EXPECT_NE(r.err.find(d.value("name", "?")), std::string::npos) << r;
  EXPECT_TRUE(nothing_written());
}

TEST_F(CliDeviceChoice, IndexPastTheListListsTheDevices) {
  const nlohmann::json list = device_list();
  const std::string index = std::to_string(list.size());
  const RunResult r = render(scene_, {"--device", index});
  EXPECT_TRUE(fails_with(r, kDeviceFailure, {index}));
  for (const nlohmann::json& d : list) EXPECT_NE(r.err.find(d.value("name", "?")), std::string::npos) << r;
  EXPECT_TRUE(nothing_written());
}

// The last device, by index and by its full name: the report says which one rendered.
TEST_F(CliDeviceChoice, ByIndexAndByName) {
  const nlohmann::json list = device_list();
  ASSERT_GE(list.size(), 1u);
  const nlohmann::json& last = list.back();
  for (const std::string& selector : {std::to_string(list.size() - 1), last.value("name", "?")}) {
    SCOPED_TRACE(selector);
    ASSERT_TRUE(succeeds(render(scene_, {"--device", selector})));
    const nlohmann::json rep = read_report();
    EXPECT_EQ(field(rep, "/device/name"), last["name"]);
    EXPECT_EQ(field(rep, "/device/index"), last["index"]);
  }
}

}  // namespace
}  // namespace parashade
