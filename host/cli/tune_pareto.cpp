#include "tune_pareto.hpp"

#include <algorithm>
#include <limits>
#include <numeric>

namespace parashade::cli {

std::vector<std::size_t> pareto_front(const std::vector<SpeedError>& points) {
  std::vector<std::size_t> order(points.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  // Fastest first, the smaller error first among equal times: a sweep then keeps each point that is more
  // exact than every faster one.
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (points[a].frame_ms != points[b].frame_ms) return points[a].frame_ms < points[b].frame_ms;
    return points[a].max_error < points[b].max_error;
  });
  std::vector<std::size_t> front;
  double least_error = std::numeric_limits<double>::infinity();
  for (std::size_t i : order)
    if (points[i].max_error < least_error) {
      front.push_back(i);
      least_error = points[i].max_error;
    }
  return front;
}

}  // namespace parashade::cli
