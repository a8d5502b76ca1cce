// The unit-error study's report (docs/unit-error.md): the table `parashade unit-error` prints, the
// verdicts on our bounds and the source's formulas, the Δδ comparison, and the JSON.
#include "parashade/unit_error_report.hpp"

#include "parashade/json_number.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace parashade {
namespace {

// JSON has no NaN: a formula the source does not print is null.

std::string num(double v, int precision = 6) {
  if (std::isnan(v)) return "-";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*g", precision, v);
  return buf;
}

std::string fixed(double v, int digits) {
  if (std::isnan(v)) return "-";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

std::string pad(const std::string& s, std::size_t width) {
  // Column widths count characters; δ and ⌊ are two or three bytes in UTF-8.
  std::size_t chars = 0;
  for (unsigned char c : s) chars += (c & 0xC0) != 0x80;
  return s + std::string(width > chars ? width - chars : 1, ' ');
}

struct Totals {
  std::uint64_t pixels = 0, bound_exceeded = 0, formula_exceeded = 0, wrapped = 0, spans = 0;
  double worst_over_formula = 0, last_ratio = 0;
  int worst_length = 0, last_length = 0;
};

Totals totals(const UnitErrorStudy& s) {
  Totals t;
  for (const UnitErrorAtLength& r : s.lengths) {
    t.pixels += r.pixels;
    t.spans += r.spans;
    t.bound_exceeded += r.bound_exceeded;
    t.formula_exceeded += r.formula_exceeded;
    t.wrapped += r.wrapped_spans;
    if (r.worst_over_formula > t.worst_over_formula) t.worst_over_formula = r.worst_over_formula, t.worst_length = r.length;
    if (r.length >= t.last_length) t.last_ratio = r.max_abs / r.bound, t.last_length = r.length;
  }
  return t;
}

std::string formula_text(const std::string& name) {
  if (name == "δ_K") return "δ_K = δ0 + z·2^-(V+1)";
  if (name == "δ_K split") return "\"error split\": δ0 + min(z, L-1-z)·2^-(V+1)";
  if (name == "δ_KH") return "δ_KH = δ0 + ⌊z/2⌋·2^-(V+2)";
  return "";
}

std::string verdict(const UnitErrorStudy& s, const Totals& t) {
  std::ostringstream v;
  v << unit_name(s.unit) << ": our bound ";
  if (t.bound_exceeded == 0)
    v << "holds (0 of " << t.pixels << " pixels above it; max/bound " << fixed(t.last_ratio, 3) << " at L = "
      << t.last_length << ")";
  else
    v << "VIOLATED at " << t.bound_exceeded << " of " << t.pixels << " pixels";
  const std::string name = source_formula_name(s.unit);
  if (name.empty()) {
    v << "; the source prints no formula for this unit";
  } else {
    v << "; source " << formula_text(name) << " with V = " << s.formula_bits << ": ";
    if (t.formula_exceeded == 0)
      v << "holds (0 of " << t.pixels << " pixels above it)";
    else
      v << "FAILS (" << t.formula_exceeded << " of " << t.pixels << " pixels above it, worst |err|/formula "
        << fixed(t.worst_over_formula, 2) << " at L = " << t.worst_length << ")";
  }
  if (t.wrapped > 0) v << "; " << t.wrapped << " of " << t.spans << " spans wrapped the register (I too small)";
  return v.str();
}

nlohmann::json to_json(const UnitErrorStudy& s, const Totals& t) {
  nlohmann::json lengths = nlohmann::json::array();
  for (const UnitErrorAtLength& r : s.lengths)
    lengths.push_back({{"length", r.length},
                       {"spans", r.spans},
                       {"uniform_spans", r.random_spans},
                       {"wrapped_spans", r.wrapped_spans},
                       {"max_abs", r.max_abs},
                       {"max_abs_uniform", r.max_abs_random},
                       {"mean_abs_uniform", r.mean_abs},
                       {"mean_span_max_uniform", r.mean_span_max},
                       {"bound", r.bound},
                       {"max_over_bound", r.max_abs / r.bound},
                       {"formula", number_or_null(r.formula)},
                       {"worst_over_formula", number_or_null(r.worst_over_formula)},
                       {"max_jump", r.max_jump},
                       {"pixels", r.pixels},
                       {"bound_exceeded", r.bound_exceeded},
                       {"formula_exceeded", r.formula_exceeded},
                       {"max_abs_by_z", r.max_by_z},
                       {"mean_abs_by_z_uniform", r.mean_by_z}});
  const std::string name = source_formula_name(s.unit);
  return {{"unit", unit_name(s.unit)},
          {"source_formula", name.empty() ? nlohmann::json(nullptr) : nlohmann::json(formula_text(name))},
          {"formula_bits", s.formula_bits},
          {"bound_holds", t.bound_exceeded == 0},
          {"source_formula_holds", name.empty() ? nlohmann::json(nullptr) : nlohmann::json(t.formula_exceeded == 0)},
          {"wrapped_spans", t.wrapped},
          {"lengths", lengths}};
}

const UnitErrorStudy* find(const std::vector<UnitErrorStudy>& studies, const std::string& name) {
  for (const auto& s : studies)
    if (unit_name(s.unit) == name) return &s;
  return nullptr;
}

// Δδ = δ_K - δ_KH at the last pixel z = L - 1: the measured worst errors of classic and the pair.
nlohmann::json delta_delta(const std::vector<UnitErrorStudy>& studies, int v, std::ostream& out) {
  nlohmann::json rows = nlohmann::json::array();
  const UnitErrorStudy* classic = find(studies, "classic");
  const UnitErrorStudy* pairs[2] = {find(studies, "interleave:2"), find(studies, "interleave:2:own")};
  if (!classic || (!pairs[0] && !pairs[1])) return rows;
  out << "\nΔδ = δ_K − δ_KH at the last pixel z = L−1 (measured: worst classic minus worst pair; printed: 3/4·z·2^-(V+1)):\n"
      << pad("L", 7) << pad("printed Δδ", 14);
  for (const auto* p : pairs)
    if (p) out << pad("classic−" + unit_name(p->unit), 28) << pad("/printed", 10);
  out << "\n";
  for (std::size_t i = 0; i < classic->lengths.size(); ++i) {
    const int length = classic->lengths[i].length;
    if (length < 2) continue;
    const int z = length - 1;
    const double printed = source_delta_delta(v, z);
    nlohmann::json row = {{"length", length}, {"z", z}, {"printed", printed}};
    out << pad(std::to_string(length), 7) << pad(num(printed), 14);
    for (const auto* p : pairs) {
      if (!p) continue;
      const double measured = classic->lengths[i].max_by_z.back() - p->lengths[i].max_by_z.back();
      row[unit_name(p->unit)] = measured;
      out << pad(num(measured), 28) << pad(fixed(measured / printed, 3), 10);
    }
    out << "\n";
    rows.push_back(row);
  }
  return rows;
}

}  // namespace

UnitErrorReport unit_error_report(const std::vector<UnitErrorStudy>& studies, const Arithmetic& a,
                                  const UnitErrorOptions& o) {
  const int v = o.formula_bits > 0 ? o.formula_bits : a.frac_bits;
  std::ostringstream out;
  out << "unit error, " << arith_name(a) << ": F = " << a.frac_bits << " fraction bits; the source's formulas with V = " << v
      << ", δ0 = 2^-" << v + 1 << " = " << num(std::ldexp(1.0, -(v + 1))) << " level; " << o.trials << " spans per length (half uniform, half on rounding ties), seed "
      << o.seed << "\nerror = register/2^F − exact value, in levels; max over all spans, mean over the uniform spans' pixels;"
      << "\nbound: our register model's (docs/unit-error.md); formula: the source's printed one at its worst z;"
      << "\njump: largest error difference between neighbouring pixels; wrapped: spans whose register wrapped around\n\n";
  out << pad("unit", 18) << pad("L", 6) << pad("max|err|", 12) << pad("mean|err|", 12) << pad("bound", 12)
      << pad("max/bound", 10) << pad("source", 11) << pad("formula", 12) << pad("max/formula", 12) << pad("jump", 11) << "wrapped\n";
  for (const UnitErrorStudy& s : studies) {
    const UnitConfig& u = s.unit;
    for (const UnitErrorAtLength& r : s.lengths)
      out << pad(unit_name(u), 18) << pad(std::to_string(r.length), 6) << pad(num(r.max_abs, 5), 12)
          << pad(num(r.mean_abs, 5), 12) << pad(num(r.bound, 5), 12) << pad(fixed(r.max_abs / r.bound, 3), 10)
          << pad(source_formula_name(u).empty() ? "-" : source_formula_name(u), 11) << pad(num(r.formula, 5), 12)
          << pad(fixed(r.max_abs / r.formula, 3), 12) << pad(num(r.max_jump, 4), 11) << r.wrapped_spans << "\n";
  }
  out << "\nverdicts:\n";
  nlohmann::json report = {{"arith", arith_name(a)}, {"trials", o.trials}, {"seed", o.seed}, {"lengths", o.lengths}};
  nlohmann::json unit_reports = nlohmann::json::array();
  for (const UnitErrorStudy& s : studies) {
    const Totals t = totals(s);
    out << "  " << verdict(s, t) << "\n";
    nlohmann::json j = to_json(s, t);
    j["verdict"] = verdict(s, t);
    unit_reports.push_back(j);
  }
  report["units"] = unit_reports;
  report["formula_bits"] = v;
  report["delta_delta"] = delta_delta(studies, v, out);
  return {out.str(), report};
}

}  // namespace parashade
