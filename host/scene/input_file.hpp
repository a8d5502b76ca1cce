#pragma once
// Checks on a file before it is read: a scene, mesh, image or triangle list path must name a regular file
// (a FIFO would block the reader forever, a link to /dev/zero or /dev/urandom would feed it without end)
// of at most a limit.
#include <cstdint>
#include <filesystem>
#include <string>

namespace parashade::detail {

constexpr std::uintmax_t kMaxSceneFileBytes = 16ull << 20;  // 16 MiB: scenes hold parameters, not geometry
constexpr std::uintmax_t kMaxMeshFileBytes = 4ull << 30;    // 4 GiB
constexpr std::uintmax_t kMaxImageFileBytes = 4ull << 30;   // 4 GiB: a 4096x4096 float EXR is 192 MiB
constexpr std::uintmax_t kMaxListFileBytes = 256ull << 20;  // 256 MiB: 25 M indices of 10 digits

// Throws InputError "<name>: no such file", "<name>: not a regular file (a FIFO)", "<name>: N bytes,
// more than the limit of M bytes for a <what>". Follows symbolic links (a link to a regular file is fine).
void check_input_file(const std::filesystem::path& path, const std::string& name, std::uintmax_t max_bytes,
                      const std::string& what);

}  // namespace parashade::detail
