#pragma once
// A command line CLI11 could not read, reported as every other error is: "parashade: error: ..." on
// stderr and exit 2 (docs/cli.md, "Exit codes").
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace parashade::cli {

// --help and --version print what they ask for (exit 0). Any other parse error prints one line per fault:
// words no command or option knows are named in command-line order, each with the nearest command or
// option when one is close ("unknown command 'rendr'; did you mean 'render'?"), then where the help is.
// Returns the exit code.
int report_parse_error(CLI::App& app, const CLI::ParseError& e);

// The lines report_parse_error prints for a parse error other than --help and --version, without the
// "parashade: error: " prefix (front ends that raise them: the Python module).
std::vector<std::string> parse_error_lines(CLI::App& app, const CLI::ParseError& e);
// The same as one message (lines joined by newlines), --help and --version included as a usage error: what
// such a front end throws (UsageError).
std::string parse_error_message(CLI::App& app, const CLI::ParseError& e);

// The commands' names, in the order --help lists them.
std::vector<std::string> command_names(const CLI::App& app);

}  // namespace parashade::cli
