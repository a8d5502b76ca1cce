// The kernels' per-span normals (kernels/normalize_span.h, through the probe kernel normalize_probe.cl)
// against the host library (host/phong/normalization.cpp) on the same spans.
//
// Parallel methods (slerp, quadratic) against the host in double. Tolerance: the kernel works in
// float; its end normals are rounded to float (2^-24 relative) and normalized by rsqrt (a few ulp),
// then each component is a sum of at most three terms with |G|, |P| <= 4 and t in [0, 1], or sin() in
// slerp (4 ulp in OpenCL 1.2 full profile) scaled by 1/sin(theta) <= 7.1 for theta <= 3: well under
// 2e-5 absolute per component. The bound 2e-5 is 170 float ulps of 1; a wrong coefficient or formula
// gives errors of 1e-3 and more.
//
// Dichotomy and the recurrence against the host's float template, which the kernel follows operation
// for operation; the tolerances are in dichotomy() and recurrence() below.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <CL/opencl.hpp>

#include "cl_fixture.hpp"
#include "parashade/normalization.hpp"
#include "parashade/kernels/constants.h"

namespace parashade {
namespace {

using namespace testing_support;

std::pair<glm::dvec3, glm::dvec3> ends(double theta) {
  const glm::dvec3 c = glm::normalize(glm::dvec3(-0.3, 0.45, 0.8));
  const glm::dvec3 t = glm::normalize(glm::cross(c, glm::dvec3(0, 1, 0)));
  return {std::cos(theta / 2) * c - std::sin(theta / 2) * t, std::cos(theta / 2) * c + std::sin(theta / 2) * t};
}

// cos(theta) in every interval of the arccos tables, of both signs.
const std::vector<double> kThetas = {0.0, 1e-6, 1e-3, 0.1, 0.376, 0.7, 1.1, 1.5, 2.2, 2.5, 2.8, 3.0};

struct Probe {
  std::vector<float> ends;     // per span: na, nb as given to the kernel
  std::vector<float> normals;  // per span and pixel: x, y, z (zero where the span fell back)
  std::vector<cl_uint> steps;  // per span: the sequential unit's steps
};

// The probe kernel on the spans of angle theta (kThetas), `length` pixels each; TILE = TILE_DEFAULT.
Probe probe(const std::string& options, const std::vector<double>& thetas, int length) {
  Device& dev = test_device();
  Probe p;
  for (double th : thetas) {
    const auto [a, b] = ends(th);
    for (const glm::dvec3& v : {a, b}) p.ends.insert(p.ends.end(), {float(v.x), float(v.y), float(v.z)});
  }
  const std::size_t spans = thetas.size();
  cl::Buffer in(dev.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, p.ends.size() * sizeof(float), p.ends.data());
  cl::Buffer out(dev.context(), CL_MEM_WRITE_ONLY, spans * length * 3 * sizeof(float));
  cl::Buffer steps(dev.context(), CL_MEM_WRITE_ONLY, spans * sizeof(cl_uint));
  cl::Kernel k(dev.program({"normalize_probe.cl"}, options), "normalize_probe");
  k.setArg(0, in);
  k.setArg(1, cl_int(length));
  k.setArg(2, out);
  k.setArg(3, steps);
  dev.queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(spans), cl::NDRange(1));
  p.normals.resize(spans * length * 3);
  p.steps.resize(spans);
  dev.queue().enqueueReadBuffer(out, CL_TRUE, 0, p.normals.size() * sizeof(float), p.normals.data());
  dev.queue().enqueueReadBuffer(steps, CL_TRUE, 0, p.steps.size() * sizeof(cl_uint), p.steps.data());
  return p;
}

void check(const std::string& method, const std::string& options) {
  for (int length : {1, 2, 3, 17, 4096}) {
    const Probe p = probe(options, kThetas, length);
    for (std::size_t s = 0; s < kThetas.size(); ++s) {
      // The host library on the float-rounded end normals, in double.
      const float* e = &p.ends[6 * s];
      const glm::dvec3 a(e[0], e[1], e[2]), b(e[3], e[4], e[5]);
      const auto want = span_normals<double>(parse_normalize(method), glm::normalize(a), glm::normalize(b), length);
      for (int i = 0; i < length; ++i) {
        const float* g = &p.normals[3 * (s * length + i)];
        ASSERT_TRUE(std::isfinite(g[0]) && std::isfinite(g[1]) && std::isfinite(g[2]));
        for (int c = 0; c < 3; ++c)
          ASSERT_NEAR(g[c], want[i][c], 2e-5) << method << " theta " << kThetas[s] << " length " << length << " pixel " << i;
      }
    }
  }
}

TEST(NormalizeGolden, QuadraticExactMid) { check("quadratic:exact", "-D NORMALIZE_METHOD=2 -D NORMALIZE_MID=0"); }
TEST(NormalizeGolden, QuadraticFit) { check("quadratic:quad", "-D NORMALIZE_METHOD=2 -D NORMALIZE_MID=1"); }
TEST(NormalizeGolden, QuadraticSourceCubic) { check("quadratic:cubic", "-D NORMALIZE_METHOD=2 -D NORMALIZE_MID=2"); }
TEST(NormalizeGolden, QuadraticCubicFit) { check("quadratic:cubic-fit", "-D NORMALIZE_METHOD=2 -D NORMALIZE_MID=3"); }
TEST(NormalizeGolden, Slerp) { check("slerp", "-D NORMALIZE_METHOD=1"); }

// The kernel's -D options for a method, written out here (not by the renderer) so that a wrong mapping
// in the renderer is not mirrored by the test.
struct Case {
  std::string method, options;
};

// Kernel vs host span_normals<float> over kThetas and `lengths`; the tolerance per pixel i of a span of
// `length` pixels. Returns the largest difference and the largest difference / tolerance seen.
std::pair<double, double> check_float(const Case& c, const std::vector<int>& lengths, const std::function<double(int, int)>& tolerance) {
  double worst = 0, ratio = 0;
  const NormalizeMethod m = parse_normalize(c.method);
  for (int length : lengths) {
    const Probe p = probe(c.options, kThetas, length);
    for (std::size_t s = 0; s < kThetas.size(); ++s) {
      const float* e = &p.ends[6 * s];
      const glm::vec3 a = glm::normalize(glm::vec3(e[0], e[1], e[2])), b = glm::normalize(glm::vec3(e[3], e[4], e[5]));
      const auto want = span_normals<float>(m, a, b, length);
      for (int i = 0; i < length; ++i) {
        const float* g = &p.normals[3 * (s * length + i)];
        for (int k = 0; k < 3; ++k) {
          EXPECT_TRUE(std::isfinite(g[k])) << c.method;
          const double diff = std::fabs(double(g[k]) - double(want[i][k]));
          worst = std::max(worst, diff);
          ratio = std::max(ratio, diff / tolerance(i, length));
          if (!(diff <= tolerance(i, length))) {
            ADD_FAILURE() << c.method << " theta " << kThetas[s] << " length " << length << " pixel " << i << " component "
                          << k << ": kernel " << g[k] << ", host " << want[i][k] << ", tolerance " << tolerance(i, length);
            return {worst, ratio};
          }
        }
      }
    }
  }
  return {worst, ratio};
}

// The figures go to the test's XML (max_abs_diff) and its output.
void report(const std::string& method, std::pair<double, double> worst) {
  ::testing::Test::RecordProperty("max_abs_diff_" + method, std::to_string(worst.first));
  std::printf("%s: kernel vs host float, max |difference| %.3g, %.2f of the tolerance\n", method.c_str(), worst.first,
              worst.second);
}

const std::vector<int> kLengths = {1, 2, 3, 5, 16, 17, 18, 33, 100, 4096};

// Dichotomy: the kernel does the host's float operations in the host's order, except that the
// polynomial scale is evaluated in float (the host in double, then rounded) and the exact scale by
// rsqrt (few ulp), and the end normals come from the kernel's rsqrt and the host's 1/sqrt. Each of
// at most K + 3 = 9 levels (K <= 6) adds one rounding of the sum, one of the scale and of the product
// (under 2^-22 relative), the segment ends a few ulp: all told below 9 * 3 * 2^-23 + 1e-6 ~ 4e-6
// relative, and a normal's components are below 1.002. Tolerance 5e-6: 80 float ulps of 1. One level
// too few or too many, a wrong dyadic point or a wrong polynomial coefficient moves a normal by
// phi/2^K (>= 3e-6 only for theta >= 1e-3 and longer segments, but then by far more) or by the
// polynomial's error (>= 2e-5 relative per level).
void dichotomy(const std::string& method, const std::string& options) {
  report(method, check_float({method, options}, kLengths, [](int, int) { return 5e-6; }));
}

TEST(NormalizeGolden, DichotomyExact) {
  dichotomy("dichotomy:exact", "-D NORMALIZE_METHOD=3 -D NORMALIZE_BISECTOR=0 -D NORMALIZE_SEGMENT_LOG2=4");
}
TEST(NormalizeGolden, DichotomySourceLinear) {
  dichotomy("dichotomy:linear", "-D NORMALIZE_METHOD=3 -D NORMALIZE_BISECTOR=1 -D NORMALIZE_SEGMENT_LOG2=4");
}
TEST(NormalizeGolden, DichotomySourceQuadratic) {
  dichotomy("dichotomy:quadratic", "-D NORMALIZE_METHOD=3 -D NORMALIZE_BISECTOR=2 -D NORMALIZE_SEGMENT_LOG2=4");
}
TEST(NormalizeGolden, DichotomyLinearFit) {
  dichotomy("dichotomy:linear-fit", "-D NORMALIZE_METHOD=3 -D NORMALIZE_BISECTOR=3 -D NORMALIZE_SEGMENT_LOG2=4");
}
TEST(NormalizeGolden, DichotomyQuadraticFit) {
  dichotomy("dichotomy:quadratic-fit", "-D NORMALIZE_METHOD=3 -D NORMALIZE_BISECTOR=4 -D NORMALIZE_SEGMENT_LOG2=4");
}
TEST(NormalizeGolden, DichotomyOtherSegments) {
  dichotomy("dichotomy:quadratic-fit:1", "-D NORMALIZE_METHOD=3 -D NORMALIZE_BISECTOR=4 -D NORMALIZE_SEGMENT_LOG2=1");
  dichotomy("dichotomy:linear:3", "-D NORMALIZE_METHOD=3 -D NORMALIZE_BISECTOR=1 -D NORMALIZE_SEGMENT_LOG2=3");
  dichotomy("dichotomy:exact:6", "-D NORMALIZE_METHOD=3 -D NORMALIZE_BISECTOR=0 -D NORMALIZE_SEGMENT_LOG2=6");
}
TEST(NormalizeGolden, DichotomyExtrapolate) {
  dichotomy("dichotomy:exact:4:extrapolate",
            "-D NORMALIZE_METHOD=3 -D NORMALIZE_BISECTOR=0 -D NORMALIZE_SEGMENT_LOG2=4 -D NORMALIZE_EXTRAPOLATE=1");
  dichotomy("dichotomy:quadratic-fit:5:extrapolate",
            "-D NORMALIZE_METHOD=3 -D NORMALIZE_BISECTOR=4 -D NORMALIZE_SEGMENT_LOG2=5 -D NORMALIZE_EXTRAPOLATE=1");
}

// The recurrence: the same float operations in the same order; what differs is theta (the host's
// acos or table in double, rounded; the kernel's in float: a few ulp) and the sines of the anchors
// and of the step (glibc against the device's library, each within 4 ulp: OpenCL 1.2). An anchor is
// a sin(s theta)/sin(theta) + b sin((1-s) theta)/sin(theta), each ratio <= 1/sin(theta) <= 7.1 for
// theta <= 3 and off by a few ulp: the two sides' anchors differ by up to ~1e-6 per component. The
// recurrence is marginally stable: it carries a difference in its two anchors forward as a
// difference in N(t+1) - N(t), which adds up to twice that per step (2cos form: x(t) = x0 + t (x1 -
// x0) where 2cos rounds to 2; the difference form likewise through D). Tolerance 1e-5 + 2e-6 per step
// since the last anchor (9e-5 after 40 steps, 8e-3 after 4095). A wrong anchor pixel, a missing re-anchor or a wrong step angle moves the
// normals of short spans by the step angle (>= 1e-3 here) and of long ones by far more than this.
// Where 2 cos(dtheta) itself rounds differently on the two sides the float 2cos form's drift differs
// wholesale; it did not on these spans (the device's cos and glibc's agree here), and if it ever does
// on another device this test says so.
void recurrence(const std::string& method, const std::string& options, int reanchor) {
  auto tolerance = [reanchor](int i, int length) {
    const int every = reanchor > 1 ? reanchor : length;
    return 1e-5 + 2e-6 * (i - i / every * every);
  };
  report(method, check_float({method, options}, kLengths, tolerance));
}

TEST(NormalizeGolden, Recurrence2cos) {
  recurrence("recurrence:exact", "-D NORMALIZE_METHOD=4 -D NORMALIZE_ARCCOS=0", 0);
  recurrence("recurrence:table", "-D NORMALIZE_METHOD=4 -D NORMALIZE_ARCCOS=1", 0);
  recurrence("recurrence:table-fixed", "-D NORMALIZE_METHOD=4 -D NORMALIZE_ARCCOS=2", 0);
}
TEST(NormalizeGolden, Recurrence2cosReanchored) {
  recurrence("recurrence:exact:64", "-D NORMALIZE_METHOD=4 -D NORMALIZE_ARCCOS=0 -D NORMALIZE_REANCHOR=64", 64);
  recurrence("recurrence:table-fixed:7", "-D NORMALIZE_METHOD=4 -D NORMALIZE_ARCCOS=2 -D NORMALIZE_REANCHOR=7", 7);
}
TEST(NormalizeGolden, RecurrenceDifference) {
  recurrence("recurrence-diff:exact", "-D NORMALIZE_METHOD=4 -D NORMALIZE_ARCCOS=0 -D NORMALIZE_DIFFERENCE=1", 0);
  recurrence("recurrence-diff:table", "-D NORMALIZE_METHOD=4 -D NORMALIZE_ARCCOS=1 -D NORMALIZE_DIFFERENCE=1", 0);
  recurrence("recurrence-diff:table-fixed:2",
             "-D NORMALIZE_METHOD=4 -D NORMALIZE_ARCCOS=2 -D NORMALIZE_DIFFERENCE=1 -D NORMALIZE_REANCHOR=2", 2);
  recurrence("recurrence-diff:exact:64",
             "-D NORMALIZE_METHOD=4 -D NORMALIZE_ARCCOS=0 -D NORMALIZE_DIFFERENCE=1 -D NORMALIZE_REANCHOR=64", 64);
}

// The sequential unit steps from the last anchor at or before each run of TILE_DEFAULT pixels the probe
// asks for (the render kernel's tiles): its steps per span, counted here from that rule.
TEST(NormalizeGolden, RecurrenceStepsFromTheAnchor) {
  for (int reanchor : {0, 5, 64}) {
    const std::string options =
        "-D NORMALIZE_METHOD=4 -D NORMALIZE_DIFFERENCE=1 -D NORMALIZE_REANCHOR=" + std::to_string(reanchor);
    for (int length : {1, 2, 3, 16, 17, 40, 4096}) {
      std::uint64_t want = 0;
      const int every = reanchor > 1 ? reanchor : length;
      for (int run = 0; run < length; run += TILE_DEFAULT)
        want += std::min(run + TILE_DEFAULT, length) - run / every * every;
      const Probe p = probe(options, {0.5}, length);
      EXPECT_EQ(p.steps[0], want) << "R " << reanchor << " length " << length;
    }
  }
}

// Nearly opposite ends: below 1 + cos = 1e-6 (theta = pi - 1e-4) the span falls back (the probe writes
// zero); just above it (theta = pi - 0.01) the methods follow the host; nothing is NaN or Inf.
TEST(NormalizeGolden, NearlyOpposite) {
  const double pi = std::acos(-1.0);
  for (const Case& c : {Case{"dichotomy:quadratic-fit", "-D NORMALIZE_METHOD=3 -D NORMALIZE_BISECTOR=4"},
                        Case{"recurrence-diff:exact", "-D NORMALIZE_METHOD=4 -D NORMALIZE_DIFFERENCE=1"},
                        Case{"recurrence:table", "-D NORMALIZE_METHOD=4 -D NORMALIZE_ARCCOS=1"}}) {
    for (int length : {2, 3, 17, 4096}) {
      const Probe p = probe(c.options, {pi - 1e-4, pi - 0.01}, length);
      for (float v : p.normals) ASSERT_TRUE(std::isfinite(v)) << c.method;
      for (int i = 0; i < 3 * length; ++i) EXPECT_EQ(p.normals[i], 0.0f) << c.method << " fell back";
      const float* e = &p.ends[6];
      const glm::vec3 a = glm::normalize(glm::vec3(e[0], e[1], e[2])), b = glm::normalize(glm::vec3(e[3], e[4], e[5]));
      const auto want = span_normals<float>(parse_normalize(c.method), a, b, length);
      // Bisecting ends 0.01 from opposite: their sum has 1/0.01 of the rounding of a unit vector's.
      for (int i = 0; i < length; ++i)
        for (int k = 0; k < 3; ++k)
          ASSERT_NEAR(p.normals[3 * (length + i) + k], want[i][k], 2e-4 + 1e-6 * i) << c.method << " pixel " << i;
    }
  }
}

}  // namespace
}  // namespace parashade
