// The kernels' per-span normals (kernels/normalize_span.h, through the probe kernel normalize_probe.cl)
// against the host library (host/core/normalization.cpp) in double on the same spans. Tolerance: the
// kernel works in float; its end normals are rounded to float (2^-24 relative) and normalized by rsqrt
// (a few ulp), then each component is a sum of at most three terms with |G|, |P| <= 4 and t in [0, 1],
// or sin() in slerp (4 ulp in OpenCL 1.2 full profile) scaled by 1/sin(theta) <= 7.1 for theta <= 3:
// well under 2e-5 absolute per component. The bound 2e-5 is 170 float ulps of 1; a wrong coefficient
// or formula gives errors of 1e-3 and more.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cl_fixture.hpp"
#include "parashade/normalization.hpp"

namespace parashade {
namespace {

using namespace testing_support;

std::pair<glm::dvec3, glm::dvec3> ends(double theta) {
  const glm::dvec3 c = glm::normalize(glm::dvec3(-0.3, 0.45, 0.8));
  const glm::dvec3 t = glm::normalize(glm::cross(c, glm::dvec3(0, 1, 0)));
  return {std::cos(theta / 2) * c - std::sin(theta / 2) * t, std::cos(theta / 2) * c + std::sin(theta / 2) * t};
}

void check(const std::string& method, const std::string& options) {
  Device& dev = test_device();
  const std::vector<double> thetas = {0.0, 1e-6, 1e-3, 0.1, 0.7, 1.5, 2.2, 3.0};
  for (int length : {1, 2, 3, 17, 4096}) {
    std::vector<float> e;
    for (double th : thetas) {
      const auto [a, b] = ends(th);
      for (const glm::dvec3& v : {a, b}) e.insert(e.end(), {float(v.x), float(v.y), float(v.z)});
    }
    const std::size_t spans = thetas.size();
    cl::Buffer in(dev.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, e.size() * sizeof(float), e.data());
    cl::Buffer out(dev.context(), CL_MEM_WRITE_ONLY, spans * length * 3 * sizeof(float));
    cl::Kernel k(dev.program({"normalize_probe.cl"}, options), "normalize_probe");
    k.setArg(0, in);
    k.setArg(1, cl_int(length));
    k.setArg(2, out);
    dev.queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(spans), cl::NDRange(1));
    std::vector<float> got(spans * length * 3);
    dev.queue().enqueueReadBuffer(out, CL_TRUE, 0, got.size() * sizeof(float), got.data());
    for (std::size_t s = 0; s < spans; ++s) {
      // The host library on the float-rounded end normals, in double.
      const glm::dvec3 a(e[6 * s], e[6 * s + 1], e[6 * s + 2]), b(e[6 * s + 3], e[6 * s + 4], e[6 * s + 5]);
      const auto want = span_normals<double>(parse_normalize(method), glm::normalize(a), glm::normalize(b), length);
      for (int i = 0; i < length; ++i) {
        const float* g = &got[3 * (s * length + i)];
        ASSERT_TRUE(std::isfinite(g[0]) && std::isfinite(g[1]) && std::isfinite(g[2]));
        for (int c = 0; c < 3; ++c)
          ASSERT_NEAR(g[c], want[i][c], 2e-5) << method << " theta " << thetas[s] << " length " << length << " pixel " << i;
      }
    }
  }
}

TEST(NormalizeGolden, QuadraticExactMid) { check("quadratic:exact", "-D NORMALIZE_METHOD=2 -D NORMALIZE_MID=0"); }
TEST(NormalizeGolden, QuadraticFit) { check("quadratic:quad", "-D NORMALIZE_METHOD=2 -D NORMALIZE_MID=1"); }
TEST(NormalizeGolden, QuadraticSourceCubic) { check("quadratic:cubic", "-D NORMALIZE_METHOD=2 -D NORMALIZE_MID=2"); }
TEST(NormalizeGolden, QuadraticCubicFit) { check("quadratic:cubic-fit", "-D NORMALIZE_METHOD=2 -D NORMALIZE_MID=3"); }
TEST(NormalizeGolden, Slerp) { check("slerp", "-D NORMALIZE_METHOD=1"); }

}  // namespace
}  // namespace parashade
