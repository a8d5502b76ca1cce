// Determinism (issue 7, item 5): the same input gives a byte-identical image across runs, across the
// number of kernel work-items and the screen tile size (neither changes what a pixel computes), and in
// fixed-point mode across PoCL's pthread and basic devices. Images are written as binary PPM, so the
// file bytes are the pixel bytes. The scene is the shipped teapot (6 320 triangles, overlapping in
// depth, both lights) at 256x192.
#include <chrono>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <thread>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli_fixture.hpp"
#include "parashade/renderer.hpp"

namespace parashade {
namespace {

using namespace testing_support;

std::string file_bytes(const std::filesystem::path& p) {
  std::ostringstream s;
  s << std::ifstream(p, std::ios::binary).rdbuf();
  return s.str();
}

class CliDeterminism : public CliTest {
 protected:
  // Renders the teapot with `extra` options into out/<name>.ppm and returns the file's bytes.
  std::string render_teapot(const std::string& name, std::vector<std::string> extra) const {
    const std::filesystem::path out = out_dir() / (name + ".ppm");
    std::vector<std::string> args = {"render", std::string(PARASHADE_SOURCE_DIR) + "/scenes/teapot.json", "-o",
                                     out.string(), "--size", "256x192", "--frames", "1", "--warmup", "0", "-q",
                                     "--no-error"};
    args.insert(args.end(), extra.begin(), extra.end());
    const RunResult r = run_parashade(args, {}, std::chrono::seconds(120));
    EXPECT_TRUE(succeeds(r)) << name;
    const std::string bytes = file_bytes(out);
    EXPECT_GT(bytes.size(), 256u * 192u * 3u) << name;
    return bytes;
  }
};

TEST_F(CliDeterminism, SameRunTwiceGivesTheSameBytes) {
  for (const std::vector<std::string>& options :
       {std::vector<std::string>{}, {"--method", "phong"}, {"--arith", "fixed:10.4"}}) {
    const std::string first = render_teapot("first", options), second = render_teapot("second", options);
    EXPECT_TRUE(first == second) << "options: " << (options.empty() ? "(none)" : options.back());
  }
}

// Issue 17, item 17: TIFF and EXR used to differ between identical runs by their time stamp (TIFF's
// DateTime, EXR's capDate, to the second). The second run starts in a later second than the first.
TEST_F(CliDeterminism, TiffAndExrOfRunsInDifferentSecondsAreIdentical) {
  const std::filesystem::path scene = input("ball.json", sphere_scene());
  std::string bytes[2][2];
  for (int run = 0; run < 2; ++run) {
    for (int format = 0; format < 2; ++format) {
      const std::filesystem::path out = out_dir() / ("run" + std::to_string(run) + (format ? ".exr" : ".tif"));
      EXPECT_TRUE(succeeds(run_parashade({"render", scene.string(), "-o", out.string(), "--frames", "1", "--warmup",
                                          "0", "-q", "--no-error"})));
      bytes[run][format] = file_bytes(out);
    }
    const std::time_t written = std::time(nullptr);  // at or after the files' time stamps
    while (run == 0 && std::time(nullptr) == written) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  for (int format = 0; format < 2; ++format) {
    EXPECT_FALSE(bytes[0][format].empty()) << format;
    EXPECT_TRUE(bytes[0][format] == bytes[1][format]) << (format ? "EXR" : "TIFF") << " files of identical runs differ";
  }
}

// Work-items split the tiles between them; each tile is rendered by one work-item in any case.
TEST_F(CliDeterminism, WorkItemCountDoesNotChangeTheImage) {
  for (const std::string& arith : {"float", "fixed:10.4"}) {
    const std::string reference = render_teapot("default", {"--arith", arith});
    for (const std::string& items : {"1", "3", "64"})
      EXPECT_TRUE(render_teapot("items" + items, {"--arith", arith, "--work-items", items}) == reference)
          << arith << ", --work-items " << items;
  }
}

// A deferred tile shades each pixel once, by the triangle that won its depth test: what the walk would have kept.
TEST_F(CliDeterminism, DeferralThresholdDoesNotChangeTheImage) {
  for (const std::string& method : {"phong", "combined:0"}) {
    std::vector<std::string> args = {"--method", method};
    if (method != "phong") args.insert(args.end(), {"--triangle-choice", "bound", "--max-error", "3"});
    const std::string reference = render_teapot(method + "-default", args);
    for (const std::string& n : {std::string("0"), std::string("4"), std::to_string(kMaxDeferMinTriangles)}) {
      std::vector<std::string> with = args;
      with.insert(with.end(), {"--defer-min-triangles", n});
      EXPECT_TRUE(render_teapot(method + "-defer" + n, with) == reference) << method << ", --defer-min-triangles " << n;
    }
  }
}

// A pixel's value does not depend on which tile it falls in: coverage is per pixel centre and the span
// values are evaluated from the triangle's planes at the pixel, in float and in fixed point.
TEST_F(CliDeterminism, TileSizeDoesNotChangeTheImage) {
  for (const std::string& arith : {"float", "fixed:10.4"}) {
    const std::string reference = render_teapot("tile16", {"--arith", arith, "--tile", "16"});
    for (const std::string& tile : {"32", "64"})
      EXPECT_TRUE(render_teapot("tile" + tile, {"--arith", arith, "--tile", tile}) == reference)
          << arith << ", --tile " << tile;
  }
}

// Fixed-point spans are integer arithmetic: PoCL's pthread device (vectorizing, several threads) and its
// basic device (one thread) must agree to the byte.
TEST_F(CliDeterminism, PthreadAndBasicDevicesAgreeInFixedPoint) {
  const ScopedEnv devices("POCL_DEVICES", "pthread basic");
  const RunResult listing = run_parashade({"devices"});
  if (listing.out.find("basic") == std::string::npos || listing.out.find("pthread") == std::string::npos)
    GTEST_SKIP() << "PoCL does not offer both devices:" << listing;
  for (const std::string& units : {"classic", "counter"}) {
    const std::string on_pthread = render_teapot("pthread", {"--arith", "fixed:10.4", "--units", units, "--device", "pthread"});
    const std::string on_basic = render_teapot("basic", {"--arith", "fixed:10.4", "--units", units, "--device", "basic"});
    EXPECT_TRUE(on_pthread == on_basic) << "--units " << units;
  }
}

}  // namespace
}  // namespace parashade
