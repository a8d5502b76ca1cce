#include "input_file.hpp"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>

#include "parashade/errors.hpp"

namespace parashade::detail {

void check_input_file(const std::filesystem::path& path, const std::string& name, std::uintmax_t max_bytes,
                      const std::string& what) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0)
    throw InputError(name + (errno == ENOENT ? std::string(": no such file") : ": " + std::string(std::strerror(errno))));
  if (S_ISDIR(st.st_mode)) throw InputError(name + ": is a directory, not a " + what);
  if (!S_ISREG(st.st_mode)) {
    const char* kind = S_ISFIFO(st.st_mode)  ? "a FIFO"
                       : S_ISCHR(st.st_mode) ? "a character device"
                       : S_ISBLK(st.st_mode) ? "a block device"
                       : S_ISSOCK(st.st_mode) ? "a socket"
                                              : "not a file";
    throw InputError(name + ": not a regular file (" + kind + ")");
  }
  if (std::uintmax_t(st.st_size) > max_bytes)
    throw InputError(name + ": " + std::to_string(st.st_size) + " bytes, more than the limit of " +
                     std::to_string(max_bytes) + " bytes for a " + what);
}

}  // namespace parashade::detail
