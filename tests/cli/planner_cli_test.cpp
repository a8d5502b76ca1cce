// The planner's commands: `render --cu/--partition` (report and image), `plan` (no rendering), and
// `tune` (a cache that render then uses, and ignores with --no-tuned).
#include <fstream>
#include <iterator>

#include <gtest/gtest.h>

#include "cli_fixture.hpp"

namespace parashade {
namespace {

using namespace testing_support;

class PlannerCli : public CliTest {};

TEST_F(PlannerCli, RenderWithUnitsReportsTheLoadAndKeepsTheImage) {
  const auto scene = input("ball.json", sphere_scene());
  ASSERT_TRUE(succeeds(render(scene, {"--no-tuned"})));
  const std::string plain = bytes_of(image());
  ASSERT_TRUE(succeeds(render(scene, {"--cu", "3", "--partition", "lpt"})));
  EXPECT_EQ(bytes_of(image()), plain) << "the planned frame's image differs from the plain one";
  const nlohmann::json r = read_report();
  EXPECT_EQ(field(r, "/plan/partition"), "lpt");
  EXPECT_EQ(field(r, "/plan/units"), 3);
  ASSERT_TRUE(field(r, "/plan/per_unit").is_array());
  EXPECT_EQ(field(r, "/plan/per_unit").size(), 3u);
  std::uint64_t sum = 0, most = 0;
  for (const auto& u : r["plan"]["per_unit"]) {
    sum += u["clocks"].get<std::uint64_t>();
    most = std::max(most, u["clocks"].get<std::uint64_t>());
  }
  EXPECT_EQ(field(r, "/plan/modeled_frame_clocks"), most);
  EXPECT_NEAR(field(r, "/plan/imbalance").get<double>(), double(most) * 3.0 / double(sum), 1e-9);
  EXPECT_TRUE(field(r, "/plan/measured_frame_ms").is_number());
}

TEST_F(PlannerCli, RefusesUnknownPartitionAndBadUnitCount) {
  const auto scene = input("ball.json", sphere_scene());
  EXPECT_TRUE(fails_with(render(scene, {"--partition", "greedy"}), kUsage, {"greedy"}));
  EXPECT_TRUE(fails_with(render(scene, {"--cu", "0"}), kUsage, {"--cu"}));
  EXPECT_TRUE(nothing_written());
}

TEST_F(PlannerCli, PlanPrintsEveryStrategyWithoutRendering) {
  const auto scene = input("ball.json", sphere_scene());
  const RunResult r = run_parashade({"plan", scene.string(), "--cu", "1,4", "--partition", "all", "--report", report().string()});
  ASSERT_TRUE(succeeds(r));
  for (const char* p : {"round-robin", "lpt", "tiles", "dynamic"})
    EXPECT_NE(r.out.find(std::string("plan ") + p + ", U = 4"), std::string::npos) << p << r;
  const nlohmann::json j = read_report();
  ASSERT_EQ(field(j, "/plans").size(), 8u);
  // One unit does all the work: its clocks are the total, imbalance 1.
  EXPECT_EQ(field(j, "/plans/0/units"), 1);
  EXPECT_EQ(field(j, "/plans/0/imbalance"), 1.0);
}

TEST_F(PlannerCli, TuneFillsTheCacheAndRenderUsesIt) {
  const auto scene = input("ball.json", sphere_scene());
  const std::string cache = (out_dir() / "tune.json").string();
  std::vector<std::string> tune = {"tune", scene.string(), "--cache", cache, "--budget-runs", "3", "--frames", "1"};
  const std::vector<std::string> device = device_args();
  tune.insert(tune.end(), device.begin(), device.end());
  const RunResult first = run_parashade(tune, {}, std::chrono::seconds(300));
  ASSERT_TRUE(succeeds(first));
  std::ifstream in(cache);
  const nlohmann::json c = nlohmann::json::parse(in, nullptr, false);
  ASSERT_EQ(field(c, "/entries").size(), 3u) << first;
  for (const auto& e : c["entries"]) {
    EXPECT_TRUE(e.value("verified", false)) << e.dump();
    EXPECT_TRUE(e.contains("device_name") && e.contains("driver_version") && e.contains("problem") && e.contains("params"));
  }
  // Resumed: the cached configurations are skipped, the budget's worth of new ones appended.
  const RunResult second = run_parashade(tune, {}, std::chrono::seconds(300));
  ASSERT_TRUE(succeeds(second));
  std::ifstream in2(cache);
  EXPECT_EQ(field(nlohmann::json::parse(in2, nullptr, false), "/entries").size(), 6u) << second;
  EXPECT_NE(second.out.find("speed-up"), std::string::npos) << second;

  const RunResult used = render(scene, {"--tune-cache", cache});
  ASSERT_TRUE(succeeds(used));
  EXPECT_NE(used.err.find("using the tuned configuration"), std::string::npos) << used;
  EXPECT_TRUE(field(read_report(), "/tuned/params").is_object());
  const RunResult ignored = render(scene, {"--tune-cache", cache, "--no-tuned"});
  ASSERT_TRUE(succeeds(ignored));
  EXPECT_EQ(ignored.err.find("tuned configuration"), std::string::npos) << ignored;
  EXPECT_TRUE(field(read_report(), "/tuned").is_null());
}

}  // namespace
}  // namespace parashade
