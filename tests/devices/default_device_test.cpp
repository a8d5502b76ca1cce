// The default device (device.hpp's default_device, docs/environment.md) among the implementations the
// tests register (tests/CMakeLists.txt's ICD folder): a render without --device and PARASHADE_DEVICE lands
// on PoCL's pthread device, not on Oclgrind when the ICD loader lists it first, nor on PoCL's `basic`,
// which PoCL lists first. Before (the first device listed), it landed on Oclgrind.
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
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

class DefaultDeviceOfTheTestFolder : public ::testing::Test {
 protected:
  // The anydevice tests' environment (tests/CMakeLists.txt): Intel's runtime needs its libraries first.
  static void SetUpTestSuite() {
    if (*PARASHADE_ICD_LIBRARY_PATH) ::setenv("LD_LIBRARY_PATH", PARASHADE_ICD_LIBRARY_PATH, 1);
    ::setenv("POCL_CACHE_DIR", PARASHADE_POCL_CACHE_DIR, 1);
  }

  // A render of the sphere without --device: its stderr, and the device's name from its report.
  std::pair<RunResult, std::string> render_by_default() const {
    const fs::path report = dir_.path() / "render.json";
    RunResult r = run_parashade({"render", (source_dir() / "scenes" / "sphere.json").string(), "--size", "48x32",
                                 "-o", (dir_.path() / "sphere.png").string(), "--report", report.string(), "--frames",
                                 "1", "--warmup", "0", "--no-error", "--no-tuned"});
    const json rendered = json::parse(slurp(report), nullptr, false);
    return {r, rendered.is_object() ? rendered.value(json::json_pointer("/device/name"), std::string()) : ""};
  }

  // An ICD folder of Oclgrind and PoCL (the two implementations every test machine has); "" when either is
  // not registered (the test then fails saying so).
  std::string use_oclgrind_and_pocl() const {
    const std::string oclgrind = registered_library("oclgrind"), pocl = registered_library("pocl");
    if (oclgrind.empty() || pocl.empty()) return "Oclgrind or PoCL is not registered in " PARASHADE_ICD_DIR;
    const fs::path vendors = dir_.path() / "two-vendors";
    fs::create_directories(vendors);
    std::ofstream(vendors / "a.icd") << oclgrind;
    std::ofstream(vendors / "b.icd") << pocl;
    ::setenv("OCL_ICD_VENDORS", vendors.c_str(), 1);
    return "";
  }

  TempDir dir_;
  const ScopedEnv devices_{"POCL_DEVICES", "basic pthread"};
  const ScopedEnv no_variable_{"PARASHADE_DEVICE", nullptr};
  const ScopedEnv vendors_{"OCL_ICD_VENDORS", nullptr};  // set below; restored after the test
};

// An ICD folder of Oclgrind and PoCL in which the loader lists Oclgrind first (the files' names decide
// the order; both ways are tried), POCL_DEVICES="basic pthread": the default is pthread, said on stderr
// and marked by `devices`.
TEST_F(DefaultDeviceOfTheTestFolder, PthreadWhenOclgrindAndBasicComeFirst) {
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

  const auto [r, rendered_on] = render_by_default();
  ASSERT_TRUE(r.exited() && r.exit_code == 0) << r;
  EXPECT_EQ(rendered_on, pthread) << r;
  EXPECT_NE(r.err.find("parashade: note: device: " + pthread + " (Portable Computing Language, "), std::string::npos) << r;
}

// The tests' whole ICD folder: Oclgrind, PoCL and, when installed, Intel's CPU runtime, which has as many
// compute units as PoCL's pthread on a CPU (one per hardware thread): the tie goes to pthread, the
// reference device, so the figures measured by default do not change where Intel's runtime is installed.
TEST_F(DefaultDeviceOfTheTestFolder, PthreadAmongTheTestImplementations) {
  ::setenv("OCL_ICD_VENDORS", PARASHADE_ICD_DIR, 1);
  const Listing listing = list_devices_with(dir_.path() / "devices.json");
  ASSERT_TRUE(listing.run.exited() && listing.run.exit_code == 0) << listing.run;
  ASSERT_TRUE(listing.devices.is_array()) << listing.run;
  int pthread = -1, pthread_units = 0, most_units_elsewhere = 0;
  bool intel = false;
  for (const json& d : listing.devices) {
    const std::string name = d.value("name", "");
    if (name.rfind("pthread-", 0) == 0) pthread = d.value("index", -1), pthread_units = d.value("compute_units", 0);
    else if (!is_oclgrind(d)) most_units_elsewhere = std::max(most_units_elsewhere, d.value("compute_units", 0));
    intel |= d.value("platform", "") == "Intel(R) OpenCL";
  }
  ASSERT_GE(pthread, 0) << listing.run;
  if (!intel) std::cout << "note: Intel's CPU OpenCL runtime is not registered (" << PARASHADE_INTEL_OPENCL_MISSING << ")\n";
  if (most_units_elsewhere > pthread_units)
    GTEST_SKIP() << "a device has more compute units than PoCL's pthread, so it is the default:" << listing.run;
  EXPECT_EQ(listing.default_device, pthread) << listing.run;
  const auto [r, rendered_on] = render_by_default();
  ASSERT_TRUE(r.exited() && r.exit_code == 0) << r;
  EXPECT_EQ(rendered_on, listing.devices[std::size_t(pthread)].value("name", "")) << r;
}

// `--device all` splits a frame across the real devices: not Oclgrind (a simulator, hundreds of times slower,
// and the first split frame gives every device an equal band) nor PoCL's `basic` (one thread on the cores of
// `pthread`), each left out with a note; named in a list (A,B) they still take a band.
TEST_F(DefaultDeviceOfTheTestFolder, AllLeavesOutTheSimulatorAndBasic) {
  const std::string missing = use_oclgrind_and_pocl();
  ASSERT_TRUE(missing.empty()) << missing;
  const fs::path report = dir_.path() / "split.json";
  const auto split = [&](const std::string& devices, bool quiet) {
    std::vector<std::string> args = {"render", (source_dir() / "scenes" / "sphere.json").string(), "--size", "48x32",
                                     "-o", (dir_.path() / "split.png").string(), "--report", report.string(),
                                     "--frames", "1", "--warmup", "0", "--device", devices};
    if (quiet) args.push_back("-q");
    const RunResult r = run_parashade(args);
    std::vector<std::string> names;
    const json rendered = json::parse(slurp(report), nullptr, false);
    if (rendered.is_object())
      for (const json& d : rendered.value("device_info", json::array())) names.push_back(d.value("name", ""));
    return std::make_pair(r, names);
  };
  const auto [all, names] = split("all", false);
  ASSERT_TRUE(all.exited() && all.exit_code == 0) << all;
  ASSERT_EQ(names.size(), 1u) << all;
  EXPECT_EQ(names[0].rfind("pthread-", 0), 0u) << all;
  EXPECT_NE(all.err.find("device list 'all' leaves out Oclgrind Simulator (a simulator, beside real devices), basic-"),
            std::string::npos) << all;
  EXPECT_NE(all.err.find("(PoCL's one-thread device, on the cores of its threaded one)"), std::string::npos) << all;
  const auto [quiet, quiet_names] = split("all", true);
  EXPECT_EQ(quiet.err.find("leaves out"), std::string::npos) << quiet;
  const auto [listed, listed_names] = split("pthread,basic", true);
  ASSERT_TRUE(listed.exited() && listed.exit_code == 0) << listed;
  EXPECT_EQ(listed_names.size(), 2u) << listed;
}

// Every command that takes the default device says which, the same way (device.hpp's default_device_note),
// and none says it when --device or PARASHADE_DEVICE chose: render, tune and scaling (render --distribute's
// rank 0 too, tests/mpi).
TEST_F(DefaultDeviceOfTheTestFolder, EveryCommandThatTakesTheDefaultSaysIt) {
  const std::string missing = use_oclgrind_and_pocl();
  ASSERT_TRUE(missing.empty()) << missing;
  const std::string scene = (source_dir() / "scenes" / "sphere.json").string();
  const std::string out = (dir_.path() / "out").string();
  fs::create_directories(out);
  const std::vector<std::vector<std::string>> commands = {
      {"render", scene, "--size", "48x32", "-o", out + "/r.png", "--frames", "1", "--warmup", "0", "--no-error",
       "--no-tuned"},
      {"tune", scene, "--size", "48x32", "--param", "tile=32", "--param", "work_items=0", "--param", "partition=none",
       "--frames", "1", "--cache", out + "/tune.json"},
      {"scaling", scene, "--size", "48x32", "--units", "classic", "--frames", "1"}};
  const std::string said = "parashade: note: device: pthread-";
  for (const std::vector<std::string>& command : commands) {
    SCOPED_TRACE(command[0]);
    const RunResult taken = run_parashade(command);
    ASSERT_TRUE(taken.exited() && taken.exit_code == 0) << taken;
    const std::size_t at = taken.err.find(said);
    EXPECT_NE(at, std::string::npos) << taken;
    EXPECT_EQ(taken.err.find(said, at + 1), std::string::npos) << "said once" << taken;
    EXPECT_NE(taken.err.find("compute units; the default: --device to choose)\n"), std::string::npos) << taken;
    std::vector<std::string> chosen = command;
    chosen.insert(chosen.end(), {"--device", "pthread"});
    const RunResult named = run_parashade(chosen);
    ASSERT_TRUE(named.exited() && named.exit_code == 0) << named;
    EXPECT_EQ(named.err.find("parashade: note: device:"), std::string::npos) << named;
    const ScopedEnv variable("PARASHADE_DEVICE", "pthread");
    const RunResult by_variable = run_parashade(command);
    ASSERT_TRUE(by_variable.exited() && by_variable.exit_code == 0) << by_variable;
    EXPECT_EQ(by_variable.err.find("parashade: note: device:"), std::string::npos) << by_variable;
  }
}

}  // namespace
}  // namespace parashade
