// Issue 46, "Messages and exit codes": each failure names its cause, the file or the value, with the
// documented exit code (2 usage, 3 bad input, 4 device), and nothing a terminal would interpret is printed
// raw (standard_output_test.cpp). Every test here failed before its fix (the issue gives the old behaviour).
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli_fixture.hpp"

namespace parashade {
namespace {

using namespace testing_support;
namespace fs = std::filesystem;

class CliNamedCauses : public CliTest {
 protected:
  fs::path scene_ = input("ball.json", sphere_scene());
  fs::path picture_ = input("good.ppm", std::string("P6\n2 1\n255\n") + std::string(6, '\x40'));
};

// "cannot read X: " with nothing after the colon.
TEST_F(CliNamedCauses, ATruncatedImageSaysWhy) {
  const fs::path cut = input("cut.ppm", std::string("P6\n4 4\n255\n") + std::string(10, '\x40'));
  const RunResult r = run_parashade({"compare", picture_.string(), cut.string()});
  ASSERT_TRUE(fails_with(r, kBadInput, {"cut.ppm"}));
  EXPECT_EQ(r.err.find("cut.ppm: \n"), std::string::npos) << r;
  EXPECT_EQ(r.err.find(": \n"), std::string::npos) << r;
}

// A 99999 x 99999 header in a 30-byte file: "out of host memory", no file named.
TEST_F(CliNamedCauses, AnImageTooLargeForMemoryIsNamedWithItsSize) {
  const fs::path huge = input("huge.ppm", std::string("P6\n99999 99999\n255\n") + std::string(10, '\x40'));
  const RunResult r = run_parashade({"compare", huge.string(), picture_.string()}, {}, std::chrono::seconds(30));
  EXPECT_TRUE(fails_with(r, kBadInput, {"huge.ppm", "99999x99999"}));
}

}  // namespace
}  // namespace parashade
