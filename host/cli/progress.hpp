#pragma once
// Progress of a run of many frames: "[i/N] ... s left" on stderr, rewritten in place, only when stderr is
// a terminal and the run is not quiet (-q); logs and pipes get nothing.
#include <unistd.h>

#include <chrono>
#include <cstdio>

namespace parashade::cli {

class FrameProgress {
 public:
  using Clock = std::chrono::steady_clock;
  FrameProgress(int total, bool quiet) : total_(total), on_(!quiet && total > 1 && ::isatty(2) == 1) {}

  // `done` of the total frames are finished.
  void step(int done) {
    if (!on_) return;
    const Clock::time_point now = Clock::now();
    if (done < total_ && done > 1 && now - shown_ < std::chrono::milliseconds(250)) return;
    shown_ = now;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const double left = done > 0 ? elapsed / done * (total_ - done) : 0.0;
    std::fprintf(stderr, "\r[%d/%d] %.1f s elapsed, about %.1f s left   ", done, total_, elapsed, left);
    if (done == total_) std::fputc('\n', stderr);
    std::fflush(stderr);
  }

 private:
  int total_;
  bool on_;
  Clock::time_point start_ = Clock::now(), shown_{};
};

// --frames and --warmup beyond this are refused (a typo of a few digits would run for days).
constexpr int kMaxFrames = 100000;

}  // namespace parashade::cli
