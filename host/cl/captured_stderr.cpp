#include "captured_stderr.hpp"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>

namespace parashade {
namespace {

std::mutex& capture_mutex() {
  static std::mutex m;
  return m;
}

}  // namespace

CapturedStderr::CapturedStderr() : lock_(capture_mutex()) {
  std::fflush(stderr);
  if (std::FILE* f = std::tmpfile()) {
    file_ = ::dup(::fileno(f));  // our own descriptor: the FILE can go, the (unlinked) file stays open
    std::fclose(f);
  }
  if (file_ < 0) return;
  saved_ = ::dup(2);
  if (saved_ < 0 || ::dup2(file_, 2) < 0) {
    if (saved_ >= 0) ::close(saved_);
    ::close(file_);
    saved_ = file_ = -1;
  }
}

void CapturedStderr::restore() {
  if (saved_ < 0) return;
  std::fflush(stderr);
  ::dup2(saved_, 2);
  ::close(saved_);
  saved_ = -1;
}

std::string CapturedStderr::take() {
  restore();
  std::string text;
  if (file_ < 0) return text;
  char buf[4096];
  ::lseek(file_, 0, SEEK_SET);
  for (ssize_t n; (n = ::read(file_, buf, sizeof buf)) > 0;) text.append(buf, std::size_t(n));
  ::close(file_);
  file_ = -1;
  return text;
}

CapturedStderr::~CapturedStderr() {
  const std::string rest = take();
  if (!rest.empty()) std::fputs(rest.c_str(), stderr);
}

}  // namespace parashade
