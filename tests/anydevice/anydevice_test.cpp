// The anydevice label: every kernel path rendered on another OpenCL implementation (Oclgrind, an
// interpreter of the kernels' LLVM IR that checks every memory access; Intel's CPU runtime, a compiler
// that vectorizes across work-items) and on PoCL, through the real `parashade render` (docs/pipeline.md,
// "What a kernel may assume of a device"). The device under test is PARASHADE_ANYDEVICE's (ctest sets it
// per device of the CMake list of that name: anydevice.oclgrind.*, anydevice.intel.*).
//   - integer and fixed-point paths: the same 8-bit image bytes as PoCL (and the same float registers
//     with --float), the same modeled clocks;
//   - float paths: coverage exact (no mismatch against the exact reference) and the error against the
//     method's ideal within 0.5 level + its documented bound (docs/error-bounds.md); where the
//     reference's ideal is not the method's (approximations against exact Phong, moved vertices),
//     coverage and error as PoCL measures them (+ the bound); every pixel within 1 + 2 bound levels of
//     PoCL's (at least 1);
//   - on Oclgrind, any diagnostic (invalid access, data race, API error, a kernel warning) fails: its
//     log (OCLGRIND_LOG) must stay empty and the run's stderr be PoCL's.
// The kernels build as OpenCL C 1.2 with warnings as errors on both (PARASHADE_KERNEL_WERROR=1).
// PARASHADE_ANYDEVICE=NAME-substring (the environment; by default the CMake list's first) tests another
// registered device (README, "Devices").
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cl/gouraud_bound.hpp"
#include "cli/run_parashade.hpp"
#include "parashade/geometry_stage.hpp"
#include "parashade/image.hpp"
#include "parashade/scene.hpp"
#include "scene/temp_dir.hpp"

namespace parashade {
namespace {

using namespace testing_support;
namespace fs = std::filesystem;
using nlohmann::json;

constexpr double kUnitRoundoff = 1.0 / (1 << 24);  // float32

// Integer and fixed-point paths must match PoCL's bytes; float paths are held to the bound of the
// method's ideal (own: the ideal is what the kernel computes in float) or, where the reference's ideal
// is not what the method computes (span normalizations, specular models and the combined method against
// exact Phong; the Sierpinski unit's parity-snapped vertices), to PoCL's error and coverage figures.
enum class Check { bytes, own_ideal, approximation };

struct KernelPath {
  const char* name;
  const char* scene;  // in scenes/
  const char* size;
  std::vector<std::string> args;
  Check check;
};

std::ostream& operator<<(std::ostream& os, const KernelPath& p) {
  os << p.scene << " --size " << p.size;
  for (const std::string& a : p.args) os << " " << a;
  return os;
}

// The paths: methods x units x arithmetic x coverage x division x normalization x specular x combined x
// plan passes (the units' depth pass and the resolve) x tile sizes, each value at least once, on small
// frames (Oclgrind interprets every instruction), some 90 pixels wide (a partial vector ends each row).
// teapot: small triangles (32-bit edge path), two lights, one a point light; default: the table's large
// triangles (64-bit span search), four materials; sphere: a local viewer; hard/big: triangles wider
// than a 64-pixel tile.
const std::vector<KernelPath>& kernel_paths() {
  static const std::vector<KernelPath> paths = {
      // --- fixed point and integers: the same bytes as PoCL -------------------------------------------
      {"ClassicFixed12_12", "teapot.json", "160x90", {"--units", "classic", "--arith", "fixed:12.12"}, Check::bytes},
      {"Segment8Fixed10_8", "default.json", "96x54", {"--units", "segment:8", "--arith", "fixed:10.8"}, Check::bytes},
      {"Interleave4Fixed16_16", "default.json", "96x54", {"--units", "interleave:4", "--arith", "fixed:16.16"},
       Check::bytes},
      {"Interleave4OwnFixed12_12", "sphere.json", "96x54", {"--units", "interleave:4:own", "--arith", "fixed:12.12"},
       Check::bytes},
      {"Sierpinski2Fixed", "teapot.json", "96x54", {"--units", "sierpinski:2", "--arith", "fixed:12.12"}, Check::bytes},
      {"Sierpinski1OddSealFixed", "default.json", "96x54", {"--units", "sierpinski:1:odd:seal", "--arith", "fixed:12.12"},
       Check::bytes},
      {"DivExactCounterFixed", "default.json", "96x54", {"--units", "counter", "--div", "exact", "--arith", "fixed:12.12"},
       Check::bytes},
      {"DivShiftAdd12Fixed", "teapot.json", "96x54", {"--div", "shiftadd:12", "--arith", "fixed:12.12"}, Check::bytes},
      {"DivShiftAdd8TruncSegment", "sphere.json", "90x50",
       {"--units", "segment:4", "--div", "shiftadd:8:trunc", "--arith", "fixed:10.14"}, Check::bytes},
      {"Tile64CounterDdaFixed", "default.json", "160x90",
       {"--tile", "64", "--units", "counter", "--coverage", "dda", "--arith", "fixed:12.12"}, Check::bytes},
      {"FixedFloatRegisters", "teapot.json", "96x54", {"--units", "counter", "--arith", "fixed:12.12", "--float"},
       Check::bytes},
      {"PlanDynamicFixed", "teapot.json", "96x54",
       {"--cu", "4", "--partition", "dynamic", "--batch", "8", "--arith", "fixed:12.12"}, Check::bytes},
      {"PlanTilesTile32Fixed", "default.json", "96x54",
       {"--cu", "3", "--partition", "tiles", "--tile", "32", "--units", "counter", "--arith", "fixed:12.12"},
       Check::bytes},
      // --- float: within the documented bound of the method's own ideal ------------------------------
      {"Flat", "teapot.json", "96x54", {"--method", "flat"}, Check::own_ideal},
      {"Gouraud", "teapot.json", "160x90", {"--method", "gouraud"}, Check::own_ideal},
      {"GouraudTile64", "default.json", "160x90", {"--method", "gouraud", "--tile", "64"}, Check::own_ideal},
      {"GouraudBigTriangles", "hard/big.json", "128x96", {"--method", "gouraud"}, Check::own_ideal},
      {"Phong", "teapot.json", "160x90", {"--method", "phong"}, Check::own_ideal},
      {"PhongTile32", "default.json", "160x90", {"--method", "phong", "--tile", "32"}, Check::own_ideal},
      {"PhongLocalViewerFloatOutput", "sphere.json", "90x50", {"--method", "phong", "--float"}, Check::own_ideal},
      {"GouraudUnitsFloat", "teapot.json", "96x54", {"--units", "counter"}, Check::own_ideal},
      {"PhongUnitsCounterFixed", "teapot.json", "96x54",
       {"--method", "phong", "--units", "counter", "--arith", "fixed:12.12"}, Check::own_ideal},
      {"PhongUnitsInterleaveFixedTile64", "default.json", "96x54",
       {"--method", "phong", "--units", "interleave:2", "--arith", "fixed:10.14", "--tile", "64"}, Check::own_ideal},
      {"PlanLptPhong", "teapot.json", "96x54", {"--method", "phong", "--cu", "4", "--partition", "lpt"},
       Check::own_ideal},
      {"PlanDynamicFlatTile64", "default.json", "96x54",
       {"--method", "flat", "--cu", "2", "--partition", "dynamic", "--tile", "64"}, Check::own_ideal},
      {"PlanRoundRobinPhongUnits", "sphere.json", "96x54",
       {"--method", "phong", "--cu", "2", "--partition", "round-robin", "--units", "segment:4"}, Check::own_ideal},
      // the lanes kernel shape: local memory, barriers, a work-group per tile
      {"LanesGouraudTile16", "teapot.json", "96x54", {"--kernel-shape", "lanes", "--tile", "16", "--work-group-size", "16"},
       Check::own_ideal},
      {"LanesPhongFloatOutput", "sphere.json", "90x50", {"--method", "phong", "--kernel-shape", "lanes", "--float"},
       Check::own_ideal},
      // --- float, the reference's ideal not the method's: error and coverage as on PoCL --------------
      {"GouraudSierpinskiFloat", "default.json", "96x54", {"--units", "sierpinski:1"}, Check::approximation},
      {"CombinedK2", "teapot.json", "96x54", {"--method", "combined:2"}, Check::approximation},
      {"CombinedAutoHighlightTest", "default.json", "96x54",
       {"--method", "combined:auto", "--max-error", "2", "--highlight-test"}, Check::approximation},
      {"CombinedChoiceBound", "default.json", "96x54", {"--method", "combined:auto", "--triangle-choice", "bound"},
       Check::approximation},
      // combined:0 on the stamps: the teapot's tiles hold enough triangles to be deferred at this size.
      {"CombinedZeroChoiceBoundStamps", "teapot.json", "96x54",
       {"--method", "combined:0", "--triangle-choice", "bound", "--max-error", "4"}, Check::approximation},
      {"CombinedZeroHighlightTestStamps", "teapot.json", "96x54", {"--method", "combined:0", "--highlight-test"},
       Check::approximation},
      {"CombinedChoiceSources", "teapot.json", "96x54", {"--method", "combined:3", "--triangle-choice", "sources"},
       Check::approximation},
      {"CombinedChoiceSourcesLiteral", "sphere.json", "90x50",
       {"--method", "combined:auto", "--triangle-choice", "sources-literal", "--combined-min-width", "4"},
       Check::approximation},
      {"NormalizeCubicFit", "teapot.json", "96x54", {"--method", "phong", "--normalize", "quadratic:cubic-fit", "--tile", "32"},
       Check::approximation},
      {"NormalizeDichotomyLinear3", "default.json", "96x54", {"--method", "phong", "--normalize", "dichotomy:linear:3"},
       Check::approximation},
      {"NormalizeDichotomyQuadraticFitExtrapolate", "sphere.json", "96x54",
       {"--method", "phong", "--normalize", "dichotomy:quadratic-fit:4:extrapolate"}, Check::approximation},
      {"NormalizeRecurrenceDiffTable", "default.json", "96x54",
       {"--method", "phong", "--normalize", "recurrence-diff:table"}, Check::approximation},
      {"NormalizeRecurrenceTableFixed64Tile64", "teapot.json", "96x54",
       {"--method", "phong", "--normalize", "recurrence:table-fixed:64", "--tile", "64"}, Check::approximation},
      {"PlanLptNormalizeSlerp", "teapot.json", "96x54",
       {"--method", "phong", "--normalize", "slerp", "--cu", "3", "--partition", "lpt"}, Check::approximation},
      {"SpecularTaylor2", "teapot.json", "96x54", {"--method", "phong", "--specular", "cosk:taylor:2"},
       Check::approximation},
      {"SpecularQuadratic", "sphere.json", "96x54", {"--method", "phong", "--specular", "quadratic"},
       Check::approximation},
      {"Specular7n16P178Units", "default.json", "96x54",
       {"--method", "phong", "--specular", "7n16:1.78", "--units", "counter", "--arith", "fixed:12.12"},
       Check::approximation},
  };
  return paths;
}

// The variable's value (or `fallback`) in lower case: device names match case-blind (open_device).
std::string env_or(const char* name, const std::string& fallback) {
  const char* v = std::getenv(name);
  std::string s = v && *v ? std::string(v) : fallback;
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// The device under test and the one it is held to (name substrings, `--device`).
std::string device_under_test() { return env_or("PARASHADE_ANYDEVICE", PARASHADE_ANYDEVICE_DEFAULT); }
std::string reference_device() { return env_or("PARASHADE_ANYDEVICE_REFERENCE", "portable computing language"); }
bool is_oclgrind(const std::string& device) { return device.find("oclgrind") != std::string::npos; }

// The tests' own ICD folder (tests/CMakeLists.txt) with the library path Intel's runtime needs (its
// folder's libraries but the ICD loader), PoCL's cache, kernel warnings as errors, and on Oclgrind its
// checks. Set in this process, so every parashade run inherits them. Oclgrind's uninitialized-value
// plugin stays off: in 21.10 it cannot read LLVM's `freeze` instruction, which every kernel here contains.
void set_test_environment() {
  ::setenv("OCL_ICD_VENDORS", PARASHADE_ICD_DIR, 1);
  if (*PARASHADE_ICD_LIBRARY_PATH) ::setenv("LD_LIBRARY_PATH", PARASHADE_ICD_LIBRARY_PATH, 1);
  ::setenv("POCL_CACHE_DIR", PARASHADE_POCL_CACHE_DIR, 1);
  ::setenv("PARASHADE_KERNEL_WERROR", "1", 1);
  for (const char* check : {"OCLGRIND_CHECK_API", "OCLGRIND_DATA_RACES"}) {
    if (is_oclgrind(device_under_test())) ::setenv(check, "1", 1);
    else ::unsetenv(check);
  }
  ::unsetenv("PARASHADE_FAIL_DEVICE");
  ::unsetenv("PARASHADE_WARN_DEVICE");
}

// How to get the device under test when it is not listed.
std::string how_to_install(const std::string& device) {
  if (is_oclgrind(device)) return "oclgrind not installed? scripts/install-deps.sh, then configure again";
  if (device.find("intel") != std::string::npos) return PARASHADE_INTEL_OPENCL_MISSING;
  return "is its ICD library in PARASHADE_TEST_ICDS? (README, \"Implementations tested\")";
}

std::string slurp(const fs::path& p) {
  std::ostringstream s;
  s << std::ifstream(p, std::ios::binary).rdbuf();
  return s.str();
}

struct Render {
  RunResult run;
  std::string diagnostics;  // Oclgrind's log
  json report;
  RenderedImage image;
};

// One `parashade render` of `path` on `device`, files in `dir` named after `tag`. Oclgrind writes its
// diagnostics to OCLGRIND_LOG instead of stderr (so they cannot mix with parashade's own messages).
Render render_on(const std::string& device, const KernelPath& path, const fs::path& dir, const std::string& tag) {
  const bool float_image = std::find(path.args.begin(), path.args.end(), "--float") != path.args.end();
  const fs::path image = dir / (tag + (float_image ? ".exr" : ".png")), report = dir / (tag + ".json");
  const fs::path log = dir / (tag + ".oclgrind.log");
  if (is_oclgrind(device)) ::setenv("OCLGRIND_LOG", log.c_str(), 1);
  std::vector<std::string> args = {"render", (fs::path(PARASHADE_SOURCE_DIR) / "scenes" / path.scene).string(),
                                   "--device", device, "--size", path.size, "--no-tuned", "--frames", "1",
                                   "--warmup", "0", "-q", "-o", image.string(), "--report", report.string()};
  args.insert(args.end(), path.args.begin(), path.args.end());
  Render r;
  r.run = run_parashade(args, {}, std::chrono::seconds(300));
  ::unsetenv("OCLGRIND_LOG");
  if (fs::exists(log)) r.diagnostics = slurp(log);
  if (r.run.exited() && r.run.exit_code == 0) {
    r.report = json::parse(slurp(report), nullptr, /*allow_exceptions=*/false);
    r.image = read_image(image);
  }
  return r;
}

// The documented float bound of the method's ideal (docs/error-bounds.md) for the scene at this size:
// Gouraud (and flat, constant per triangle) |I - I*| <= 8u (max|I_v| + |dI_G| w + |A6| h) over the
// triangles; Phong 64u * 255 * sum_l I_l (k_d + k_s (n + 1)), times the number of lights as the kernel
// tests take it; the combined method interpolates Phong values linearly along segments: both added.
double documented_bound(const KernelPath& path) {
  Scene scene = load_scene(fs::path(PARASHADE_SOURCE_DIR) / "scenes" / path.scene);
  const std::string size = path.size;
  scene.width = std::stoi(size.substr(0, size.find('x')));
  scene.height = std::stoi(size.substr(size.find('x') + 1));
  const auto at = std::find(path.args.begin(), path.args.end(), "--method");
  const std::string method = at != path.args.end() && at + 1 != path.args.end() ? *(at + 1) : "gouraud";
  ScreenGeometry g;
  build_screen_geometry(scene, {Method::gouraud, false}, g);
  const double gouraud = gouraud_bound(g);
  if (method == "gouraud" || method == "flat") return gouraud;
  double phong = 0.0;
  for (const Light& l : scene.lights)
    for (const Material& m : scene.materials)
      for (int c = 0; c < 3; ++c)
        phong = std::max(phong, double(l.color[c]) * (m.diffuse[c] + m.specular[c] * (m.shininess + 1.0)));
  phong *= 64.0 * kUnitRoundoff * 255.0 * double(scene.lights.size());
  return method == "phong" ? phong : phong + gouraud;
}

// Pixels (8-bit RGB) that differ, the largest difference, and the first one, for the message.
struct ImageDifference {
  std::size_t pixels = 0;
  int max_levels = 0;
  std::string first;
};

ImageDifference compare_images(const RenderedImage& a, const RenderedImage& b) {
  ImageDifference d;
  if (a.width != b.width || a.height != b.height) {
    d.pixels = std::size_t(-1);
    d.first = "sizes differ";
    return d;
  }
  for (std::size_t p = 0; p < std::size_t(a.width) * a.height; ++p) {
    int worst = 0;
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(int(a.rgba[4 * p + c]) - int(b.rgba[4 * p + c])));
    if (worst == 0) continue;
    if (d.pixels++ == 0) {
      std::ostringstream s;
      s << "first at (" << p % a.width << ", " << p / a.width << "): " << int(a.rgba[4 * p]) << " "
        << int(a.rgba[4 * p + 1]) << " " << int(a.rgba[4 * p + 2]) << " vs " << int(b.rgba[4 * p]) << " "
        << int(b.rgba[4 * p + 1]) << " " << int(b.rgba[4 * p + 2]);
      d.first = s.str();
    }
    d.max_levels = std::max(d.max_levels, worst);
  }
  return d;
}

json field(const json& j, const std::string& pointer) {
  const json::json_pointer p(pointer);
  return j.contains(p) ? j.at(p) : json();
}

class AnyDevice : public ::testing::TestWithParam<KernelPath> {
 protected:
  static void SetUpTestSuite() { set_test_environment(); }
  TempDir dir_;
};

TEST_P(AnyDevice, RendersAsOnPoCL) {
  const KernelPath& path = GetParam();
  const std::string device = device_under_test();
  SCOPED_TRACE(::testing::Message() << "parashade render " << path << " on '" << device << "' vs '"
                                    << reference_device() << "'");
  const Render tested = render_on(device, path, dir_.path(), "tested");
  ASSERT_TRUE(tested.run.exited() && tested.run.exit_code == 0) << tested.run;
  // Oclgrind's diagnostics: an invalid access, a data race, an API error, a kernel warning.
  EXPECT_EQ(tested.diagnostics, "") << "Oclgrind reported:\n" << tested.diagnostics;
  const Render reference = render_on(reference_device(), path, dir_.path(), "reference");
  ASSERT_TRUE(reference.run.exited() && reference.run.exit_code == 0) << reference.run;
  // A quiet render prints only the host's warnings (register wraps, vanishing triangles), the same on
  // both devices; anything more is the implementation's (Oclgrind's reports, a runtime's messages).
  EXPECT_EQ(tested.run.err, reference.run.err) << "stderr of a quiet render on " << device << ":" << tested.run;
  const std::string tested_name = field(tested.report, "/device/name").get<std::string>();
  const std::string reference_name = field(reference.report, "/device/name").get<std::string>();
  ASSERT_NE(tested_name, reference_name) << "the same device twice: is the second implementation registered?";
  std::string tested_text = field(tested.report, "/device/platform").get<std::string>() + " / " + tested_name;
  for (char& c : tested_text) c = char(std::tolower(static_cast<unsigned char>(c)));
  EXPECT_NE(tested_text.find(device), std::string::npos) << "--device " << device << " rendered on " << tested_text;
  RecordProperty("devices", tested_name + " vs " + reference_name);

  const ImageDifference d = compare_images(tested.image, reference.image);
  const json& te = field(tested.report, "/error/implementation");
  const json& re = field(reference.report, "/error/implementation");
  ASSERT_TRUE(te.is_object() && re.is_object()) << "no error figures in the reports";
  // The figures, for a summary across devices (--gtest_output=json: docs/pipeline.md's table).
  RecordProperty("pixels_differ", std::to_string(d.pixels));
  RecordProperty("max_levels_differ", std::to_string(d.max_levels));
  RecordProperty("max_abs_error", te.value("max_abs", json(-1)).dump());
  RecordProperty("reference_max_abs_error", re.value("max_abs", json(-1)).dump());
  if (path.check == Check::bytes) {
    EXPECT_EQ(d.pixels, 0u) << d.pixels << " pixels differ, by up to " << d.max_levels << " levels; " << d.first;
    EXPECT_EQ(tested.image.rgb_float, reference.image.rgb_float) << "the --float register values differ";
    EXPECT_EQ(field(tested.report, "/modeled_clocks"), field(reference.report, "/modeled_clocks"));
    EXPECT_EQ(te.value("coverage_mismatch", -1), re.value("coverage_mismatch", -2));
    EXPECT_EQ(field(tested.report, "/plan/per_unit"), field(reference.report, "/plan/per_unit"));
    return;
  }
  // Float: coverage exact (as PoCL's where the method moves vertices), the documented bound, and pixels
  // as close to PoCL's as two values each within 0.5 + bound of the same ideal can be.
  const double bound = documented_bound(path);
  RecordProperty("bound_levels", std::to_string(bound));
  EXPECT_EQ(te.value("coverage_mismatch", -1), re.value("coverage_mismatch", -2)) << te.dump() << "\nPoCL: " << re.dump();
  if (path.check == Check::own_ideal) EXPECT_EQ(te.value("coverage_mismatch", -1), 0) << te.dump();
  const double tested_max = te.value("max_abs", 1e9), reference_max = re.value("max_abs", 1e9);
  if (path.check == Check::own_ideal) {
    EXPECT_LE(tested_max, 0.5 + bound) << te.dump();
  } else {  // the approximation's own error, which PoCL measures too, plus the float bound
    EXPECT_LE(tested_max, std::max(0.5, reference_max) + bound) << te.dump() << "\nPoCL: " << re.dump();
  }
  EXPECT_LE(d.max_levels, std::max(1, int(1.0 + 2.0 * bound))) << d.pixels << " pixels differ; " << d.first;
  if (!tested.image.rgb_float.empty()) {
    ASSERT_EQ(tested.image.rgb_float.size(), reference.image.rgb_float.size());
    double worst = 0.0;
    for (std::size_t i = 0; i < tested.image.rgb_float.size(); ++i)
      worst = std::max(worst, double(std::abs(tested.image.rgb_float[i] - reference.image.rgb_float[i])));
    EXPECT_LE(worst, 2.0 * bound + 1e-3) << "float images differ by " << worst << " levels";
  }
}

INSTANTIATE_TEST_SUITE_P(Paths, AnyDevice, ::testing::ValuesIn(kernel_paths()),
                         [](const ::testing::TestParamInfo<KernelPath>& info) { return std::string(info.param.name); });

// `parashade devices` lists both implementations from the tests' ICD folder (RendersAsOnPoCL checks
// that `--device oclgrind` picks Oclgrind).
TEST(AnyDeviceSetup, DevicesListsBothImplementations) {
  set_test_environment();
  const RunResult r = run_parashade({"devices", "--json"});
  ASSERT_TRUE(r.exited() && r.exit_code == 0) << r;
  const json list = json::parse(r.out, nullptr, false);
  ASSERT_TRUE(list.is_array()) << r;
  bool tested = false, reference = false;
  for (const json& d : list) {
    std::string text = d.value("platform", "") + " / " + d.value("name", "");
    for (char& c : text) c = char(std::tolower(static_cast<unsigned char>(c)));
    tested |= text.find(device_under_test()) != std::string::npos;
    reference |= text.find(reference_device()) != std::string::npos;
  }
  EXPECT_TRUE(tested) << "'" << device_under_test() << "' is not listed (" << how_to_install(device_under_test())
                      << "):" << r;
  EXPECT_TRUE(reference) << "'" << reference_device() << "' is not listed:" << r;
}

// PARASHADE_KERNEL_WERROR=1 fails a build that warns, on either device: a warning injected ahead of the
// kernels (PARASHADE_WARN_DEVICE) ends the render with exit 4 naming it. PoCL's kernel cache would
// skip the compiler (and its log) for a program it built before: this run uses no cache.
TEST(AnyDeviceSetup, KernelWarningsAreErrorsOnBothDevices) {
  set_test_environment();
  TempDir dir;
  for (const std::string& device : {device_under_test(), reference_device()}) {
    SCOPED_TRACE(device);
    ::setenv("POCL_KERNEL_CACHE", "0", 1);
    // The device's name (not its platform's) must hold the substring: ask the device for it.
    const RunResult list = run_parashade({"devices", "--json"});
    std::string name;
    for (const json& d : json::parse(list.out, nullptr, false)) {
      std::string text = d.value("platform", "") + " / " + d.value("name", "");
      for (char& c : text) c = char(std::tolower(static_cast<unsigned char>(c)));
      if (name.empty() && text.find(device) != std::string::npos) name = d.value("name", "");
    }
    ASSERT_FALSE(name.empty()) << list;
    ::setenv("PARASHADE_WARN_DEVICE", name.c_str(), 1);
    const RunResult r = run_parashade({"render", (fs::path(PARASHADE_SOURCE_DIR) / "scenes" / "teapot.json").string(),
                                       "--device", device, "--size", "32x18", "--no-tuned", "--no-error", "--frames", "1",
                                       "--warmup", "0", "-q", "-o", (dir.path() / "warned.png").string()},
                                      {}, std::chrono::seconds(300));
    ::unsetenv("PARASHADE_WARN_DEVICE");
    ::unsetenv("POCL_KERNEL_CACHE");
    EXPECT_TRUE(r.exited() && r.exit_code == 4) << r;
    EXPECT_NE(r.err.find("warning injected by PARASHADE_WARN_DEVICE"), std::string::npos) << r;
    EXPECT_NE(r.err.find("PARASHADE_KERNEL_WERROR"), std::string::npos) << r;
    EXPECT_FALSE(fs::exists(dir.path() / "warned.png"));
  }
}

// A tuned entry is used by the device it was tuned on only (docs/tuning.md): one tuned on PoCL (the
// reference) renders PoCL's frames with it, but not the device under test's, which says why.
TEST(AnyDeviceSetup, AnEntryTunedOnPoCLIsNotUsedOnTheDevice) {
  set_test_environment();
  TempDir dir;
  const std::string scene = (fs::path(PARASHADE_SOURCE_DIR) / "scenes" / "sphere.json").string();
  const std::string cache = (dir.path() / "tune.json").string();
  const RunResult tuned = run_parashade({"tune", scene, "--size", "48x32", "--device", reference_device(), "--param",
                                         "tile=32", "--param", "work_items=0", "--param", "partition=none", "--frames",
                                         "1", "--cache", cache, "-q"},
                                        {}, std::chrono::seconds(300));
  ASSERT_TRUE(tuned.exited() && tuned.exit_code == 0) << tuned;
  const auto render_with_cache = [&](const std::string& device) {
    return run_parashade({"render", scene, "--size", "48x32", "--device", device, "--tune-cache", cache, "--frames",
                          "1", "--warmup", "0", "--no-error", "-o", (dir.path() / "sphere.png").string(), "--report",
                          (dir.path() / "sphere.json").string()},
                         {}, std::chrono::seconds(300));
  };
  const RunResult on_reference = render_with_cache(reference_device());
  ASSERT_TRUE(on_reference.exited() && on_reference.exit_code == 0) << on_reference;
  EXPECT_NE(on_reference.err.find("using the tuned configuration"), std::string::npos) << on_reference;
  const RunResult on_device = render_with_cache(device_under_test());
  ASSERT_TRUE(on_device.exited() && on_device.exit_code == 0) << on_device;
  EXPECT_EQ(on_device.err.find("using the tuned configuration"), std::string::npos) << on_device;
  EXPECT_NE(on_device.err.find("1 entry of another device"), std::string::npos) << on_device;
  const json report = json::parse(slurp(dir.path() / "sphere.json"), nullptr, false);
  EXPECT_TRUE(field(report, "/tuned").is_null()) << report.dump(1);
}

}  // namespace
}  // namespace parashade
