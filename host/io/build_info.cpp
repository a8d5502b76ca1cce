// Set from CMake on this file only (CMakeLists.txt): a new commit reconfigured recompiles this file, not
// every translation unit.
#include "parashade/build_info.hpp"

#ifndef PARASHADE_VERSION
#error "PARASHADE_VERSION must be defined by the build (CMake's project VERSION)"
#endif
#ifndef PARASHADE_GIT_HASH
#define PARASHADE_GIT_HASH "unknown"
#endif

namespace parashade {

const char* parashade_version() { return PARASHADE_VERSION; }
const char* parashade_git_hash() { return PARASHADE_GIT_HASH; }

}  // namespace parashade
