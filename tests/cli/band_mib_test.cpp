// `render --band-mib N`: a frame whose triangle records would exceed N MiB is prepared and shaded in bands
// of tile rows (bench/README.md, "Peak memory: streamed bands"); 0 never streams. The image is the same
// either way; the report says how many bands the frame took and the budget; bad values are refused.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>

#include "cli_fixture.hpp"

namespace parashade {
namespace {

using namespace testing_support;

class CliBandMib : public CliTest {};

TEST_F(CliBandMib, StreamsBelowTheBudgetWithTheSameImage) {
  const auto scene = input("fine.json", many_triangles_scene());
  ASSERT_TRUE(succeeds(render(scene, {"--band-mib", "0"})));
  const std::string whole = bytes_of(image());
  const nlohmann::json never = read_report();
  EXPECT_EQ(never["band_mib"], 0);
  EXPECT_EQ(never["stats"]["bands"], 1);
  ASSERT_TRUE(succeeds(render(scene, {"--band-mib", "1"})));
  const nlohmann::json banded = read_report();
  EXPECT_EQ(banded["band_mib"], 1);
  EXPECT_GT(banded["stats"]["bands"].get<int>(), 1) << "a 1 MiB budget should cut ~3 MiB of records into bands";
  EXPECT_EQ(bytes_of(image()), whole) << "the banded frame differs from the whole one";
  ASSERT_TRUE(succeeds(render(scene)));
  EXPECT_EQ(read_report()["stats"]["bands"], 1) << "the default budget (16 MiB) streams this small frame";
}

TEST_F(CliBandMib, BadValuesAreRefused) {
  const auto scene = input("ball.json", sphere_scene());
  for (const char* bad : {"-1", "many", "2000000"}) {
    EXPECT_TRUE(fails_with(render(scene, {"--band-mib", bad}), kUsage, {"--band-mib"})) << bad;
    EXPECT_TRUE(nothing_written()) << bad;
  }
}

}  // namespace
}  // namespace parashade
