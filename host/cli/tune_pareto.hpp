#pragma once
// `tune --objective pareto`: the speed-vs-error Pareto front of the verified candidates (docs/tuning.md): the
// candidates no other one beats on both frame time and error against the exact reference. Device-free, so
// that a test can give it made-up points.
#include <cstddef>
#include <vector>

namespace parashade::cli {

struct SpeedError {
  double frame_ms;   // median frame time, ms
  double max_error;  // largest error against the exact reference, 8-bit levels
};

// The indices of the points on the front, fastest first: a point is on it when no other is at most as slow
// and at most as wrong and better in one of the two. Of identical points the first alone is kept.
std::vector<std::size_t> pareto_front(const std::vector<SpeedError>& points);

}  // namespace parashade::cli
