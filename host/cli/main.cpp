// parashade: OpenCL models of parallel Gouraud/Phong shading hardware, measured for speed and error.
#include <cstdlib>
#include <iostream>
#include <vector>
#include <new>

#include <CLI/CLI.hpp>

#include "commands.hpp"
#include "parse_errors.hpp"
#include "standard_streams.hpp"
#include "parashade/environment.hpp"
#include "parashade/errors.hpp"
#include "parashade/output_file.hpp"
#include "parashade/version.hpp"
#include "parashade/report_header.hpp"

namespace {

int run(int argc, char** argv) {
  using namespace parashade;
  set_report_command_line(argc, argv);  // every report names it
  CLI::App app{"parashade — parallel Gouraud and Phong shading units, emulated in OpenCL and measured"};
  app.set_version_flag("--version", std::string("parashade ") + version + " (git " + git_hash + ")");
  // At most one command; none is reported below, so that an unknown word is named ("unknown command X")
  // instead of CLI11's "A subcommand is required".
  app.require_subcommand(0, 1);
  app.footer(
      "Exit codes (every command; docs/cli.md): 0 ok, 1 compare above --fail (or an internal error), 2 usage error\n"
      "(the command line or a PARASHADE_* variable), 3 bad input (a file: scene, mesh, image, an output's folder),\n"
      "4 OpenCL or device failure, 128 + N ended by signal N.\n"
      "Run 'parashade COMMAND --help' for a command's options.");
  const std::vector<cli::Command> commands = cli::add_commands(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return cli::report_parse_error(app, e);
  }
  try {
    check_environment();  // a bad PARASHADE_* value stops every command alike, before any work
    // "compiling kernels for ...": not with -q, and under mpirun from rank 0 alone (every rank builds).
    const char* rank = std::getenv("OMPI_COMM_WORLD_RANK");
    if (const std::optional<int> status = cli::run_parsed(commands, !(rank && std::string(rank) != "0"))) return *status;
    std::string names;
    for (const std::string& n : cli::command_names(app)) names += (names.empty() ? "" : ", ") + n;
    std::cerr << "parashade: error: a command is required: " << names << "\nRun 'parashade --help' for the commands.\n";
    return int(ExitCode::usage);
  } catch (const Error& e) {
    if (*e.what()) std::cerr << "parashade: error: " << e.what() << "\n";  // empty: MPI ranks stopped, rank 0 said why
    return int(e.code());
  } catch (const std::bad_alloc&) {
    std::cerr << "parashade: error: out of host memory\n";
    return int(ExitCode::bad_input);
  } catch (const std::exception& e) {
    std::cerr << "parashade: internal error: " << e.what() << "\n";
    return int(ExitCode::internal);
  }
}

}  // namespace

int main(int argc, char** argv) {
  parashade::cli::guard_standard_streams();  // escaped; a closed stdout never taken by an output file
  parashade::install_signal_cleanup();  // no temporary output file left behind, exit 128 + signal
  return parashade::cli::finish_standard_output(run(argc, argv));  // printed results checked
}
