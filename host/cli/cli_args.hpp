#pragma once
// Command-line values the commands share: lists, sizes, output destinations.
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "parashade/errors.hpp"
#include "parashade/frame_config.hpp"
#include "parashade/scene.hpp"

namespace parashade::cli {

// "a,b,c" -> {"a", "b", "c"}; an empty entry is a usage error naming the option.
std::vector<std::string> split_list(const std::string& list, const std::string& option);

// Runs `call` (a library parser or device opener) and puts `option` in front of its usage error: the
// library names the value at fault but knows no flags ("--units: unit 'interleave:17': M = 17 is not in
// 1..16").
template <typename Call>
decltype(auto) for_option(const std::string& option, Call&& call) {
  try {
    return call();
  } catch (const UsageError& e) {
    throw UsageError(option + ": " + e.what());
  }
}

// A comma-separated list of values, each parsed; two entries naming the same value (by `name`) are a
// usage error naming the option.
template <typename Parse, typename Name>
auto parse_unique_list(const std::string& list, const std::string& option, Parse parse, Name name) {
  std::vector<decltype(parse(list))> out;
  std::vector<std::string> names;
  for (const std::string& spec : split_list(list, option)) {
    auto value = for_option(option, [&] { return parse(spec); });
    const std::string n = name(value);
    for (const std::string& seen : names)
      if (seen == n) throw UsageError(option + " lists '" + spec + "' twice (as " + n + ")");
    names.push_back(n);
    out.push_back(std::move(value));
  }
  return out;
}

// The scene file, at `size` when given (--size overrides the scene's resolution); both resolutions are
// checked against the 12-bit address limit, naming the culprit.
// `files`, when given, receives every file read (load_scene in scene_files.hpp).
Scene load_scene_at(const std::string& file, const std::optional<std::pair<int, int>>& size, const std::string& size_text,
                    std::vector<std::filesystem::path>* files = nullptr);

// Checks `config` (check_frame_config) on `devices`; a refused combination becomes a usage error that
// names this command line's options for the values at fault.
void check_config_options(const FrameConfig& config, DeviceMode devices = DeviceMode::one);

// A report is written after the work; a folder that is not there must stop the run before it.
void check_report_destination(const std::filesystem::path& report);

// No output may be another output or an input file (the scene, its meshes): compared as files
// (std::filesystem::equivalent where both exist, else the normalized absolute paths with symbolic links
// resolved), not as strings. `outputs` pairs an option with its path; an empty path is an option not
// given. A collision is a usage error naming both.
void check_distinct_files(const std::vector<std::pair<std::string, std::filesystem::path>>& outputs,
                          const std::vector<std::filesystem::path>& inputs);

}  // namespace parashade::cli
