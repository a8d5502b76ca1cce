// render --against METHOD (host/cli/against_frames.hpp): a second renderer's frames alternate with the
// rendered method's in one process, and the report holds both medians and the pairs' ratios. The ratio
// figures are checked against the frame times the report gives for the same frames, not against a speed.
#include <algorithm>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli_fixture.hpp"

namespace parashade {
namespace {

using namespace testing_support;

class CliAgainst : public CliTest {
 protected:
  // render SCENE EXTRA with `frames` timed frames (the fixture times one); the report.
  nlohmann::json render_frames(const std::filesystem::path& scene, std::vector<std::string> extra, int frames) {
    std::vector<std::string> args = render_args(scene, std::move(extra));
    *(std::find(args.begin(), args.end(), "--frames") + 1) = std::to_string(frames);
    EXPECT_TRUE(succeeds(run_parashade(args)));
    return read_report();
  }
};

// The median of the pairs' ratios: the against frame over this render's frame of the same pair.
double median_pair_ratio(const nlohmann::json& report) {
  const std::vector<double> mine = report["timing"]["samples_ms"], theirs = report["against"]["samples_ms"];
  EXPECT_EQ(mine.size(), theirs.size());
  std::vector<double> ratios;
  for (std::size_t i = 0; i < mine.size() && i < theirs.size(); ++i) ratios.push_back(theirs[i] / mine[i]);
  std::sort(ratios.begin(), ratios.end());
  return ratios.empty() ? 0.0 : ratios[ratios.size() / 2];
}

TEST_F(CliAgainst, ReportsPairsOfBothRenderers) {
  const auto scene = input("ball.json", sphere_scene());
  const nlohmann::json r = render_frames(scene, {"--method", "gouraud", "--against", "phong"}, 7);
  const nlohmann::json& a = r["against"];
  EXPECT_EQ(a["method"], "phong");
  EXPECT_EQ(a["pairs"], 7) << "one against frame per timed frame";
  EXPECT_GT(a["frame_ms"].get<double>(), 0.0);
  const double lo = a["frame_ratio"]["p10"], mid = a["frame_ratio"]["median"], hi = a["frame_ratio"]["p90"];
  EXPECT_LE(lo, mid);
  EXPECT_LE(mid, hi);
  EXPECT_DOUBLE_EQ(mid, median_pair_ratio(r));
  EXPECT_EQ(r["method"], "gouraud") << "the rendered method is still the one reported";
}

// render --against-device: the same request on another device (here PoCL's pthread device twice: two
// contexts of one device, whatever the test device), its frames alternating with these.
TEST_F(CliAgainst, PairsFramesOfAnotherDevice) {
  const auto scene = input("ball.json", sphere_scene());
  const nlohmann::json r = render_frames(scene, {"--method", "phong", "--against-device", "pthread"}, 5);
  const nlohmann::json& a = r["against"];
  EXPECT_EQ(a["method"], "phong") << "the same request: this render's method";
  EXPECT_NE(a["device"].get<std::string>().find("pthread"), std::string::npos) << a["device"];
  EXPECT_EQ(a["pairs"], 5);
  EXPECT_DOUBLE_EQ(a["frame_ratio"]["median"].get<double>(), median_pair_ratio(r));
  EXPECT_GT(a["kernel_ratio"]["median"].get<double>(), 0.0);
}

TEST_F(CliAgainst, AgainstDeviceRefusesWhatItCannotPair) {
  const auto scene = input("ball.json", sphere_scene());
  EXPECT_TRUE(fails_with(render(scene, {"--against-device", "no-such-device"}), kDeviceFailure,
                         {"--against-device 'no-such-device'"}));
  EXPECT_TRUE(fails_with(render(scene, {"--against-device", "pthread", "--against", "flat"}), kUsage,
                         {"--against and --against-device"}));
  EXPECT_TRUE(fails_with(render(scene, {"--against-device", "all"}), kUsage, {"--against-device", "'all'"}));
  EXPECT_TRUE(fails_with(render(scene, {"--against-device", "pthread", "--device", "all"}), kUsage,
                         {"--against-device", "'all'"}));
  EXPECT_TRUE(nothing_written());
}

// The second renderer's frame is in the host memory budget: at 4096x4096 the sphere needs about 1.5 GiB alone
// and 128 MiB more with a second renderer (8 bytes a pixel), so a limit between the two refuses only the pair.
TEST_F(CliAgainst, TheSecondRendererIsInTheMemoryBudget) {
  const auto scene = input("ball.json", sphere_scene());
  const ScopedEnv limit("PARASHADE_MEMORY_LIMIT", "1600M");
  EXPECT_TRUE(succeeds(render(scene, {"--size", "4096x4096"})));
  EXPECT_TRUE(fails_with(render(scene, {"--size", "4096x4096", "--against-device", "pthread"}), kBadInput,
                         {"host memory", "--against-device"}));
  EXPECT_TRUE(fails_with(render(scene, {"--size", "4096x4096", "--against", "phong"}), kBadInput,
                         {"host memory", "--against"}));
}

TEST_F(CliAgainst, OnlyPlainMethods) {
  const auto scene = input("ball.json", sphere_scene());
  EXPECT_TRUE(fails_with(render(scene, {"--against", "combined:2"}), kUsage, {"--against", "combined:2"}));
  EXPECT_TRUE(fails_with(render(scene, {"--against", "blinn"}), kUsage, {"--against", "blinn"}));
  EXPECT_TRUE(nothing_written());
}

TEST_F(CliAgainst, NotAcrossDevices) {
  const auto scene = input("ball.json", sphere_scene());
  EXPECT_TRUE(fails_with(render(scene, {"--against", "phong", "--device", "all"}), kUsage, {"--against", "'all'"}));
  EXPECT_TRUE(nothing_written());
}

}  // namespace
}  // namespace parashade
