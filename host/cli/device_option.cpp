#include "device_option.hpp"

#include <cstdlib>

namespace parashade::cli {

namespace {
constexpr const char* kDeviceVariable = "PARASHADE_DEVICE";
}

CLI::Option* add_device_option(CLI::App& cmd, std::string& device, const std::string& help) {
  return cmd.add_option("--device", device,
                        help + ". Default: the PARASHADE_DEVICE environment variable when set, else the first device");
}

std::string device_from_environment(std::string& device) {
  const char* value = std::getenv(kDeviceVariable);
  if (!device.empty() || !value || !*value) return "--device";
  device = value;
  return std::string(kDeviceVariable) + "='" + device + "' (the device when --device is not given)";
}

}  // namespace parashade::cli
