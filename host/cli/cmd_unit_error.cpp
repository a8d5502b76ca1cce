// parashade unit-error: the accumulated fixed-point error of the shading units per span length,
// against our register model's bounds and the source's printed formulas (docs/unit-error.md). The
// study and its report are host/studies/; this reads the command line and writes the files.
#include <filesystem>
#include <iostream>
#include <memory>
#include <regex>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_args.hpp"
#include "commands.hpp"
#include "common_options.hpp"
#include "parashade/command_files.hpp"
#include "parashade/errors.hpp"
#include "parashade/report.hpp"
#include "parashade/unit_error.hpp"
#include "parashade/unit_error_report.hpp"
#include "parashade/unit_table.hpp"

namespace parashade::cli {
namespace {

struct UnitErrorArgs {
  std::string units = unit_specs(&UnitRow::error_study);
  std::string arith = "fixed:12.8";
  std::string lengths = "1,2,3,4,8,16,64,256,1024,4096";
  int trials = 2000;
  std::uint64_t seed = 1;
  int formula_bits = 0;
  std::string report;
  bool quiet = false;
};

constexpr int kMaxLength = 65536;

std::vector<int> parse_lengths(const std::string& list) {
  std::vector<int> lengths;
  for (const std::string& item : split_list(list, "--lengths")) {
    if (!std::regex_match(item, std::regex(R"(\d{1,6})")) || std::stoi(item) < 1 || std::stoi(item) > kMaxLength)
      throw UsageError("--lengths: '" + item + "' is not a span length in 1.." + std::to_string(kMaxLength));
    lengths.push_back(std::stoi(item));
  }
  return lengths;
}

int run(const UnitErrorArgs& args) {
  const Arithmetic a = for_option("--arith", [&] { return parse_arith(args.arith); });
  if (!a.fixed) throw UsageError("--arith '" + args.arith + "': the unit error study needs fixed point, fixed:I.F");
  std::vector<UnitConfig> units;
  for (const std::string& u : split_list(args.units, "--units")) {
    units.push_back(for_option("--units", [&] { return parse_units(u); }));
    if (!is_span_unit(units.back()))
      throw UsageError("--units '" + u + "': the study covers the span units " + unit_specs_help(true));
  }
  UnitErrorOptions o;
  o.lengths = parse_lengths(args.lengths);
  o.trials = args.trials;
  o.seed = args.seed;
  o.formula_bits = args.formula_bits;
  // checked before the table is printed: a failed run prints nothing
  CommandFiles files;
  files.output("--report", args.report);
  files.check();
  std::vector<UnitErrorStudy> studies;
  for (const UnitConfig& u : units) studies.push_back(study_unit_error(u, a, o));
  const UnitErrorReport report = unit_error_report(studies, a, o);
  std::cout << report.text << std::flush;
  if (!args.report.empty()) write_report(args.report, report.json, "unit-error");
  print_wrote({args.report});
  return 0;
}

}  // namespace

Command add_unit_error_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "unit-error",
      "Accumulated fixed-point error of the shading units per span length, against our bounds and the source's formulas");
  auto args = std::make_shared<UnitErrorArgs>();
  cmd->add_option("--units", args->units, "Comma-separated units: " + unit_specs_help(true))
      ->capture_default_str();
  cmd->add_option("--arith", args->arith, "Span register format fixed:I.F")->capture_default_str();
  cmd->add_option("--lengths", args->lengths, "Comma-separated span lengths in pixels (1.." + std::to_string(kMaxLength) + ")")
      ->capture_default_str();
  cmd->add_option("--trials", args->trials, "Spans per length (half uniform random, half on rounding ties)")
      ->check(CLI::Range(1, 10000000))
      ->capture_default_str();
  cmd->add_option("--seed", args->seed, "Seed of the span draws")->capture_default_str();
  cmd->add_option("--formula-bits", args->formula_bits,
                  "V for the source's formulas (default: V = F); e.g. F = V + 1 tests a pair with one extra bit")
      ->check(CLI::Range(1, 31));
  CLI::Option* report = add_report_option(*cmd, args->report, "the results, per pixel offset too");
  add_deprecated_spelling(*cmd, report, "--json", args->report);
  add_quiet_flag(*cmd, args->quiet);  // nothing to silence: the study prints results only
  return {cmd, [args]() { return run(*args); }};
}

}  // namespace parashade::cli
