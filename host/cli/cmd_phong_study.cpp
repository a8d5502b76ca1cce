// parashade phong-study: every normalization method, approximation and specular model of [Dembitsky 2025, software/hardware rendering] ch. 2–3
// measured against double-precision exact values (the study: host/studies/phong_study.cpp); this
// checks the destinations, prints the Markdown and writes the files.
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include "cli_args.hpp"
#include "commands.hpp"
#include "common_options.hpp"
#include "parashade/command_files.hpp"
#include "parashade/errors.hpp"
#include "parashade/phong_study.hpp"
#include "parashade/report.hpp"

namespace parashade::cli {
namespace {

struct StudyArgs {
  std::string report, output;
  bool quiet = false;
};

int run(const StudyArgs& args) {
  CommandFiles files;
  files.output("--report", args.report);
  files.output("-o", args.output);
  files.check();
  const PhongStudy study = phong_study();
  std::cout << study.markdown << std::flush;
  if (!args.report.empty()) write_report(args.report, study.report, "phong-study");
  if (!args.output.empty()) write_text_atomically(args.output, study.markdown);
  print_wrote({args.output, args.report});
  return study.nonfinite_spans ? int(ExitCode::internal) : 0;
}

}  // namespace

Command add_phong_study_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("phong-study",
                                 "Normalization methods, approximations and specular models of the Phong family against exact values, with the sources' claims");
  auto args = std::make_shared<StudyArgs>();
  // -o is every command's main output (docs/cli.md); --markdown, its old long name, warns for one release.
  CLI::Option* output = cmd->add_option("-o,--output", args->output, "Write the tables and the claims table as Markdown");
  add_deprecated_spelling(*cmd, output, "--markdown", args->output);
  CLI::Option* report =
      add_report_option(*cmd, args->report, "the measurements and claims: id, source figure, measured, verdict");
  add_deprecated_spelling(*cmd, report, "--json", args->report);
  add_quiet_flag(*cmd, args->quiet);  // nothing to silence: the study prints results only
  return {cmd, [args]() { return run(*args); }};
}

}  // namespace parashade::cli
