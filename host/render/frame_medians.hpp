#pragma once
// Median of each stage over timed frames (render's report, and --against's).
#include <vector>

#include "parashade/renderer.hpp"

namespace parashade {

FrameTimings median_timings(const std::vector<FrameTimings>& f);

}  // namespace parashade
