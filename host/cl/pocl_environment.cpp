#include "pocl_environment.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <system_error>

#include "parashade/errors.hpp"

namespace parashade {
namespace {

namespace fs = std::filesystem;

const char* set_value(const char* name) {
  const char* value = std::getenv(name);
  return value && *value ? value : nullptr;
}

// The folder PoCL 3.1 keeps its kernel cache in (pocl_cache_init_topdir) and the variable that chose it.
struct CacheFolder {
  std::string variable, value;
  fs::path folder;
};

CacheFolder pocl_cache_folder() {
  if (const char* v = set_value("POCL_CACHE_DIR")) return {"POCL_CACHE_DIR", v, v};
  // As PoCL joins them ("%s/pocl/kcache"): an empty HOME gives /.cache/pocl/kcache.
  if (const char* v = set_value("XDG_CACHE_HOME")) return {"XDG_CACHE_HOME", v, std::string(v) + "/pocl/kcache"};
  if (const char* v = std::getenv("HOME")) return {"HOME", v, std::string(v) + "/.cache/pocl/kcache"};
  return {"", "", "/tmp/pocl/kcache"};
}

// PoCL creates the folder and its parents: the nearest existing one must be a writable folder.
void check_cache_folder(const CacheFolder& c) {
  const std::string named = c.variable.empty() ? "PoCL's kernel cache folder '" + c.folder.string() + "'"
                                               : c.variable + "='" + c.value + "'";
  const std::string fix = ": PoCL keeps its compiled kernels in '" + c.folder.string() + "'; " +
                          (c.variable == "POCL_CACHE_DIR" ? "point POCL_CACHE_DIR at a writable folder or unset it"
                                                          : "point POCL_CACHE_DIR at a writable folder");
  fs::path at = fs::absolute(c.folder);
  std::error_code ec;
  while (!fs::exists(at, ec) && at.has_relative_path()) at = at.parent_path();
  if (!fs::is_directory(at, ec))
    throw DeviceError(named + " is unusable: '" + at.string() + "' is not a folder" + fix);
  if (::access(at.c_str(), W_OK | X_OK) != 0)
    throw DeviceError(named + " is unusable: '" + at.string() + "': " + std::strerror(errno) + fix);
}

}  // namespace

std::string pocl_kernel_cache_place() {
  if (const char* off = set_value("POCL_KERNEL_CACHE"); off && std::string(off) == "0")
    return "PoCL's kernel cache is off: POCL_KERNEL_CACHE=0";
  return "first run; cached in " + pocl_cache_folder().folder.string();
}

void prepare_pocl_environment() {
  if (const char* v = std::getenv("POCL_CACHE_DIR"); v && !*v) ::unsetenv("POCL_CACHE_DIR");
  check_cache_folder(pocl_cache_folder());
  if (!set_value("PATH")) {
    const std::size_t n = ::confstr(_CS_PATH, nullptr, 0);
    std::string path(n > 0 ? n : 1, '\0');
    if (n > 0) ::confstr(_CS_PATH, path.data(), n);
    path.resize(std::strlen(path.c_str()));
    ::setenv("PATH", path.empty() ? "/usr/bin:/bin" : path.c_str(), 1);
  }
}

}  // namespace parashade
