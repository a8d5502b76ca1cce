#include "device_option.hpp"

namespace parashade::cli {

CLI::Option* add_device_option(CLI::App& cmd, std::string& device, const std::string& help) {
  return cmd.add_option("--device", device,
                        help + ". Default: the PARASHADE_DEVICE environment variable when set, else the real device "
                               "with the most compute units ('parashade devices' marks it)");
}

}  // namespace parashade::cli
