#include "parashade/combined.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>

#include "../scene/input_file.hpp"
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
    c.rule = TriangleRule::bound;
    return c;
  }
  char* end = nullptr;
  const long k = std::strtol(arg.c_str(), &end, 10);
  if (arg.empty() || *end != '\0' || k < 0 || k > kCombinedMaxK)
    throw UsageError("method '" + text + "': K must be an integer 0.." + std::to_string(kCombinedMaxK) + " or 'auto'");
  c.k = int(k);
  return c;
}

namespace {

// list:FILE's triangles: whitespace-separated indices, each below 2^31.
std::shared_ptr<const std::vector<std::uint32_t>> read_phong_list(const std::string& file) {
  // Before opening: a FIFO would block, /dev/zero would fill memory (issue 46, item 9).
  detail::check_input_file(file, "--triangle-choice list: '" + file + "'", detail::kMaxListFileBytes, "triangle list");
  std::ifstream in(file);
  if (!in) throw InputError("--triangle-choice list: cannot read '" + file + "'");
  auto listed = std::make_shared<std::vector<std::uint32_t>>();
  std::string word;
  while (in >> word) {
    char* end = nullptr;
    const long long t = std::strtoll(word.c_str(), &end, 10);
    if (*end != '\0' || t < 0 || t > std::numeric_limits<std::int32_t>::max())
      throw InputError("--triangle-choice list: '" + file + "' holds '" + word + "', not a triangle index");
    listed->push_back(std::uint32_t(t));
  }
  if (in.bad()) throw InputError("--triangle-choice list: reading '" + file + "' failed");
  std::sort(listed->begin(), listed->end());
  listed->erase(std::unique(listed->begin(), listed->end()), listed->end());
  return listed;
}

}  // namespace

void parse_triangle_rule(const std::string& text, CombinedConfig& c) {
  const std::size_t colon = text.find(':');
  const std::string name = text.substr(0, colon);
  if (name == "list") {
    if (colon == std::string::npos || colon + 1 == text.size())
      throw UsageError("triangle choice '" + text + "': list needs a file, list:FILE");
    c.list_file = text.substr(colon + 1);
    c.phong_list = read_phong_list(c.list_file);
    c.rule = TriangleRule::list;
    return;
  }
  if (name == "none") c.rule = TriangleRule::none;
  else if (name == "bound") c.rule = TriangleRule::bound;
  else if (name == "sources") c.rule = TriangleRule::sources;
  else if (name == "sources-literal") c.rule = TriangleRule::sources_literal;
  else throw UsageError("triangle choice '" + text + "': expected none, bound, sources[:M,Q,P], sources-literal[:M,Q,P] or list:FILE");
  if (colon == std::string::npos) return;
  const bool sources = c.rule == TriangleRule::sources || c.rule == TriangleRule::sources_literal;
  double v[3];
  char tail = 0;
  if (!sources || std::sscanf(text.c_str() + colon + 1, "%lf,%lf,%lf%c", &v[0], &v[1], &v[2], &tail) != 3 ||
      !(v[0] >= -1.0 && v[0] <= 1.0) || !(v[1] >= 0.0) || !(v[2] >= 0.0) || !std::isfinite(v[1]) || !std::isfinite(v[2]))
    throw UsageError("triangle choice '" + text +
                     "': thresholds go with sources only, as M,Q,P (M in [-1, 1], Q and P >= 0), e.g. sources:0.9,0.004,0.008");
  c.source_m = v[0];
  c.source_q = v[1];
  c.source_p = v[2];
}

std::string triangle_rule_name(const CombinedConfig& c) {
  switch (c.rule) {
    case TriangleRule::none: return "none";
    case TriangleRule::bound: return "bound";
    case TriangleRule::sources: return "sources";
    case TriangleRule::sources_literal: return "sources-literal";
    case TriangleRule::list: return "list";
  }
  return "none";
}

bool uses_highlight_mask(const CombinedConfig& c) { return c.highlight_test || c.rule == TriangleRule::bound; }

int combined_min_width(const CombinedConfig& c) {
  if (c.min_width >= 0) return c.min_width;
  if (c.automatic) return 8;
  // Segments of one pixel are Phong's pixels: walking them only adds the walk's fixed costs.
  return c.k == 0 ? kNeverWalk : 2 << c.k;
}

double combined_shading_budget(const CombinedConfig& c) { return std::max(0.0, c.max_error - 0.5); }

double dropped_specular_levels(const CombinedConfig& c, double shading_budget, std::size_t lights) {
  if (!(c.automatic || c.rule == TriangleRule::bound) || lights == 0) return c.negligible_specular;
  return std::min(c.negligible_specular, std::max(0.0, shading_budget) / double(lights));
}

double phong_float_error_bound(const Scene& s) {
  double worst = 0.0;
  for (const Material& m : s.materials) {
    double sum = 0.0;
    for (const Light& l : s.lights) {
      double largest = 0.0;
      for (int c = 0; c < 3; ++c)
        largest = std::max(largest, double(l.color[c]) * (double(m.diffuse[c]) + double(m.specular[c]) * (double(m.shininess) + 1.0)));
      sum += largest;
    }
    worst = std::max(worst, sum);
  }
  return 64.0 * 0x1p-24 * 255.0 * worst;
}

std::string combined_name(const CombinedConfig& c) {
  return c.automatic ? "combined:auto" : "combined:" + std::to_string(c.k);
}

double chord_error_bound(double phi, double n, bool crosses_zero) {
  // Symmetric peak: exact 1 at the middle, chord cos^n(phi/2) (the sources' formula).
  const double peak = 1.0 - std::pow(std::cos(0.5 * phi), n);
  if (!crosses_zero) return peak;
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

double angle_shift_error(double shift, double n) {
  return n >= 1.0 ? term_slope_bound(n) * shift : std::pow(shift, n);
}

double segment_term_bound(double psi, double n, bool crosses_zero) {
  if (!(psi < 1.0)) return 1.0;
  const double phi = std::asin(psi);
  const double root = std::sqrt(1.0 + psi);
  const double delta = (root - 1.0) / (root + 1.0);
  // The interior normal sits at the chord parameter s' instead of s, |s' - s| <= delta; on the circle
  // that moves the angle by at most 2 delta tan(phi/2). Normalizing a point of the chord is not uniform
  // in angle either: theta(u) = atan(u tan(phi/2)) against u phi/2 (u = 2s - 1), at most nonuniform_angle.
  const double shift = 2.0 * delta * std::tan(0.5 * phi) + nonuniform_angle(phi);
  return std::min(1.0, chord_error_bound(phi, n, crosses_zero) + angle_shift_error(shift, n));
}

double segment_error_levels(const Scene& s, const Material& m, double psi, SegmentTerms terms) {
  const double diffuse = segment_term_bound(psi, 1.0, terms.terminator);
  const double specular = terms.specular ? segment_term_bound(psi, m.shininess) : 0.0;
  double worst = 0.0;
  for (int c = 0; c < 3; ++c) {
    double sum = 0.0;
    for (const Light& l : s.lights)
      sum += 255.0 * l.color[c] * (m.diffuse[c] * diffuse + m.specular[c] * specular);
    worst = std::max(worst, sum);
  }
  return worst;
}

double psi_limit(const Scene& s, const Material& m, double budget_levels, SegmentTerms terms) {
  if (segment_error_levels(s, m, 0.0, terms) > budget_levels) return 0.0;
  double lo = 0.0, hi = 1.0;  // the error grows with psi
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (segment_error_levels(s, m, mid, terms) <= budget_levels ? lo : hi) = mid;
  }
  return lo;
}

}  // namespace parashade
