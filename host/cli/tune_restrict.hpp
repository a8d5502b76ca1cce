#pragma once
// `tune --restrict EXPR` (repeatable): a point of the space is searched only when every expression is true
// (non-zero) at it, as Kernel Tuner's restrictions ("tile*work_items<=4096"). The expressions are parsed and
// evaluated by muParser (Debian's libmuparser-dev): + - * / ^, % (defined here, as Python's), comparisons,
// && ||, ?:, min, max, ...; the names are the numeric parameters of the space (tile, work_items,
// work_group_size, cu, batch), each the point's value (a parameter the point does not read, "-" in the
// report, holds its first value). A bad expression, an unknown name (with a suggestion) or a parameter that
// is a name, not a number, is a usage error naming the expression. docs/tuning.md "Restrictions".
#include <memory>
#include <string>
#include <vector>

#include "tune_space.hpp"

namespace parashade::cli {

class TuneRestriction {
 public:
  explicit TuneRestriction(const std::string& expression);  // UsageError when it does not parse
  ~TuneRestriction();
  TuneRestriction(TuneRestriction&&) noexcept;
  TuneRestriction& operator=(TuneRestriction&&) noexcept;

  const std::string& expression() const { return expression_; }
  // The expression as Python, the language of Kernel Tuner's restriction strings: muParser's && || ^ as
  // Python's and, or, ** (the rest of muParser's comparisons and arithmetic, and min, max and abs, read
  // alike). Throws UsageError naming the expression for what has no such reading: the conditional a ? b : c,
  // another function (sqrt, ...), a constant (_pi, _e).
  std::string python() const;
  // True when the expression is non-zero at the point. A division by zero gives inf or NaN and the comparison
  // decides (Kernel Tuner keeps a point whose restriction raises ZeroDivisionError: docs/tuning.md).
  bool allows(const TuneSpace& space, const TunePoint& point) const;

 private:
  struct Parser;
  std::string expression_;
  std::unique_ptr<Parser> parser_;
};

// Each `--restrict` expression, checked.
std::vector<TuneRestriction> parse_restrictions(const std::vector<std::string>& expressions);
// True when every restriction allows the point.
bool allowed(const std::vector<TuneRestriction>& restrictions, const TuneSpace& space, const TunePoint& point);

}  // namespace parashade::cli
