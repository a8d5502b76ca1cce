// The unit-error study (docs/unit-error.md): random and adversarial exact spans through setup's plane
// registers and each unit's golden model, every pixel against the exact value, next to the unit's own
// bound and the source's formula (both the unit's row of the unit table).
#include "parashade/unit_error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

#include "parashade/setup.hpp"
#include "parashade/unit_table.hpp"

namespace parashade {
namespace {

// A register load's rounding, 2^-(F+1) levels, and setup's plane rounding, 2^-(PLANE_FRAC+1).
double half_lsb(const Arithmetic& a) { return std::ldexp(1.0, -(a.frac_bits + 1)); }
constexpr double kPlaneHalfLsb = 1.0 / double(std::uint64_t(1) << (PLANE_FRAC + 1));

// The unit's own bound (unit_table.hpp) with one register load's rounding h and the plane's e.
double bound(const UnitConfig& unit, const Arithmetic& a, int length, int z, double e) {
  const UnitModel& model = *unit_row(unit.kind).model;
  if (!model.error_bound)
    throw std::invalid_argument("the unit error study covers the span units " + unit_specs_help(true));
  return model.error_bound(unit, length, z, half_lsb(a), e);
}

// SplitMix64: decorrelates (seed, length) into the generator's seed.
std::uint64_t mix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

struct Random {
  std::mt19937_64 g;
  double unit() { return double(g() >> 11) * 0x1p-53; }                 // [0, 1)
  double uniform(double lo, double hi) { return lo + (hi - lo) * unit(); }
  std::int64_t integer(std::int64_t lo, std::int64_t hi) { return lo + std::int64_t(g() % std::uint64_t(hi - lo + 1)); }
  bool coin() { return (g() >> 63) != 0; }
};

ExactSpan uniform_span(Random& r, int length) {
  const double from = r.uniform(0, 255), to = r.uniform(0, 255);
  return {from, length > 1 ? (to - from) / (length - 1) : to - from, length};
}

}  // namespace

bool is_span_unit(const UnitConfig& unit) { return unit_row(unit.kind).model->error_bound != nullptr; }

SpanLoad load_exact_span(const ExactSpan& s, const UnitConfig& unit, const Arithmetic& a) {
  FixedPlanes p{};
  p.ref[0] = to_plane_register(s.start);
  p.ddx[0] = to_plane_register(s.step);
  p.ddy[0] = 0;
  return load_span(p, 0, 0, s.length - 1, 0, unit, a);
}

SpanError measure_span_error(const UnitConfig& unit, const Arithmetic& a, const ExactSpan& s) {
  const SpanTrace t = run_unit(unit, a, load_exact_span(s, unit, a));
  const long double range = std::ldexp(1.0L, a.int_bits);  // levels a W-bit register spans
  SpanError out;
  out.error.resize(std::size_t(s.length));
  for (int z = 0; z < s.length; ++z) {
    const long double exact = (long double)s.start + (long double)z * (long double)s.step;
    long double err = std::ldexp((long double)t.values[std::size_t(z)], -a.frac_bits) - exact;
    if (std::fabs(err) >= range / 2) {
      err -= range * std::nearbyint(err / range);
      out.wrapped = true;
    }
    out.error[std::size_t(z)] = double(err);
  }
  return out;
}

double unit_error_bound(const UnitConfig& unit, const Arithmetic& a, int length, int z) {
  return bound(unit, a, length, z, kPlaneHalfLsb);
}

double unit_error_bound_registers_only(const UnitConfig& unit, const Arithmetic& a, int length, int z) {
  return bound(unit, a, length, z, 0.0);
}

double source_formula(const UnitConfig& unit, int v, int length, int z) {
  const UnitModel& model = *unit_row(unit.kind).model;
  return model.source_formula ? model.source_formula(unit, v, length, z) : std::numeric_limits<double>::quiet_NaN();
}

std::string source_formula_name(const UnitConfig& unit) {
  const UnitModel& model = *unit_row(unit.kind).model;
  return model.source_formula_name ? model.source_formula_name(unit) : "";
}

double source_delta_delta(int v, int z) { return 0.75 * z * std::ldexp(1.0, -(v + 1)); }

std::vector<ExactSpan> draw_spans(int length, int trials, std::uint64_t seed, const Arithmetic& a) {
  if (length < 1) throw std::invalid_argument("a span has at least one pixel");
  Random r{std::mt19937_64(mix(seed ^ mix(std::uint64_t(length))))};
  const double q = std::ldexp(1.0, -a.frac_bits);  // one register LSB, levels
  const double steps = std::max(1, length - 1);
  std::vector<ExactSpan> spans;
  spans.reserve(std::size_t(std::max(trials, 0)));
  for (int t = 0; t < trials; ++t) {
    ExactSpan s = uniform_span(r, length);
    if (t % 2 == 1) {
      const int u = t / 2, family = u % 3;
      // Exact ties round up (+2^-(F+1)); just below a tie rounds down (-2^-(F+1) + tiny): same sign.
      const double below = r.coin() ? r.uniform(0x1p-32, 0x1p-27) : 0.0;
      const double sign = r.coin() ? 1.0 : -1.0;
      if (family != 2) {
        // Increment (n + f) q with f = 1/2 (family 0) or f = (2i+1)/(2M) so that M (n + f) q is a tie.
        const int m = 2 + (u / 3) % 15;
        const double f = family == 0 ? 0.5 : (2.0 * double(r.integer(0, m - 1)) + 1.0) / (2.0 * m);
        const double n_max = std::floor(255.0 / (steps * q) - 1.0);
        const double n = n_max >= 1 ? double(r.integer(0, std::int64_t(std::min(n_max, 1e15)))) : 0.0;
        const double step = sign * (n + f) * q - below;
        if (std::fabs(step) * (length - 1) <= 255.0) s.step = step;  // else: no tie fits, keep uniform
      }
      const double reach = s.step * (length - 1);
      const double lo = std::max(0.0, -reach), hi = std::min(255.0, 255.0 - reach);
      double start = (std::floor(r.uniform(lo, hi) / q - 0.5) + 0.5) * q;  // a tie at or below
      if (start < lo) start += q;
      s.start = start - below;
    }
    spans.push_back(s);
  }
  return spans;
}

UnitErrorStudy study_unit_error(const UnitConfig& unit, const Arithmetic& a, const UnitErrorOptions& o) {
  if (!a.fixed) throw std::invalid_argument("the unit error study is for fixed-point arithmetic");
  if (o.trials < 1) throw std::invalid_argument("at least one span per length");
  if (!is_span_unit(unit))
    throw std::invalid_argument("the unit error study covers the span units " + unit_specs_help(true));
  if (o.formula_bits < 0) throw std::invalid_argument("V is at least 0");
  const int v = o.formula_bits > 0 ? o.formula_bits : a.frac_bits;
  UnitErrorStudy study{unit, a, v, {}};
  for (int length : o.lengths) {
    if (length < 1) throw std::invalid_argument("a span has at least one pixel");
    UnitErrorAtLength r;
    r.length = length;
    r.max_by_z.assign(std::size_t(length), 0.0);
    r.mean_by_z.assign(std::size_t(length), 0.0);
    const std::size_t n = static_cast<std::size_t>(length);
    std::vector<double> bound_z(n), formula_z(n), slack_z(n);
    r.formula = 0;
    for (int z = 0; z < length; ++z) {
      bound_z[std::size_t(z)] = unit_error_bound(unit, a, length, z);
      slack_z[std::size_t(z)] = bound_z[std::size_t(z)] - unit_error_bound_registers_only(unit, a, length, z);
      formula_z[std::size_t(z)] = source_formula(unit, v, length, z);
      r.bound = std::max(r.bound, bound_z[std::size_t(z)]);
      r.formula = std::isnan(formula_z[std::size_t(z)]) ? formula_z[std::size_t(z)] : std::max(r.formula, formula_z[std::size_t(z)]);
    }
    const std::vector<ExactSpan> spans = draw_spans(length, o.trials, o.seed, a);
    double sum_abs = 0, sum_span_max = 0;
    for (std::size_t i = 0; i < spans.size(); ++i) {
      const bool uniform = i % 2 == 0;
      const SpanError e = measure_span_error(unit, a, spans[i]);
      ++r.spans;
      r.random_spans += uniform;
      r.wrapped_spans += e.wrapped;
      double span_max = 0;
      for (int z = 0; z < length; ++z) {
        const std::size_t k = std::size_t(z);
        const double v = std::fabs(e.error[k]);
        if (z > 0) r.max_jump = std::max(r.max_jump, std::fabs(e.error[k] - e.error[k - 1]));
        span_max = std::max(span_max, v);
        r.max_by_z[k] = std::max(r.max_by_z[k], v);
        if (uniform) r.mean_by_z[k] += v;
        r.bound_exceeded += v > bound_z[k];
        if (!std::isnan(formula_z[k])) {
          r.formula_exceeded += v > formula_z[k] + slack_z[k];
          r.worst_over_formula = std::max(r.worst_over_formula, v / formula_z[k]);
        }
      }
      r.pixels += std::uint64_t(length);
      r.max_abs = std::max(r.max_abs, span_max);
      if (uniform) {
        r.max_abs_random = std::max(r.max_abs_random, span_max);
        sum_span_max += span_max;
        for (int z = 0; z < length; ++z) sum_abs += std::fabs(e.error[std::size_t(z)]);
      }
    }
    if (r.random_spans > 0) {
      for (double& m : r.mean_by_z) m /= double(r.random_spans);
      r.mean_abs = sum_abs / (double(r.random_spans) * length);
      r.mean_span_max = sum_span_max / double(r.random_spans);
    }
    if (std::isnan(r.formula)) r.worst_over_formula = std::numeric_limits<double>::quiet_NaN();
    study.lengths.push_back(std::move(r));
  }
  return study;
}

}  // namespace parashade
