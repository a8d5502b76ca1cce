#include "parse_errors.hpp"

#include <iostream>

#include "parashade/errors.hpp"
#include "suggest.hpp"

namespace parashade::cli {
namespace {

// Every spelling of `app`'s options ("--size", "-o", "--output"), --help's included.
std::vector<std::string> option_names(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::Option* o : app.get_options()) {
    for (const std::string& l : o->get_lnames()) names.push_back("--" + l);
    for (const std::string& s : o->get_snames()) names.push_back("-" + s);
  }
  return names;
}

// The messages for the words `where` did not take (CLI11's ExtrasError lists them backwards and guesses
// nothing): each unknown option with its nearest spelling, in command-line order; a first word that is no
// command; or an argument beyond the command's positional ones.
std::vector<std::string> unknown_words(const CLI::App& app, const CLI::App& where, const std::vector<std::string>& words) {
  const std::string of = &where == &app ? "" : " of " + where.get_name();
  std::vector<std::string> lines;
  for (const std::string& w : words) {
    if (w.size() > 1 && w[0] == '-') {
      const std::string name = w.substr(0, w.find('='));
      lines.push_back("unknown option '" + name + "'" + of + did_you_mean(name, option_names(where)));
    } else if (lines.empty() && &where == &app) {
      return {"unknown command '" + w + "'" + did_you_mean(w, command_names(app))};
    } else if (lines.empty()) {
      lines.push_back("unexpected argument '" + w + "'" + of + " (its positional arguments are all given)");
    }
  }
  return lines;
}

}  // namespace

std::vector<std::string> command_names(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) names.push_back(sub->get_name());
  return names;
}

std::vector<std::string> parse_error_lines(CLI::App& app, const CLI::ParseError& e) {
  const std::vector<CLI::App*> chosen = app.get_subcommands();
  const CLI::App* command = chosen.empty() ? nullptr : chosen.front();
  // Words no one took come first, whatever CLI11 threw: CLI11 checks the required options before it
  // looks at them, and "--output is required" alone hides the "--outptu" that meant it. Words before the
  // command are the top level's; the command's own come after them.
  std::vector<std::string> lines = unknown_words(app, app, app.remaining());
  if (command)
    for (const std::string& l : unknown_words(app, *command, command->remaining())) lines.push_back(l);
  if (lines.empty() || !dynamic_cast<const CLI::ExtrasError*>(&e)) lines.push_back(e.what());
  return lines;
}

std::string parse_error_message(CLI::App& app, const CLI::ParseError& e) {
  if (e.get_exit_code() == 0) return "--help and --version are the command line's: parashade [COMMAND] --help";
  std::string message;
  for (const std::string& l : parse_error_lines(app, e)) message += (message.empty() ? "" : "\n") + l;
  return message;
}

int report_parse_error(CLI::App& app, const CLI::ParseError& e) {
  if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
  for (const std::string& l : parse_error_lines(app, e)) std::cerr << "parashade: error: " << l << "\n";
  const std::vector<CLI::App*> chosen = app.get_subcommands();
  std::cerr << (chosen.empty() ? std::string("Run 'parashade --help' for the commands.\n")
                               : "Run 'parashade " + chosen.front()->get_name() + " --help' for its options.\n");
  return int(ExitCode::usage);
}

}  // namespace parashade::cli
