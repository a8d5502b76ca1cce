#include "cli_args.hpp"

#include <tuple>

#include "parashade/errors.hpp"
#include "parashade/memory_budget.hpp"
#include "parashade/scene_files.hpp"

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

Scene load_scene_at(const std::string& file, const std::optional<std::pair<int, int>>& size, const std::string& size_text,
                    std::vector<std::filesystem::path>* files) {
  std::vector<std::filesystem::path> read;
  Scene scene = load_scene(file, files ? *files : read);
  if (size) {
    std::tie(scene.width, scene.height) = *size;
    check_resolution(scene.width, scene.height, "--size " + size_text);
  }
  check_resolution(scene.width, scene.height, "scene '" + file + "'");
  if (size) {  // the scene was budgeted at its own resolution
    std::vector<MemoryItem> budget;
    for (const Object& o : scene.objects)
      budget.push_back({"'" + o.name + "'", o.mesh->triangles.size(), o.mesh->positions.size()});
    check_host_memory(file + " at --size " + size_text, budget, scene.width, scene.height);
  }
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

namespace {

bool same_file(const std::filesystem::path& a, const std::filesystem::path& b) {
  namespace fs = std::filesystem;
  std::error_code ec_a, ec_b;
  if (fs::exists(a, ec_a) && fs::exists(b, ec_b)) {
    std::error_code ec;
    return fs::equivalent(a, b, ec);
  }
  std::error_code ec;
  const fs::path ca = fs::weakly_canonical(fs::absolute(a, ec), ec);
  const fs::path cb = fs::weakly_canonical(fs::absolute(b, ec), ec);
  return ca == cb;
}

}  // namespace

void check_distinct_files(const std::vector<std::pair<std::string, std::filesystem::path>>& outputs,
                          const std::vector<std::filesystem::path>& inputs) {
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    const auto& [option, path] = outputs[i];
    if (path.empty()) continue;
    for (std::size_t j = 0; j < i; ++j)
      if (!outputs[j].second.empty() && same_file(outputs[j].second, path))
        throw UsageError(outputs[j].first + " '" + outputs[j].second.string() + "' and " + option + " '" +
                         path.string() + "' are the same file: one would overwrite the other");
    for (const std::filesystem::path& input : inputs)
      if (same_file(input, path))
        throw UsageError(option + " '" + path.string() + "' is the input file '" + input.string() +
                         "': writing it would destroy the input");
  }
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
