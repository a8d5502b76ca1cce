// Issue 47, "Silence": a cold first render spent 9 s compiling kernels behind "rendering teapot ..." with
// nothing said; the printed stages did not add up to the frame (4.73 ms against 2.15 ms of stages, and
// launch_ms, in the report, not printed); tune printed medians alone and a bare speed-up. Now a build that
// takes long says "compiling kernels for DEVICE (first run; cached in DIR)..." while it runs (not with -q),
// the frame line has launch and other, and tune gives each candidate's spread and the speed-up's interval.
#include <regex>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli_fixture.hpp"

namespace parashade {
namespace {

using namespace testing_support;

class CliHonestTimings : public CliTest {
 protected:
  std::filesystem::path scene_ = input("ball.json", sphere_scene());

  // render_args without -q.
  std::vector<std::string> loud(std::vector<std::string> extra = {}) const {
    std::vector<std::string> args = render_args(scene_, std::move(extra));
    args.erase(std::find(args.begin(), args.end(), "-q"));
    return args;
  }
};

// An empty PoCL cache: the kernels compile (seconds), and the run says so; the next run takes them from the
// cache and says nothing; -q says nothing even while compiling.
TEST_F(CliHonestTimings, AKernelBuildThatCompilesIsAnnounced) {
  const std::filesystem::path kcache = dir_.path() / "kcache";
  const ScopedEnv cache("POCL_CACHE_DIR", kcache.string());
  const RunResult cold = run_parashade(loud());
  ASSERT_TRUE(succeeds(cold));
  EXPECT_NE(cold.err.find("compiling kernels for "), std::string::npos) << cold;
  if (!std::getenv("PARASHADE_TEST_DEVICE"))  // PoCL, the default device: its cache is named
    EXPECT_NE(cold.err.find("(first run; cached in " + kcache.string() + ")..."), std::string::npos) << cold;
  EXPECT_LT(cold.err.find("rendering ball"), cold.err.find("compiling kernels")) << cold;
  const RunResult warm = run_parashade(loud());
  ASSERT_TRUE(succeeds(warm));
  EXPECT_EQ(warm.err.find("compiling kernels"), std::string::npos) << warm;
  const ScopedEnv off("POCL_KERNEL_CACHE", "0");
  const RunResult quiet = render(scene_);
  ASSERT_TRUE(succeeds(quiet));
  EXPECT_EQ(quiet.err.find("compiling kernels"), std::string::npos) << quiet;
}

TEST_F(CliHonestTimings, ThePrintedStagesAddUpToTheFrame) {
  std::vector<std::string> args = render_args(scene_);
  *(std::find(args.begin(), args.end(), "--frames") + 1) = "3";
  const RunResult r = run_parashade(args);
  ASSERT_TRUE(succeeds(r));
  std::smatch m;
  const std::regex line(R"(frame: ([0-9.]+) ms \(median of 3 after 0 warm-up; geometry ([0-9.]+), setup ([0-9.]+), )"
                        R"(binning ([0-9.]+), launch ([0-9.]+) \(kernel ([0-9.]+) of it\), read-back ([0-9.]+), )"
                        R"(other (-?[0-9.]+)\))");
  ASSERT_TRUE(std::regex_search(r.out, m, line)) << r;
  double stages = 0;
  for (int i : {2, 3, 4, 5, 7, 8}) stages += std::stod(m[i]);
  EXPECT_NEAR(stages, std::stod(m[1]), 0.0035) << r;  // six values rounded to 0.001
  EXPECT_LE(std::stod(m[6]), std::stod(m[5]) + 0.001) << "the kernel is part of the launch:" << r;
  EXPECT_NEAR(std::stod(m[5]), field(read_report(), "/stages_ms/launch_ms").get<double>(), 0.0005) << r;
}

TEST_F(CliHonestTimings, TuneGivesSpreadsAndTheSpeedUpsInterval) {
  std::vector<std::string> args = {"tune", scene_.string(), "--cache", (out_dir() / "cache.json").string(),
                                   "--report", report().string(), "--frames", "3", "-q", "--param", "tile=32,64",
                                   "--param", "work_items=0", "--param", "partition=none"};
  const std::vector<std::string> device = device_args();
  args.insert(args.end(), device.begin(), device.end());
  const RunResult r = run_parashade(args);
  ASSERT_TRUE(succeeds(r));
  const std::regex candidate(R"(tile=\d+ +([0-9.]+) ms \(([0-9.]+)\.\.([0-9.]+)\))");
  int seen = 0;
  for (std::sregex_iterator it(r.out.begin(), r.out.end(), candidate), end; it != end; ++it, ++seen) {
    EXPECT_LE(std::stod((*it)[2]), std::stod((*it)[1])) << r;
    EXPECT_LE(std::stod((*it)[1]), std::stod((*it)[3])) << r;
  }
  EXPECT_GE(seen, 2) << "no candidate line with its spread:" << r;
  EXPECT_TRUE(std::regex_search(r.out, std::regex(R"(speed-up [0-9.]+x, \d+ % interval [0-9.]+x\.\.[0-9.]+x)"))) << r;
  const nlohmann::json c = field(read_report(), "/confirmation");
  EXPECT_LE(field(c, "/speedup_interval/low").get<double>(), field(c, "/speedup").get<double>()) << c;
  EXPECT_GE(field(c, "/speedup_interval/high").get<double>(), field(c, "/speedup").get<double>()) << c;
  EXPECT_NEAR(field(c, "/speedup_interval/confidence").get<double>(), 0.9375, 1e-9) << c;  // 5 pairs: min..max
}

}  // namespace
}  // namespace parashade
