// Lower-degree specular models ([Dembitsky 2025, software/hardware rendering] ch. 3). The lobe rule solves
//   int_0^{pi/2} cos^n(x) sin(x) dx = 1/(n+1) = int_0^{min(pi/(2a), pi/2)} cos^k(a x) sin(x) dx
// for a by bisection (the right side falls as a grows), with Simpson's rule for the integral.
#include "parashade/specular_models.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <regex>
#include <utility>

#include "parashade/errors.hpp"

namespace parashade {
namespace {

constexpr double kPi = 3.14159265358979323846;

double lobe_integral(double a, int k) {
  const double end = std::min(kPi / (2.0 * a), kPi / 2.0);
  const int steps = 2000;  // even
  const double h = end / steps;
  double s = 0.0;
  for (int i = 0; i <= steps; ++i) {
    const double x = i * h;
    const double f = std::pow(std::max(0.0, std::cos(a * x)), k) * std::sin(x);
    s += f * (i == 0 || i == steps ? 1.0 : i % 2 ? 4.0 : 2.0);
  }
  return s * h / 3.0;
}

double clamp_power(double base, double p) { return base > 0.0 ? std::pow(base, p) : 0.0; }

}  // namespace

double taylor_scale(double n, int k) { return std::sqrt(n / k); }

double lobe_scale(double n, int k) {
  // Memoized: the renderer asks per material and frame, and one solve takes ~160k cosines.
  static std::mutex mutex;
  static std::map<std::pair<double, int>, double> cache;
  {
    std::lock_guard<std::mutex> lock(mutex);
    const auto it = cache.find({n, k});
    if (it != cache.end()) return it->second;
  }
  const double target = 1.0 / (n + 1.0);
  double lo = 1e-3, hi = 1e3;
  for (int i = 0; i < 80; ++i) {
    const double mid = std::sqrt(lo * hi);
    (lobe_integral(mid, k) > target ? lo : hi) = mid;
  }
  const double a = std::sqrt(lo * hi);
  std::lock_guard<std::mutex> lock(mutex);
  cache[{n, k}] = a;
  return a;
}

double specular_value(const SpecularModel& m, double n, double c, double scale) {
  if (!(c > 0.0)) return 0.0;
  c = std::min(c, 1.0);
  switch (m.kind) {
    case SpecularKind::exact: return std::pow(c, n);
    case SpecularKind::cosk_taylor:
    case SpecularKind::cosk_lobe: {
      const double x = scale * std::acos(c);
      return x >= kPi / 2.0 ? 0.0 : std::pow(std::cos(x), m.k);
    }
    case SpecularKind::quadratic: return clamp_power(1.0 + 0.5 * n * (c - 1.0), 2.0);
    case SpecularKind::sevenths: return clamp_power(1.0 + (7.0 / 16.0) * n * (c - 1.0), m.p);
  }
  return 0.0;
}

double specular_value(const SpecularModel& m, double n, double c) {
  const double scale = m.kind == SpecularKind::cosk_taylor ? taylor_scale(n, m.k)
                       : m.kind == SpecularKind::cosk_lobe ? lobe_scale(n, m.k)
                                                           : 1.0;
  return specular_value(m, n, c, scale);
}

SpecularModel parse_specular(const std::string& text) {
  static const std::regex re(R"((exact)|cosk:(taylor|lobe):([24])|(quadratic)|7n16(?::(\d(?:\.\d{1,3})?))?)");
  std::smatch g;
  if (!std::regex_match(text, g, re))
    throw UsageError("specular model '" + text + "': expected exact, cosk:taylor:2|4, cosk:lobe:2|4, quadratic or 7n16[:P]");
  SpecularModel m;
  if (g[1].matched) m.kind = SpecularKind::exact;
  else if (g[2].matched) {
    m.kind = g[2] == "taylor" ? SpecularKind::cosk_taylor : SpecularKind::cosk_lobe;
    m.k = std::stoi(g[3]);
  } else if (g[4].matched) m.kind = SpecularKind::quadratic;
  else {
    m.kind = SpecularKind::sevenths;
    if (g[5].matched) m.p = std::stod(g[5]);
    if (!(m.p >= 1.0 && m.p <= 8.0)) throw UsageError("specular model '" + text + "': exponent P must be in 1..8");
  }
  return m;
}

std::string specular_name(const SpecularModel& m) {
  switch (m.kind) {
    case SpecularKind::exact: return "exact";
    case SpecularKind::cosk_taylor: return "cosk:taylor:" + std::to_string(m.k);
    case SpecularKind::cosk_lobe: return "cosk:lobe:" + std::to_string(m.k);
    case SpecularKind::quadratic: return "quadratic";
    case SpecularKind::sevenths: {
      char buf[32];
      std::snprintf(buf, sizeof buf, "7n16:%g", m.p);
      return buf;
    }
  }
  return "";
}

}  // namespace parashade
