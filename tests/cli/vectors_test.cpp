// parashade vectors: the file's header and its first span worked out by hand, the same seed giving the
// same file; command lines it cannot take (exit 2, the word at fault named, nothing written).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "cli_fixture.hpp"

namespace parashade {
namespace {

using namespace testing_support;

class CliVectors : public CliTest {
 protected:
  std::filesystem::path file() const { return out_dir() / "v.txt"; }
  RunResult run(std::vector<std::string> extra) const {
    std::vector<std::string> args = {"vectors"};
    args.insert(args.end(), extra.begin(), extra.end());
    return run_parashade(args);
  }
  std::string text() const {
    std::ifstream in(file());
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }
};

TEST_F(CliVectors, HelpListsItsOptions) {
  const RunResult r = run_parashade({"vectors", "--help"});
  ASSERT_TRUE(succeeds(r));
  for (const char* option : {"--unit", "--arith", "--spans", "--seed", "--output"})
    EXPECT_NE(r.out.find(option), std::string::npos) << option << ":" << r;
}

// The first span is the golden tests' S = 100, dI = 7, L = 5 (register units); in 12.4 a level is 16,
// so 100 -> 6.25 -> 6, 107 -> 6.69 -> 7, 114 -> 7.125 -> 7, 121 -> 7.56 -> 8, 128 -> 8.
TEST_F(CliVectors, ClassicHeaderAndFirstSpanByHand) {
  ASSERT_TRUE(succeeds(run({"--unit", "classic", "--arith", "fixed:12.4", "--spans", "3", "-o", file().string()})));
  const std::string t = text();
  for (const char* line : {"format parashade-vectors 1\n", "unit classic\n", "lanes 1\n", "arith fixed:12.4\n",
                           "int_bits 12\n", "frac_bits 4\n", "load_clocks 1\n",
                           "span 5 100 131 7 8 6\nclock 0 100 6\nclock 1 107 7\nclock 2 114 7\nclock 3 121 8\n"
                           "clock 4 128 8\nspan "})
    EXPECT_NE(t.find(line), std::string::npos) << "'" << line << "' missing";
  EXPECT_EQ(t.substr(t.size() - 4), "end\n");
  EXPECT_EQ(out_entries(), std::vector<std::string>{"v.txt"});
}

// Counter: two pixels per clock, the left lane first; the odd middle pixel alone in the last clock.
TEST_F(CliVectors, CounterPairsTheEnds) {
  ASSERT_TRUE(succeeds(run({"--unit", "counter", "--arith", "fixed:12.4", "--spans", "0", "-o", file().string()})));
  EXPECT_NE(text().find("span 5 100 131 7 15 4\nclock 0 100 6 4 131 8\nclock 1 107 7 3 124 8\nclock 2 114 7\n"),
            std::string::npos)
      << text().substr(0, 400);
}

TEST_F(CliVectors, TheSeedDecidesTheRandomSpans) {
  auto write = [&](const char* seed) {
    EXPECT_TRUE(succeeds(run({"--unit", "segment:4", "--spans", "20", "--seed", seed, "-o", file().string()})));
    return text();
  };
  const std::string a = write("5"), b = write("5"), c = write("6");
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
}

TEST_F(CliVectors, BadCommandLines) {
  const std::string o = file().string();
  EXPECT_TRUE(fails_with(run({"--unit", "diagonal", "-o", o}), kUsage, {"diagonal"}));
  EXPECT_TRUE(fails_with(run({"--unit", "sierpinski:1", "-o", o}), kUsage, {"sierpinski:1", "span units"}));
  EXPECT_TRUE(fails_with(run({"--unit", "interleave:17", "-o", o}), kUsage, {"interleave:17"}));
  EXPECT_TRUE(fails_with(run({"--unit", "classic", "--arith", "float", "-o", o}), kUsage, {"float", "fixed"}));
  EXPECT_TRUE(fails_with(run({"--unit", "classic", "--arith", "fixed:8.8", "-o", o}), kUsage, {"fixed:8.8"}));
  EXPECT_TRUE(fails_with(run({"--unit", "classic", "--spans", "-1", "-o", o}), kUsage, {"--spans"}));
  EXPECT_TRUE(fails_with(run({"--unit", "classic", "--spans", "100001", "-o", o}), kUsage, {"--spans"}));
  EXPECT_TRUE(fails_with(run({"--unit", "classic"}), kUsage, {"--output"}));
  EXPECT_TRUE(fails_with(run({"-o", o}), kUsage, {"--unit"}));
  EXPECT_TRUE(nothing_written());
}

TEST_F(CliVectors, AMissingDirectoryIsBadInputAndNothingIsWritten) {
  const std::filesystem::path missing = out_dir() / "absent" / "v.txt";
  EXPECT_TRUE(fails_with(run({"--unit", "classic", "-o", missing.string()}), kBadInput, {missing.string()}));
  EXPECT_TRUE(nothing_written());
}

}  // namespace
}  // namespace parashade
