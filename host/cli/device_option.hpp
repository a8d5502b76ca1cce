#pragma once
// --device and its default from the environment: PARASHADE_DEVICE, as the benchmarks read it
// (bench/bench_device.hpp), so one variable picks the device for every run of a session (docs/environment.md).
#include <string>

#include <CLI/CLI.hpp>

#include "cli_args.hpp"
#include "parashade/errors.hpp"

namespace parashade::cli {

// Adds --device to `cmd`, bound to `device`; the help text gains the default.
CLI::Option* add_device_option(CLI::App& cmd, std::string& device, const std::string& help);

// Called after parsing: when --device was absent (`device` empty) and PARASHADE_DEVICE is set, `device`
// takes the variable's value. Returns what errors about the device name: "--device", or the variable and
// its value, which the command line does not show.
std::string device_from_environment(std::string& device);

// Runs `open` (a device opener) for a selector named by `origin` (device_from_environment): usage errors
// name --device; when the selector came from PARASHADE_DEVICE, every error names the variable.
template <typename Open>
decltype(auto) for_device(const std::string& origin, Open&& open) {
  if (origin == "--device") return for_option(origin, open);
  try {
    return open();
  } catch (const Error& e) {
    throw Error(e.code(), origin + ": " + e.what());
  }
}

}  // namespace parashade::cli
