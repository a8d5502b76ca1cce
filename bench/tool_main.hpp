#pragma once
// main() of the bench tools that are not Google Benchmark programs (bench_kernel_ab, bench_host_noise):
// run(argc, argv), with parashade's exit code for its errors (errors.hpp) and 1 for any other exception,
// the message after the tool's name.
#include <cstdio>
#include <exception>

#include "parashade/errors.hpp"
#include "parashade/report_header.hpp"

namespace parashade {

inline int tool_main(const char* name, int (*run)(int, char**), int argc, char** argv) {
  set_report_command_line(argc, argv);  // the command_line of a --json file (report_header.hpp)
  try {
    return run(argc, argv);
  } catch (const Error& e) {
    std::fprintf(stderr, "%s: %s\n", name, e.what());
    return int(e.code());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", name, e.what());
    return 1;
  }
}

}  // namespace parashade
