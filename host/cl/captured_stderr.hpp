#pragma once
// What a compiler writes straight to the process's stderr while an OpenCL program builds (PoCL's clang
// prints "1 error generated." there, ahead of parashade's own message), caught in a temporary file so that
// it can go into the build error instead. One capture at a time (file descriptor 2 is the process's).
#include <mutex>
#include <string>

namespace parashade {

class CapturedStderr {
 public:
  CapturedStderr();   // from here on, fd 2 goes to a temporary file (nothing is caught if that fails)
  ~CapturedStderr();  // restores fd 2; text not taken is written to it after all
  std::string take();  // restores fd 2 and returns what was written meanwhile
  CapturedStderr(const CapturedStderr&) = delete;
  CapturedStderr& operator=(const CapturedStderr&) = delete;

 private:
  void restore();
  std::unique_lock<std::mutex> lock_;
  int saved_ = -1, file_ = -1;
};

}  // namespace parashade
