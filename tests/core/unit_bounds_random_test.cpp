// The units' error bounds (docs/unit-error.md, docs/error-bounds.md) on random triangles (issue 17, item 14):
// 10^5 triangles per unit through the real setup (setup_triangles: edge functions, planes in setup's 32-bit
// fraction format), one row span of each through the unit's golden model, every pixel against the exact
// value of the triangle's plane, solved here in long double from the vertices. The vertex values are
// normal components x 255 (what Phong through a unit puts in the registers): random normals, opposite
// normals (n, -n: the value sweeps -255..255) and equal ones (a flat span). One triangle in 200 spans the
// whole 4096-pixel row. With few integer bits the registers wrap: the wraps the study flags must be the
// ones the unbounded classic sum predicts, and each must be exactly one register range.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "parashade/golden_units.hpp"
#include "parashade/planner.hpp"
#include "parashade/setup.hpp"
#include "parashade/unit_error.hpp"
#include "parashade/unit_table.hpp"

namespace parashade {
namespace {

constexpr int kWidth = 4096, kHeight = 16, kTriangles = 130000;  // about 80 % get a span

// A triangle's screen vertices (pixels) and one channel's vertex values (levels).
struct RandomTriangle {
  glm::dvec2 p[3];
  double value[3];
};

glm::dvec3 random_normal(std::mt19937_64& g) {
  std::normal_distribution<double> n;
  glm::dvec3 v;
  do v = glm::dvec3(n(g), n(g), n(g));
  while (glm::length(v) < 1e-3);
  return glm::normalize(v);
}

// Triangle t: kind t % 3 gives random, opposite or equal end normals; the channel is t / 3 % 3.
RandomTriangle random_triangle(std::mt19937_64& g, int t) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  RandomTriangle r;
  if (t % 200 == 0) {  // reaching past both screen edges: its top rows are spans of all 4096 pixels
    r.p[0] = {-0.5 - 10 * u(g), -0.5};
    r.p[1] = {2.0 * kWidth, -0.5};
    r.p[2] = {-0.5, kHeight + 0.5 + 4 * u(g)};
  } else {  // widths log-uniform from about 1 to 256 pixels
    const double w = std::exp(std::log(256.0) * u(g)) + 0.5, h = 1.0 + (kHeight - 1) * u(g);
    const double x = (kWidth - w) * u(g), y = (kHeight - h) * u(g);
    for (glm::dvec2& q : r.p) q = {x + w * u(g), y + h * u(g)};
  }
  const glm::dvec3 n0 = random_normal(g);
  const glm::dvec3 n[3] = {n0, t % 3 == 1 ? -n0 : t % 3 == 2 ? n0 : random_normal(g),
                           t % 3 == 2 ? n0 : random_normal(g)};
  for (int k = 0; k < 3; ++k) r.value[k] = 255.0 * n[k][t / 3 % 3];
  return r;
}

// The triangles as screen geometry (sub-pixel vertices, wound as setup wants), with the value in every channel.
ScreenGeometry screen_geometry(std::vector<RandomTriangle>& tris) {
  ScreenGeometry g;
  g.width = kWidth;
  g.height = kHeight;
  for (RandomTriangle& r : tris) {
    glm::ivec2 q[3];
    for (int k = 0; k < 3; ++k) {
      q[k] = glm::ivec2(glm::round(r.p[k] * double(kSubpixel)));
      r.p[k] = glm::dvec2(q[k]) / double(kSubpixel);  // the exact plane goes through the snapped vertices
    }
    const std::int64_t e = std::int64_t(q[1].x - q[0].x) * (q[2].y - q[0].y) - std::int64_t(q[1].y - q[0].y) * (q[2].x - q[0].x);
    if (e == 0) continue;
    if (e < 0) std::swap(r.p[1], r.p[2]), std::swap(r.value[1], r.value[2]), std::swap(q[1], q[2]);
    const std::uint32_t base = std::uint32_t(g.xy.size());
    for (int k = 0; k < 3; ++k) {
      g.xy.push_back(q[k]);
      g.depth.push_back(0.5f);
      g.inv_w.push_back(1.0f);
      g.color.push_back(glm::vec3(float(r.value[k])));
      r.value[k] = double(float(r.value[k]));  // setup sees the float vertex value
    }
    g.triangles.push_back({base, base + 1, base + 2});
    g.material.push_back(0);
    g.face.push_back(std::uint32_t(g.triangles.size() - 1));
  }
  tris.erase(std::remove_if(tris.begin(), tris.end(), [](const RandomTriangle& r) {
               const glm::dvec2 a = r.p[1] - r.p[0], b = r.p[2] - r.p[0];
               return a.x * b.y - a.y * b.x == 0.0;
             }),
             tris.end());
  return g;
}

// The triangle's plane, solved in long double from its vertices: the exact value at the centre of pixel
// (x, y) is at(x, y), levels.
struct ExactPlane {
  long double v0, dx, dy, ax, ay;
  explicit ExactPlane(const RandomTriangle& r) {
    const long double bx = r.p[1].x - r.p[0].x, by = r.p[1].y - r.p[0].y, cx = r.p[2].x - r.p[0].x,
                      cy = r.p[2].y - r.p[0].y, d = bx * cy - cx * by;
    const long double db = (long double)r.value[1] - r.value[0], dc = (long double)r.value[2] - r.value[0];
    v0 = r.value[0];
    ax = r.p[0].x;
    ay = r.p[0].y;
    dx = (db * cy - dc * by) / d;
    dy = (dc * bx - db * cx) / d;
  }
  long double at(int x, int y) const { return v0 + (x + 0.5L - ax) * dx + (y + 0.5L - ay) * dy; }
};

// The bound models rounding, not saturation: a span whose start, end or increment (or M times it) does not
// fit the register is left out of the bound and counted apart.
bool saturates(std::int64_t plane, const Arithmetic& a) {
  const int shift = PLANE_FRAC - a.frac_bits;
  const std::int64_t rounded = (plane >> shift) + ((plane >> (shift - 1)) & 1);
  return rounded != saturate_register(rounded, a.width());
}
bool span_saturates(const FixedPlanes& p, int xl, int xr, int dy, const UnitConfig& unit, const Arithmetic& a) {
  return saturates(plane_value(p.ref[0], p.ddx[0], p.ddy[0], xl, dy), a) ||
         saturates(plane_value(p.ref[0], p.ddx[0], p.ddy[0], xr, dy), a) || saturates(p.ddx[0], a) ||
         (unit.own_step && saturates(std::int64_t(std::uint64_t(p.ddx[0]) * std::uint64_t(unit.lanes)), a));
}

struct Tally {
  std::uint64_t triangles = 0, spans = 0, long_spans = 0, saturated_spans = 0, pixels = 0, over_bound = 0, wrapped = 0,
                predicted_wraps = 0, not_one_range = 0;
  double worst_ratio = 0;  // max |error| / bound(z)
};

Tally run(const UnitConfig& unit, const Arithmetic& a, std::uint64_t seed) {
  std::mt19937_64 g(seed);
  std::vector<RandomTriangle> tris;
  for (int t = 0; t < kTriangles; ++t) tris.push_back(random_triangle(g, t));
  const ScreenGeometry geometry = screen_geometry(tris);
  const std::size_t n = geometry.triangles.size();
  std::vector<TriangleGeometry> rec(n);
  std::vector<float> attrs(n * attribute_floats(Method::gouraud));
  std::vector<FixedPlanes> planes(n);
  setup_triangles(geometry, Method::gouraud, rec.data(), attrs.data(), planes.data());
  const long double range = std::ldexp(1.0L, a.int_bits), lo = -std::ldexp(1.0L, a.width() - 1),
                    hi = std::ldexp(1.0L, a.width() - 1) - 1;
  Tally tally;
  tally.triangles = n;
  std::uniform_int_distribution<int> pick(0, 1 << 20);
  for (std::size_t t = 0; t < n; ++t) {
    const TriangleGeometry& r = rec[t];
    if (r.x0 > r.x1) continue;
    // One row: the top one for the whole-row triangles, else the first covered row from a random one on.
    const int rows = r.y1 - r.y0 + 1;
    int dy = r.x1 - r.x0 + 1 == kWidth ? 0 : pick(g) % rows, xl = 0, xr = -1;
    int tried = 0;
    while (tried < rows && !record_row_span(r, dy, xl, xr)) dy = (dy + 1) % rows, ++tried;
    if (tried == rows) continue;
    if (span_saturates(planes[t], xl, xr, dy, unit, a)) {
      ++tally.saturated_spans;
      continue;
    }
    const SpanLoad load = load_span(planes[t], 0, xl, xr, dy, unit, a);
    const SpanTrace trace = run_unit(unit, a, load);
    ++tally.spans;
    tally.long_spans += load.length == kWidth;
    const ExactPlane plane(tris[t]);
    for (int z = 0; z < load.length; ++z) {
      const long double exact = plane.at(r.x0 + xl + z, r.y0 + dy);
      long double error = std::ldexp((long double)trace.values[std::size_t(z)], -a.frac_bits) - exact;
      if (std::fabs(error) >= range / 2) {  // a wrap: off by whole register ranges
        ++tally.wrapped;
        const long double k = std::nearbyint(error / range);
        error -= range * k;
        tally.not_one_range += std::fabs(k) != 1;
      }
      if (unit.kind == UnitKind::classic) {  // the adders' sum without the wrap
        const long double unbounded = (long double)load.start + (long double)z * load.step;
        tally.predicted_wraps += unbounded < lo || unbounded > hi;
      }
      const double bound = unit_error_bound(unit, a, load.length, z);
      tally.over_bound += double(std::fabs(error)) > bound;
      tally.worst_ratio = std::max(tally.worst_ratio, double(std::fabs(error)) / bound);
      ++tally.pixels;
    }
  }
  return tally;
}

std::vector<std::string> bounded_units() {
  std::vector<std::string> specs;
  for (const UnitRow& row : unit_table())
    for (const std::string& spec : row.error_study) specs.push_back(spec);
  return specs;
}

TEST(UnitBoundsOnRandomTriangles, EveryPixelWithinTheBoundAndNoWrap) {
  const std::vector<std::string> specs = bounded_units();
  ASSERT_GE(specs.size(), 4u);
  for (const std::string& spec : specs) {
    const Tally t = run(parse_units(spec), Arithmetic{true, 12, 6}, 17);
    EXPECT_GE(t.triangles, 129000u) << spec;
    EXPECT_GE(t.spans, 100000u) << spec;
    EXPECT_GE(t.long_spans, 400u) << spec;
    EXPECT_EQ(t.over_bound, 0u) << spec << ": worst error " << t.worst_ratio << " x the bound over " << t.pixels << " pixels";
    EXPECT_GT(t.worst_ratio, 0.5) << spec << ": the bound is far from what the unit reaches";
    EXPECT_EQ(t.wrapped, 0u) << spec << ": 12 integer bits hold +-255 and any accumulated error";
    EXPECT_LT(t.saturated_spans, t.spans / 20) << spec << ": steep slivers saturate an increment, few others";
  }
}

TEST(UnitBoundsOnRandomTriangles, FewIntegerBitsWrapAsPredictedAndOnlyByOneRange) {
  // 9.1: the register holds -256..255.5 and an increment's rounding (up to 1/4 level) accumulates over
  // 4096 pixels far past the 1-level margin of a value near +-255.
  for (const std::string& spec : bounded_units()) {
    const UnitConfig unit = parse_units(spec);
    const Tally t = run(unit, Arithmetic{true, 9, 1}, 29);  // wraps are rare: all 130 000 triangles
    // The counter unit cannot wrap while its end registers fit: the increment rounds to 0 when |dI| is
    // below half an LSB, else to at most twice |dI|, so neither half passes the end value it runs toward.
    if (unit.kind == UnitKind::counter) EXPECT_EQ(t.wrapped, 0u) << spec;
    else EXPECT_GT(t.wrapped, 0u) << spec << ": no register wrapped (" << t.long_spans << " long spans)";
    EXPECT_GE(t.spans, 50000u) << spec << " (" << t.saturated_spans << " spans saturated a load)";
    EXPECT_EQ(t.not_one_range, 0u) << spec;
    EXPECT_EQ(t.over_bound, 0u) << spec << ": worst reduced error " << t.worst_ratio << " x the bound";
    if (unit.kind == UnitKind::classic) EXPECT_EQ(t.wrapped, t.predicted_wraps) << spec;
  }
}

}  // namespace
}  // namespace parashade
