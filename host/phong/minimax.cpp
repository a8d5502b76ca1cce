// Remez exchange for low-degree polynomials: the reference points start at the Chebyshev extrema; each
// round solves p(x_i) + (-1)^i E / w(x_i) = f(x_i) and moves the reference to the alternating extrema
// of the weighted error found on a dense grid. Ten rounds are plenty for degree <= 3.
#include "parashade/minimax.hpp"

#include <cmath>
#include <stdexcept>

namespace parashade {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Gaussian elimination with partial pivoting; a is n x n row-major, solved in place into b.
std::vector<double> solve(std::vector<double> a, std::vector<double> b) {
  const std::size_t n = b.size();
  for (std::size_t c = 0; c < n; ++c) {
    std::size_t p = c;
    for (std::size_t r = c + 1; r < n; ++r)
      if (std::fabs(a[r * n + c]) > std::fabs(a[p * n + c])) p = r;
    for (std::size_t k = 0; k < n; ++k) std::swap(a[c * n + k], a[p * n + k]);
    std::swap(b[c], b[p]);
    for (std::size_t r = c + 1; r < n; ++r) {
      const double m = a[r * n + c] / a[c * n + c];
      for (std::size_t k = c; k < n; ++k) a[r * n + k] -= m * a[c * n + k];
      b[r] -= m * b[c];
    }
  }
  std::vector<double> x(n);
  for (std::size_t i = n; i-- > 0;) {
    double s = b[i];
    for (std::size_t k = i + 1; k < n; ++k) s -= a[i * n + k] * x[k];
    x[i] = s / a[i * n + i];
  }
  return x;
}

}  // namespace

double eval_poly(const std::vector<double>& coeffs, double x) {
  double s = 0.0;
  for (std::size_t i = coeffs.size(); i-- > 0;) s = s * x + coeffs[i];
  return s;
}

double max_fit_error(const std::vector<double>& coeffs, const std::function<double(double)>& f, double lo, double hi,
                     const std::function<double(double)>& weight, int samples) {
  double worst = 0.0;
  for (int i = 0; i < samples; ++i) {
    const double x = lo + (hi - lo) * i / (samples - 1);
    const double w = weight ? weight(x) : 1.0;
    worst = std::fmax(worst, std::fabs(w * (eval_poly(coeffs, x) - f(x))));
  }
  return worst;
}

MinimaxFit minimax_fit(const std::function<double(double)>& f, double lo, double hi, int degree,
                       const std::function<double(double)>& weight) {
  if (!(lo < hi)) throw std::invalid_argument("minimax_fit: empty interval");
  if (degree < 0) throw std::invalid_argument("minimax_fit: negative degree");
  const int n = degree + 2;
  auto w = [&](double x) { return weight ? weight(x) : 1.0; };
  std::vector<double> ref(n);
  for (int i = 0; i < n; ++i) ref[i] = 0.5 * (lo + hi) - 0.5 * (hi - lo) * std::cos(kPi * i / (n - 1));
  const int grid = 4001;
  std::vector<double> coeffs(degree + 1, 0.0);
  for (int round = 0; round < 12; ++round) {
    std::vector<double> a(n * n), b(n);
    for (int i = 0; i < n; ++i) {
      double p = 1.0;
      for (int k = 0; k <= degree; ++k, p *= ref[i]) a[i * n + k] = p;
      a[i * n + degree + 1] = (i % 2 ? -1.0 : 1.0) / w(ref[i]);
      b[i] = f(ref[i]);
    }
    const std::vector<double> x = solve(a, b);
    coeffs.assign(x.begin(), x.begin() + degree + 1);
    // New reference: per sign run of the error on the grid, the point of largest |error|.
    std::vector<double> xs, es;
    double run_x = lo, run_e = 0.0;
    int run_sign = 0;
    for (int g = 0; g < grid; ++g) {
      const double xg = lo + (hi - lo) * g / (grid - 1);
      const double e = w(xg) * (eval_poly(coeffs, xg) - f(xg));
      const int s = e >= 0 ? 1 : -1;
      if (run_sign != 0 && s != run_sign) {
        xs.push_back(run_x);
        es.push_back(run_e);
        run_e = 0.0;
      }
      if (run_sign == 0 || s != run_sign || std::fabs(e) > std::fabs(run_e)) run_x = xg, run_e = e;
      run_sign = s;
    }
    xs.push_back(run_x);
    es.push_back(run_e);
    // Keep n alternating extrema: drop the smallest at either end while there are too many.
    while (static_cast<int>(xs.size()) > n) {
      if (std::fabs(es.front()) < std::fabs(es.back())) xs.erase(xs.begin()), es.erase(es.begin());
      else xs.pop_back(), es.pop_back();
    }
    if (static_cast<int>(xs.size()) < n) break;  // converged to (near) equioscillation already
    ref = xs;
  }
  MinimaxFit fit;
  fit.coeffs = coeffs;
  fit.lo = lo;
  fit.hi = hi;
  fit.max_error = max_fit_error(coeffs, f, lo, hi, weight);
  return fit;
}

}  // namespace parashade
