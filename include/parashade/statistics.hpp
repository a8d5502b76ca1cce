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

}  // namespace parashade
