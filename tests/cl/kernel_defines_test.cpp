// RenderOptions::kernel_defines reach the frame kernel's build (bench_kernel_ab compares two builds told
// apart by them): a define that the kernel turns into a compile error makes the render fail with the
// build's own error, and the defines are appended to the variant's options as they are given.
#include <string>

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

}  // namespace
}  // namespace parashade
