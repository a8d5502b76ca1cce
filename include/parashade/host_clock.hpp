#pragma once
// The host clock of the stage timings and the bench tools: steady (never set back), read in milliseconds.
#include <chrono>

namespace parashade {

using Clock = std::chrono::steady_clock;

inline double ms_since(Clock::time_point t) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

}  // namespace parashade
