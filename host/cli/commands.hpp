#pragma once
// The parashade subcommands: each registers its options on the CLI11 app and runs when chosen.
#include <functional>
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

}  // namespace parashade::cli
