// `parashade combinations`: the table of what combines (combinations.hpp), generated from the table the
// renderer checks, so the listing and the checks cannot disagree.
#include <cstdio>

#include "commands.hpp"
#include "parashade/combinations.hpp"

namespace parashade::cli {

Command add_combinations_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "combinations", "List which methods, units, arithmetics, coverage rules, plans and device modes combine, and why "
                      "the others are refused");
  return {cmd, []() {
            std::fputs(describe_combinations().c_str(), stdout);
            std::puts("\nOn the command line: method --method, unit --units, arith --arith, coverage --coverage, "
                      "division --div,\nnormalize --normalize, specular --specular, choice --triangle-choice, highlight "
                      "--highlight-test,\nplan --cu/--partition, devices --device (a list or sub:NAME:N: bands; "
                      "sub:NAME:N with --cu: the units' pass).");
            return 0;
          }};
}

}  // namespace parashade::cli
