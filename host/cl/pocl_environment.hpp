#pragma once
// The environment PoCL reads when it starts, made usable or refused before it does (issue 46, item 7):
// - POCL_CACHE_DIR set but empty made PoCL abort on an assertion: it is unset, so PoCL takes its default.
// - The folder PoCL keeps compiled kernels in (POCL_CACHE_DIR, else $XDG_CACHE_HOME/pocl/kcache, else
//   $HOME/.cache/pocl/kcache, else /tmp/pocl/kcache) must be creatable and writable: an unusable one made
//   PoCL report "no device" or fail builds with an empty log. Throws DeviceError (exit 4) naming the
//   variable, the path and the reason.
// - Without PATH (env -i) PoCL's compiler could not find the linker `ld` and a cold kernel cache aborted
//   the process: an unset or empty PATH gets the system's default search path (confstr _CS_PATH).
#include <string>

namespace parashade {

void prepare_pocl_environment();

// Where PoCL keeps the kernels it compiles, for the notice of a long build: "first run; cached in DIR",
// or "PoCL's kernel cache is off: POCL_KERNEL_CACHE=0".
std::string pocl_kernel_cache_place();

}  // namespace parashade
