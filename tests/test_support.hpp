#pragma once
// Helpers shared by the test programs.
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>

namespace parashade::testing_support {

// ../shared/meshes as given by PARASHADE_MESH_DIR; nullopt (and the test skips) when unset or absent.
inline std::optional<std::filesystem::path> mesh_dir() {
  const char* dir = std::getenv("PARASHADE_MESH_DIR");
  if (!dir || !*dir || !std::filesystem::is_directory(dir)) return std::nullopt;
  return std::filesystem::path(dir);
}

#define PARASHADE_REQUIRE_MESH_DIR(var)                                                        \
  const auto var##_opt = ::parashade::testing_support::mesh_dir();                             \
  if (!var##_opt) GTEST_SKIP() << "PARASHADE_MESH_DIR is not set (or not a directory): skipping";\
  const std::filesystem::path var = *var##_opt

inline std::filesystem::path source_dir() { return PARASHADE_SOURCE_DIR; }

}  // namespace parashade::testing_support
