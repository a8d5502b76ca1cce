#include "tune_restrict.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>

#include <muParser.h>

#include "parashade/errors.hpp"
#include "suggest.hpp"

namespace parashade::cli {

namespace {

const std::vector<std::string>& numeric_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> v;
    for (const std::string& n : tune_param_names())
      if (is_number_param(n)) v.push_back(n);
    return v;
  }();
  return names;
}

std::string joined(const std::vector<std::string>& words) {
  std::string s;
  for (const std::string& w : words) s += (s.empty() ? "" : ", ") + w;
  return s;
}

// Python's % on the values tune's parameters take (non-negative): the remainder.
double remainder_of(double a, double b) { return std::fmod(a, b); }

}  // namespace

// One muParser per expression, with a variable per numeric parameter that allows() sets.
struct TuneRestriction::Parser {
  mu::Parser parser;
  std::map<std::string, double> values;
};

TuneRestriction::TuneRestriction(const std::string& expression)
    : expression_(expression), parser_(std::make_unique<Parser>()) {
  const std::string quoted = "--restrict '" + expression + "'";
  mu::Parser& p = parser_->parser;
  try {
    p.DefineOprt("%", remainder_of, mu::prMUL_DIV, mu::oaLEFT);
    p.SetExpr(expression);
    for (const auto& [name, unused] : p.GetUsedVar()) {
      if (is_number_param(name)) continue;
      const std::vector<std::string>& all = tune_param_names();
      if (std::find(all.begin(), all.end(), name) != all.end())
        throw UsageError(quoted + ": " + name + " is a name, not a number: a restriction reads the numeric parameters (" +
                         joined(numeric_names()) + ")");
      throw UsageError(quoted + ": unknown name '" + name + "'" + did_you_mean(name, numeric_names()) +
                       " (the names are the numeric parameters: " + joined(numeric_names()) + ")");
    }
    for (const std::string& n : numeric_names()) p.DefineVar(n, &parser_->values[n]);
    for (auto& [name, value] : parser_->values) value = 1;
    p.Eval();  // the faults GetUsedVar's parse does not see (e.g. an operator without operands)
  } catch (const mu::Parser::exception_type& e) {
    throw UsageError(quoted + ": " + e.GetMsg());  // muParser's message names the position (from 0)
  }
}

TuneRestriction::~TuneRestriction() = default;
TuneRestriction::TuneRestriction(TuneRestriction&&) noexcept = default;
TuneRestriction& TuneRestriction::operator=(TuneRestriction&&) noexcept = default;

namespace {

// Throws when `e` holds what python() does not translate: ?:, a function other than min, max and abs (Python's
// builtins of the same meaning), a name other than the numeric parameters (muParser's constants).
void check_translatable(const std::string& e) {
  const auto refuse = [&e](const std::string& what) {
    throw UsageError("--restrict '" + e + "': --export-kt writes the restrictions as Python for Kernel Tuner, and " +
                     what + " is not translated (what is: the numeric parameters, numbers, + - * / % ^, comparisons, "
                     "&& ||, min, max, abs); write it without, or leave out --export-kt");
  };
  if (e.find('?') != std::string::npos) refuse("the conditional a ? b : c");
  const auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.'; };
  for (std::size_t i = 0; i < e.size();) {
    if (!word(e[i])) {
      ++i;
      continue;
    }
    std::size_t end = i;
    while (end < e.size() && word(e[end])) ++end;
    if (std::isdigit(static_cast<unsigned char>(e[i])) || e[i] == '.') {  // a number, 1e3 and 1e-3 included
      if (end < e.size() && (e[end] == '+' || e[end] == '-') && (e[end - 1] == 'e' || e[end - 1] == 'E')) ++end;
      while (end < e.size() && word(e[end])) ++end;
    } else {
      const std::string name = e.substr(i, end - i);
      const std::size_t next = e.find_first_not_of(" \t", end);
      const bool call = next != std::string::npos && e[next] == '(';
      if (call && name != "min" && name != "max" && name != "abs") refuse("the function '" + name + "'");
      if (!call && !is_number_param(name)) refuse("the constant '" + name + "'");
    }
    i = end;
  }
}

}  // namespace

std::string TuneRestriction::python() const {
  check_translatable(expression_);
  std::string s;
  for (std::size_t i = 0; i < expression_.size(); ++i) {
    const std::string two = expression_.substr(i, 2);
    if (two == "&&" || two == "||") {
      // A space either side, unless the expression has one there already.
      if (!s.empty() && s.back() != ' ') s += ' ';
      s += two == "&&" ? "and" : "or";
      if (i + 2 < expression_.size() && expression_[i + 2] != ' ') s += ' ';
      ++i;
    } else if (expression_[i] == '^') {
      s += "**";
    } else {
      s += expression_[i];
    }
  }
  return s;
}

bool TuneRestriction::allows(const TuneSpace& space, const TunePoint& point) const {
  for (std::size_t d = 0; d < space.names.size(); ++d) {
    auto it = parser_->values.find(space.names[d]);
    if (it != parser_->values.end()) it->second = std::stod(space.values[d][point[d]]);
  }
  return parser_->parser.Eval() != 0;
}

std::vector<TuneRestriction> parse_restrictions(const std::vector<std::string>& expressions) {
  std::vector<TuneRestriction> out;
  for (const std::string& e : expressions) out.emplace_back(e);
  return out;
}

bool allowed(const std::vector<TuneRestriction>& restrictions, const TuneSpace& space, const TunePoint& point) {
  for (const TuneRestriction& r : restrictions)
    if (!r.allows(space, point)) return false;
  return true;
}

}  // namespace parashade::cli
