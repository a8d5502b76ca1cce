// Issue 46, item 6: results printed to standard output are part of the work. When stdout cannot take them
// (/dev/full, a closed descriptor) the run says so on stderr and exits non-zero instead of 0 with the
// results lost; a pipe whose reader went away ends the run by SIGPIPE (as for any Unix tool) or with the
// same message, never with 0. Nothing a terminal would interpret is printed raw.
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <thread>

#include <gtest/gtest.h>

#include "cli_fixture.hpp"

namespace parashade {
namespace {

using namespace testing_support;
namespace fs = std::filesystem;

enum class Stdout { dev_full, closed, broken_pipe };

struct StdoutRun {
  int exit_code = -1, signal = 0;
  std::string err;
};

// Runs parashade with stdout on /dev/full, closed, or the write end of a pipe whose read end is closed;
// stderr goes to `err_file`. Killed after 60 s (a hang fails the test).
StdoutRun run_with_stdout(Stdout how, const std::vector<std::string>& args, const fs::path& err_file) {
  std::vector<std::string> text = {parashade_binary().string()};
  text.insert(text.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : text) argv.push_back(a.data());
  argv.push_back(nullptr);
  int pipe_fds[2] = {-1, -1};
  if (how == Stdout::broken_pipe && ::pipe(pipe_fds) != 0) return {};
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int err = ::open(err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    if (err < 0 || ::dup2(err, 2) < 0) ::_exit(126);
    ::signal(SIGPIPE, SIG_DFL);  // as a shell leaves it
    if (how == Stdout::dev_full) {
      const int full = ::open("/dev/full", O_WRONLY);
      if (full < 0 || ::dup2(full, 1) < 0) ::_exit(126);
    } else if (how == Stdout::closed) {
      ::close(1);
    } else {
      ::close(pipe_fds[0]);
      if (::dup2(pipe_fds[1], 1) < 0) ::_exit(126);
    }
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  if (how == Stdout::broken_pipe) ::close(pipe_fds[0]), ::close(pipe_fds[1]);
  StdoutRun r;
  int status = 0;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (::waitpid(pid, &status, WNOHANG) == 0) {
    if (std::chrono::steady_clock::now() > deadline) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      return r;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  if (WIFEXITED(status)) r.exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
  r.err = bytes_of(err_file);
  return r;
}

// No control character reaches the terminal: ESC starts escape sequences, BEL rings.
::testing::AssertionResult no_control_characters(const std::string& text) {
  for (const char c : text)
    if ((static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t') || c == '\x7f')
      return ::testing::AssertionFailure() << "control character " << int(c) << " printed raw in: " << text;
  return ::testing::AssertionSuccess();
}

class CliStandardOutput : public CliTest {
 protected:
  fs::path err_file() const { return dir_.path() / "stderr.txt"; }
  // compare of an image with itself: no device, three lines of figures on stdout.
  std::vector<std::string> compare_args() const {
    return {"compare", picture_.string(), picture_.string()};
  }
  fs::path picture_ = input("picture.ppm", std::string("P6\n2 1\n255\n") + std::string("\x10\x20\x30\x40\x50\x60", 6));
};

TEST_F(CliStandardOutput, AFullStdoutIsAnErrorNotSilence) {
  const StdoutRun r = run_with_stdout(Stdout::dev_full, compare_args(), err_file());
  EXPECT_EQ(r.signal, 0) << r.err;
  EXPECT_EQ(r.exit_code, kBadInput) << r.err;
  EXPECT_NE(r.err.find("standard output"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("No space left on device"), std::string::npos) << r.err;
}

TEST_F(CliStandardOutput, AClosedStdoutIsAnErrorNotSilence) {
  const StdoutRun r = run_with_stdout(Stdout::closed, compare_args(), err_file());
  EXPECT_EQ(r.signal, 0) << r.err;
  EXPECT_EQ(r.exit_code, kBadInput) << r.err;
  EXPECT_NE(r.err.find("standard output"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("closed"), std::string::npos) << r.err;
}

// A render's outputs are whole (written before the summary is printed), but the summary is lost: say so.
TEST_F(CliStandardOutput, ARenderWhoseSummaryCannotBePrintedFails) {
  const fs::path scene = input("ball.json", sphere_scene());
  const StdoutRun r = run_with_stdout(Stdout::dev_full, render_args(scene), err_file());
  EXPECT_EQ(r.exit_code, kBadInput) << r.err;
  EXPECT_NE(r.err.find("standard output"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(image()));
}

// A closed descriptor 1 must not be taken by a file the command opens (its output would go there).
TEST_F(CliStandardOutput, AClosedStdoutDoesNotLeakIntoAnOutputFile) {
  const fs::path scene = input("ball.json", sphere_scene());
  const StdoutRun r = run_with_stdout(Stdout::closed, render_args(scene), err_file());
  EXPECT_EQ(r.exit_code, kBadInput) << r.err;
  const nlohmann::json report = read_report();
  EXPECT_TRUE(report.is_object()) << "the report is not JSON: " << bytes_of(this->report());
}

// A scene name and a path holding terminal escape sequences were printed raw (a title change, a screen
// clear); they are printed escaped.
TEST_F(CliStandardOutput, EscapeSequencesInNamesAndPathsAreNotPrintedRaw) {
  const fs::path named = input("named.json", R"({"name": "\u001b]0;owned\u0007\u001b[2Jball",
    "resolution": [32, 24], "objects": [{"shape": "sphere"}]})");
  const RunResult r = render(named);
  ASSERT_TRUE(succeeds(r));
  EXPECT_TRUE(no_control_characters(r.out));
  EXPECT_TRUE(no_control_characters(r.err));
  EXPECT_NE(r.out.find("ball"), std::string::npos) << r;
  const RunResult missing = render(in_dir() / "\x1b[2Jgone.json");
  EXPECT_TRUE(fails_with(missing, kBadInput, {"gone.json"}));
  EXPECT_TRUE(no_control_characters(missing.err));
}

// A reader that went away: SIGPIPE ends the run (the default, as for cat or grep), or the run reports
// the failed write; either way not 0.
TEST_F(CliStandardOutput, ABrokenPipeIsNeverSuccess) {
  const StdoutRun r = run_with_stdout(Stdout::broken_pipe, compare_args(), err_file());
  EXPECT_TRUE(r.signal == SIGPIPE || (r.exit_code == kBadInput && r.err.find("standard output") != std::string::npos))
      << "exit " << r.exit_code << ", signal " << r.signal << ": " << r.err;
}

}  // namespace
}  // namespace parashade
