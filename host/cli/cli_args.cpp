#include "cli_args.hpp"

#include <regex>
#include <tuple>

#include "parashade/errors.hpp"

namespace parashade::cli {

std::vector<std::string> split_list(const std::string& list, const std::string& option) {
  std::vector<std::string> items;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = list.find(',', start);
    const std::string item = list.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    if (item.empty()) throw UsageError(option + " '" + list + "' has an empty entry (a comma-separated list)");
    items.push_back(item);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return items;
}

std::optional<std::pair<int, int>> parse_size(const std::string& size) {
  if (size.empty()) return std::nullopt;
  std::smatch m;
  if (!std::regex_match(size, m, std::regex(R"((\d{1,9})x(\d{1,9}))")))
    throw UsageError("--size '" + size + "' is not of the form WIDTHxHEIGHT, e.g. 1920x1080");
  return std::make_pair(std::stoi(m[1]), std::stoi(m[2]));
}

Scene load_scene_at(const std::string& file, const std::optional<std::pair<int, int>>& size, const std::string& size_text) {
  Scene scene = load_scene(file);
  if (size) {
    std::tie(scene.width, scene.height) = *size;
    check_resolution(scene.width, scene.height, "--size " + size_text);
  }
  check_resolution(scene.width, scene.height, "scene '" + file + "'");
  return scene;
}

void check_report_destination(const std::filesystem::path& report) {
  const std::filesystem::path dir = report.parent_path().empty() ? "." : report.parent_path();
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec))
    throw InputError("cannot write '" + report.string() + "': directory '" + dir.string() + "' does not exist");
  if (std::filesystem::is_directory(report, ec))
    throw InputError("cannot write '" + report.string() + "': it is a directory");
}

void check_config_options(const FrameConfig& config, DeviceMode devices) {
  try {
    check_frame_config(config, devices);
  } catch (const ConfigError& e) {
    std::string flags;
    for (Axis a : e.axes) {
      const char* flag = "";
      switch (a) {
        case Axis::method: flag = "--method"; break;
        case Axis::unit: flag = config.units ? "--units" : "--arith/--coverage (on the classic unit)"; break;
        case Axis::arith: flag = "--arith"; break;
        case Axis::coverage: flag = "--coverage"; break;
        case Axis::division: flag = "--div"; break;
        case Axis::normalize: flag = "--normalize"; break;
        case Axis::specular: flag = "--specular"; break;
        case Axis::choice: flag = "--triangle-choice"; break;
        case Axis::highlight: flag = "--highlight-test"; break;
        case Axis::plan: flag = "--cu/--partition"; break;
        case Axis::devices:
          flag = devices == DeviceMode::ranks_sort_first || devices == DeviceMode::ranks_sort_last ? "--distribute"
                                                                                                  : "--device";
          break;
      }
      flags += (flags.empty() ? "" : ", ") + std::string(flag);
    }
    throw UsageError(flags + ": " + e.what() + " (parashade combinations lists what combines)");
  }
}

}  // namespace parashade::cli
