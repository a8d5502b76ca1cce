// Command lines of the combined method that cannot be honoured: exit 2, the word at fault named, nothing
// written.
#include <gtest/gtest.h>

#include "cli_fixture.hpp"

namespace parashade {
namespace {

using namespace testing_support;

class CliCombinedUsage : public CliTest {
 protected:
  std::filesystem::path scene_ = input("ball.json", sphere_scene());
};

TEST_F(CliCombinedUsage, SegmentLog2OutOfRangeIsNamed) {
  EXPECT_TRUE(fails_with(render(scene_, {"--method", "combined:9"}), kUsage, {"combined:9"}));
  EXPECT_TRUE(fails_with(render(scene_, {"--method", "combined:x"}), kUsage, {"combined:x"}));
  EXPECT_TRUE(nothing_written());
}

TEST_F(CliCombinedUsage, MaxErrorNeedsCombinedAuto) {
  EXPECT_TRUE(fails_with(render(scene_, {"--method", "phong", "--max-error", "2"}), kUsage, {"--max-error"}));
  EXPECT_TRUE(fails_with(render(scene_, {"--method", "combined:2", "--max-error", "2"}), kUsage, {"--max-error"}));
  EXPECT_TRUE(nothing_written());
}

TEST_F(CliCombinedUsage, MaxErrorMustBePositive) {
  EXPECT_TRUE(fails_with(render(scene_, {"--method", "combined:auto", "--max-error", "-1"}), kUsage, {"--max-error"}));
  EXPECT_TRUE(nothing_written());
}

TEST_F(CliCombinedUsage, HighlightTestNeedsCombined) {
  EXPECT_TRUE(fails_with(render(scene_, {"--method", "gouraud", "--highlight-test"}), kUsage, {"--highlight-test"}));
  EXPECT_TRUE(nothing_written());
}

}  // namespace
}  // namespace parashade
