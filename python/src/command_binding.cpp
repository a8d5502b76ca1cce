// parashade.compare, tune and devices (docs/python.md): the command run in this process by the command
// line's own definition (host/cli/commands.hpp), the GIL released; its report is what the module returns.
#include <CLI/CLI.hpp>

#include "../../host/cli/commands.hpp"
#include "../../host/cli/parse_errors.hpp"
#include "bindings.hpp"
#include "parashade/environment.hpp"
#include "parashade/errors.hpp"
#include "parashade/report_header.hpp"

namespace parashade::python {

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
  if (const std::optional<int> status = cli::run_parsed(commands, true)) return *status;
  throw UsageError("a command is required");
}

}  // namespace parashade::python
