#pragma once
// What the CLI tests share: a scratch directory with in/ (files given to parashade) and out/ (the only
// place a run may write), the documented exit codes, a small scene, and the checks for a failed run.
#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "run_parashade.hpp"
#include "scene/temp_dir.hpp"
#include "test_support.hpp"

namespace parashade::testing_support {

// The exit codes `parashade --help` documents (README, "Using it"); written out here rather than taken
// from errors.hpp, so that the tests hold the binary to its documentation.
constexpr int kOk = 0, kUsage = 2, kBadInput = 3, kDeviceFailure = 4;

// 64x48, one coarse white sphere (8 slices x 5 stacks: 2*8*4 = 64 triangles, scenes/README.md) in the
// middle of a blue-grey background, lit from the camera; back faces culled.
inline std::string sphere_scene() {
  return R"({
  "name": "ball",
  "resolution": [64, 48],
  "background": [0.2, 0.4, 0.6],
  "camera": {"position": [0, 0, 4], "target": [0, 0, 0], "fov": 40, "near": 1, "far": 10},
  "lights": [{"type": "directional", "direction": [0, 0, -1]}],
  "objects": [{"shape": {"type": "sphere", "slices": 8, "stacks": 5}}],
  "cull_backfaces": true
})";
}
constexpr int kSphereTriangles = 64;

// 640x360, a 256 x 128 sphere: ~21 000 screen triangles after culling, ~3 MiB of Gouraud records (a frame
// that streams under a 1 MiB band budget and not under the default).
inline std::string many_triangles_scene() {
  return R"({
  "name": "fine ball",
  "resolution": [640, 360],
  "camera": {"position": [0, 0, 3], "target": [0, 0, 0], "fov": 45},
  "lights": [{"type": "directional", "direction": [-0.3, -0.4, -1]}],
  "objects": [{"shape": {"type": "sphere", "slices": 256, "stacks": 128}}],
  "cull_backfaces": true
})";
}

// A regular tetrahedron around the origin, faces wound outward: the smallest closed mesh.
inline std::string tetrahedron_obj() {
  return "# regular tetrahedron\n"
         "v 1 1 1\nv 1 -1 -1\nv -1 1 -1\nv -1 -1 1\n"
         "f 1 2 3\nf 1 4 2\nf 1 3 4\nf 2 4 3\n";
}

// A file's whole contents (an image compared byte for byte).
inline std::string bytes_of(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

class CliTest : public ::testing::Test {
 protected:
  CliTest() { std::filesystem::create_directories(out_dir()); }

  std::filesystem::path in_dir() const { return dir_.path() / "in"; }
  std::filesystem::path out_dir() const { return dir_.path() / "out"; }
  std::filesystem::path image() const { return out_dir() / "image.png"; }
  std::filesystem::path report() const { return out_dir() / "report.json"; }

  // Writes in/<name> and returns its path.
  std::filesystem::path input(const std::string& name, const std::string& text) const {
    return dir_.write("in/" + name, text);
  }

  enum class ErrorFigures { skip, compute };

  // --device for the device the OpenCL tests use (PARASHADE_TEST_DEVICE), or nothing: the first.
  static std::vector<std::string> device_args() {
    const char* device = std::getenv("PARASHADE_TEST_DEVICE");
    if (!device || !*device) return {};
    return {"--device", device};
  }

  // render SCENE -o out/image.png --report out/report.json, one timed frame and no warm-up, quiet, by
  // default without the error figures (most tests are about the command, not the error), then `extra`.
  // The device is the one the OpenCL tests use (PARASHADE_TEST_DEVICE) unless `extra` picks one.
  std::vector<std::string> render_args(const std::filesystem::path& scene, std::vector<std::string> extra = {},
                                       ErrorFigures errors = ErrorFigures::skip) const {
    std::vector<std::string> args = {"render", scene.string(), "-o", image().string(), "--report", report().string(),
                                     "--frames", "1", "--warmup", "0", "-q"};
    if (errors == ErrorFigures::skip) args.push_back("--no-error");
    if (std::find(extra.begin(), extra.end(), "--device") == extra.end()) {
      const std::vector<std::string> device = device_args();
      args.insert(args.end(), device.begin(), device.end());
    }
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
  }

  RunResult render(const std::filesystem::path& scene, std::vector<std::string> extra = {},
                   ErrorFigures errors = ErrorFigures::skip) const {
    return run_parashade(render_args(scene, std::move(extra), errors));
  }

  // Every entry of out/, hidden ones (temporary files) included.
  std::vector<std::string> out_entries() const {
    std::vector<std::string> names;
    for (const auto& e : std::filesystem::recursive_directory_iterator(out_dir()))
      names.push_back(std::filesystem::relative(e.path(), out_dir()).string());
    std::sort(names.begin(), names.end());
    return names;
  }

  // A failed run leaves out/ as it found it: empty. No image, no report, no temporary file.
  ::testing::AssertionResult nothing_written() const {
    const std::vector<std::string> names = out_entries();
    if (names.empty()) return ::testing::AssertionSuccess();
    auto failure = ::testing::AssertionFailure() << "left behind in out/:";
    for (const std::string& n : names) failure << " " << n;
    return failure;
  }

  nlohmann::json read_report() const {
    std::ifstream in(report());
    if (!in) ADD_FAILURE() << "no report at " << report();
    return nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  }

  TempDir dir_;
};

// A test name from a string parameter: "64 x 48" -> 64_x_48 (gtest and ctest take only [A-Za-z0-9_]).
inline std::string name_from(std::string text) {
  for (char& c : text)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return text;
}
struct StringParamName {
  template <class Info>
  std::string operator()(const Info& info) const {
    return name_from(info.param);
  }
};

// The value at a JSON pointer ("/error/method/max_abs"), null when it is not there: a missing field
// fails the comparison that uses it instead of throwing.
inline nlohmann::json field(const nlohmann::json& j, const std::string& pointer) {
  const nlohmann::json::json_pointer p(pointer);
  return j.contains(p) ? j.at(p) : nlohmann::json();
}

// The run ended by itself (no crash, no hang) with `code` and its stderr names every culprit. Nothing
// goes to stdout: the summary lines belong to a finished render.
inline ::testing::AssertionResult fails_with(const RunResult& r, int code, const std::vector<std::string>& culprits) {
  if (!r.exited()) return ::testing::AssertionFailure() << "did not exit normally:" << r;
  if (r.exit_code != code) return ::testing::AssertionFailure() << "expected exit code " << code << ":" << r;
  for (const std::string& c : culprits)
    if (r.err.find(c) == std::string::npos)
      return ::testing::AssertionFailure() << "stderr does not name '" << c << "':" << r;
  if (!r.out.empty()) return ::testing::AssertionFailure() << "a failed run printed to stdout:" << r;
  return ::testing::AssertionSuccess();
}
inline ::testing::AssertionResult fails_with(const RunResult& r, int code,
                                            std::initializer_list<std::string> culprits) {
  return fails_with(r, code, std::vector<std::string>(culprits));
}

inline ::testing::AssertionResult succeeds(const RunResult& r) {
  if (r.exited() && r.exit_code == kOk) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "expected exit code 0:" << r;
}

}  // namespace parashade::testing_support
