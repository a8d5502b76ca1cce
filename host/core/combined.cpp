#include "parashade/combined.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "parashade/errors.hpp"

namespace parashade {

CombinedConfig parse_combined(const std::string& text) {
  const std::string prefix = "combined:";
  CombinedConfig c;
  if (text.compare(0, prefix.size(), prefix) != 0)
    throw UsageError("'" + text + "' is not a combined method (combined:K or combined:auto)");
  const std::string arg = text.substr(prefix.size());
  if (arg == "auto") {
    c.automatic = true;
    return c;
  }
  char* end = nullptr;
  const long k = std::strtol(arg.c_str(), &end, 10);
  if (arg.empty() || *end != '\0' || k < 0 || k > kCombinedMaxK)
    throw UsageError("method '" + text + "': K must be an integer 0.." + std::to_string(kCombinedMaxK) + " or 'auto'");
  c.k = int(k);
  return c;
}

std::string combined_name(const CombinedConfig& c) {
  return c.automatic ? "combined:auto" : "combined:" + std::to_string(c.k);
}

double chord_error_bound(double phi, double n) {
  // Symmetric peak: exact 1 at the middle, chord cos^n(phi/2) (the sources' formula).
  const double peak = 1.0 - std::pow(std::cos(0.5 * phi), n);
  // A segment across the zero of the clamped term (the terminator, or N.H = 0): for n = 1 the kink
  // gives first-order error <= max_a a*sin(phi - a)/phi <= phi/4; for n < 2 (steeper or less smooth
  // zero) the looser (phi/2)^n; for n >= 2 the peak case is the worst (checked numerically).
  if (n == 1.0) return std::max(peak, 0.25 * phi);
  if (n < 2.0) return std::max(peak, std::pow(0.5 * phi, n));
  return peak;
}

double term_slope_bound(double n) {
  if (n <= 1.0) return 1.0;
  // d/dtheta cos^n = -n cos^(n-1) sin, largest at sin^2 = 1/n.
  return std::sqrt(n) * std::pow((n - 1.0) / n, 0.5 * (n - 1.0));
}

double nonuniform_angle(double phi) {
  const double t = std::tan(0.5 * phi), a = std::atan(t);
  if (!(t > 1e-6)) return 0.0;  // ~phi^3/27 below float resolution
  const double u = std::min(1.0, std::sqrt(std::max(0.0, t / a - 1.0)) / t);  // where d/du = 0
  return std::atan(u * t) - u * a;
}

double segment_term_bound(double psi, double n) {
  if (!(psi < 1.0)) return 1.0;
  const double phi = std::asin(psi);
  const double root = std::sqrt(1.0 + psi);
  const double delta = (root - 1.0) / (root + 1.0);
  // The interior normal sits at the chord parameter s' instead of s, |s' - s| <= delta; on the circle
  // that moves the angle by at most 2 delta tan(phi/2). Normalizing a point of the chord is not uniform
  // in angle either: theta(u) = atan(u tan(phi/2)) against u phi/2 (u = 2s - 1), at most nonuniform_angle.
  const double shift = 2.0 * delta * std::tan(0.5 * phi) + nonuniform_angle(phi);
  const double moved = n >= 1.0 ? term_slope_bound(n) * shift : std::pow(shift, n);
  return std::min(1.0, chord_error_bound(phi, n) + moved);
}

double segment_error_levels(const Scene& s, const Material& m, double psi) {
  const double diffuse = segment_term_bound(psi, 1.0), specular = segment_term_bound(psi, m.shininess);
  double worst = 0.0;
  for (int c = 0; c < 3; ++c) {
    double sum = 0.0;
    for (const Light& l : s.lights)
      sum += 255.0 * l.color[c] * (m.diffuse[c] * diffuse + m.specular[c] * specular);
    worst = std::max(worst, sum);
  }
  return worst;
}

double psi_limit(const Scene& s, const Material& m, double budget_levels) {
  if (segment_error_levels(s, m, 0.0) > budget_levels) return 0.0;
  double lo = 0.0, hi = 1.0;  // the error grows with psi
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (segment_error_levels(s, m, mid) <= budget_levels ? lo : hi) = mid;
  }
  return lo;
}

}  // namespace parashade
