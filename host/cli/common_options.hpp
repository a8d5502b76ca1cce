#pragma once
// The options every command spells alike (docs/cli.md, "Conventions"): -q, --report FILE, --size WxH,
// count lists such as --cu, and an old spelling kept for one release with a warning.
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "parashade/report_header.hpp"

namespace parashade::cli {

// -q,--quiet: no progress lines or notes on stderr; results and errors still print.
CLI::Option* add_quiet_flag(CLI::App& cmd, bool& quiet);

// --report FILE: the command's JSON report (schema parashade.<kind>/1, schemas/).
CLI::Option* add_report_option(CLI::App& cmd, std::string& report, const std::string& what);

// `old_name` stores into `value` like `current` does and warns on stderr that it is deprecated; the two
// exclude each other.
void add_deprecated_spelling(CLI::App& cmd, CLI::Option* current, const std::string& old_name, std::string& value);

// --error-scale, --error-legend, --flip and --flip-map, spelled alike by render and compare (docs/pictures.md).
void add_error_picture_options(CLI::App& cmd, std::string& scale, std::string& legend, bool& flip, std::string& flip_map);

// --size WIDTHxHEIGHT, checked for its form when the command line is parsed.
CLI::Option* add_size_option(CLI::App& cmd, std::string& size);
const CLI::Validator& size_validator();

// --tile: one of the tile sizes (frame_config.hpp), named in the message when not.
const CLI::Validator& tile_validator();

// --rank-timeout SECONDS (under mpirun: --distribute, --mpi): the rank watchdog's limit on one wait for
// the other ranks, a number of seconds >= 0 (0: none); the default is `seconds`' value. `note` ends the help.
CLI::Option* add_rank_timeout_option(CLI::App& cmd, double& seconds, const std::string& with, const std::string& note = "");

// A comma-separated list of integers in 1..max (e.g. --cu); `list` false: exactly one.
CLI::Validator count_list_validator(int max, bool list);

// "wrote A and B" on stdout, the files a command wrote (empty names, options not given, are left out;
// nothing when none is left), as render's summary ends: every command that writes a file says so.
void print_wrote(const std::vector<std::string>& files);

// Writes the stamped report whole or not at all.
void write_report(const std::string& path, nlohmann::json body, const std::string& kind);

}  // namespace parashade::cli
