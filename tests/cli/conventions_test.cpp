// One command-line convention (docs/cli.md, "Conventions"): every command takes -q and --report FILE,
// the old spellings (--json) still work for one release with a warning, --size and --cu are checked
// when the command line is read, and the unit lists in the help come from the unit table.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli_fixture.hpp"
#include "parashade/report_header.hpp"
#include "parashade/unit_table.hpp"

namespace parashade {
namespace {

using namespace testing_support;

// The commands as `parashade --help` lists them, so that a new command is held to the convention too.
std::vector<std::string> commands() {
  const RunResult r = run_parashade({"--help"});
  EXPECT_TRUE(succeeds(r));
  std::vector<std::string> out;
  const std::size_t at = r.out.find("Subcommands:");
  EXPECT_NE(at, std::string::npos) << r;
  if (at == std::string::npos) return out;
  const std::string list = r.out.substr(at, r.out.find("\n\n", at) - at);
  const std::regex line(R"(\n  ([a-z][a-z-]*) )");
  for (std::sregex_iterator m(list.begin(), list.end(), line), end; m != end; ++m) out.push_back((*m)[1]);
  return out;
}

TEST(CliConventions, EveryCommandTakesQuietAndReport) {
  const std::vector<std::string> all = commands();
  EXPECT_GE(all.size(), 9u);
  for (const std::string& c : all) {
    const RunResult r = run_parashade({c, "--help"});
    ASSERT_TRUE(succeeds(r)) << c;
    EXPECT_TRUE(std::regex_search(r.out, std::regex(R"(-q,--quiet)"))) << c << " --help has no -q,--quiet:" << r;
    EXPECT_TRUE(std::regex_search(r.out, std::regex(R"(--report TEXT)"))) << c << " --help has no --report:" << r;
  }
}

// The commands that need no scene run with -q and --report and write a versioned report.
TEST_F(CliTest, QuietCommandsWriteVersionedReports) {
  for (const std::string& c : {"devices", "combinations"}) {
    const RunResult r = run_parashade({c, "-q", "--report", report().string()});
    ASSERT_TRUE(succeeds(r)) << c;
    EXPECT_EQ(field(read_report(), "/schema"), "parashade." + c + "/" + std::to_string(kReportVersion));
  }
}

TEST_F(CliTest, RenderReportIsSelfDescribing) {
  const auto scene = input("ball.json", sphere_scene());
  ASSERT_TRUE(succeeds(run_parashade({"render", scene.string(), "-o", image().string(), "--report", report().string(),
                                      "--frames", "3", "--warmup", "1", "-q", "--no-error", "--no-tuned"})));
  const nlohmann::json rep = read_report();
  EXPECT_EQ(field(rep, "/schema"), "parashade.render/2");
  EXPECT_TRUE(std::regex_match(field(rep, "/created_utc").get<std::string>(),
                               std::regex(R"(\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ)")));
  EXPECT_FALSE(field(rep, "/parashade/version").get<std::string>().empty());
  EXPECT_FALSE(field(rep, "/parashade/git_hash").get<std::string>().empty());
  const nlohmann::json argv = field(rep, "/command_line");
  ASSERT_GE(argv.size(), 3u);
  EXPECT_EQ(argv[1], "render");
  EXPECT_EQ(argv[2], scene.string());
  EXPECT_EQ(field(rep, "/timing/frames"), 3);
  EXPECT_EQ(field(rep, "/timing/warmup"), 1);
  ASSERT_EQ(field(rep, "/timing/samples_ms").size(), 3u);
  std::vector<double> s = field(rep, "/timing/samples_ms").get<std::vector<double>>();
  std::sort(s.begin(), s.end());
  EXPECT_DOUBLE_EQ(field(rep, "/timing/min_ms").get<double>(), s[0]);
  EXPECT_DOUBLE_EQ(field(rep, "/timing/median_ms").get<double>(), s[1]);
  const double mean = (s[0] + s[1] + s[2]) / 3;
  const double var = ((s[0] - mean) * (s[0] - mean) + (s[1] - mean) * (s[1] - mean) + (s[2] - mean) * (s[2] - mean)) / 2;
  EXPECT_NEAR(field(rep, "/timing/stddev_ms").get<double>(), std::sqrt(var), 1e-9 + 1e-9 * std::sqrt(var));
  EXPECT_GT(field(rep, "/device/compute_units"), 0);
  EXPECT_TRUE(field(rep, "/host/load_1min").is_number());
}

// --json, the old spelling of --report: works with a warning on stderr; with --report as well, a usage error.
TEST_F(CliTest, DeprecatedJsonSpellingWarns) {
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"unit-error", "--units", "counter", "--lengths", "4", "--trials", "10"},
        std::vector<std::string>{"phong-study"}}) {
    std::vector<std::string> old = args;
    old.insert(old.end(), {"--json", report().string()});
    const RunResult r = run_parashade(old);
    ASSERT_TRUE(succeeds(r)) << args[0];
    EXPECT_NE(r.err.find("--json is deprecated"), std::string::npos) << r;
    EXPECT_NE(r.err.find("use --report"), std::string::npos) << r;
    // The report --json wrote is the report --report writes (the format is report_header.hpp's).
    EXPECT_EQ(field(read_report(), "/schema"), "parashade." + args[0] + "/" + std::to_string(kReportVersion));
    std::vector<std::string> both = old;
    both.insert(both.end(), {"--report", (out_dir() / "other.json").string()});
    EXPECT_TRUE(fails_with(run_parashade(both), kUsage, {"--json", "--report"}));
  }
  // The current spelling has no warning.
  const RunResult r = run_parashade({"unit-error", "--units", "counter", "--lengths", "4", "--trials", "10", "--report",
                                     report().string()});
  ASSERT_TRUE(succeeds(r));
  EXPECT_EQ(r.err.find("deprecated"), std::string::npos) << r;
}

TEST_F(CliTest, SizeAndCountsAreCheckedWhenReadWithTheOptionNamed) {
  const auto scene = input("ball.json", sphere_scene());
  for (const std::string& cmd : {"render", "plan", "scaling", "tune"})
    for (const std::string& size : {"64", "64x", "x48", "64X48", "64x48x2"}) {
      std::vector<std::string> args = {cmd, scene.string(), "--size", size};
      if (cmd == "render") args.insert(args.end(), {"-o", image().string()});
      EXPECT_TRUE(fails_with(run_parashade(args), kUsage, {"--size", size, "WIDTHxHEIGHT"})) << cmd;
    }
  for (const std::string& cu : {"0", "x", "2,", "1,0", "99999"})
    EXPECT_TRUE(fails_with(run_parashade({"plan", scene.string(), "--cu", cu}), kUsage, {"--cu", cu})) << cu;
  EXPECT_TRUE(fails_with(render(scene, {"--cu", "2,4"}), kUsage, {"--cu", "2,4"}));
  EXPECT_TRUE(succeeds(run_parashade({"plan", scene.string(), "--cu", "1,2,4", "--size", "32x24"})));
  EXPECT_TRUE(nothing_written());
}

// Every unit of the table in the help of each command that takes --units, and the help does not say
// the units shade Gouraud only (Phong's normal components run through them too).
TEST(CliConventions, UnitHelpListsEveryUnitOfTheTable) {
  for (const std::string& cmd : {"render", "scaling", "plan"}) {
    const RunResult r = run_parashade({cmd, "--help"});
    ASSERT_TRUE(succeeds(r));
    std::string help = std::regex_replace(r.out, std::regex(R"(\s+)"), " ");  // CLI11 wraps lines
    for (const UnitRow& row : unit_table())
      EXPECT_NE(help.find(row.spec), std::string::npos) << cmd << " --help does not list '" << row.spec << "'";
    EXPECT_EQ(help.find("Gouraud through a modeled"), std::string::npos) << cmd;
  }
}

}  // namespace
}  // namespace parashade
