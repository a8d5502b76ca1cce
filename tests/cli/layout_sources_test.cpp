// Where render's layout comes from (docs/pipeline.md "Defaults from the device"): without options or a
// tuned entry the device's properties give the kernel shape, the work-group and the work-items, the frame
// gives the tile, and the summary line and the report's `layout` say so; options given are named as the
// source. On a CPU (the tests' devices) the rule is the vector shape, work-groups of one and one work-item a
// tile up to 256 per compute unit. A tuned entry as the source: tune_test.cpp.
#include <algorithm>
#include <string>

#include <gtest/gtest.h>

#include "cli_fixture.hpp"

namespace parashade {
namespace {

using namespace testing_support;

class CliLayoutSources : public CliTest {};

TEST_F(CliLayoutSources, FromTheDeviceWithoutOptions) {
  const auto scene = input("ball.json", sphere_scene());
  // 640x480 in tiles of 16: 40 x 30 = 1200 tiles, more than 256 per compute unit of a 2-core CPU.
  const RunResult r = render(scene, {"--no-tuned", "--size", "640x480", "--tile", "16"});
  ASSERT_TRUE(succeeds(r));
  const nlohmann::json rep = read_report();
  const int units = field(rep, "/device/compute_units").get<int>();
  ASSERT_GE(units, 1);
  EXPECT_EQ(field(rep, "/work_items"), std::min(1200, 256 * units)) << rep.dump(1);
  EXPECT_EQ(field(rep, "/layout/kernel_shape"), "vector");
  EXPECT_EQ(field(rep, "/layout/work_group_size"), 1);
  EXPECT_EQ(field(rep, "/layout/sources/kernel_shape"), "device properties");
  EXPECT_EQ(field(rep, "/layout/sources/work_group_size"), "device properties");
  EXPECT_EQ(field(rep, "/layout/sources/work_items"), "device properties");
  EXPECT_EQ(field(rep, "/layout/sources/tile"), "option");
  const std::string line = "layout: vector kernel shape (device properties), work-groups of 1 (device properties), " +
                           std::to_string(std::min(1200, 256 * units)) + " work-items (device properties), tile 16 (option)\n";
  EXPECT_NE(r.out.find(line), std::string::npos) << r;
  // Without --tile the frame chooses it (tile_choice.hpp).
  ASSERT_TRUE(succeeds(render(scene, {"--no-tuned"})));
  EXPECT_EQ(field(read_report(), "/layout/sources/tile"), "frame");
}

TEST_F(CliLayoutSources, OptionsAreTheirOwnSource) {
  const auto scene = input("ball.json", sphere_scene());
  const RunResult r = render(scene, {"--tile", "16", "--work-items", "6", "--kernel-shape", "vector",
                                     "--work-group-size", "2"});
  ASSERT_TRUE(succeeds(r));
  const nlohmann::json rep = read_report();
  for (const char* setting : {"kernel_shape", "work_group_size", "work_items", "tile"})
    EXPECT_EQ(field(rep, std::string("/layout/sources/") + setting), "option") << setting;
  EXPECT_EQ(field(rep, "/layout/work_group_size"), 2);
  EXPECT_EQ(field(rep, "/work_items"), 6);
  EXPECT_NE(r.out.find("work-groups of 2 (option), 6 work-items (option), tile 16 (option)"), std::string::npos) << r;
}

}  // namespace
}  // namespace parashade
