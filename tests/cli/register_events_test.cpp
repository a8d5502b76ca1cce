// Register wraps and saturations in `render` (issue 17, item 9): a fixed-point unit whose registers are
// too narrow for the frame's values turns pixels black; the run must say so on stderr and count them in
// the report. The count is checked against the image itself: every wrapped pixel of the ramp below is black.
#include <string>

#include <gtest/gtest.h>

#include "cli_fixture.hpp"
#include "parashade/image.hpp"

namespace parashade {
namespace {

using namespace testing_support;

// A 4096x4 frame filled by one quad whose Gouraud intensity ramps from 0 at the left edge to 510 levels at
// the right (white material of colour 2 under a light along the right vertices' normal; the left ones are
// perpendicular to it). The orthographic camera maps world x to pixel x + 2048.
std::string ramp_obj() {
  return "v -2048 -2 0\nv 2048 -2 0\nv 2048 2 0\nv -2048 2 0\nvn 1 0 0\nvn 0 0 1\n"
         "f 1//1 2//2 3//2\nf 1//1 3//2 4//1\n";
}
std::string ramp_scene(const std::string& colour = "2") {
  return R"({
  "name": "ramp",
  "resolution": [4096, 4],
  "background": [0, 0, 0],
  "camera": {"type": "orthographic", "position": [0, 0, 10], "target": [0, 0, 0], "height": 4, "near": 1, "far": 50},
  "lights": [{"type": "directional", "direction": [0, 0, -1]}],
  "materials": {"white": {"color": [)" + colour + ", " + colour + ", " + colour + R"(], "ka": 0, "kd": 1, "ks": 0, "n": 1}},
  "objects": [{"mesh": "ramp.obj", "material": "white"}],
  "cull_backfaces": false
})";
}

class CliRegisterEvents : public CliTest {
 protected:
  std::filesystem::path ramp(const std::string& colour = "2") const {
    input("ramp.obj", ramp_obj());
    return input("ramp.json", ramp_scene(colour));
  }
  // Black pixels of the right half, where the exact intensity is 255 levels or more: a register of 9
  // integer bits holds at most 256 - 2^-F, so there only a wrap gives black.
  std::uint64_t black_in_right_half() const {
    const RenderedImage img = read_image(image());
    std::uint64_t black = 0;
    for (int y = 0; y < img.height; ++y)
      for (int x = img.width / 2; x < img.width; ++x) black += img.rgba[4 * (std::size_t(y) * img.width + x)] == 0;
    return black;
  }
};

TEST_F(CliRegisterEvents, NarrowRegistersOnARampAreCountedAndWarned) {
  const RunResult r = render(ramp(), {"--units", "classic", "--arith", "fixed:9.4"});
  ASSERT_TRUE(succeeds(r));
  const std::uint64_t black = black_in_right_half();
  // Intensity >= 256 from x = 2056 on: about 2040 pixels a row (the rounding errors move the edge a little).
  EXPECT_GT(black, 4u * 2000u);
  EXPECT_LE(black, 4u * 2048u);
  const nlohmann::json rep = read_report();
  EXPECT_EQ(field(rep, "/registers/wrapped_pixels"), black) << rep.dump(2);
  EXPECT_EQ(field(rep, "/registers/span_pixels"), 4096 * 4) << rep.dump(2);
  EXPECT_GT(field(rep, "/registers/saturated_loads"), 0) << rep.dump(2);  // the right ends: 510 levels
  EXPECT_NE(r.err.find("warning: fixed:9.4 span registers wrapped around on " + std::to_string(black) + " of 16384"),
            std::string::npos)
      << r;
  EXPECT_NE(r.err.find("span register loads saturated"), std::string::npos) << r;
}

TEST_F(CliRegisterEvents, WideEnoughRegistersReportNoneAndStayQuiet) {
  const RunResult r = render(ramp(), {"--units", "counter", "--arith", "fixed:12.4"});
  ASSERT_TRUE(succeeds(r));
  EXPECT_EQ(black_in_right_half(), 0u);
  const nlohmann::json rep = read_report();
  EXPECT_EQ(field(rep, "/registers/wrapped_pixels"), 0) << rep.dump(2);
  EXPECT_EQ(field(rep, "/registers/saturated_loads"), 0) << rep.dump(2);
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << r;
}

// Issue 46, item 16: the sierpinski unit's copies get their values through one adder each from an offset
// register (I(P) + I(C - P) for a point-reflected copy: up to twice the ramp's 255 levels). With 9 integer
// bits that load saturates at 256 and the copies come out ~40 levels low; it used to count as nothing (0
// wrapped, 0 saturated) and no warning was given.
TEST_F(CliRegisterEvents, SierpinskiCopiesWhoseOffsetSaturatesAreCountedAndWarned) {
  const RunResult r = render(ramp("1"), {"--units", "sierpinski", "--arith", "fixed:9.23"});
  ASSERT_TRUE(succeeds(r));
  const nlohmann::json rep = read_report();
  EXPECT_EQ(field(rep, "/registers/wrapped_pixels"), 0) << rep.dump(2);
  EXPECT_GT(field(rep, "/registers/saturated_loads"), 0) << rep.dump(2);
  EXPECT_NE(r.err.find("warning: fixed:9.23: "), std::string::npos) << r;
  EXPECT_NE(r.err.find("span register loads saturated"), std::string::npos) << r;
  // The same frame with room for the offsets: nothing saturates, nothing is said.
  const RunResult wide = render(ramp("1"), {"--units", "sierpinski", "--arith", "fixed:10.22"});
  ASSERT_TRUE(succeeds(wide));
  EXPECT_EQ(field(read_report(), "/registers/saturated_loads"), 0);
  EXPECT_EQ(wide.err.find("warning"), std::string::npos) << wide;
}

TEST_F(CliRegisterEvents, FloatRendersHaveNoRegisterSection) {
  const RunResult r = render(ramp(), {});
  ASSERT_TRUE(succeeds(r));
  EXPECT_FALSE(read_report().contains("registers"));
}

}  // namespace
}  // namespace parashade
