#pragma once
// "compiling kernels for DEVICE (first run; cached in DIR)..." on stderr while a kernel build takes long:
// PoCL compiling a program its cache does not hold took 9 s behind "rendering teapot ..." with nothing
// said. A build that ends within kSlowBuild (PoCL's cache serves one in tens of milliseconds) prints
// nothing; one still running then is compiling, and is said to be then, during the wait, once per device
// and process. Off unless the command line turns it on (not with -q); the library's other users (tests,
// benchmarks) hear nothing.
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

namespace parashade {

// The command line's switch (main: on unless -q).
void set_kernel_build_notices(bool on);

constexpr std::chrono::milliseconds kSlowBuild{500};

class SlowBuildNotice {
 public:
  // Starts the timer for a build on `device`, `pocl` when PoCL runs it (the notice then names its kernel
  // cache). Create it before CapturedStderr: the notice is written to the standard error this constructor
  // found (the capture takes descriptor 2).
  SlowBuildNotice(const std::string& device, bool pocl);
  ~SlowBuildNotice();  // stop()
  void stop();         // the build ended: nothing more is printed
  SlowBuildNotice(const SlowBuildNotice&) = delete;
  SlowBuildNotice& operator=(const SlowBuildNotice&) = delete;

 private:
  std::mutex mutex_;
  std::condition_variable done_;
  bool stopped_ = false;
  int fd_ = -1;  // a duplicate of the standard error
  std::thread timer_;
};

}  // namespace parashade
