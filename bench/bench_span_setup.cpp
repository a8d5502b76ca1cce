// Host cost of Gouraud span increments per triangle ([Gouraud simplification] and [Romanyuk & Obidnyk 2011, faster shading]), whole triangles: edge walking,
// edge intensities, span increments, pixel intensities by accumulation, 8-bit RGB pixels written to a
// frame. Only the span increment differs between the variants:
//   div_*         one division per span and channel, (I_R - I_L) / k (double, float, 16.16 integers);
//   recip_double  one division per span, then a product per channel;
//   shiftadd8*    the division replaced by the shift-add approximation of 1/k, n = 8 rounded (the
//                 source's Table 1), its digits looked up per span length k: adds only where i_j = 1
//                 (shiftadd8_fixed), all 9 shifted terms masked by their digits, branch-free
//                 (shiftadd8masked_fixed), or the digits as one integer product (shiftadd8mul_fixed);
//   const216_*    the constant span increment once per triangle by formula 2.16 (ConstantSpanIncrement),
//   const215_*    ... or by formula 2.15 (constant_span_increment_longest_span, once per channel);
//                 spans then need neither a division nor the right edge's intensities.
// Triangle sets: "small" (~100 pixels, spans <= 16: the source's average triangle), "medium" (~1000),
// "large" (~14000), "example" (the source's triangle dx_AB=7, dy_AB=8, dx_AC=9, dy_AC=12, dx_BC=16,
// dy_BC=4 at random places), each in a frame small enough to stay in cache (64^2 .. 288^2 pixels), so
// the arithmetic is measured rather than store misses; "small_1k" is "small" spread over a 1024^2 frame
// (3 MB) to show what those misses do. Ratios against the division variants are printed after the run
// (CPU time; minimum and median of the repetitions, all from this one run). On a shared machine use
// --benchmark_repetitions=9 --benchmark_enable_random_interleaving=true.
//   --print-table  Table 1 of [Romanyuk & Obidnyk 2011, faster shading] recomputed, its summary claims, and the extension to other k, n
//   --print-ops    operation counts for the example triangle per variant (vs the source's 408 / 42) and
//                  each variant's pixel error against the classic method and against the exact plane
// Both are handled before benchmark::Initialize and exit without running benchmarks.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <random>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "parashade/setup.hpp"
#include "parashade/shift_add_division.hpp"
#include "parashade/kernels/constants.h"
#include "benchmark_schema.hpp"

namespace parashade {
namespace {

// ---------------------------------------------------------------------------------------------------
// Operation counting: the shading code reports its arithmetic on intensities per stage (the rows of
// the source's Table 2). The timed code uses NoCount, which compiles away.
enum Stage { kEdgeIncrements, kEdgePoints, kSpanIncrements, kSpanPoints, kTriangleSetup, kStages };
const char* const kStageNames[kStages] = {"edge increments", "edge points", "span increments", "span points",
                                          "triangle setup (dI_G)"};

struct NoCount {
  void add(Stage, int) {}
  void muldiv(Stage, int) {}
  void shift(Stage, int) {}
};
struct Count {
  std::uint64_t add_[kStages] = {}, muldiv_[kStages] = {}, shift_[kStages] = {};
  void add(Stage s, int n) { add_[s] += std::uint64_t(n); }
  void muldiv(Stage s, int n) { muldiv_[s] += std::uint64_t(n); }
  void shift(Stage s, int n) { shift_[s] += std::uint64_t(n); }
};

// ---------------------------------------------------------------------------------------------------
// Number formats of the intensity registers. Pixels are written truncated to 8 bits and saturated, in
// every format (approximate increments can overshoot a span's end).
inline std::uint8_t saturate(int v) { return std::uint8_t(v < 0 ? 0 : v > 255 ? 255 : v); }
struct DoubleFormat {
  using T = double;
  static T from(double v) { return v; }
  static T div(T d, int k) { return d / T(k); }
  static std::uint8_t level(T v) { return saturate(int(v)); }
};
struct FloatFormat {
  using T = float;
  static T from(double v) { return T(v); }
  static T div(T d, int k) { return d / T(k); }
  static std::uint8_t level(T v) { return saturate(int(v)); }
};
constexpr int kFrac = 16;  // 16.16 integers: 255 levels and any difference fit in 32 bits
struct FixedFormat {
  using T = std::int32_t;
  static T from(double v) { return T(std::lrint(std::ldexp(v, kFrac))); }
  static T div(T d, int k) { return d / k; }
  static std::uint8_t level(T v) { return saturate(v >> kFrac); }
};

// A triangle: integer pixel positions sorted by y (A top, B middle, C bottom), RGB levels per vertex.
struct Tri {
  int x[3], y[3];
  float c[3][3];
};

struct Frame {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;
  Frame(int w, int h) : width(w), height(h), rgb(std::size_t(w) * std::size_t(h) * 3, 0) {}
  std::uint8_t* at(int x, int y) { return rgb.data() + (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 3; }
};

// ---------------------------------------------------------------------------------------------------
// Span increment rules.
template <class F>
struct DivideRule {
  static constexpr bool per_span = true;
  template <class Ops>
  void span(const typename F::T* diff, int k, typename F::T* d, Ops& ops) const {
    for (int c = 0; c < 3; ++c) d[c] = F::div(diff[c], k);
    ops.muldiv(kSpanIncrements, 3);
  }
};

struct ReciprocalRule {  // double: 1/k once per span, a product per channel
  static constexpr bool per_span = true;
  template <class Ops>
  void span(const double* diff, int k, double* d, Ops& ops) const {
    const double r = 1.0 / k;
    for (int c = 0; c < 3; ++c) d[c] = diff[c] * r;
    ops.muldiv(kSpanIncrements, 4);
  }
};

// The digits m of 1/k (n = 8, rounded) for every span length the frames can hold, looked up per span.
constexpr int kShiftAddBits = 8;
constexpr int kMaxSpan = MAX_RESOLUTION;  // 12-bit pixel addresses
const std::vector<std::uint32_t>& shift_add_digits() {
  static const std::vector<std::uint32_t> table = [] {
    std::vector<std::uint32_t> t(kMaxSpan + 1, 0);
    for (int k = 1; k <= kMaxSpan; ++k)
      t[std::size_t(k)] = std::uint32_t(shift_add_reciprocal(k, kShiftAddBits, ReciprocalRounding::nearest).bits);
    return t;
  }();
  return table;
}

// The hardware's way in software: for every digit i_j = 1 add diff >> j (arithmetic shift: GCC's and
// C++20's >> on negative values, the same floor as shift_add_divide).
struct ShiftAddRule {
  static constexpr bool per_span = true;
  const std::uint32_t* digits = shift_add_digits().data();
  template <class Ops>
  void span(const std::int32_t* diff, int k, std::int32_t* d, Ops& ops) const {
    const std::uint32_t m0 = digits[k];
    for (int c = 0; c < 3; ++c) {
      std::int32_t s = 0;
      for (std::uint32_t m = m0; m != 0; m &= m - 1) s += diff[c] >> (kShiftAddBits - __builtin_ctz(m));
      d[c] = s;
    }
    const int ones = __builtin_popcount(m0);
    ops.add(kSpanIncrements, 3 * ones);
    ops.shift(kSpanIncrements, 3 * ones);
  }
};

// The hardware's clocks without branches: every shifted term, masked by its digit i_j (j = 0 only for
// k = 1). The loop over the ones above mispredicts where k changes from span to span; this one does not.
struct ShiftAddMaskedRule {
  static constexpr bool per_span = true;
  const std::uint32_t* digits = shift_add_digits().data();
  template <class Ops>
  void span(const std::int32_t* diff, int k, std::int32_t* d, Ops& ops) const {
    const std::uint32_t m = digits[k];
    for (int c = 0; c < 3; ++c) {
      std::int32_t s = 0;
      for (int j = 0; j <= kShiftAddBits; ++j) s += (diff[c] >> j) & -std::int32_t((m >> (kShiftAddBits - j)) & 1u);
      d[c] = s;
    }
    ops.add(kSpanIncrements, 3 * (kShiftAddBits + 1));  // plus as many ANDs, not counted
    ops.shift(kSpanIncrements, 3 * kShiftAddBits);
  }
};

// The same digits used as an 8-bit reciprocal: one product and one shift per channel.
struct ShiftAddMulRule {
  static constexpr bool per_span = true;
  const std::uint32_t* digits = shift_add_digits().data();
  template <class Ops>
  void span(const std::int32_t* diff, int k, std::int32_t* d, Ops& ops) const {
    const std::int64_t m = digits[k];
    for (int c = 0; c < 3; ++c) d[c] = std::int32_t((std::int64_t(diff[c]) * m) >> kShiftAddBits);
    ops.muldiv(kSpanIncrements, 3);
    ops.shift(kSpanIncrements, 3);
  }
};

glm::dvec2 pos(const Tri& t, int v) { return glm::dvec2(t.x[v], t.y[v]); }

// Formula 2.16 as host/pipeline/setup.cpp evaluates it: 4 differences, 2 products, a difference and a
// division for the triangle; 3 differences and 3 products per channel.
template <class F>
struct Constant216Rule {
  static constexpr bool per_span = false;
  template <class Ops>
  void triangle(const Tri& t, typename F::T* d, Ops& ops) const {
    const ConstantSpanIncrement inc(pos(t, 0), pos(t, 1), pos(t, 2));
    for (int c = 0; c < 3; ++c) d[c] = F::from(inc(t.c[0][c], t.c[1][c], t.c[2][c]));
    ops.add(kTriangleSetup, 5 + 3 * 3);
    ops.muldiv(kTriangleSetup, 3 + 3 * 3);
  }
};

// Formula 2.15 as host/pipeline/setup.cpp evaluates it, once per channel: 8 additions or differences,
// 2 products and 2 divisions per call.
template <class F>
struct Constant215Rule {
  static constexpr bool per_span = false;
  template <class Ops>
  void triangle(const Tri& t, typename F::T* d, Ops& ops) const {
    for (int c = 0; c < 3; ++c)
      d[c] = F::from(constant_span_increment_longest_span(pos(t, 0), pos(t, 1), pos(t, 2), t.c[0][c], t.c[1][c],
                                                          t.c[2][c]));
    ops.add(kTriangleSetup, 3 * 8);
    ops.muldiv(kTriangleSetup, 3 * 4);
  }
};

// ---------------------------------------------------------------------------------------------------
// One edge, one step per row: x in 16.16 (offset by half a pixel, so x >> 16 rounds) and, where the
// variant needs them, the intensities.
template <class F>
struct EdgeWalk {
  std::int32_t x = 0, dx = 0;
  typename F::T i[3] = {}, di[3] = {};
  bool shaded = false;
};

template <class F, class Ops>
EdgeWalk<F> start_edge(const Tri& t, int v0, int v1, const typename F::T (*value)[3], bool shaded, Ops& ops) {
  EdgeWalk<F> e;
  const int dy = t.y[v1] - t.y[v0];
  e.x = (t.x[v0] << kFrac) + (1 << (kFrac - 1));
  if (dy > 0) e.dx = ((t.x[v1] - t.x[v0]) * (1 << kFrac)) / dy;
  e.shaded = shaded;
  for (int c = 0; c < 3; ++c) e.i[c] = value[v0][c];
  if (shaded && dy > 0) {
    for (int c = 0; c < 3; ++c) e.di[c] = F::div(value[v1][c] - value[v0][c], dy);
    ops.add(kEdgeIncrements, 3);
    ops.muldiv(kEdgeIncrements, 3);
  }
  return e;
}

template <class F, class Ops>
inline void step(EdgeWalk<F>& e, Ops& ops) {
  e.x += e.dx;
  if (e.shaded) {
    for (int c = 0; c < 3; ++c) e.i[c] += e.di[c];
    ops.add(kEdgePoints, 3);
  }
}

template <class F, class Rule, class Ops>
inline void shade_span(int y, const EdgeWalk<F>& l, const EdgeWalk<F>& r, const typename F::T* d_triangle,
                       const Rule& rule, Ops& ops, Frame& frame) {
  using T = typename F::T;
  const int x0 = l.x >> kFrac, k = (r.x >> kFrac) - x0;  // k: span length (pixels - 1)
  if (k < 0) return;  // only 16.16 drift on a sliver's last row can cross the ends
  T v[3] = {l.i[0], l.i[1], l.i[2]}, d[3] = {T(0), T(0), T(0)};
  if constexpr (Rule::per_span) {
    if (k > 0) {
      const T diff[3] = {T(r.i[0] - l.i[0]), T(r.i[1] - l.i[1]), T(r.i[2] - l.i[2])};
      ops.add(kSpanIncrements, 1 + 3);  // the span length, the three differences
      rule.span(diff, k, d, ops);
    }
  } else {
    for (int c = 0; c < 3; ++c) d[c] = d_triangle[c];
  }
  std::uint8_t* p = frame.at(x0, y);
  p[0] = F::level(v[0]), p[1] = F::level(v[1]), p[2] = F::level(v[2]);
  for (int j = 1; j <= k; ++j) {
    p += 3;
    v[0] += d[0], v[1] += d[1], v[2] += d[2];
    p[0] = F::level(v[0]), p[1] = F::level(v[1]), p[2] = F::level(v[2]);
  }
  ops.add(kSpanPoints, 3 * k);
}

// Rows ya..yc: the short edges AB (rows ya..yb-1) and BC (rows yb..yc) on one side, AC on the other.
template <class F, class Rule, class Ops>
void shade_triangle(const Tri& t, const Rule& rule, Ops& ops, Frame& frame) {
  using T = typename F::T;
  T value[3][3];
  for (int v = 0; v < 3; ++v)
    for (int c = 0; c < 3; ++c) value[v][c] = F::from(t.c[v][c]);
  // B left of AC: (x_B - x_A) * dy_AC < (x_C - x_A) * dy_AB.
  const bool b_left = (t.x[1] - t.x[0]) * (t.y[2] - t.y[0]) < (t.x[2] - t.x[0]) * (t.y[1] - t.y[0]);
  // Per-span rules need both ends' intensities; constant increments only the left edge's.
  const bool short_shaded = Rule::per_span || b_left, long_shaded = Rule::per_span || !b_left;
  T d_triangle[3] = {T(0), T(0), T(0)};
  if constexpr (!Rule::per_span) rule.triangle(t, d_triangle, ops);

  EdgeWalk<F> ac = start_edge<F>(t, 0, 2, value, long_shaded, ops);
  EdgeWalk<F> ab = start_edge<F>(t, 0, 1, value, short_shaded, ops);
  for (int y = t.y[0]; y < t.y[1]; ++y) {
    if (b_left) shade_span<F>(y, ab, ac, d_triangle, rule, ops, frame);
    else shade_span<F>(y, ac, ab, d_triangle, rule, ops, frame);
    if (y + 1 < t.y[1]) step(ab, ops);
    step(ac, ops);
  }
  EdgeWalk<F> bc = start_edge<F>(t, 1, 2, value, short_shaded, ops);
  for (int y = t.y[1]; y <= t.y[2]; ++y) {
    if (b_left) shade_span<F>(y, bc, ac, d_triangle, rule, ops, frame);
    else shade_span<F>(y, ac, bc, d_triangle, rule, ops, frame);
    if (y == t.y[2]) break;
    step(bc, ops);
    step(ac, ops);
  }
}

// ---------------------------------------------------------------------------------------------------
// Triangle sets.
struct TriangleSet {
  std::string name;
  std::vector<Tri> tris;
  int width = 0, height = 0;
  double pixels_per_triangle = 0.0;
  int max_span = 0;
};

void sort_by_y(Tri& t) {
  int idx[3] = {0, 1, 2};
  std::sort(idx, idx + 3, [&](int a, int b) { return t.y[a] != t.y[b] ? t.y[a] < t.y[b] : t.x[a] < t.x[b]; });
  Tri s = t;
  for (int v = 0; v < 3; ++v) {
    s.x[v] = t.x[idx[v]];
    s.y[v] = t.y[idx[v]];
    for (int c = 0; c < 3; ++c) s.c[v][c] = t.c[idx[v]][c];
  }
  t = s;
}

// Pixels and longest span (k) of a set, from the same edge walk (a counting pass).
struct SpanCount {
  std::uint64_t adds = 0;  // 3 per pixel after each span's first
  int max_k = 0;
  void add(Stage s, int n) {
    if (s != kSpanPoints) return;
    adds += std::uint64_t(n);
    max_k = std::max(max_k, n / 3);
  }
  void muldiv(Stage, int) {}
  void shift(Stage, int) {}
};

void measure(TriangleSet& set) {
  std::uint64_t pixels = 0;
  SpanCount ops;
  Frame frame(set.width, set.height);
  for (const Tri& t : set.tris) {
    const std::uint64_t before = ops.adds;
    shade_triangle<DoubleFormat>(t, Constant216Rule<DoubleFormat>{}, ops, frame);
    pixels += (ops.adds - before) / 3 + std::uint64_t(t.y[2] - t.y[0] + 1);  // one span per row
  }
  set.pixels_per_triangle = double(pixels) / double(set.tris.size());
  set.max_span = ops.max_k;
}

float random_level(std::mt19937& rng) { return std::uniform_real_distribution<float>(16.0f, 239.0f)(rng); }

// Random triangles with vertices in a box_w x box_h box, twice the area in [area2_min, area2_max],
// placed at random in the frame.
TriangleSet random_set(const std::string& name, int count, int box_w, int box_h, int area2_min, int area2_max,
                       int frame_w, int frame_h, unsigned seed) {
  TriangleSet set;
  set.name = name;
  set.width = frame_w;
  set.height = frame_h;
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> bx(0, box_w), by(0, box_h), ox(1, frame_w - box_w - 2),
      oy(1, frame_h - box_h - 2);
  while (int(set.tris.size()) < count) {
    Tri t;
    for (int v = 0; v < 3; ++v) {
      t.x[v] = bx(rng);
      t.y[v] = by(rng);
    }
    const int area2 = std::abs((t.x[1] - t.x[0]) * (t.y[2] - t.y[0]) - (t.x[2] - t.x[0]) * (t.y[1] - t.y[0]));
    if (area2 < area2_min || area2 > area2_max) continue;
    const int dx = ox(rng), dy = oy(rng);
    for (int v = 0; v < 3; ++v) {
      t.x[v] += dx;
      t.y[v] += dy;
      for (int c = 0; c < 3; ++c) t.c[v][c] = random_level(rng);
    }
    sort_by_y(t);
    set.tris.push_back(t);
  }
  measure(set);
  return set;
}

// The source's example: A = (0, 0), B = (-7, 8), C = (9, 12) (dx_AB = 7, dy_AB = 8, dx_AC = 9,
// dy_AC = 12, dx_BC = 16, dy_BC = 4).
Tri example_triangle(int ox, int oy) {
  Tri t = {{ox, ox - 7, ox + 9}, {oy, oy + 8, oy + 12}, {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}};
  return t;
}

TriangleSet example_set(int count, int frame_size, unsigned seed) {
  TriangleSet set;
  set.name = "example";
  set.width = set.height = frame_size;
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> ox(8, frame_size - 11), oy(1, frame_size - 14);
  for (int i = 0; i < count; ++i) {
    Tri t = example_triangle(ox(rng), oy(rng));
    for (int v = 0; v < 3; ++v)
      for (int c = 0; c < 3; ++c) t.c[v][c] = random_level(rng);
    set.tris.push_back(t);
  }
  measure(set);
  return set;
}

const std::vector<TriangleSet>& triangle_sets() {
  static const std::vector<TriangleSet> sets = {
      random_set("small", 4096, 16, 20, 140, 240, 64, 64, 1),
      random_set("small_1k", 4096, 16, 20, 140, 240, 1024, 1024, 1),
      random_set("medium", 512, 64, 64, 1400, 2600, 128, 128, 2),
      random_set("large", 32, 256, 256, 22000, 42000, 288, 288, 3),
      example_set(4096, 64, 4),
  };
  return sets;
}

// ---------------------------------------------------------------------------------------------------
// Variants.
using ShadeFn = void (*)(const Tri&, NoCount&, Frame&);
using CountFn = void (*)(const Tri&, Count&, Frame&);

template <class F, class Rule, class Ops>
void shade_with(const Tri& t, Ops& ops, Frame& frame) {
  static const Rule rule{};
  shade_triangle<F>(t, rule, ops, frame);
}

struct Variant {
  const char* name;
  const char* baseline;  // the division variant of the same number format
  ShadeFn shade;
  CountFn count;
};

#define PARASHADE_VARIANT(name, base, F, Rule) \
  Variant { name, base, &shade_with<F, Rule, NoCount>, &shade_with<F, Rule, Count> }

const std::vector<Variant>& variants() {
  static const std::vector<Variant> v = {
      PARASHADE_VARIANT("div_double", "div_double", DoubleFormat, DivideRule<DoubleFormat>),
      PARASHADE_VARIANT("recip_double", "div_double", DoubleFormat, ReciprocalRule),
      PARASHADE_VARIANT("const216_double", "div_double", DoubleFormat, Constant216Rule<DoubleFormat>),
      PARASHADE_VARIANT("const215_double", "div_double", DoubleFormat, Constant215Rule<DoubleFormat>),
      PARASHADE_VARIANT("div_float", "div_float", FloatFormat, DivideRule<FloatFormat>),
      PARASHADE_VARIANT("const216_float", "div_float", FloatFormat, Constant216Rule<FloatFormat>),
      PARASHADE_VARIANT("const215_float", "div_float", FloatFormat, Constant215Rule<FloatFormat>),
      PARASHADE_VARIANT("div_fixed", "div_fixed", FixedFormat, DivideRule<FixedFormat>),
      PARASHADE_VARIANT("shiftadd8_fixed", "div_fixed", FixedFormat, ShiftAddRule),
      PARASHADE_VARIANT("shiftadd8masked_fixed", "div_fixed", FixedFormat, ShiftAddMaskedRule),
      PARASHADE_VARIANT("shiftadd8mul_fixed", "div_fixed", FixedFormat, ShiftAddMulRule),
      PARASHADE_VARIANT("const216_fixed", "div_fixed", FixedFormat, Constant216Rule<FixedFormat>),
      PARASHADE_VARIANT("const215_fixed", "div_fixed", FixedFormat, Constant215Rule<FixedFormat>),
  };
  return v;
}

void span_benchmark(benchmark::State& state, const TriangleSet* set, const Variant* variant) {
  Frame frame(set->width, set->height);
  NoCount ops;
  for (auto _ : state) {
    for (const Tri& t : set->tris) variant->shade(t, ops, frame);
    benchmark::DoNotOptimize(frame.rgb.data());
    benchmark::ClobberMemory();
  }
  const double n = double(set->tris.size());
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(n));
  state.counters["triangles"] = n;
  state.counters["px_per_tri"] = set->pixels_per_triangle;
  state.counters["max_span"] = set->max_span;
}

void register_all() {
  for (const TriangleSet& set : triangle_sets())
    for (const Variant& v : variants())
      benchmark::RegisterBenchmark(("span/" + set.name + "/" + v.name).c_str(),
                                   [&set, &v](benchmark::State& st) { span_benchmark(st, &set, &v); })
          ->Unit(benchmark::kMicrosecond);
}

// ---------------------------------------------------------------------------------------------------
// Ratios within the run, per triangle, from CPU time (a shared machine preempts the process: real time
// then counts other processes' work). Two estimators over the repetitions: the minimum (interference only
// adds time) and the median.
class RatioReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& r : runs) {
      const bool median = r.run_type == Run::RT_Aggregate && r.aggregate_name == "median";
      if (r.error_occurred || (r.run_type != Run::RT_Iteration && !median)) continue;
      const auto tri = r.counters.find("triangles");
      if (tri == r.counters.end()) continue;
      const double seconds = r.GetAdjustedCPUTime() / benchmark::GetTimeUnitMultiplier(r.time_unit);
      // Runs, or (with --benchmark_report_aggregates_only) only their median.
      (median ? medians_ : times_)[r.run_name.function_name].push_back(seconds / tri->second.value * 1e9);
    }
  }

  void print_ratios() const {
    if (times_.empty() && medians_.empty()) return;
    std::printf("\nCPU time per triangle (ns) over the repetitions, and the speed-up over the division variant of "
                "the same format\n(div_double for recip_double). Claims: constant increment 1.7x, shift-add 1.43x.\n");
    std::printf("%-38s %4s | %9s %8s %8s | %9s %8s %8s\n", "benchmark", "reps", "min ns", "vs div", "vs dbl",
                "median ns", "vs div", "vs dbl");
    for (const TriangleSet& set : triangle_sets())
      for (const Variant& v : variants()) {
        const std::string name = "span/" + set.name + "/" + v.name;
        const Stats t = stats(name);
        if (t.n == 0) continue;
        const Stats base = stats("span/" + set.name + "/" + v.baseline), dbl = stats("span/" + set.name + "/div_double");
        std::printf("%-38s %4d | %9.1f %8s %8s | %9.1f %8s %8s\n", name.c_str(), t.n, t.min, ratio(base.min, t.min).c_str(),
                    ratio(dbl.min, t.min).c_str(), t.median, ratio(base.median, t.median).c_str(),
                    ratio(dbl.median, t.median).c_str());
      }
  }

 private:
  struct Stats {
    int n = 0;
    double min = -1.0, median = -1.0;
  };
  Stats stats(const std::string& name) const {
    std::vector<double> v;
    for (const auto* m : {&times_, &medians_}) {
      const auto it = m->find(name);
      if (it != m->end() && !it->second.empty()) {
        v = it->second;
        break;
      }
    }
    Stats s;
    if (v.empty()) return s;
    std::sort(v.begin(), v.end());
    const std::size_t m = v.size() / 2;
    s.n = int(v.size());
    s.min = v.front();
    s.median = v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
    return s;
  }
  static std::string ratio(double base, double t) {
    if (base <= 0 || t <= 0) return "-";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2fx", base / t);
    return buf;
  }
  std::map<std::string, std::vector<double>> times_, medians_;
};

// ---------------------------------------------------------------------------------------------------
// --print-table: Table 1 of [Romanyuk & Obidnyk 2011, faster shading] and its claims.
struct PrintedRow {
  int k;
  const char* terms;
  double error;
  double rel_percent;
};
// As printed in the source (OCR read back from the figures; "1/16" etc. restored from the layout).
const PrintedRow kSourceTable1[] = {
    {2, "1/2", 0, 0},
    {3, "1/4 + 1/16 + 1/64 + 1/256", -0.3320, -0.39},
    {4, "1/4", 0, 0},
    {5, "1/8 + 1/16 + 1/128 + 1/256", -0.1992, -0.39},
    {6, "1/8 + 1/32 + 1/128 + 1/256", 0.3320, 0.78},
    {7, "1/8 + 1/64 + 1/256", 0.4269, 1.17},
    {8, "1/8", 0, 0},
    {9, "1/16 + 1/32 + 1/64", -0.4427, -1.56},
    {10, "1/16 + 1/32 + 1/128", 0.3984, 1.56},
    {11, "1/16 + 1/64 + 1/128 + 1/256", -0.2716, -1.17},
    {12, "1/16 + 1/64 + 1/256", -0.3320, -1.56},
    {13, "1/16 + 1/64", 0.3065, 1.56},
    {14, "1/16 + 1/128", -0.2846, -1.56},
    {15, "1/16 + 1/256", -0.0664, -0.39},
    {16, "1/16", 0, 0},
};

const char* mode_name(ReciprocalRounding r) { return r == ReciprocalRounding::nearest ? "nearest" : "truncate"; }

void print_table() {
  using R = ReciprocalRounding;
  std::printf("Table 1 of [Romanyuk & Obidnyk 2011, faster shading] recomputed: k = 2..16, n = 8, dI for a 0 -> 255 ramp over k pixels\n"
              "(error = dI_approx - dI_exact, as the source prints it; 'adds' = adder activations, i_j = 1)\n\n");
  std::printf("%3s | %-28s %8s %6s | %-28s %9s %8s %7s %4s | %-28s %9s %7s %4s\n", "k", "source: terms", "error",
              "rel%", "nearest at bit 8: terms", "dI", "error", "rel%", "adds", "truncated: terms", "error", "rel%",
              "adds");
  const auto near = division_error_table(2, 16, 8, R::nearest);
  const auto trunc = division_error_table(2, 16, 8, R::truncate);
  int agree_near = 0, agree_trunc = 0;
  for (std::size_t i = 0; i < near.size(); ++i) {
    const PrintedRow& s = kSourceTable1[i];
    const DivisionErrorRow &a = near[i], &b = trunc[i];
    const bool an = a.reciprocal.terms() == s.terms && std::abs(a.abs_error - s.error) < 1e-4;
    const bool bt = b.reciprocal.terms() == s.terms && std::abs(b.abs_error - s.error) < 1e-4;
    agree_near += an;
    agree_trunc += bt;
    std::printf("%3d | %-28s %8.4f %6.2f | %-28s %9.4f %8.4f %7.3f %4d | %-28s %9.4f %7.3f %4d%s\n", s.k, s.terms,
                s.error, s.rel_percent, a.reciprocal.terms().c_str(), a.approx, a.abs_error, 100 * a.rel_error,
                a.reciprocal.adds(), b.reciprocal.terms().c_str(), b.abs_error, 100 * b.rel_error,
                b.reciprocal.adds(), bt ? "" : "  <- truncation differs from the source");
  }
  std::printf("\nRows matching the source (terms, and error within 1e-4): nearest %d/15, truncated %d/15\n", agree_near,
              agree_trunc);

  std::printf("\nSource's claims for n = 8, k = 2..16: max |error of dI| 0.4427, mean relative error 0.81 %%\n");
  std::printf("%-9s %3s | %9s %5s | %13s %17s %9s %9s %9s\n", "rounding", "n", "max|err|", "at k", "mean|rel|% all",
              "mean|rel|% inexact", "max|rel|%", "mean adds", "max adds");
  for (int n = 4; n <= 12; ++n)
    for (R mode : {R::nearest, R::truncate}) {
      const DivisionErrorSummary s = summarize(division_error_table(2, 16, n, mode));
      const bool hit_max = std::abs(s.max_abs_error - 0.4427) < 5e-5;
      const bool hit_mean = std::abs(100 * s.mean_rel_error - 0.81) < 0.005 ||
                            std::abs(100 * s.mean_rel_error_inexact - 0.81) < 0.005;
      std::printf("%-9s %3d | %9.4f %5d | %13.3f %17.3f %9.3f %9.2f %9d%s%s\n", mode_name(mode), n, s.max_abs_error,
                  s.k_at_max_abs, 100 * s.mean_rel_error, 100 * s.mean_rel_error_inexact, 100 * s.max_rel_error,
                  s.mean_adds, s.max_adds, hit_max ? "  <- 0.4427" : "", hit_mean ? "  <- 0.81 %" : "");
    }

  std::printf("\nSource's figure 2 (relative error per k for n = 6, 7, 8), rounded to nearest, %%:\n   k:");
  for (int k = 2; k <= 16; ++k) std::printf(" %6d", k);
  std::printf("\n");
  for (int n = 6; n <= 8; ++n) {
    std::printf("n = %d:", n);
    for (const DivisionErrorRow& r : division_error_table(2, 16, n, R::nearest)) std::printf(" %6.2f", 100 * r.rel_error);
    std::printf("\n");
  }

  std::printf("\nExtension: spans k = 2..K, dI for 0 -> 255. 'end' = k * |error of dI|: the intensity error the\n"
              "accumulation reaches at the far end of the span (levels), worst over k.\n");
  std::printf("%-9s %3s %5s | %9s %5s | %9s %10s %6s | %9s %6s | %9s %8s\n", "rounding", "n", "K", "max|err|",
              "at k", "max end", "mean|rel|%", "", "max|rel|%", "at k", "mean adds", "max adds");
  for (R mode : {R::nearest, R::truncate})
    for (int n : {6, 8, 10, 12, 16, 20, 24})
      for (int K : {16, 64, 256, 4096}) {
        if (n != 8 && K != 4096 && !(K == 16 && n <= 12)) continue;
        const auto rows = division_error_table(2, K, n, mode);
        const DivisionErrorSummary s = summarize(rows);
        double max_end = 0.0;
        for (const DivisionErrorRow& r : rows) max_end = std::max(max_end, std::abs(r.abs_error) * r.reciprocal.k);
        std::printf("%-9s %3d %5d | %9.4f %5d | %9.4f %10.3f %6s | %9.3f %6d | %9.2f %8d\n", mode_name(mode), n, K,
                    s.max_abs_error, s.k_at_max_abs, max_end, 100 * s.mean_rel_error, "", 100 * s.max_rel_error,
                    s.k_at_max_rel, s.mean_adds, s.max_adds);
      }

  std::printf("\nFewest digits n (rounded) so that every k = 2..K keeps |rel error| <= 1.5625 %% (the source's worst"
              " case at n = 8, k <= 16)\nand so that the span-end error k * |error of dI| of a 0 -> 255 ramp stays "
              "below half a level:\n");
  std::printf("%6s %14s %18s\n", "K", "rel <= 1.5625%", "span end < 0.5");
  for (int K : {16, 64, 256, 1024, 4096}) {
    int n_rel = 0, n_end = 0;
    for (int n = 1; n <= kMaxShiftAddBits && (!n_rel || !n_end); ++n) {
      const auto rows = division_error_table(2, K, n, R::nearest);
      double max_rel = 0.0, max_end = 0.0;
      for (const DivisionErrorRow& r : rows) {
        max_rel = std::max(max_rel, std::abs(r.rel_error));
        max_end = std::max(max_end, std::abs(r.abs_error) * r.reciprocal.k);
      }
      if (!n_rel && max_rel <= 0.015625 + 1e-15) n_rel = n;
      if (!n_end && max_end < 0.5) n_end = n;
    }
    std::printf("%6d %14d %18d\n", K, n_rel, n_end);
  }
}

// ---------------------------------------------------------------------------------------------------
// --print-ops: operation counts for the source's example triangle, and each variant's pixel error.
void print_ops() {
  // Intensities 0..255 spread over the vertices; counts do not depend on them.
  Tri t = example_triangle(20, 2);
  const float levels[3][3] = {{40, 200, 90}, {230, 60, 120}, {100, 150, 250}};
  std::memcpy(t.c, levels, sizeof levels);
  sort_by_y(t);
  std::printf("Operations on intensities for the source's example triangle A=(0,0), B=(-7,8), C=(9,12)\n"
              "(3 channels; one span per row, rows %d, spans with k >= 1 need an increment). Source's Table 2:\n"
              "edge increments 18 add/sub + 9 mul/div, edge points 99, span increments 66 + 33, span points 225;\n"
              "total 408 add/sub, 42 mul/div. Shift-add: 'adds' are adder activations (i_j = 1).\n\n",
              t.y[2] - t.y[0] + 1);
  std::printf("%-22s", "variant");
  for (int s = 0; s < kStages; ++s) std::printf(" | %-21s", kStageNames[s]);
  std::printf(" | %-17s\n%-22s", "total", "");
  for (int s = 0; s <= kStages; ++s) std::printf(" | %6s %6s %7s", "add", "mul/div", "shift");
  std::printf("\n");
  for (const Variant& v : variants()) {
    Frame frame(64, 32);
    Count ops;
    v.count(t, ops, frame);
    std::uint64_t add = 0, md = 0, sh = 0;
    std::printf("%-22s", v.name);
    for (int s = 0; s < kStages; ++s) {
      std::printf(" | %6llu %6llu %7llu", (unsigned long long)ops.add_[s], (unsigned long long)ops.muldiv_[s],
                  (unsigned long long)ops.shift_[s]);
      add += ops.add_[s], md += ops.muldiv_[s], sh += ops.shift_[s];
    }
    std::printf(" | %6llu %6llu %7llu\n", (unsigned long long)add, (unsigned long long)md, (unsigned long long)sh);
  }
  {
    SpanCount pc;
    Frame frame(64, 32);
    shade_triangle<DoubleFormat>(t, Constant216Rule<DoubleFormat>{}, pc, frame);
    std::printf("\nThe example triangle covers %llu pixels in this edge walk (area 78), longest span k = %d.\n",
                (unsigned long long)(pc.adds / 3 + std::uint64_t(t.y[2] - t.y[0] + 1)), pc.max_k);
  }

  // The benchmark's shift-add loops against the library's hardware model.
  {
    const ShiftAddRule ones;
    const ShiftAddMaskedRule masked;
    NoCount none;
    long long mismatches = 0, checked = 0;
    for (int k = 1; k <= kMaxSpan; ++k)
      for (std::int32_t d = -(255 << kFrac); d <= (255 << kFrac); d += 4099) {
        const std::int32_t diff[3] = {d, -d, d / 3};
        std::int32_t a[3], b[3];
        ones.span(diff, k, a, none);
        masked.span(diff, k, b, none);
        const ShiftAddReciprocal r = shift_add_reciprocal(k, kShiftAddBits, ReciprocalRounding::nearest);
        for (int c = 0; c < 3; ++c) {
          const std::int64_t want = shift_add_divide(diff[c], r).value;
          mismatches += (a[c] != want) + (b[c] != want);
          checked += 2;
        }
      }
    std::printf("Benchmark's shift-add loops vs shift_add_divide (k = 1..%d, differences over +-255 levels): "
                "%lld mismatches in %lld\n",
                kMaxSpan, mismatches, checked);
  }

  // Pixel error: against the classic method in double (div_double) and against the exact plane through the
  // vertices at each pixel (the value the constant increment reproduces), 8-bit truncated levels.
  std::printf("\nPixel error per variant (levels, 8-bit truncated; max / mean over covered channel samples):\n");
  std::printf("%-22s", "variant");
  for (const TriangleSet& set : triangle_sets()) std::printf(" | %-27s", set.name.c_str());
  std::printf("\n%-22s", "");
  for (std::size_t i = 0; i < triangle_sets().size(); ++i) std::printf(" | %13s %13s", "vs classic", "vs plane");
  std::printf("\n");
  for (const Variant& v : variants()) {
    std::printf("%-22s", v.name);
    for (const TriangleSet& set : triangle_sets()) {
      double max_c = 0, sum_c = 0, max_p = 0, sum_p = 0;
      std::uint64_t n = 0;
      // One triangle at a time so overlaps do not hide errors.
      for (std::size_t ti = 0; ti < set.tris.size(); ti += std::max<std::size_t>(1, set.tris.size() / 256)) {
        const Tri& tri = set.tris[ti];
        const int x0 = std::min({tri.x[0], tri.x[1], tri.x[2]}), y0 = tri.y[0];
        Tri local = tri;
        for (int k = 0; k < 3; ++k) {
          local.x[k] -= x0 - 1;
          local.y[k] -= y0 - 1;
        }
        const int w = std::max({local.x[0], local.x[1], local.x[2]}) + 3, h = local.y[2] + 3;
        Frame classic(w, h), mine(w, h), mask(w, h);
        NoCount none;
        shade_with<DoubleFormat, DivideRule<DoubleFormat>, NoCount>(local, none, classic);
        v.shade(local, none, mine);
        // Coverage: all 255.
        Tri white = local;
        for (auto& vc : white.c)
          for (float& c : vc) c = 255.0f;
        shade_with<DoubleFormat, DivideRule<DoubleFormat>, NoCount>(white, none, mask);
        const ConstantSpanIncrement plane_dx(pos(local, 0), pos(local, 1), pos(local, 2));
        for (int y = 0; y < h; ++y)
          for (int x = 0; x < w; ++x) {
            if (mask.at(x, y)[0] == 0) continue;
            for (int c = 0; c < 3; ++c) {
              // Exact plane: I = I_A + dI/dx (x - x_A) + dI/dy (y - y_A), dI/dy from the same formula with
              // x and y swapped.
              const auto swap = [](glm::dvec2 p) { return glm::dvec2(p.y, p.x); };
              const double gx = plane_dx(local.c[0][c], local.c[1][c], local.c[2][c]);
              const double gy = ConstantSpanIncrement(swap(pos(local, 0)), swap(pos(local, 1)), swap(pos(local, 2)))(
                  local.c[0][c], local.c[1][c], local.c[2][c]);
              const double plane = local.c[0][c] + gx * (x - local.x[0]) + gy * (y - local.y[0]);
              const double m = mine.at(x, y)[c];
              const double dc = std::abs(m - classic.at(x, y)[c]), dp = std::abs(m - std::floor(plane));
              max_c = std::max(max_c, dc), sum_c += dc, max_p = std::max(max_p, dp), sum_p += dp;
              ++n;
            }
          }
      }
      std::printf(" | %6.0f %6.3f %6.0f %6.3f", max_c, sum_c / double(n), max_p, sum_p / double(n));
    }
    std::printf("\n");
  }
  std::printf("\nTriangle sets:");
  for (const TriangleSet& set : triangle_sets())
    std::printf(" %s: %zu triangles, %.1f pixels each, longest span %d;", set.name.c_str(), set.tris.size(),
                set.pixels_per_triangle, set.max_span);
  std::printf("\n");
}

}  // namespace
}  // namespace parashade

int main(int argc, char** argv) {
  bool table = false, ops = false;
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--print-table") == 0) table = true;
    else if (std::strcmp(argv[i], "--print-ops") == 0) ops = true;
    else argv[kept++] = argv[i];
  }
  argc = kept;
  if (table || ops) {
    if (table) parashade::print_table();
    if (table && ops) std::printf("\n");
    if (ops) parashade::print_ops();
    return 0;
  }
  benchmark::Initialize(&argc, argv);
  parashade::add_schema_context();
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
  parashade::register_all();
  parashade::RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  reporter.print_ratios();
  benchmark::Shutdown();
  return 0;
}
