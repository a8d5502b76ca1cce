// `parashade combinations`: the table of what combines (combinations.hpp), generated from the table the
// renderer checks, so the listing and the checks cannot disagree.
#include <cstdio>

#include "cli_args.hpp"
#include "commands.hpp"
#include "common_options.hpp"
#include "parashade/command_files.hpp"
#include "parashade/combinations.hpp"

namespace parashade::cli {
namespace {

// The table as data: the axes with their values, each refused pattern with the values it covers.
nlohmann::json combinations_json() {
  nlohmann::json axes = nlohmann::json::object();
  for (int i = 0; i < kAxes; ++i) axes[axis_name(Axis(i))] = axis_values(Axis(i));
  nlohmann::json refused = nlohmann::json::array();
  for (const Refusal& r : refused_combinations()) {
    nlohmann::json covers = nlohmann::json::object();
    for (int i = 0; i < kAxes; ++i) {
      const std::vector<std::string>& values = axis_values(Axis(i));
      std::vector<std::string> in;
      for (std::size_t v = 0; v < values.size(); ++v)
        if (r.mask[i] >> v & 1u) in.push_back(values[v]);
      if (in.size() != values.size()) covers[axis_name(Axis(i))] = in;  // an axis it does not restrict is left out
    }
    refused.push_back({{"values", covers}, {"reason", r.reason}});
  }
  return {{"axes", axes}, {"refused", refused}};
}

}  // namespace

Command add_combinations_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "combinations", "List which methods, units, arithmetics, coverage rules, plans and device modes combine, and why "
                      "the others are refused");
  // Kept alive by the command's callback: CLI11 writes the options when it parses, after this returns.
  struct Args {
    std::string report;
    bool quiet = false;  // nothing to silence: combinations prints results only
  };
  auto a = std::make_shared<Args>();
  add_report_option(*cmd, a->report, "the axes and every refused pattern with its reason");
  add_quiet_flag(*cmd, a->quiet);
  return {cmd, [a]() {
            if (!a->report.empty()) {
              CommandFiles files;
              files.output("--report", a->report);
              files.check();
              write_report(a->report, combinations_json(), "combinations");
            }
            std::fputs(describe_combinations().c_str(), stdout);
            std::puts("\nOn the command line: method --method, unit --units, arith --arith, coverage --coverage, "
                      "division --div,\nnormalize --normalize, specular --specular, choice --triangle-choice, highlight "
                      "--highlight-test,\nplan --cu/--partition, devices --device (a list or sub:NAME:N: bands; "
                      "sub:NAME:N with --cu: the units' pass).");
            print_wrote({a->report});
            return 0;
          }};
}

}  // namespace parashade::cli
