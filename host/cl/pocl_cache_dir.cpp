#include "pocl_cache_dir.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <system_error>

#include "parashade/errors.hpp"

namespace parashade {

void check_pocl_cache_dir() {
  const char* value = std::getenv("POCL_CACHE_DIR");
  if (!value || !*value) return;
  namespace fs = std::filesystem;
  const std::string fix = ": PoCL keeps its compiled kernels there; point POCL_CACHE_DIR at a writable folder or unset it";
  // PoCL creates the folder and its parents: the nearest existing one must be a writable folder.
  fs::path at = fs::absolute(fs::path(value));
  std::error_code ec;
  while (!fs::exists(at, ec) && at.has_relative_path()) at = at.parent_path();
  if (!fs::is_directory(at, ec))
    throw DeviceError(std::string("POCL_CACHE_DIR='") + value + "' is unusable: '" + at.string() +
                      "' is not a folder" + fix);
  if (::access(at.c_str(), W_OK | X_OK) != 0)
    throw DeviceError(std::string("POCL_CACHE_DIR='") + value + "' is unusable: '" + at.string() + "': " +
                      std::strerror(errno) + fix);
}

}  // namespace parashade
