#include <iostream>

#include <nlohmann/json.hpp>

#include "cli_args.hpp"
#include "commands.hpp"
#include "common_options.hpp"
#include "parashade/command_files.hpp"
#include "parashade/device.hpp"
#include "parashade/report.hpp"

namespace parashade::cli {
namespace {

struct DevicesArgs {
  std::string report;
  bool json = false, quiet = false;
};

int run(const DevicesArgs& a) {
  CommandFiles files;
  files.output("--report", a.report);
  files.check();
  const auto devices = list_devices();
  const int chosen = default_device(devices);  // what render takes without --device and PARASHADE_DEVICE
  nlohmann::json list = nlohmann::json::array();
  for (const auto& d : devices) list.push_back(to_json(d));
  if (!a.report.empty()) write_report(a.report, {{"devices", list}, {"default_device", chosen}}, "devices");
  if (a.json) {  // deprecated: the bare array, as before, for one release
    std::cerr << "parashade: warning: devices --json is deprecated and goes in the next release; use --report FILE "
                 "(a versioned report, docs/reports.md)\n";
    std::cout << list.dump(2) << "\n";  // stdout holds the bare array alone: no "wrote" line
    return 0;
  }
  for (const auto& d : devices) {
    std::cout << d.index << ": " << d.name << (d.index == chosen ? "  (the default)" : "") << "\n"
              << "   platform " << d.platform << ", " << d.type << ", " << d.compute_units << " compute units, "
              << d.global_memory / (1024 * 1024) << " MiB, " << d.version << ", driver " << d.driver << "\n";
  }
  std::cout.flush();
  print_wrote({a.report});
  return 0;
}

}  // namespace

Command add_devices_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("devices", "List every OpenCL platform and device with its compute units");
  auto a = std::make_shared<DevicesArgs>();
  add_report_option(*cmd, a->report, "every device");
  cmd->add_flag("--json", a->json, "Deprecated: print the devices as a JSON array instead of the table (use --report)");
  add_quiet_flag(*cmd, a->quiet);  // nothing to silence: devices prints results only
  return {cmd, [a]() { return run(*a); }};
}

}  // namespace parashade::cli
