// Issue 47, one output convention (docs/cli.md): -o is the main output, --report the JSON; every command
// that writes a file ends its results with "wrote FILE" on stdout (as render always did, -q or not);
// a missing folder is refused for every output a user names, the tune cache PARASHADE_TUNE_CACHE names
// included (it was made, folders and all, while --report's was refused).
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli_fixture.hpp"

namespace parashade {
namespace {

using namespace testing_support;

class CliOutputs : public CliTest {
 protected:
  std::string out(const std::string& name) const { return (out_dir() / name).string(); }
};

TEST_F(CliOutputs, EveryCommandThatWritesSaysWhat) {
  const std::string picture = input("a.ppm", std::string("P6\n2 1\n255\n") + std::string(6, '\x40')).string();
  const std::vector<std::vector<std::string>> lines = {
      {"devices", "-q", "--report", out("d.json")},
      {"combinations", "-q", "--report", out("c.json")},
      {"plan", input("ball.json", sphere_scene()).string(), "-q", "--report", out("p.json")},
      {"unit-error", "--units", "counter", "--lengths", "4", "--trials", "10", "-q", "--report", out("u.json")},
      {"vectors", "--unit", "classic", "--spans", "2", "-q", "-o", out("v.txt"), "--report", out("v.json")},
      {"compare", picture, picture, "-q", "--error-map", out("map.png"), "--report", out("cmp.json")},
      {"phong-study", "-q", "-o", out("study.md"), "--report", out("study.json")}};
  for (const auto& args : lines) {
    SCOPED_TRACE(args[0]);
    const RunResult r = run_parashade(args);
    ASSERT_TRUE(succeeds(r));
    std::string files;  // the outputs in the order given: "wrote A and B"
    for (std::size_t i = 0; i + 1 < args.size(); ++i)
      if (args[i] == "-o" || args[i] == "--report" || args[i] == "--error-map") files += (files.empty() ? "" : " and ") + args[i + 1];
    EXPECT_NE(r.out.find("wrote " + files + "\n"), std::string::npos) << r;
  }
}

// phong-study's -o had the long name --markdown; it still works for one release, with a warning.
TEST_F(CliOutputs, PhongStudyMarkdownIsTheOldSpellingOfOutput) {
  const RunResult r = run_parashade({"phong-study", "--markdown", out("study.md")});
  ASSERT_TRUE(succeeds(r));
  EXPECT_NE(r.err.find("--markdown is deprecated"), std::string::npos) << r;
  EXPECT_TRUE(std::filesystem::exists(out("study.md")));
}

// devices --json prints the bare array (the old format): nothing else may share stdout.
TEST_F(CliOutputs, DevicesJsonStaysBareWithAReport) {
  const RunResult r = run_parashade({"devices", "--json", "--report", out("d.json")});
  ASSERT_TRUE(succeeds(r));
  EXPECT_TRUE(nlohmann::json::parse(r.out, nullptr, false).is_array()) << r;
}

TEST_F(CliOutputs, ATuneCacheFolderTheEnvironmentNamesIsNotMade) {
  const std::filesystem::path cache = out_dir() / "missing" / "deeper" / "tune.json";
  const ScopedEnv named("PARASHADE_TUNE_CACHE", cache.string());
  const RunResult r = run_parashade({"tune", input("ball.json", sphere_scene()).string(), "--budget-runs", "1",
                                     "--frames", "1", "-q", "--param", "tile=32", "--param", "work_items=0",
                                     "--param", "partition=none"});
  EXPECT_TRUE(fails_with(r, kBadInput, {"PARASHADE_TUNE_CACHE", "directory", "does not exist"}));
  EXPECT_TRUE(nothing_written());
}

}  // namespace
}  // namespace parashade
