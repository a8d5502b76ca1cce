// parashade unit-error: the table, the verdicts and the JSON file; command lines it cannot take
// (exit 2, the word at fault named, nothing printed or written).
#include <gtest/gtest.h>

#include "cli_fixture.hpp"

namespace parashade {
namespace {

using namespace testing_support;

class CliUnitError : public CliTest {
 protected:
  std::filesystem::path json() const { return out_dir() / "unit-error.json"; }
  RunResult run(std::vector<std::string> extra) const {
    std::vector<std::string> args = {"unit-error", "--trials", "40"};
    args.insert(args.end(), extra.begin(), extra.end());
    return run_parashade(args);
  }
};

TEST_F(CliUnitError, HelpListsItsOptions) {
  const RunResult r = run_parashade({"unit-error", "--help"});
  ASSERT_TRUE(succeeds(r));
  for (const char* option : {"--units", "--arith", "--lengths", "--trials", "--seed", "--report", "--formula-bits"})
    EXPECT_NE(r.out.find(option), std::string::npos) << option << ":" << r;
}

TEST_F(CliUnitError, TableVerdictsAndJson) {
  const RunResult r = run({"--lengths", "1,16,256", "--report", json().string()});
  ASSERT_TRUE(succeeds(r));
  for (const char* text : {"fixed:12.8", "max/bound", "verdicts:", "classic: our bound holds", "δ_KH", "FAILS", "Δδ"})
    EXPECT_NE(r.out.find(text), std::string::npos) << "'" << text << "' missing:" << r;
  EXPECT_EQ(r.out.find("VIOLATED"), std::string::npos) << r;
  std::ifstream in(json());
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  ASSERT_FALSE(j.is_discarded());
  EXPECT_EQ(j["arith"], "fixed:12.8");
  ASSERT_EQ(j["units"].size(), 6u);  // the default list
  for (const auto& u : j["units"]) {
    EXPECT_EQ(u["bound_holds"], true) << u["unit"];
    ASSERT_EQ(u["lengths"].size(), 3u);
    EXPECT_EQ(u["lengths"][2]["max_abs_by_z"].size(), 256u);
  }
  EXPECT_EQ(j["units"][0]["unit"], "classic");
  EXPECT_EQ(j["units"][0]["source_formula_holds"], true);
  EXPECT_EQ(j["units"][2]["unit"], "interleave:2");
  EXPECT_EQ(j["units"][2]["source_formula_holds"], false);
  EXPECT_TRUE(j["units"][4]["source_formula_holds"].is_null());  // interleave:4:own: none printed
  EXPECT_EQ(out_entries(), std::vector<std::string>{"unit-error.json"});
}

TEST_F(CliUnitError, BadCommandLines) {
  EXPECT_TRUE(fails_with(run({"--units", "classic,diagonal"}), kUsage, {"diagonal"}));
  EXPECT_TRUE(fails_with(run({"--units", "interleave:17"}), kUsage, {"--units", "interleave:17"}));
  EXPECT_TRUE(fails_with(run({"--units", "classic,,counter"}), kUsage, {"--units", "empty"}));
  EXPECT_TRUE(fails_with(run({"--lengths", "0"}), kUsage, {"--lengths", "'0'"}));
  EXPECT_TRUE(fails_with(run({"--lengths", "8,x"}), kUsage, {"--lengths", "'x'"}));
  EXPECT_TRUE(fails_with(run({"--lengths", "8,"}), kUsage, {"--lengths"}));
  EXPECT_TRUE(fails_with(run({"--lengths", "70000"}), kUsage, {"70000"}));
  EXPECT_TRUE(fails_with(run({"--arith", "float"}), kUsage, {"float", "fixed"}));
  EXPECT_TRUE(fails_with(run({"--arith", "fixed:8.8"}), kUsage, {"--arith", "fixed:8.8"}));
  EXPECT_TRUE(fails_with(run({"--trials", "0"}), kUsage, {"--trials"}));
  EXPECT_TRUE(fails_with(run({"--trials", "many"}), kUsage, {"--trials"}));
  EXPECT_TRUE(fails_with(run({"--formula-bits", "0"}), kUsage, {"--formula-bits"}));
  EXPECT_TRUE(nothing_written());
}

TEST_F(CliUnitError, ReportInAMissingDirectoryIsBadInputBeforeAnyOutput) {
  const std::filesystem::path missing = out_dir() / "absent" / "u.json";
  EXPECT_TRUE(fails_with(run({"--lengths", "4", "--report", missing.string()}), kBadInput, {missing.string()}));
  EXPECT_TRUE(nothing_written());
}

}  // namespace
}  // namespace parashade
