// parashade.compare, tune and devices (docs/python.md): the command run in this process by the command
// line's own definition (host/cli/commands.hpp), the GIL released; its report is what the module returns.
#include <cstdio>
#include <iostream>
#include <streambuf>

#include <CLI/CLI.hpp>

#include "../../host/cli/commands.hpp"
#include "../../host/cli/parse_errors.hpp"
#include "bindings.hpp"
#include "parashade/environment.hpp"
#include "parashade/errors.hpp"
#include "parashade/report_header.hpp"

namespace parashade::python {
namespace {

// What the command prints on stdout (its results, "wrote ..." lines) is in the report the caller gets back:
// a library call prints none of it. C stdio's stdout and std::cout go to a sink while the command runs;
// stderr (notes, warnings, errors) stays. Python's own prints write to descriptor 1 and are not affected.
class DiscardedStdout {
 public:
  DiscardedStdout() {
    std::cout.flush();
    std::fflush(stdout);
    cookie_io_functions_t io{};
    io.write = [](void*, const char*, std::size_t size) -> ssize_t { return ssize_t(size); };
    sink_ = ::fopencookie(nullptr, "w", io);
    if (sink_) std::swap(stdout, sink_);
    saved_buf_ = std::cout.rdbuf(&null_buf_);
  }
  ~DiscardedStdout() {
    std::cout.rdbuf(saved_buf_);
    if (!sink_) return;
    std::swap(stdout, sink_);
    std::fclose(sink_);
  }
  DiscardedStdout(const DiscardedStdout&) = delete;
  DiscardedStdout& operator=(const DiscardedStdout&) = delete;

 private:
  struct NullBuffer : std::streambuf {
    int overflow(int c) override { return traits_type::not_eof(c); }
    std::streamsize xsputn(const char*, std::streamsize n) override { return n; }
  } null_buf_;
  std::FILE* sink_ = nullptr;
  std::streambuf* saved_buf_ = nullptr;
};

}  // namespace

int run_command(const std::vector<std::string>& words) {
  pybind11::gil_scoped_release unlocked;
  const std::unique_lock<std::mutex> lock = hold_without_kept_render();  // tune writes the tune cache
  CLI::App app;
  app.require_subcommand(1, 1);
  const std::vector<cli::Command> commands = cli::add_commands(app);
  std::vector<const char*> argv = {"parashade"};
  for (const std::string& w : words) argv.push_back(w.c_str());
  set_report_command_line(int(argv.size()), argv.data());
  std::vector<std::string> reversed(words.rbegin(), words.rend());  // CLI11 takes a vector last word first
  try {
    app.parse(reversed);
  } catch (const CLI::ParseError& e) {
    throw UsageError(cli::parse_error_message(app, e));
  }
  check_environment();
  const DiscardedStdout quiet;
  if (const std::optional<int> status = cli::run_parsed(commands, true)) return *status;
  throw UsageError("a command is required");
}

}  // namespace parashade::python
