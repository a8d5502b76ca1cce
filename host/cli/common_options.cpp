#include "common_options.hpp"

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <regex>

#include "parashade/errors.hpp"
#include "parashade/frame_config.hpp"
#include "parashade/report.hpp"
#include "parashade/report_header.hpp"
#include "parashade/scene.hpp"

namespace parashade::cli {

CLI::Option* add_quiet_flag(CLI::App& cmd, bool& quiet) {
  return cmd.add_flag("-q,--quiet", quiet, "No progress lines or notes on stderr (results and errors still print)");
}

CLI::Option* add_report_option(CLI::App& cmd, std::string& report, const std::string& what) {
  return cmd.add_option("--report", report,
                        "Write a JSON report (" + what + "), versioned by its \"schema\" field (docs/reports.md)");
}

void add_deprecated_spelling(CLI::App& cmd, CLI::Option* current, const std::string& old_name, std::string& value) {
  const std::string now = current->get_name();
  CLI::Option* old = cmd.add_option_function<std::string>(
      old_name,
      [&value, old_name, now](const std::string& v) {
        std::cerr << "parashade: warning: " << old_name << " is deprecated and goes in the next release; use " << now
                  << " FILE\n";
        value = v;
      },
      "Deprecated spelling of " + now);
  old->excludes(current);
}

void add_error_picture_options(CLI::App& cmd, std::string& scale, std::string& legend, bool& flip, std::string& flip_map) {
  cmd.add_option("--error-scale", scale,
                 "Colours of --error-map's picture: linear, gamma (t^0.4: one-level errors show beside a large "
                 "maximum), gamma:G, or log (ln(1 + e) / ln(1 + max)); an EXR map holds the values whatever the scale")
      ->capture_default_str();
  cmd.add_option("--error-legend", legend,
                 "Also write the error map's scale (a colour bar labelled in levels) as a picture of its own, as tall "
                 "as the map (the map itself keeps the image's size, to lay over it)");
  cmd.add_flag("--flip", flip,
               "Also compute LDR-FLIP (NVIDIA's perceptual difference, 67 pixels per degree) over the whole frame: its "
               "mean and max in the figures and the report (about 0.8 s of host time at 1920x1080)");
  cmd.add_option("--flip-map", flip_map,
                 "Also write the per-pixel FLIP (implies --flip): magma from 0 to 1 as FLIP's tools draw it, or to "
                 ".exr the values, one float channel");
}

const CLI::Validator& size_validator() {
  // The form and the range alike: a value the command line gives wrong is a usage error (exit 2), as
  // `--size 640x48O` always was; `--size 0x48` was bad input (3), checked later as a scene's resolution.
  static const CLI::Validator v(
      [](std::string& text) -> std::string {
        if (!std::regex_match(text, std::regex(R"(\d{1,9}x\d{1,9})")))
          return "'" + text + "' is not of the form WIDTHxHEIGHT, e.g. 1920x1080";
        try {
          const auto wh = parse_size(text);
          check_resolution(wh->first, wh->second, "'" + text + "'");
        } catch (const Error& e) {
          return e.what();
        }
        return "";
      },
      "WIDTHxHEIGHT", "size");
  return v;
}

CLI::Option* add_size_option(CLI::App& cmd, std::string& size) {
  const std::string most = std::to_string(kMaxResolution);
  return cmd.add_option("--size", size, "Resolution WIDTHxHEIGHT (at most " + most + "x" + most + "), overriding the scene's")
      ->check(size_validator());
}

const CLI::Validator& tile_validator() {
  // CLI11's IsMember said only "--tile: 99999999999999999999" for a number beyond int (issue 46).
  static const CLI::Validator v(
      [](std::string& text) -> std::string {
        for (const int t : tile_sizes())
          if (text == std::to_string(t)) return "";
        return "'" + text + "' is not a tile size: " + tile_sizes_text();
      },
      "16|32|64", "tile");
  return v;
}

CLI::Option* add_rank_timeout_option(CLI::App& cmd, double& seconds, const std::string& with, const std::string& note) {
  static const CLI::Validator seconds_validator(
      [](std::string& text) -> std::string {
        char* end = nullptr;
        const double v = std::strtod(text.c_str(), &end);
        if (end != text.c_str() && *end == '\0' && v >= 0 && v <= 1e9) return "";
        return "'" + text + "' is not a number of seconds from 0 (no limit) to 1e9";
      },
      "SECONDS", "seconds");
  return cmd
      .add_option("--rank-timeout", seconds,
                  with + ": end the whole job when a rank waits longer than SECONDS in one MPI call for the others "
                         "(a rank stopped or hung; exit 4); 0 waits forever" + note)
      ->check(seconds_validator)
      ->capture_default_str();
}

CLI::Validator count_list_validator(int max, bool list) {
  const std::string range = "1.." + std::to_string(max);
  return CLI::Validator(
      [max, list, range](std::string& text) -> std::string {
        const std::regex one(R"([0-9]{1,9})"), many(R"([0-9]{1,9}(,[0-9]{1,9})*)");
        const bool form = std::regex_match(text, list ? many : one);
        if (form) {
          std::size_t start = 0;
          bool in_range = true;
          while (start <= text.size()) {
            const std::size_t comma = std::min(text.find(',', start), text.size());
            const long v = std::stol(text.substr(start, comma - start));
            in_range = in_range && v >= 1 && v <= max;
            start = comma + 1;
          }
          if (in_range) return "";
        }
        return "'" + text + "' is not " + (list ? "a comma-separated list of numbers in " : "a number in ") + range;
      },
      list ? "N[,N...]" : "N", "count");
}

void print_wrote(const std::vector<std::string>& files) {
  std::string line;
  for (const std::string& f : files)
    if (!f.empty()) line += (line.empty() ? "wrote " : " and ") + f;
  if (!line.empty()) std::printf("%s\n", line.c_str());
}

void write_report(const std::string& path, nlohmann::json body, const std::string& kind) {
  write_text_atomically(path, report_text(std::move(body), kind));
}

}  // namespace parashade::cli
