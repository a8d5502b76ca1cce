#include "cli_args.hpp"

#include <iostream>
#include <tuple>

#include "parashade/errors.hpp"
#include "parashade/memory_budget.hpp"
#include "parashade/notes.hpp"
#include "parashade/scene_files.hpp"
#include "parashade/split_renderer.hpp"
#include "parashade/sub_devices.hpp"

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

std::optional<std::pair<int, int>> checked_size(const std::string& size) {
  const auto wh = parse_size(size);
  try {  // size_validator checked it when the command line was read; a usage error either way
    if (wh) check_resolution(wh->first, wh->second, "--size " + size);
  } catch (const InputError& e) {
    throw UsageError(e.what());
  }
  return wh;
}

Scene load_scene_at(const std::string& file, const std::optional<std::pair<int, int>>& size,
                    std::vector<std::filesystem::path>* files) {
  std::vector<std::filesystem::path> read;
  return load_scene(file, files ? *files : read, size);
}

namespace {

// The command line's options for the axes a refused combination names.
std::string option_names(const ConfigError& e, const FrameConfig& config, DeviceMode devices) {
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
      case Axis::shape: flag = "--kernel-shape"; break;
      case Axis::devices:
        flag = devices == DeviceMode::ranks_sort_first || devices == DeviceMode::ranks_sort_last ? "--distribute"
                                                                                                : "--device";
        break;
    }
    flags += (flags.empty() ? "" : ", ") + std::string(flag);
  }
  return flags;
}

}  // namespace

void with_option_names(const FrameConfig& config, DeviceMode devices, const std::function<void()>& call) {
  try {
    call();
  } catch (const ConfigError& e) {
    throw UsageError(option_names(e, config, devices) + ": " + e.what() + " (parashade combinations lists what combines)");
  }
}

ResolvedRender resolve_with_option_names(const RenderRequest& request, CommandFiles& files, DeviceCache* devices) {
  try {
    return resolve_render(request, files, devices);
  } catch (const DeviceSelectorError& e) {
    throw UsageError(std::string("--device: ") + e.what());
  } catch (const ConfigError& e) {
    const DeviceMode mode = request.options.plan && is_sub_device_selector(request.device) ? DeviceMode::unit_sub_devices
                            : is_device_list(request.device)                             ? DeviceMode::bands
                                                                                         : DeviceMode::one;
    throw ConfigError(option_names(e, request.options, mode) + ": " + e.what() +
                          " (parashade combinations lists what combines)",
                      e.axes);  // still a usage error (exit 2), named by the options
  }
}

void print_resolved(const ResolvedRender& r) {
  for (const std::string& w : r.warnings) std::cerr << "parashade: warning: " << w << "\n";
  for (const std::string& n : r.notes) print_note(n);
}

}  // namespace parashade::cli
