#pragma once
// Unit normals along a span without a per-pixel normalization ([Dembitsky 2025, software/hardware rendering] ch. 2, docs/phong-methods.md).
// A span of `length` pixels runs from the unit normal na (pixel 0) to the unit normal nb (pixel
// length-1); the renderer's exact Phong normal at pixel i is normalize(na + (nb - na) w), w = i/(length-1).
// Every method writes one vector per pixel (not renormalized: the methods' own length error is part
// of their error) and never a NaN or Inf: where a method's formula breaks down (end normals nearly
// equal or nearly opposite, a zero interpolated normal) it falls back and counts the pixels it did.
// Templated on the scalar (float as the kernels, double as the reference).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace parashade {

// 1/sqrt(2 + u), u = 2 cos(phi): the scale of the bisector of two unit vectors at angle phi.
enum class BisectorScale { exact, linear_source, quadratic_source, linear_fit, quadratic_fit };
// h(r) = 1/sqrt(2 (1 + r)), r = na . nb: the mid normal N_c = h (na + nb).
enum class MidScale { exact, quadratic_fit, cubic_source, cubic_fit };
// arccos for the recurrence's step angle.
enum class Arccos { exact, table_source, table_fixed };

enum class NormalizeKind { exact, slerp, dichotomy, quadratic, recurrence };

struct NormalizeMethod {
  NormalizeKind kind = NormalizeKind::exact;
  BisectorScale bisector = BisectorScale::exact;  // dichotomy
  MidScale mid = MidScale::exact;                 // quadratic
  Arccos arccos = Arccos::exact;                  // recurrence
  int segment_log2 = 4;   // dichotomy: segments of 2^k pixels with exact ends
  // dichotomy, last (shorter) segment: false = bisect between its real ends and take the nearest dyadic
  // point per pixel; true = the source's rule ([Romanyuk & Romanyuk, combined shading]): 2^k long with an extrapolated end normal.
  bool extrapolate_last = false;
  int reanchor = 0;       // recurrence: restart from exact normals every this many pixels (0: never)
  // recurrence in difference form: N(t+1) = N(t) + D(t), D(t) = D(t-1) - k N(t), k = 4 sin^2(dtheta/2);
  // algebraically the source's recurrence, but k keeps its precision where 2 cos(dtheta) rounds to 2.
  bool difference_form = false;
};

// "exact", "slerp", "dichotomy:exact|linear|quadratic|linear-fit|quadratic-fit[:K][:extrapolate]",
// "quadratic:exact|quad|cubic|cubic-fit", "recurrence[-diff][:exact|table|table-fixed][:R]".
// Throws UsageError naming the text.
NormalizeMethod parse_normalize(const std::string& text);
std::string normalize_name(const NormalizeMethod& m);

struct NormalizeCounters {
  std::uint64_t pixels = 0;
  std::uint64_t fallback_pixels = 0;  // pixels a method gave to its fallback (zero normal, theta ~ 0 or pi)
};

template <typename T>
std::vector<glm::vec<3, T>> span_normals(const NormalizeMethod& m, glm::vec<3, T> na, glm::vec<3, T> nb, int length,
                                         NormalizeCounters* counters = nullptr);

// The recurrence d(t+1) = 2 cos(dtheta) d(t) - d(t-1) applied to a dot product with a fixed vector
// (N.L of a directional light, N.H of a distant viewer): d0 = na.v, d1 = N(1).v.
template <typename T>
std::vector<T> recurrence_dots(T d0, T d1, T cos_step, int length);
// The same in difference form: d(t+1) = d(t) + e(t), e(t) = e(t-1) - k d(t), k = 4 sin^2(dtheta/2).
template <typename T>
std::vector<T> recurrence_dots_difference(T d0, T d1, T k, int length);

// The approximations, each usable alone (the study measures them).
double bisector_scale(BisectorScale s, double u);  // ~ 1/sqrt(2+u)
double mid_scale(MidScale s, double r);            // ~ 1/sqrt(2(1+r))
double arccos_approx(Arccos a, double x);          // ~ acos(x), x in [-1, 1] (odd symmetry below 0)
// Piece `piece` of a table (table_source or table_fixed) at x in [0, 1], whichever interval x lies in: each
// interval measured by its own piece, also at the ends it shares (arccos_approx takes the lower one there).
double arccos_piece(Arccos a, std::size_t piece, double x);

// Coefficients (c0 + c1 x + c2 x^2 + ...) and the interval each is documented for.
struct PolyApprox {
  std::string name;
  std::vector<double> coeffs;
  double lo, hi;
};
const std::vector<PolyApprox>& bisector_polys();  // linear_source, quadratic_source, linear_fit, quadratic_fit
const std::vector<PolyApprox>& mid_polys();       // quadratic_fit, cubic_source, cubic_fit
// The source's arccos table 3.1 (as printed) and the fixed one: per interval of x.
const std::vector<PolyApprox>& arccos_table_source();
const std::vector<PolyApprox>& arccos_table_fixed();  // last interval: sqrt(1-x) q(x)

}  // namespace parashade
