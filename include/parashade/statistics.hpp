#pragma once
// Small summary statistics for repeated timings.
#include <algorithm>
#include <cmath>
#include <vector>

namespace parashade {

// Median of the values (mean of the middle two for an even count); 0 for none.
inline double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  const std::size_t mid = v.size() / 2;
  std::nth_element(v.begin(), v.begin() + mid, v.end());
  const double upper = v[mid];
  if (v.size() % 2) return upper;
  return 0.5 * (upper + *std::max_element(v.begin(), v.begin() + mid));
}

// The q-quantile (0 <= q <= 1) by the nearest rank: the smallest value with at least q of the values at or
// below it; 0 for none.
inline double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  const double rank = std::ceil(std::clamp(q, 0.0, 1.0) * double(v.size()));
  const std::size_t at = rank < 1.0 ? 0 : std::size_t(rank) - 1;
  std::nth_element(v.begin(), v.begin() + at, v.end());
  return v[at];
}

// A distribution-free confidence interval for the median of the values, from their order statistics:
// [v(k), v(n+1-k)] (sorted, from 1) with the largest k whose coverage, 1 - 2 P(Binomial(n, 1/2) < k), is at
// least `level`; with too few values for `level` (n < 6 for 95 %), the whole range with the coverage it has
// (93.75 % for 5). `confidence` is the coverage of the interval given. All 0 for no values.
struct MedianInterval {
  double low = 0, high = 0, confidence = 0;
};

inline MedianInterval median_interval(std::vector<double> v, double level = 0.95) {
  const std::size_t n = v.size();
  if (n == 0) return {};
  std::sort(v.begin(), v.end());
  // below[j]: P(Binomial(n, 1/2) < j + 1), the probability that fewer than j + 1 values lie below the median.
  std::vector<double> below;
  double sum = 0;
  for (std::size_t i = 0; i < n; ++i) {
    sum += std::exp(std::lgamma(double(n) + 1) - std::lgamma(double(i) + 1) - std::lgamma(double(n - i) + 1) -
                    double(n) * std::log(2.0));
    below.push_back(sum);
  }
  std::size_t k = 1;
  while (k + 1 <= (n + 1) / 2 && 1 - 2 * below[k] >= level) ++k;  // k + 1 still covers `level`
  return {v[k - 1], v[n - k], 1 - 2 * below[k - 1]};
}

}  // namespace parashade
