// Unit normals along a span ([Dembitsky 2025, software/hardware rendering] ch. 2): exact, slerp, dichotomy, quadratic, spherical-angular
// recurrence, and the polynomial approximations they use. Coefficients: docs/phong-methods.md, where
// the "fit" ones were produced by minimax_fit (Remez) on the stated interval.
#include "parashade/normalization.hpp"

#include <algorithm>
#include <cmath>
#include <regex>
#include <stdexcept>

#include "parashade/errors.hpp"
#include "parashade/minimax.hpp"
#include "parashade/kernels/constants.h"

namespace parashade {
namespace {

constexpr double kSqrt2 = 1.41421356237309505;

// Below this 1 + na.nb the end normals count as opposite: the bisector, slerp's plane and the mid
// normal are undefined (and the exact Phong normal passes through zero).
template <typename T>
constexpr T opposite_eps() {
  return sizeof(T) == 4 ? T(1e-6) : T(1e-12);
}

template <typename T>
using V3 = glm::vec<3, T>;

// Exact Phong: normalize(na + (nb - na) w); a zero vector stays zero (the kernel shades it with
// ambient only) and counts as a fallback.
template <typename T>
V3<T> exact_normal(V3<T> na, V3<T> nb, T w, NormalizeCounters* c) {
  const V3<T> v = na + (nb - na) * w;
  const T len2 = glm::dot(v, v);
  if (!(len2 > T(0)) || !std::isfinite(len2)) {
    if (c) ++c->fallback_pixels;
    return V3<T>(0);
  }
  return v / std::sqrt(len2);
}

// sin(a x) / sin(x) for x in [0, pi), finite as x -> 0 (limit a).
template <typename T>
T sin_ratio(T a, T x) {
  if (x < T(1e-4)) return a * (T(1) - (a * a - T(1)) * x * x / T(6));
  return std::sin(a * x) / std::sin(x);
}

template <typename T>
T clamp_cos(T r) {
  return std::min(T(1), std::max(T(-1), r));
}

template <typename T>
std::vector<V3<T>> exact_span(V3<T> na, V3<T> nb, int length, NormalizeCounters* c) {
  std::vector<V3<T>> out(length);
  for (int i = 0; i < length; ++i) out[i] = exact_normal(na, nb, length > 1 ? T(i) / T(length - 1) : T(0), c);
  return out;
}

// Nearly opposite end normals: the span goes to the exact method and counts as a fallback.
template <typename T>
std::vector<V3<T>> opposite_fallback(V3<T> na, V3<T> nb, int length, NormalizeCounters* c) {
  if (c) c->fallback_pixels += static_cast<std::uint64_t>(length);
  return exact_span<T>(na, nb, length, nullptr);
}

template <typename T>
std::vector<V3<T>> slerp_span(V3<T> na, V3<T> nb, int length, NormalizeCounters* c) {
  const T r = clamp_cos(glm::dot(na, nb));
  if (T(1) + r < opposite_eps<T>()) return opposite_fallback(na, nb, length, c);
  const T theta = std::acos(r);
  std::vector<V3<T>> out(length);
  for (int i = 0; i < length; ++i) {
    const T w = length > 1 ? T(i) / T(length - 1) : T(0);
    out[i] = na * sin_ratio(T(1) - w, theta) + nb * sin_ratio(w, theta);
  }
  return out;
}

// Recursive bisection of one segment of 2^k pixels: out[0] = a, out[2^k] = b.
template <typename T>
void bisect(BisectorScale s, std::vector<V3<T>>& pts, int lo, int hi, T u) {
  if (hi - lo < 2) return;
  const int mid = (lo + hi) / 2;
  const T scale = T(bisector_scale(s, double(u)));
  pts[mid] = (pts[lo] + pts[hi]) * scale;
  const T next = std::sqrt(std::max(T(0), T(2) + u));  // 2 cos(phi/2) = sqrt(2 + 2 cos phi)
  bisect(s, pts, lo, mid, next);
  bisect(s, pts, mid, hi, next);
}

// Bisection of pts[0] .. pts[n], n = 2^k, the two ends set: the polynomials are documented for bisected
// angles <= 45 degrees (u >= sqrt 2); a wider first step is taken exactly, the rest with the chosen scale.
template <typename T>
void bisect_segment(BisectorScale s, std::vector<V3<T>>& pts, int n) {
  if (n < 2) return;
  const T u = T(2) * clamp_cos(glm::dot(pts[0], pts[n]));
  if (u < T(kSqrt2) && s != BisectorScale::exact) {
    const int mid = n / 2;
    pts[mid] = (pts[0] + pts[n]) / std::sqrt(T(2) + u);
    const T next = std::sqrt(T(2) + u);
    bisect(s, pts, 0, mid, next);
    bisect(s, pts, mid, n, next);
  } else {
    bisect(s, pts, 0, n, u);
  }
}

template <typename T>
std::vector<V3<T>> dichotomy_span(const NormalizeMethod& m, V3<T> na, V3<T> nb, int length, NormalizeCounters* c) {
  const int seg = 1 << m.segment_log2;
  std::vector<V3<T>> out(length);
  std::vector<V3<T>> pts(seg + 1);
  const T denom = length > 1 ? T(length - 1) : T(1);
  out[0] = na;
  for (int start = 0; start < length - 1; start += seg) {
    const int last = length - 1;
    // A whole segment, or the source's rule for the last one: 2^k long, its end extrapolated.
    const bool whole = start + seg <= last || m.extrapolate_last;
    const int steps = whole ? seg : last - start;       // pixels from the segment's start to its end
    // A partial segment whose length is no power of two is bisected three levels finer than it needs,
    // so the nearest dyadic point is within phi/(16 steps) of the pixel's own.
    int levels = 0;
    while ((1 << levels) < steps) ++levels;
    if ((1 << levels) != steps) levels += 3;
    const int n = whole ? seg : 1 << levels;           // dyadic points of the bisection
    if (static_cast<int>(pts.size()) < n + 1) pts.resize(n + 1);
    NormalizeCounters ends;
    pts[0] = exact_normal(na, nb, T(start) / denom, &ends);
    pts[n] = exact_normal(na, nb, T(start + steps) / denom, &ends);
    const int count = std::min(seg, last - start);      // pixels start+1 .. start+count are written here
    if (ends.fallback_pixels || T(1) + clamp_cos(glm::dot(pts[0], pts[n])) < T(2) * opposite_eps<T>()) {
      for (int i = 1; i <= count; ++i) out[start + i] = exact_normal(na, nb, T(start + i) / denom, nullptr);
      if (c) c->fallback_pixels += static_cast<std::uint64_t>(count);
      continue;
    }
    bisect_segment(m.bisector, pts, n);
    // Pixel start + i sits at i/steps of the segment: dyadic point i n / steps (exact when steps = n,
    // else the nearest one).
    for (int i = 1; i <= count; ++i) out[start + i] = pts[(2 * i * n + steps) / (2 * steps)];
  }
  return out;
}

// N(t) = G t^2 + P t + Q by forward differences: additions only per pixel.
template <typename T>
std::vector<V3<T>> quadratic_span(const NormalizeMethod& m, V3<T> na, V3<T> nb, int length, NormalizeCounters* c) {
  const T r = clamp_cos(glm::dot(na, nb));
  if (T(1) + r < opposite_eps<T>()) return opposite_fallback(na, nb, length, c);
  // The fits are documented for r in [0, 1]; below, h is computed exactly.
  const T h = T(r >= T(0) ? mid_scale(m.mid, double(r)) : mid_scale(MidScale::exact, double(r)));
  const V3<T> sum = na + nb;
  const V3<T> g = sum * (T(2) * (T(1) - T(2) * h));
  const V3<T> p = sum * (T(4) * h - T(3)) + nb * T(2);
  std::vector<V3<T>> out(length);
  const T dt = length > 1 ? T(1) / T(length - 1) : T(0);
  V3<T> n = na, w = (g * dt + p) * dt;
  const V3<T> dw = g * (T(2) * dt * dt);
  for (int i = 0; i < length; ++i) {
    out[i] = n;
    n += w;
    w += dw;
  }
  return out;
}

template <typename T>
std::vector<V3<T>> recurrence_span(const NormalizeMethod& m, V3<T> na, V3<T> nb, int length, NormalizeCounters* c) {
  const T r = clamp_cos(glm::dot(na, nb));
  if (T(1) + r < opposite_eps<T>()) return opposite_fallback(na, nb, length, c);
  if (length <= 2) return slerp_span(na, nb, length, c);
  const T theta = T(arccos_approx(m.arccos, double(r)));
  const T step = theta / T(length - 1), two_cos = T(2) * std::cos(step);
  // Anchors (pixels k R and k R + 1) from slerp with the table's theta: what a unit restarting the
  // recurrence would load.
  auto anchor = [&](int i) {
    const T w = T(i) / T(length - 1);
    return na * sin_ratio(T(1) - w, theta) + nb * sin_ratio(w, theta);
  };
  std::vector<V3<T>> out(length);
  const int every = m.reanchor > 1 ? m.reanchor : length;
  const T half = std::sin(step / T(2)), k = T(4) * half * half;  // 2 - 2 cos(step), without cancellation
  V3<T> d(0);
  for (int i = 0; i < length; ++i) {
    if (i % every == 0 || i % every == 1) {
      out[i] = anchor(i);
      if (i % every == 1) d = out[i] - out[i - 1];
    } else if (m.difference_form) {
      d -= out[i - 1] * k;
      out[i] = out[i - 1] + d;
    } else {
      out[i] = out[i - 1] * two_cos - out[i - 2];
    }
  }
  return out;
}

const std::vector<PolyApprox> kBisector = {
    {"linear_source", {0.64, -0.07}, kSqrt2, 2.0},
    {"quadratic_source", {0.681, -0.119, 0.014}, kSqrt2, 2.0},
    {"linear_fit", {0.640040939, -0.0703261419}, kSqrt2, 2.0},
    {"quadratic_fit", {0.680849766, -0.118921801, 0.0142534992}, kSqrt2, 2.0},
};
const std::vector<PolyApprox> kMid = {
    {"quadratic_fit", {0.705190045, -0.31033697, 0.107063661}, 0.0, 1.0},
    {"cubic_source", {0.707, -0.341, 0.193, -0.059}, 0.0, 1.0},
    {"cubic_fit", {0.706818541, -0.342553233, 0.196821778, -0.0613753257}, 0.0, 1.0},
};
// Table 3.1 of [Dembitsky 2025, software/hardware rendering] as printed, columns read as C + B x + A x^2.
const std::vector<PolyApprox> kArccosSource = {
    {"0-0.5", {1.57, -0.972, -0.144}, 0.0, 0.5},
    {"0.5-0.75", {1.439, -0.447, -0.677}, 0.5, 0.75},
    {"0.75-0.9", {0.454, 2.154, -2.397}, 0.75, 0.9},
    {"0.9-0.96", {-5.529, 15.47, -9.806}, 0.9, 0.96},
    {"0.96-1", {-33.838, 74.547, -40.535}, 0.96, 1.0},
};
// Relative-error minimax quadratics on the same intervals; the last is sqrt(1 - x) q(x), because a
// polynomial in x cannot follow acos(x) ~ sqrt(2 (1 - x)) to a small relative error near x = 1.
const std::vector<PolyApprox> kArccosFixed = {
    {"0-0.5", {1.56967418, -0.966445134, -0.154023842}, 0.0, 0.5},
    {"0.5-0.75", {1.42897092, -0.412448371, -0.704801676}, 0.5, 0.75},
    {"0.75-0.9", {0.351904584, 2.4039881, -2.54792052}, 0.75, 0.9},
    {"0.9-0.96", {-6.04446671, 16.5781328, -10.4018351}, 0.9, 0.96},
    {"0.96-1 (sqrt(1-x) q(x))", {1.55905524, -0.17183946, 0.0269977955}, 0.96, 1.0},
};

// Piece i of the table at a in [0, 1] (the last piece of the fixed table is sqrt(1 - a) q(a)), clamped at 0.
double table_piece(const std::vector<PolyApprox>& table, std::size_t i, double a, bool sqrt_last) {
  double v = eval_poly(table[i].coeffs, a);
  if (sqrt_last && i + 1 == table.size()) v *= std::sqrt(1.0 - a);
  return std::max(0.0, v);
}

double table_arccos(const std::vector<PolyApprox>& table, double x, bool sqrt_last) {
  const double a = std::fabs(std::min(1.0, std::max(-1.0, x)));
  double v = 0.0;
  for (std::size_t i = 0; i < table.size(); ++i) {
    if (a <= table[i].hi || i + 1 == table.size()) {
      v = table_piece(table, i, a, sqrt_last);
      break;
    }
  }
  return x < 0 ? 3.14159265358979323846 - v : v;  // acos(-x) = pi - acos(x)
}

}  // namespace

double bisector_scale(BisectorScale s, double u) {
  switch (s) {
    case BisectorScale::exact: return 1.0 / std::sqrt(std::max(2.0 + u, 1e-300));
    case BisectorScale::linear_source: return eval_poly(kBisector[0].coeffs, u);
    case BisectorScale::quadratic_source: return eval_poly(kBisector[1].coeffs, u);
    case BisectorScale::linear_fit: return eval_poly(kBisector[2].coeffs, u);
    case BisectorScale::quadratic_fit: return eval_poly(kBisector[3].coeffs, u);
  }
  return 0.0;
}

double mid_scale(MidScale s, double r) {
  switch (s) {
    case MidScale::exact: return 1.0 / std::sqrt(std::max(2.0 * (1.0 + r), 1e-300));
    case MidScale::quadratic_fit: return eval_poly(kMid[0].coeffs, r);
    case MidScale::cubic_source: return eval_poly(kMid[1].coeffs, r);
    case MidScale::cubic_fit: return eval_poly(kMid[2].coeffs, r);
  }
  return 0.0;
}

double arccos_approx(Arccos a, double x) {
  switch (a) {
    case Arccos::exact: return std::acos(std::min(1.0, std::max(-1.0, x)));
    case Arccos::table_source: return table_arccos(kArccosSource, x, false);
    case Arccos::table_fixed: return table_arccos(kArccosFixed, x, true);
  }
  return 0.0;
}

double arccos_piece(Arccos a, std::size_t piece, double x) {
  const bool fixed = a == Arccos::table_fixed;
  const std::vector<PolyApprox>& table = fixed ? kArccosFixed : kArccosSource;
  if (a == Arccos::exact || piece >= table.size()) throw std::invalid_argument("arccos_piece: no such table piece");
  return table_piece(table, piece, std::min(1.0, std::max(0.0, x)), fixed);
}

const std::vector<PolyApprox>& bisector_polys() { return kBisector; }
const std::vector<PolyApprox>& mid_polys() { return kMid; }
const std::vector<PolyApprox>& arccos_table_source() { return kArccosSource; }
const std::vector<PolyApprox>& arccos_table_fixed() { return kArccosFixed; }

template <typename T>
std::vector<V3<T>> span_normals(const NormalizeMethod& m, V3<T> na, V3<T> nb, int length, NormalizeCounters* c) {
  if (length < 1) return {};
  if (c) c->pixels += static_cast<std::uint64_t>(length);
  switch (m.kind) {
    case NormalizeKind::exact: return exact_span(na, nb, length, c);
    case NormalizeKind::slerp: return slerp_span(na, nb, length, c);
    case NormalizeKind::dichotomy: return dichotomy_span(m, na, nb, length, c);
    case NormalizeKind::quadratic: return quadratic_span(m, na, nb, length, c);
    case NormalizeKind::recurrence: return recurrence_span(m, na, nb, length, c);
  }
  return {};
}

template <typename T>
std::vector<T> recurrence_dots(T d0, T d1, T cos_step, int length) {
  std::vector<T> d(std::max(length, 0));
  for (int i = 0; i < length; ++i) d[i] = i == 0 ? d0 : i == 1 ? d1 : T(2) * cos_step * d[i - 1] - d[i - 2];
  return d;
}

template <typename T>
std::vector<T> recurrence_dots_difference(T d0, T d1, T k, int length) {
  std::vector<T> d(std::max(length, 0));
  T e = d1 - d0;
  for (int i = 0; i < length; ++i) {
    if (i < 2) {
      d[i] = i == 0 ? d0 : d1;
      continue;
    }
    e -= k * d[i - 1];
    d[i] = d[i - 1] + e;
  }
  return d;
}

template std::vector<float> recurrence_dots_difference(float, float, float, int);
template std::vector<double> recurrence_dots_difference(double, double, double, int);
template std::vector<V3<float>> span_normals(const NormalizeMethod&, V3<float>, V3<float>, int, NormalizeCounters*);
template std::vector<V3<double>> span_normals(const NormalizeMethod&, V3<double>, V3<double>, int, NormalizeCounters*);
template std::vector<float> recurrence_dots(float, float, float, int);
template std::vector<double> recurrence_dots(double, double, double, int);

NormalizeMethod parse_normalize(const std::string& text) {
  std::smatch g;
  NormalizeMethod m;
  static const std::regex re(
      R"((exact|slerp)|dichotomy:(exact|linear|quadratic|linear-fit|quadratic-fit)(?::(\d))?(:extrapolate)?|quadratic:(exact|quad|cubic|cubic-fit)|recurrence(-diff)?(?::(exact|table|table-fixed))?(?::(\d{1,5}))?)");
  if (!std::regex_match(text, g, re))
    throw UsageError("normalization '" + text +
                     "': expected exact, slerp, dichotomy:exact|linear|quadratic|linear-fit|quadratic-fit[:K][:extrapolate], "
                     "quadratic:exact|quad|cubic|cubic-fit or recurrence[-diff][:exact|table|table-fixed][:R]");
  if (g[1].matched) {
    m.kind = g[1] == "exact" ? NormalizeKind::exact : NormalizeKind::slerp;
  } else if (g[2].matched) {
    m.kind = NormalizeKind::dichotomy;
    const std::string s = g[2];
    m.bisector = s == "exact"       ? BisectorScale::exact
                 : s == "linear"    ? BisectorScale::linear_source
                 : s == "quadratic" ? BisectorScale::quadratic_source
                 : s == "linear-fit" ? BisectorScale::linear_fit
                                     : BisectorScale::quadratic_fit;
    if (g[3].matched) {
      m.segment_log2 = std::stoi(g[3]);
      if (m.segment_log2 < 1 || m.segment_log2 > MAX_DICHOTOMY_SEGMENT_LOG2)
        throw UsageError("normalization '" + text + "': segment size 2^K needs K in 1.." +
                         std::to_string(MAX_DICHOTOMY_SEGMENT_LOG2));
    }
    m.extrapolate_last = g[4].matched;
  } else if (g[5].matched) {
    m.kind = NormalizeKind::quadratic;
    const std::string s = g[5];
    m.mid = s == "exact" ? MidScale::exact : s == "quad" ? MidScale::quadratic_fit : s == "cubic" ? MidScale::cubic_source
                                                                                                 : MidScale::cubic_fit;
  } else {
    m.kind = NormalizeKind::recurrence;
    m.difference_form = g[6].matched;
    const std::string s = g[7].matched ? std::string(g[7]) : "exact";
    m.arccos = s == "exact" ? Arccos::exact : s == "table" ? Arccos::table_source : Arccos::table_fixed;
    if (g[8].matched) {
      m.reanchor = std::stoi(g[8]);
      if (m.reanchor < 2) throw UsageError("normalization '" + text + "': re-anchor period R needs R >= 2");
    }
  }
  return m;
}

std::string normalize_name(const NormalizeMethod& m) {
  switch (m.kind) {
    case NormalizeKind::exact: return "exact";
    case NormalizeKind::slerp: return "slerp";
    case NormalizeKind::dichotomy: {
      const char* s[] = {"exact", "linear", "quadratic", "linear-fit", "quadratic-fit"};
      return std::string("dichotomy:") + s[int(m.bisector)] + ":" + std::to_string(m.segment_log2) +
             (m.extrapolate_last ? ":extrapolate" : "");
    }
    case NormalizeKind::quadratic: {
      const char* s[] = {"exact", "quad", "cubic", "cubic-fit"};
      return std::string("quadratic:") + s[int(m.mid)];
    }
    case NormalizeKind::recurrence: {
      const char* s[] = {"exact", "table", "table-fixed"};
      return std::string(m.difference_form ? "recurrence-diff:" : "recurrence:") + s[int(m.arccos)] + (m.reanchor ? ":" + std::to_string(m.reanchor) : "");
    }
  }
  return "";
}

}  // namespace parashade
