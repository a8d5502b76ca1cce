// parashade phong-study: every normalization method, approximation and specular model of [Dembitsky 2025, software/hardware rendering] ch. 2–3
// measured against double-precision exact values (the study: host/studies/phong_study.cpp); this
// checks the destinations, prints the Markdown and writes the files.
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include "commands.hpp"
#include "parashade/errors.hpp"
#include "parashade/phong_study.hpp"
#include "parashade/report.hpp"

namespace parashade::cli {
namespace {

struct StudyArgs {
  std::string json, markdown;
};

int run(const StudyArgs& args) {
  for (const std::string& path : {args.json, args.markdown}) {
    if (path.empty()) continue;
    const std::filesystem::path p(path), dir = p.parent_path().empty() ? "." : p.parent_path();
    std::error_code ec;
    if (!std::filesystem::is_directory(dir, ec))
      throw InputError("cannot write '" + path + "': directory '" + dir.string() + "' does not exist");
    if (std::filesystem::is_directory(p, ec)) throw InputError("cannot write '" + path + "': it is a directory");
  }
  const PhongStudy study = phong_study();
  std::cout << study.markdown;
  if (!args.json.empty()) write_text_atomically(args.json, study.report.dump(1) + "\n");
  if (!args.markdown.empty()) write_text_atomically(args.markdown, study.markdown);
  return study.nonfinite_spans ? int(ExitCode::internal) : 0;
}

}  // namespace

Command add_phong_study_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("phong-study",
                                 "Normalization methods, approximations and specular models of the Phong family against exact values, with the sources' claims");
  auto args = std::make_shared<StudyArgs>();
  cmd->add_option("--json", args->json, "Write the measurements and claims (id, source figure, measured, verdict) as JSON");
  cmd->add_option("-o,--markdown", args->markdown, "Write the tables and the claims table as Markdown");
  return {cmd, [args]() { return run(*args); }};
}

}  // namespace parashade::cli
