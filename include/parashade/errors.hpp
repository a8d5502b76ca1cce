#pragma once
// Errors carry the process exit code the CLI documents: 2 usage, 3 bad input, 4 OpenCL/device.
#include <stdexcept>
#include <string>

namespace parashade {

enum class ExitCode : int { ok = 0, usage = 2, bad_input = 3, device = 4, internal = 1 };

class Error : public std::runtime_error {
 public:
  Error(ExitCode code, const std::string& message) : std::runtime_error(message), code_(code) {}
  ExitCode code() const { return code_; }

 private:
  ExitCode code_;
};

// A command line that cannot be understood (unknown option, malformed value syntax).
struct UsageError : Error {
  explicit UsageError(const std::string& m) : Error(ExitCode::usage, m) {}
};
// A scene, mesh or value that is wrong; the message names the file or value at fault.
struct InputError : Error {
  explicit InputError(const std::string& m) : Error(ExitCode::bad_input, m) {}
};
// No platform, no device, kernel build failure, out of resources.
struct DeviceError : Error {
  explicit DeviceError(const std::string& m) : Error(ExitCode::device, m) {}
};

}  // namespace parashade
