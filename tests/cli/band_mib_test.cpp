// `render --band-mib N`: a frame whose triangle records would exceed N MiB is prepared and shaded in bands
// of tile rows (bench/README.md, "Peak memory: streamed bands"); 0 never streams; the default grows with the
// frame. The image is the same either way; the report says how many bands the frame took and the budget;
// bad values are refused.
#include <cmath>
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
  const nlohmann::json by_default = read_report();
  EXPECT_EQ(by_default["stats"]["bands"], 1) << "the default budget streams this small frame";
  // The default: 16 MiB plus the frame's colour and depth, 8 bytes a pixel, rounded up to whole MiB.
  const double pixel_mib = by_default["width"].get<double>() * by_default["height"].get<double>() * 8 / (1 << 20);
  EXPECT_EQ(by_default["band_mib"].get<int>(), 16 + int(std::ceil(pixel_mib)));
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
