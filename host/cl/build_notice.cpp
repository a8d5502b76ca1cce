#include "build_notice.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <set>

#include "pocl_environment.hpp"

namespace parashade {
namespace {

std::atomic<bool> notices_on{false};

// The devices a notice was printed for (once each per process).
bool first_notice(const std::string& device) {
  static std::mutex m;
  static std::set<std::string> shown;
  std::lock_guard<std::mutex> lock(m);
  return shown.insert(device).second;
}

std::string notice_text(const std::string& device, bool pocl) {
  return "compiling kernels for " + device + (pocl ? " (" + pocl_kernel_cache_place() + ")" : "") + "...\n";
}

}  // namespace

void set_kernel_build_notices(bool on) { notices_on = on; }

SlowBuildNotice::SlowBuildNotice(const std::string& device, bool pocl) {
  if (!notices_on) return;
  fd_ = ::fcntl(2, F_DUPFD_CLOEXEC, 3);
  if (fd_ < 0) return;
  timer_ = std::thread([this, device, pocl] {
    std::unique_lock<std::mutex> lock(mutex_);
    if (done_.wait_for(lock, kSlowBuild, [this] { return stopped_; }) || !first_notice(device)) return;
    const std::string text = notice_text(device, pocl);
    [[maybe_unused]] const ssize_t n = ::write(fd_, text.data(), text.size());  // a notice: nothing to do if lost
  });
}

void SlowBuildNotice::stop() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopped_ = true;
  }
  done_.notify_all();
  if (timer_.joinable()) timer_.join();
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

SlowBuildNotice::~SlowBuildNotice() { stop(); }

}  // namespace parashade
