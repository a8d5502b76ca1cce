// Issue 47: one exit-code table (docs/cli.md, "Exit codes") that every command follows: 2 for a command
// line or a PARASHADE_* variable that is wrong in itself, 3 for a file it names (missing, or an output whose
// folder is missing), 4 for a device that cannot be had. Every command `parashade --help` lists is held to
// it, so that a new command is too.
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli_fixture.hpp"

namespace parashade {
namespace {

using namespace testing_support;

// A command line of each command that would run, and which failures it can meet.
struct CommandCase {
  std::vector<std::string> args;
  std::size_t input = 0;  // index of a file argument read (0: none)
  bool device = false;    // takes --device
};

class CliExitCodes : public CliTest {
 protected:
  std::filesystem::path scene_ = input("ball.json", sphere_scene());
  std::filesystem::path picture_ = input("a.ppm", std::string("P6\n2 1\n255\n") + std::string(6, '\x40'));

  std::map<std::string, CommandCase> cases() const {
    const std::string s = scene_.string(), out = out_dir().string();
    return {{"devices", {{"devices"}}},
            {"phong-study", {{"phong-study"}}},
            {"combinations", {{"combinations"}}},
            {"render", {{"render", s, "-o", out + "/i.png", "--frames", "1", "--warmup", "0", "--no-error"}, 1, true}},
            {"plan", {{"plan", s}, 1}},
            {"tune", {{"tune", s, "--budget-runs", "1", "--frames", "1", "--cache", out + "/c.json"}, 1, true}},
            {"scaling", {{"scaling", s, "--units", "classic", "--frames", "1"}, 1, true}},
            {"unit-error", {{"unit-error", "--units", "counter", "--lengths", "4", "--trials", "10"}}},
            {"vectors", {{"vectors", "--unit", "classic", "-o", out + "/v.txt"}}},
            {"compare", {{"compare", picture_.string(), picture_.string()}, 1}}};
  }
};

// The commands as `parashade --help` lists them.
std::vector<std::string> listed_commands() {
  const RunResult r = run_parashade({"--help"});
  std::vector<std::string> out;
  const std::size_t at = r.out.find("Subcommands:");
  const std::string list = at == std::string::npos ? "" : r.out.substr(at, r.out.find("\n\n", at) - at);
  const std::regex line(R"(\n  ([a-z][a-z-]*) )");
  for (std::sregex_iterator m(list.begin(), list.end(), line), end; m != end; ++m) out.push_back((*m)[1]);
  return out;
}

std::vector<std::string> with(std::vector<std::string> args, std::initializer_list<std::string> more) {
  args.insert(args.end(), more);
  return args;
}

TEST_F(CliExitCodes, EveryCommandFollowsTheTable) {
  const std::map<std::string, CommandCase> all = cases();
  const std::vector<std::string> listed = listed_commands();
  ASSERT_GE(listed.size(), 10u);
  for (const std::string& command : listed) {
    SCOPED_TRACE(command);
    ASSERT_TRUE(all.count(command)) << "no case for '" << command << "': add one to this table";
    const CommandCase& c = all.at(command);
    EXPECT_TRUE(fails_with(run_parashade(with(c.args, {"--no-such-option"})), kUsage, {"--no-such-option"}));
    {
      const ScopedEnv threads("PARASHADE_HOST_THREADS", "many");
      EXPECT_TRUE(fails_with(run_parashade(c.args), kUsage, {"PARASHADE_HOST_THREADS='many'"}));
    }
    const std::string missing = (out_dir() / "missing" / "r.json").string();
    EXPECT_TRUE(fails_with(run_parashade(with(c.args, {"--report", missing})), kBadInput,
                           {"--report", "directory", "does not exist"}));
    if (c.input) {
      std::vector<std::string> absent = c.args;
      absent[c.input] = (in_dir() / "absent.file").string();
      EXPECT_TRUE(fails_with(run_parashade(absent), kBadInput, {"absent.file"}));
    }
    if (c.device)
      EXPECT_TRUE(fails_with(run_parashade(with(c.args, {"--device", "no-such-device"})), kDeviceFailure,
                             {"no-such-device"}));
  }
  EXPECT_TRUE(nothing_written());
}

// The codes the test holds the commands to are the ones docs/cli.md's table and --help give.
TEST(CliExitCodeTable, DocsAndHelpGiveTheCodes) {
  std::ifstream in(std::string(PARASHADE_SOURCE_DIR) + "/docs/cli.md");
  std::stringstream text;
  text << in.rdbuf();
  for (const char* row : {"| 0 |", "| 1 |", "| 2 |", "| 3 |", "| 4 |", "| 128 + N |"})
    EXPECT_NE(text.str().find(row), std::string::npos) << "docs/cli.md's exit-code table has no row " << row;
  const RunResult help = run_parashade({"--help"});
  for (const char* code : {"0 ok", "1 compare above --fail", "2 usage", "3 bad input", "4 OpenCL", "128 + N"})
    EXPECT_NE(help.out.find(code), std::string::npos) << "--help does not give '" << code << "':" << help;
}

}  // namespace
}  // namespace parashade
