// Staged output files (output_file.hpp): checked writes, rename into place, removal on failure or signal.
#include "parashade/output_file.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <utility>

#include "parashade/errors.hpp"

namespace parashade {
namespace {

namespace fs = std::filesystem;

// The temporary files a signal must remove. The handler may only read what is published whole: a slot
// is `busy` while its path is written and `live` once it may be unlinked.
constexpr int kSlots = 16;
constexpr std::size_t kPathMax = 4096;
constexpr std::size_t kNameMax = 255;  // NAME_MAX of Linux file systems
enum : int { kFree = 0, kBusy = 1, kLive = 2 };
struct Slot {
  std::atomic<int> state{kFree};
  char path[kPathMax];
};
Slot g_slots[kSlots];

int register_temporary(const fs::path& p) {
  const std::string text = p.string();
  if (text.size() >= kPathMax) return -1;
  for (int i = 0; i < kSlots; ++i) {
    int expected = kFree;
    if (!g_slots[i].state.compare_exchange_strong(expected, kBusy)) continue;
    std::memcpy(g_slots[i].path, text.c_str(), text.size() + 1);
    g_slots[i].state.store(kLive, std::memory_order_release);
    return i;
  }
  return -1;  // more than kSlots at once: not removed on a signal (never the case in parashade)
}

void unregister_temporary(int slot) {
  if (slot >= 0) g_slots[slot].state.store(kFree, std::memory_order_release);
}

extern "C" void remove_temporaries_and_exit(int sig) {
  for (Slot& s : g_slots)
    if (s.state.load(std::memory_order_acquire) == kLive) ::unlink(s.path);
  ::_exit(128 + sig);
}

std::string errno_text(int e) { return std::strerror(e); }

}  // namespace

StagedFile::StagedFile(fs::path destination) : destination_(std::move(destination)) {
  // A link is written through: the file replaces the link's target, not the link.
  std::error_code ec;
  if (fs::is_symlink(destination_, ec)) {
    fs::path target = fs::weakly_canonical(fs::absolute(destination_, ec), ec);
    if (!ec) destination_ = std::move(target);
  }
  static std::atomic<unsigned> counter{0};
  const std::string tail = ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++) +
                           destination_.extension().string();
  // A legal name of up to 255 bytes must leave a legal temporary name: the stem is cut to fit (issue 46).
  std::string stem = destination_.stem().string();
  const std::size_t room = kNameMax > tail.size() + 1 ? kNameMax - tail.size() - 1 : 0;
  if (stem.size() > room) stem.resize(room);
  temporary_ = destination_.parent_path() / ("." + stem + tail);
  slot_ = register_temporary(temporary_);
  reclaim_signal_cleanup();
}

StagedFile::StagedFile(StagedFile&& o) noexcept
    : destination_(std::move(o.destination_)), temporary_(std::move(o.temporary_)), fd_(std::exchange(o.fd_, -1)),
      slot_(std::exchange(o.slot_, -1)), committed_(std::exchange(o.committed_, true)), error_(std::move(o.error_)) {}

StagedFile::~StagedFile() {
  if (!committed_) discard();
}

void StagedFile::discard() noexcept {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  ::unlink(temporary_.c_str());
  unregister_temporary(slot_);
  slot_ = -1;
}

void StagedFile::fail(const std::string& why) {
  if (error_.empty()) error_ = why.empty() ? std::string("write failed") : why;
}

int StagedFile::open_fd() {
  fd_ = ::open(temporary_.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd_ < 0) {
    const fs::path dir = destination_.parent_path().empty() ? fs::path(".") : destination_.parent_path();
    throw InputError("cannot write " + destination_.string() + ": cannot create a file in '" + dir.string() +
                     "': " + errno_text(errno));
  }
  return fd_;
}

bool StagedFile::pwrite_all(const void* data, std::size_t size, std::size_t offset) {
  const char* p = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t n = ::pwrite(fd_, p, size, off_t(offset));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      fail(n < 0 ? errno_text(errno) : "nothing written");
      return false;
    }
    p += n;
    offset += std::size_t(n);
    size -= std::size_t(n);
  }
  return true;
}

bool StagedFile::close_fd() {
  if (fd_ < 0) return error_.empty();
  const int r = ::close(fd_);
  fd_ = -1;
  if (r != 0) fail(errno_text(errno));
  return error_.empty();
}

void StagedFile::commit() {
  close_fd();
  if (error_.empty()) {
    struct stat st;
    if (::stat(destination_.c_str(), &st) == 0 && S_ISREG(st.st_mode) &&
        ::chmod(temporary_.c_str(), st.st_mode & 07777) != 0)
      fail("cannot keep the permissions of the file it replaces: " + errno_text(errno));
  }
  if (error_.empty() && ::rename(temporary_.c_str(), destination_.c_str()) != 0) fail(errno_text(errno));
  if (!error_.empty()) {
    discard();
    committed_ = true;
    throw InputError("cannot write " + destination_.string() + ": " + error_);
  }
  unregister_temporary(slot_);
  slot_ = -1;
  committed_ = true;
}

void check_output_folder(const std::string& option, const fs::path& path) {
  const fs::path dir = path.parent_path().empty() ? fs::path(".") : path.parent_path();
  std::error_code ec;
  if (fs::is_directory(dir, ec)) return;
  const std::string at = (option.empty() ? "" : option + ": ") + "cannot write " + path.string() + ": ";
  const fs::file_status st = fs::status(dir, ec);
  if (st.type() == fs::file_type::not_found) throw InputError(at + "directory '" + dir.string() + "' does not exist");
  if (ec) throw InputError(at + "'" + dir.string() + "': " + ec.message());
  throw InputError(at + "'" + dir.string() + "' is not a folder");
}

StagedFile stage_text(const fs::path& path, const std::string& text) {
  StagedFile file(path);
  file.open_fd();
  file.pwrite_all(text.data(), text.size(), 0);
  file.close_fd();
  if (!file.error().empty()) throw InputError("cannot write " + path.string() + ": " + file.error());
  return file;
}

namespace {

// The signals that end a run: their default would leave temporary files. SIGQUIT and SIGUSR1 are also
// those LLVM (inside PoCL) swallows once it has registered its own handlers: it runs its cleanup for
// SIGQUIT and returns, and prints nothing for SIGUSR1, so the render went on (issue 46). LLVM hands
// SIGINT, SIGTERM, SIGHUP and SIGUSR2 back to the handler it found, which is ours.
constexpr int kEndingSignals[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGUSR1, SIGUSR2};
constexpr int kSwallowedSignals[] = {SIGQUIT, SIGUSR1};
std::atomic<unsigned> g_claimed{0};  // bit s: signal s is ours (not ignored when the process started)

void claim(int sig) {
  struct sigaction sa {};
  sa.sa_handler = remove_temporaries_and_exit;
  sigemptyset(&sa.sa_mask);
  sigaction(sig, &sa, nullptr);
}

}  // namespace

void install_signal_cleanup() {
  for (const int sig : kEndingSignals) {
    struct sigaction old {};
    // A signal ignored from the start stays ignored (nohup's SIGHUP, a background job's SIGQUIT).
    if (sig != SIGINT && sig != SIGTERM && sigaction(sig, nullptr, &old) == 0 && old.sa_handler == SIG_IGN) continue;
    claim(sig);
    g_claimed.fetch_or(1u << sig);
  }
}

void reclaim_signal_cleanup() {
  for (const int sig : kSwallowedSignals) {
    struct sigaction now {};
    if ((g_claimed.load() & (1u << sig)) && sigaction(sig, nullptr, &now) == 0 &&
        now.sa_handler != remove_temporaries_and_exit)
      claim(sig);
  }
}

}  // namespace parashade
