// parashade scaling: the sweep over the modeled shading units runs, its report holds every row with the
// modeled clocks and the error figures, and the clocks order as the units' definitions say. Bad command
// lines and inputs fail with the documented codes and write nothing.
#include <algorithm>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli_fixture.hpp"

namespace parashade {
namespace {

using namespace testing_support;

class CliScaling : public CliTest {
 protected:
  // scaling SCENE --report out/report.json -q on the test device, then `extra`, then --frames 1 unless
  // `extra` gives --frames (a second --frames would be refused by the parser, not by the check under test).
  RunResult scaling(const std::filesystem::path& scene, std::vector<std::string> extra) const {
    std::vector<std::string> args = {"scaling", scene.string(), "--report", report().string(), "-q"};
    if (std::find(extra.begin(), extra.end(), "--frames") == extra.end()) extra.insert(extra.end(), {"--frames", "1"});
    const std::vector<std::string> device = device_args();
    args.insert(args.end(), device.begin(), device.end());
    args.insert(args.end(), extra.begin(), extra.end());
    return run_parashade(args, {}, std::chrono::seconds(120));
  }
  std::filesystem::path sphere_ = std::filesystem::path(PARASHADE_SOURCE_DIR) / "scenes/sphere.json";
};

nlohmann::json row_of(const nlohmann::json& report, const std::string& unit) {
  for (const auto& r : field(report, "/rows"))
    if (r.value("unit", "") == unit) return r;
  ADD_FAILURE() << "no row for " << unit << " in " << report.dump(2);
  return {};
}

TEST_F(CliScaling, SphereClocksOrderAsTheUnitsPromise) {
  const RunResult r = scaling(sphere_, {"--size", "160x120", "--units", "classic,counter,segment:4"});
  ASSERT_TRUE(succeeds(r));
  EXPECT_EQ(out_entries(), std::vector<std::string>{"report.json"});
  // The table names every configuration and the device.
  for (const char* text : {"classic", "counter", "segment:4", "fixed:12.12", "compute units"})
    EXPECT_NE(r.out.find(text), std::string::npos) << "stdout lacks '" << text << "':" << r;

  const nlohmann::json rep = read_report();
  EXPECT_EQ(field(rep, "/width"), 160);
  EXPECT_EQ(field(rep, "/height"), 120);
  EXPECT_TRUE(field(rep, "/device/name").is_string()) << rep.dump(2);
  EXPECT_GT(field(rep, "/device/compute_units"), 0) << rep.dump(2);
  ASSERT_EQ(field(rep, "/rows").size(), 3u) << rep.dump(2);

  for (const auto& row : field(rep, "/rows")) {
    SCOPED_TRACE(row.dump(2));
    EXPECT_EQ(field(row, "/arith"), "fixed:12.12");  // the default
    EXPECT_GT(field(row, "/modeled_clocks/clocks"), 0);
    EXPECT_GT(field(row, "/modeled_clocks/span_pixels"), 0);
    ASSERT_TRUE(field(row, "/frame_ms").is_number());
    EXPECT_GT(field(row, "/frame_ms"), 0.0);
    EXPECT_TRUE(field(row, "/kernel_ms").is_number());
    EXPECT_TRUE(field(row, "/measured_speedup").is_number());
    EXPECT_TRUE(field(row, "/modeled_speedup").is_number());
    for (const std::string kind : {"/error/implementation", "/error/method"})
      for (const char* key : {"/nmse", "/max_abs", "/mean_abs"})
        EXPECT_TRUE(field(row, kind + key).is_number()) << kind << key;
    // Fixed 12.12 through any unit stays within a level of the ideal Gouraud on this sphere.
    EXPECT_LT(field(row, "/error/implementation/max_abs"), 1.0);
  }

  const nlohmann::json classic = row_of(rep, "classic"), counter = row_of(rep, "counter"),
                       segment = row_of(rep, "segment:4");
  // The same spans and pixels whatever the unit; only the clocks differ.
  EXPECT_EQ(field(counter, "/modeled_clocks/spans"), field(classic, "/modeled_clocks/spans"));
  EXPECT_EQ(field(segment, "/modeled_clocks/span_pixels"), field(classic, "/modeled_clocks/span_pixels"));
  const double classic_clocks = field(classic, "/modeled_clocks/clocks");
  const double counter_clocks = field(counter, "/modeled_clocks/clocks");
  const double segment_clocks = field(segment, "/modeled_clocks/clocks");
  // Two intensities per clock halve the span clocks, not the load clock of each span.
  EXPECT_LE(counter_clocks, classic_clocks);
  EXPECT_GE(counter_clocks, classic_clocks / 2);
  EXPECT_LE(segment_clocks, counter_clocks);
  EXPECT_DOUBLE_EQ(field(classic, "/modeled_speedup").get<double>(), 1.0);
  EXPECT_NEAR(field(counter, "/modeled_speedup").get<double>(), classic_clocks / counter_clocks, 1e-9);
}

TEST_F(CliScaling, SeveralArithmeticsGiveEveryPair) {
  const RunResult r = scaling(sphere_, {"--size", "64x48", "--units", "classic,interleave:2", "--arith",
                                        "float,fixed:10.4"});
  ASSERT_TRUE(succeeds(r));
  const nlohmann::json rows = field(read_report(), "/rows");
  ASSERT_EQ(rows.size(), 4u) << rows.dump(2);
  std::vector<std::string> pairs;
  for (const auto& row : rows) pairs.push_back(row.value("unit", "") + " " + row.value("arith", ""));
  EXPECT_EQ(pairs, (std::vector<std::string>{"classic float", "interleave:2 float", "classic fixed:10.4",
                                             "interleave:2 fixed:10.4"}));
}

// Phong through the units: the normal's components in the registers; the clocks are the same spans'
// (one unit per span, whatever it interpolates), the error is against the ideal Phong, and a coarse
// register format costs error that the fine one does not.
TEST_F(CliScaling, PhongSweepsNormalsThroughTheUnits) {
  const RunResult r = scaling(sphere_, {"--size", "160x120", "--units", "classic,counter", "--arith", "fixed:12.12,fixed:9.1",
                                        "--method", "phong"});
  ASSERT_TRUE(succeeds(r));
  const nlohmann::json rep = read_report();
  EXPECT_EQ(field(rep, "/method"), "phong");
  const nlohmann::json rows = field(rep, "/rows");
  ASSERT_EQ(rows.size(), 4u) << rows.dump(2);
  for (const auto& row : rows) {
    SCOPED_TRACE(row.dump(2));
    EXPECT_EQ(field(row, "/error/implementation/reference"), "ideal phong");
    EXPECT_EQ(field(row, "/modeled_clocks/span_pixels"), field(rows[0], "/modeled_clocks/span_pixels"));
  }
  EXPECT_LT(field(rows[0], "/error/implementation/max_abs").get<double>(), 1.0);   // classic fixed:12.12
  EXPECT_GT(field(rows[2], "/error/implementation/max_abs").get<double>(), 1.0);   // classic fixed:9.1
}

TEST_F(CliScaling, PhongRefusesSierpinskiAndFlatIsNoUnitMethod) {
  EXPECT_TRUE(fails_with(scaling(sphere_, {"--method", "phong", "--units", "classic,sierpinski:1"}), kUsage,
                         {"sierpinski:1"}));
  EXPECT_TRUE(fails_with(scaling(sphere_, {"--method", "flat"}), kUsage, {"flat"}));
  EXPECT_TRUE(fails_with(scaling(sphere_, {"--units", "classic,classic"}), kUsage, {"twice"}));
  EXPECT_TRUE(nothing_written());
}

TEST_F(CliScaling, BadUnitIsAUsageErrorNamingIt) {
  EXPECT_TRUE(fails_with(scaling(sphere_, {"--units", "classic,zigzag:3"}), kUsage, {"zigzag:3"}));
  EXPECT_TRUE(nothing_written());
  EXPECT_TRUE(fails_with(scaling(sphere_, {"--units", "classic,segment:5"}), kUsage, {"segment:5"}));
  EXPECT_TRUE(nothing_written());
}

TEST_F(CliScaling, BadArithmeticOrEmptyEntryIsAUsageError) {
  EXPECT_TRUE(fails_with(scaling(sphere_, {"--arith", "fixed:4.4"}), kUsage, {"fixed:4.4"}));
  EXPECT_TRUE(fails_with(scaling(sphere_, {"--units", "classic,,counter"}), kUsage, {"--units"}));
  EXPECT_TRUE(fails_with(scaling(sphere_, {"--frames", "0"}), kUsage, {"--frames must be 1..100000"}));
  // Issue 46, item 10: the render's cap holds here too (999999999 frames were accepted).
  EXPECT_TRUE(fails_with(scaling(sphere_, {"--frames", "999999999"}), kUsage, {"--frames must be 1..100000"}));
  EXPECT_TRUE(nothing_written());
}

TEST_F(CliScaling, MissingSceneIsBadInput) {
  const auto missing = in_dir() / "nowhere.json";
  EXPECT_TRUE(fails_with(scaling(missing, {"--units", "classic"}), kBadInput, {"nowhere.json"}));
  EXPECT_TRUE(nothing_written());
}

TEST(CliScalingHelp, ListsItsOptions) {
  const RunResult r = run_parashade({"scaling", "--help"});
  ASSERT_TRUE(succeeds(r));
  for (const char* option : {"--units", "--arith", "--size", "--frames", "--device", "--report", "--quiet",
                             "interleave:M", "segment:P", "fixed:I.F"})
    EXPECT_NE(r.out.find(option), std::string::npos) << "scaling --help does not mention " << option << ":" << r;
  const RunResult top = run_parashade({"--help"});
  EXPECT_NE(top.out.find("scaling"), std::string::npos) << top;
}

}  // namespace
}  // namespace parashade
