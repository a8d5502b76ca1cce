// The default device (device.hpp's default_device, docs/environment.md) among the implementations the
// tests register (tests/CMakeLists.txt's ICD folder): a render without --device and PARASHADE_DEVICE lands
// on PoCL's pthread device, not on Oclgrind when the ICD loader lists it first, nor on PoCL's `basic`,
// which PoCL lists first. Before (the first device listed), it landed on Oclgrind.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli/run_parashade.hpp"
#include "scene/temp_dir.hpp"
#include "test_support.hpp"

namespace parashade {
namespace {

using namespace testing_support;
namespace fs = std::filesystem;
using nlohmann::json;

std::string slurp(const fs::path& p) {
  std::ostringstream s;
  s << std::ifstream(p, std::ios::binary).rdbuf();
  return s.str();
}

// The content (a library path) of the test ICD folder's .icd file that names `word`, or "".
std::string registered_library(const std::string& word) {
  for (const fs::directory_entry& e : fs::directory_iterator(PARASHADE_ICD_DIR))
    if (e.path().extension() == ".icd" && slurp(e.path()).find(word) != std::string::npos) return slurp(e.path());
  return "";
}

struct Listing {
  RunResult run;
  json devices;
  json default_device;
};

Listing list_devices_with(const fs::path& report) {
  Listing l;
  l.run = run_parashade({"devices", "--report", report.string()});
  const json r = json::parse(slurp(report), nullptr, /*allow_exceptions=*/false);
  if (r.is_object()) l.devices = r.value("devices", json()), l.default_device = r.value("default_device", json());
  return l;
}

bool is_oclgrind(const json& d) { return d.value("platform", "") == "Oclgrind"; }

class DefaultDevice : public ::testing::Test {
 protected:
  TempDir dir_;
  const ScopedEnv devices_{"POCL_DEVICES", "basic pthread"};
  const ScopedEnv no_variable_{"PARASHADE_DEVICE", nullptr};
  const ScopedEnv vendors_{"OCL_ICD_VENDORS", nullptr};  // set below; restored after the test
};

// An ICD folder of Oclgrind and PoCL in which the loader lists Oclgrind first (the files' names decide
// the order; both ways are tried), POCL_DEVICES="basic pthread": the default is pthread, said on stderr
// and marked by `devices`.
TEST_F(DefaultDevice, PthreadWhenOclgrindAndBasicComeFirst) {
  const std::string oclgrind = registered_library("oclgrind"), pocl = registered_library("pocl");
  ASSERT_FALSE(oclgrind.empty()) << "Oclgrind is not registered in " << PARASHADE_ICD_DIR
                                 << " (scripts/install-deps.sh installs oclgrind; then configure again)";
  ASSERT_FALSE(pocl.empty()) << "PoCL is not registered in " << PARASHADE_ICD_DIR;
  const fs::path vendors = dir_.path() / "vendors";
  Listing listing;
  for (const bool oclgrind_as_a : {true, false}) {
    fs::remove_all(vendors);
    fs::create_directories(vendors);
    std::ofstream(vendors / "a.icd") << (oclgrind_as_a ? oclgrind : pocl);
    std::ofstream(vendors / "b.icd") << (oclgrind_as_a ? pocl : oclgrind);
    ::setenv("OCL_ICD_VENDORS", vendors.c_str(), 1);
    listing = list_devices_with(dir_.path() / "devices.json");
    ASSERT_TRUE(listing.run.exited() && listing.run.exit_code == 0) << listing.run;
    if (listing.devices.is_array() && !listing.devices.empty() && is_oclgrind(listing.devices[0])) break;
  }
  ASSERT_TRUE(listing.devices.is_array() && listing.devices.size() == 3) << listing.run;
  if (!is_oclgrind(listing.devices[0]))
    GTEST_SKIP() << "the ICD loader lists Oclgrind after PoCL whatever the files' names:" << listing.run;
  const std::string basic = listing.devices[1].value("name", ""), pthread = listing.devices[2].value("name", "");
  ASSERT_EQ(basic.rfind("basic-", 0), 0u) << listing.run;
  ASSERT_EQ(pthread.rfind("pthread-", 0), 0u) << listing.run;
  EXPECT_EQ(listing.default_device, 2) << listing.run;
  EXPECT_NE(listing.run.out.find("2: " + pthread + "  (the default)\n"), std::string::npos) << listing.run;

  const fs::path report = dir_.path() / "render.json";
  const RunResult r = run_parashade({"render", (source_dir() / "scenes" / "sphere.json").string(), "--size", "48x32",
                                     "-o", (dir_.path() / "sphere.png").string(), "--report", report.string(),
                                     "--frames", "1", "--warmup", "0", "--no-error", "--no-tuned"});
  ASSERT_TRUE(r.exited() && r.exit_code == 0) << r;
  const json rendered = json::parse(slurp(report), nullptr, false);
  EXPECT_EQ(rendered.value(json::json_pointer("/device/name"), std::string()), pthread) << r;
  EXPECT_NE(r.err.find("parashade: device: " + pthread + " (Portable Computing Language, "), std::string::npos) << r;
}

}  // namespace
}  // namespace parashade
