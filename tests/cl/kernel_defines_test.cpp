// RenderOptions::kernel_defines reach the frame kernel's build (bench_kernel_ab compares two builds told
// apart by them): a define that the kernel turns into a compile error makes the render fail with the
// build's own error, and the defines are appended to the variant's options as they are given.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../../host/cl/kernel_variant.hpp"
#include "cl_fixture.hpp"
#include "parashade/errors.hpp"

namespace parashade {
namespace {

using namespace testing_support;

TEST(KernelDefines, ReachTheFrameKernelsBuild) {
  Scene scene = pixel_scene(32, 32);
  RenderOptions o = render_options(Method::gouraud, false, 16);
  o.kernel_defines = "-D PARASHADE_FAIL_BUILD";  // common.h: #error under this macro
  Renderer renderer(test_device(), o);
  try {
    renderer.render(scene);
    FAIL() << "the kernel built with -D PARASHADE_FAIL_BUILD";
  } catch (const DeviceError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("-D PARASHADE_FAIL_BUILD"), std::string::npos) << message;
    EXPECT_NE(message.find("build failure injected"), std::string::npos) << message;
  }
}

TEST(KernelDefines, AppendedToTheVariantsOptions) {
  Scene scene = pixel_scene(32, 32);
  RenderOptions o = render_options(Method::phong, false, 16);
  const std::string plain = kernel_variant(scene, o).build_options();
  o.kernel_defines = "-D PREFETCH_AHEAD=2";
  EXPECT_EQ(kernel_variant(scene, o).build_options(), plain + " -D PREFETCH_AHEAD=2");
}

// The stamps rule in one place: the host's KernelVariant::plain_frame() and the kernel's PLAIN_FRAME
// (kernels/tile_paths.h) are the same rule. The kernel refuses STAMPS off its plain frame, so a build forced
// to stamps must succeed exactly where the host calls the frame plain.
TEST(KernelDefines, TheHostsPlainFrameIsTheKernels) {
  const Scene scene = pixel_scene(32, 32);
  struct Case {
    const char* what;
    RenderOptions options;
    int plan_pass;
  };
  std::vector<Case> cases;
  for (Method m : {Method::flat, Method::gouraud, Method::phong, Method::combined})
    cases.push_back({method_name(m), render_options(m, false, 16), 0});
  cases.push_back({"float read-back", render_options(Method::phong, true, 16), 0});
  RenderOptions unit = render_options(Method::gouraud, false, 16);
  unit.units = parse_units("counter");
  cases.push_back({"a unit", unit, 0});
  RenderOptions span = render_options(Method::phong, false, 16);
  span.normalize = parse_normalize("slerp");
  cases.push_back({"per-span normals", span, 0});
  RenderOptions planned = render_options(Method::gouraud, false, 16);
  planned.plan = PlanOptions{};
  planned.plan->units = 2;
  cases.push_back({"the units' depth pass", planned, 1});
  cases.push_back({"the plan's resolve", planned, 2});
  int plain = 0;
  for (Case& c : cases) {
    c.options.stamps = false;  // the host passes no STAMPS; the test forces it
    KernelVariant v = kernel_variant(scene, c.options);
    v.plan_pass = c.plan_pass;
    bool built = true;
    try {
      test_device().program(kernel_files(v), v.build_options() + " -D STAMPS=1");
    } catch (const DeviceError&) {
      built = false;
    }
    EXPECT_EQ(built, v.plain_frame()) << c.what;
    plain += v.plain_frame();
  }
  EXPECT_EQ(plain, 4) << "the four methods' frames are plain, the rest are not";
}

}  // namespace
}  // namespace parashade
