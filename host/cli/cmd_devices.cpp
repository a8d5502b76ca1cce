#include <iostream>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "parashade/device.hpp"
#include "parashade/report.hpp"

namespace parashade::cli {

Command add_devices_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("devices", "List every OpenCL platform and device with its compute units");
  auto json = std::make_shared<bool>(false);
  cmd->add_flag("--json", *json, "Print JSON instead of a table");
  return {cmd, [json]() {
    const auto devices = list_devices();
    if (*json) {
      nlohmann::json out = nlohmann::json::array();
      for (const auto& d : devices) out.push_back(to_json(d));
      std::cout << out.dump(2) << "\n";
      return 0;
    }
    for (const auto& d : devices) {
      std::cout << d.index << ": " << d.name << "\n"
                << "   platform " << d.platform << ", " << d.type << ", " << d.compute_units << " compute units, "
                << d.global_memory / (1024 * 1024) << " MiB, " << d.version << ", driver " << d.driver << "\n";
    }
    return 0;
  }};
}

}  // namespace parashade::cli
