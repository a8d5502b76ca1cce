#pragma once
// Runs the real parashade binary as a child process and captures what a user would see: the exit
// status, stdout and stderr. A child that outlives its time limit is killed and reported as a hang.
#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace parashade::testing_support {

struct RunResult {
  int exit_code = -1;      // valid when the child exited normally
  int signal = 0;          // the signal that ended it (a crash), or 0
  bool timed_out = false;  // killed after the time limit
  long max_rss_kib = 0;    // the child's peak resident memory (getrusage's ru_maxrss)
  std::string out, err;
  bool exited() const { return signal == 0 && !timed_out && exit_code >= 0; }
};

// For failure messages: everything the run produced.
inline std::ostream& operator<<(std::ostream& os, const RunResult& r) {
  os << "\n  exit code " << r.exit_code;
  if (r.signal) os << ", killed by signal " << r.signal;
  if (r.timed_out) os << ", timed out";
  return os << "\n  stdout: " << r.out << "\n  stderr: " << r.err;
}

// The binary under test: this build's, or PARASHADE_TEST_BINARY's (to see new tests fail on an older build).
inline std::filesystem::path parashade_binary() {
  const char* other = std::getenv("PARASHADE_TEST_BINARY");
  return other && *other ? std::filesystem::path(other) : std::filesystem::path(PARASHADE_BINARY);
}

namespace detail {

inline std::string slurp_and_remove(const std::filesystem::path& p) {
  std::ostringstream s;
  s << std::ifstream(p, std::ios::binary).rdbuf();
  std::error_code ec;
  std::filesystem::remove(p, ec);
  return s.str();
}

}  // namespace detail

// Runs `parashade args...` in `cwd` (the test's current directory when empty). Output goes to files
// rather than pipes, so a chatty child cannot block on a full pipe while the parent waits.
inline RunResult run_parashade(const std::vector<std::string>& args, const std::filesystem::path& cwd = {},
                               std::chrono::seconds limit = std::chrono::seconds(60)) {
  namespace fs = std::filesystem;
  static int serial = 0;
  const std::string stem = "parashade_cli_" + std::to_string(::getpid()) + "_" + std::to_string(serial++);
  const fs::path out_file = fs::temp_directory_path() / (stem + ".out");
  const fs::path err_file = fs::temp_directory_path() / (stem + ".err");

  std::vector<std::string> argv_text = {parashade_binary().string()};
  argv_text.insert(argv_text.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : argv_text) argv.push_back(a.data());
  argv.push_back(nullptr);

  RunResult r;
  const pid_t pid = ::fork();
  if (pid < 0) {
    r.err = "fork failed";
    return r;
  }
  if (pid == 0) {
    // Child: only async-signal-safe calls until exec.
    const int out = ::open(out_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    const int err = ::open(err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    if (out < 0 || err < 0 || ::dup2(out, 1) < 0 || ::dup2(err, 2) < 0) ::_exit(126);
    if (!cwd.empty() && ::chdir(cwd.c_str()) != 0) ::_exit(126);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }

  const auto deadline = std::chrono::steady_clock::now() + limit;
  int status = 0;
  struct rusage usage {};
  while (::wait4(pid, &status, WNOHANG, &usage) == 0) {
    if (std::chrono::steady_clock::now() > deadline) {
      ::kill(pid, SIGKILL);
      ::wait4(pid, &status, 0, &usage);
      r.timed_out = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  r.max_rss_kib = usage.ru_maxrss;
  if (!r.timed_out) {
    if (WIFEXITED(status)) r.exit_code = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
  }
  r.out = detail::slurp_and_remove(out_file);
  r.err = detail::slurp_and_remove(err_file);
  return r;
}

}  // namespace parashade::testing_support
