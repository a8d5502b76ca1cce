#pragma once
// The parashade subcommands: each registers its options on the CLI11 app and runs when chosen.
#include <functional>
#include <optional>
#include <vector>

#include <CLI/CLI.hpp>

namespace parashade::cli {

// A registered subcommand and the function that runs it (returning the exit code).
struct Command {
  CLI::App* app;
  std::function<int()> run;
};
Command add_combinations_command(CLI::App& app);
Command add_compare_command(CLI::App& app);
Command add_devices_command(CLI::App& app);
Command add_phong_study_command(CLI::App& app);
Command add_render_command(CLI::App& app);
Command add_plan_command(CLI::App& app);
Command add_tune_command(CLI::App& app);
Command add_scaling_command(CLI::App& app);
Command add_unit_error_command(CLI::App& app);
Command add_vectors_command(CLI::App& app);
// Every command, registered on `app` in the order --help lists them (main, the Python module).
std::vector<Command> add_commands(CLI::App& app);
// The command the parse chose, run, its "compiling kernels" notices off under -q or where `notices` is false;
// nullopt when no command was given. The command line's and the Python module's one dispatch.
std::optional<int> run_parsed(const std::vector<Command>& commands, bool notices);

}  // namespace parashade::cli
