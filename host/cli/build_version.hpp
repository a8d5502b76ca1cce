#pragma once
// What build of parashade made a result: the project version, and the git commit when the build knows
// it (PARASHADE_GIT_HASH, a compile definition). The tune cache keys its entries on it: a timing from
// another build of the kernels or the host stages says nothing about this one.
#include <string>

namespace parashade::cli {

// "0.1.0", or "0.1.0+abc1234" with PARASHADE_GIT_HASH defined.
std::string build_version();

}  // namespace parashade::cli
