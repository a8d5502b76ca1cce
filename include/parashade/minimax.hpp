#pragma once
// Minimax (Chebyshev best-approximation) polynomial fits by the Remez exchange, used to refit the
// sources' approximations of 1/sqrt(2+z), h(r) = 1/sqrt(2(1+r)) and arccos (docs/phong-methods.md).
#include <functional>
#include <vector>

namespace parashade {

struct MinimaxFit {
  std::vector<double> coeffs;  // c0 + c1 x + c2 x^2 + ...
  double lo = 0.0, hi = 0.0;   // interval fitted
  double max_error = 0.0;      // max |w(x) (p(x) - f(x))| on a dense grid of the interval
};

double eval_poly(const std::vector<double>& coeffs, double x);

// Degree-`degree` polynomial minimizing max |weight(x) * (p(x) - f(x))| on [lo, hi]. weight = 1 gives
// the absolute-error fit, weight = 1/|f| the relative one. Throws std::invalid_argument on lo >= hi or
// a negative degree.
MinimaxFit minimax_fit(const std::function<double(double)>& f, double lo, double hi, int degree,
                       const std::function<double(double)>& weight = nullptr);

// Max |weight (p - f)| of given coefficients on [lo, hi] (dense grid, `samples` points, end points included).
double max_fit_error(const std::vector<double>& coeffs, const std::function<double(double)>& f, double lo, double hi,
                     const std::function<double(double)>& weight = nullptr, int samples = 20001);

}  // namespace parashade
