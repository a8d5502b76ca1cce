#pragma once
// --device. Its default, the PARASHADE_DEVICE variable (docs/environment.md), is the library's
// (open_device, resolve_render), as the benchmarks read it.
#include <string>

#include <CLI/CLI.hpp>


namespace parashade::cli {

// Adds --device to `cmd`, bound to `device`; the help text gains the default.
CLI::Option* add_device_option(CLI::App& cmd, std::string& device, const std::string& help);

}  // namespace parashade::cli
