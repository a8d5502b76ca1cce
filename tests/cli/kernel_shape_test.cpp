// --kernel-shape vector|lanes and --work-group-size N (docs/pipeline.md): one name from the command line to the
// kernel's macros (KERNEL_SHAPE, WORK_GROUP_SIZE in the report's kernel_build), the same image either way, the
// default build's options unchanged, and what the lanes shape does not model refused with exit 2, naming the
// options and why.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli_fixture.hpp"

namespace parashade {
namespace {

using namespace testing_support;

struct BadShape {
  const char* label;
  std::vector<std::string> args;
  std::vector<std::string> named;  // words stderr must hold: the options and the reason's key words
};

void PrintTo(const BadShape& b, std::ostream* os) { *os << b.label; }

class CliKernelShapeRefused : public CliTest, public ::testing::WithParamInterface<BadShape> {};

TEST_P(CliKernelShapeRefused, IsAUsageErrorNamingTheOptions) {
  const auto scene = input("ball.json", sphere_scene());
  EXPECT_TRUE(fails_with(render(scene, GetParam().args), kUsage, GetParam().named));
  EXPECT_TRUE(nothing_written());
}

INSTANTIATE_TEST_SUITE_P(
    Cli, CliKernelShapeRefused,
    ::testing::Values(
        BadShape{"unknown_shape", {"--kernel-shape", "cubes"}, {"--kernel-shape", "cubes", "vector, lanes"}},
        BadShape{"group_not_a_power_of_two", {"--work-group-size", "48"}, {"--work-group-size", "48", "power of two"}},
        BadShape{"negative_group", {"--work-group-size", "-4"}, {"--work-group-size", "-4"}},
        BadShape{"group_over_the_tile",
                 {"--kernel-shape", "lanes", "--tile", "16", "--work-group-size", "512"},
                 {"--work-group-size", "512", "16x16 tile"}},
        BadShape{"lanes_on_a_unit",
                 {"--kernel-shape", "lanes", "--units", "counter"},
                 {"--kernel-shape", "--units", "lanes", "counter", "span registers"}},
        BadShape{"lanes_in_fixed_point",
                 {"--kernel-shape", "lanes", "--arith", "fixed:12.12"},
                 {"--kernel-shape", "lanes", "classic", "fixed point"}},
        BadShape{"lanes_planned",
                 {"--kernel-shape", "lanes", "--cu", "2", "--partition", "lpt"},
                 {"--kernel-shape", "--cu/--partition", "planned depth pass"}},
        BadShape{"lanes_span_normals",
                 {"--kernel-shape", "lanes", "--method", "phong", "--normalize", "slerp"},
                 {"--kernel-shape", "--normalize", "slerp", "per-span normals"}},
        BadShape{"lanes_deferral_threshold",
                 {"--kernel-shape", "lanes", "--method", "phong", "--defer-min-triangles", "8"},
                 {"--defer-min-triangles 8", "lanes shape"}}),
    [](const auto& info) { return std::string(info.param.label); });

class CliKernelShape : public CliTest {
 protected:
  // The image's bytes and the report's kernel_build and work_items of a render with `extra`.
  struct Rendered {
    std::string image, kernel_build;
    long work_items = -1;
  };
  Rendered render_with(const std::filesystem::path& scene, std::vector<std::string> extra) {
    Rendered r;
    const RunResult run = render(scene, extra);
    EXPECT_TRUE(succeeds(run));
    r.image = bytes_of(image());
    const nlohmann::json report = read_report();
    r.kernel_build = report.value("kernel_build", std::string());
    r.work_items = report.value("work_items", -1L);
    return r;
  }
};

TEST_F(CliKernelShape, EachShapeBindsItsMacrosAndDrawsTheSameImage) {
  const auto scene = input("ball.json", sphere_scene());
  for (const char* method : {"gouraud", "phong"}) {
    SCOPED_TRACE(method);
    const Rendered plain = render_with(scene, {"--method", method, "--tile", "16", "--no-tuned"});
    // The default build's options hold neither macro: existing reports and images are unchanged.
    EXPECT_EQ(plain.kernel_build.find("KERNEL_SHAPE"), std::string::npos) << plain.kernel_build;
    EXPECT_EQ(plain.kernel_build.find("WORK_GROUP_SIZE"), std::string::npos) << plain.kernel_build;
    const Rendered lanes =
        render_with(scene, {"--method", method, "--tile", "16", "--kernel-shape", "lanes", "--work-group-size", "64"});
    EXPECT_NE(lanes.kernel_build.find("-D KERNEL_SHAPE=1 -D WORK_GROUP_SIZE=64"), std::string::npos) << lanes.kernel_build;
    EXPECT_EQ(lanes.image, plain.image);
    // The ball's 64x48 frame is 4x3 tiles of 16: a work-group of 64 per tile.
    EXPECT_EQ(lanes.work_items, 4 * 3 * 64);
    const Rendered grouped = render_with(scene, {"--method", method, "--tile", "16", "--work-group-size", "4"});
    EXPECT_NE(grouped.kernel_build.find("-D WORK_GROUP_SIZE=4"), std::string::npos) << grouped.kernel_build;
    EXPECT_EQ(grouped.kernel_build.find("KERNEL_SHAPE"), std::string::npos) << grouped.kernel_build;
    EXPECT_EQ(grouped.image, plain.image);
    EXPECT_EQ(grouped.work_items % 4, 0) << "the vector shape's work-items in whole work-groups";
  }
}

}  // namespace
}  // namespace parashade
