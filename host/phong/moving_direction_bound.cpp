#include "parashade/moving_direction_bound.hpp"

#include <algorithm>
#include <cmath>

#include "parashade/combined.hpp"

namespace parashade {

double curvature_factor(double n) {
  // n (n - 1) c^(n-2) (1 - c^2) is largest at c^2 = (n - 2) / n, where it is 2 (n - 1) ((n-2)/n)^((n-2)/2);
  // n c^(n-1) is largest at c = 1. The sum of the two maxima bounds the maximum of the sum.
  if (n < 2.0) return INFINITY;
  const double x = (n - 2.0) / n;
  const double first = n == 2.0 ? 2.0 : 2.0 * (n - 1.0) * std::pow(x, 0.5 * (n - 2.0));
  return first + n;
}

double moving_term_bound(const SegmentRates& r, double n, bool specular, bool crosses_zero) {
  if (specular && !(n >= 2.0)) return 1.0;
  const double curvature = specular ? curvature_factor(n) : 1.0, slope = specular ? term_slope_bound(n) : 1.0;
  return std::min(1.0, moving_term_bound_uncapped(r, curvature, slope, specular, crosses_zero));
}

double moving_term_bound_uncapped(const SegmentRates& r, double curvature, double slope, bool specular, bool crosses_zero) {
  // The unit vectors along a line: N = normalize(N_a + s w) turns at |N'| <= |w| / |N| with tangential
  // acceleration 2 |N.w| / |N| |N'| <= 2 |N'|^2; L = normalize(P - p(s)) the same with p' constant, and
  // its whole second derivative is at most sqrt(5) |L'|^2 (tangential 2 |L'|^2, normal |L'|^2).
  double rate = r.light, accel = 2.0 * r.light * r.light;
  if (specular) {
    if (!(curvature > 0.0) || !(r.half_min > 0.0)) return INFINITY;
    // H = u / |u|, u = L + V: |H'| <= |u'| / |u|; the tangential part of H'' is P u'' / |u| - 2 H' (H.u') / |u|.
    const double moving = r.light + r.view;
    rate = moving / r.half_min;
    accel = (std::sqrt(5.0) * (r.light * r.light + r.view * r.view) + 2.0 * rate * moving) / r.half_min;
  }
  const double w = r.normal + rate, a = 2.0 * r.normal * r.normal + accel;
  // |c'| <= w sqrt(1 - c^2): N' and D' are perpendicular to N and D, and N's part across D is sqrt(1 - c^2).
  // c'' = N''.D + 2 N'.D' + N.D'': the normal parts of N'' and D'' give -(|N'|^2 + |D'|^2) c, the cross
  // term at most 2 |N'||D'|, the tangential parts at most a sqrt(1 - c^2); c <= 1 gives |c c''| <= w^2 c + a c.
  // Specular: |g''| <= w^2 curvature_factor(n) + a term_slope_bound(n) (n c^(n-1) sqrt(1 - c^2) <= slope);
  // the lit diffuse term g = c: |g''| <= w^2 + a.
  double bound = (specular ? w * w * curvature + a * slope : w * w + a) / 8.0;
  // max(0, c) = max(0, l) + (at most |c''| / 8), l the chord of c, whose kink costs |l'| / 4 <= w / 4.
  if (!specular && crosses_zero) bound += 0.25 * w;
  return bound;
}

}  // namespace parashade
