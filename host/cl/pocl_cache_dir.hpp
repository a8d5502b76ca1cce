#pragma once
// POCL_CACHE_DIR checked before PoCL sees it: PoCL keeps every compiled kernel there, and an unusable
// folder made it report "no device" (a path under a regular file) or fail builds with an empty log (a
// read-only folder). Throws DeviceError (exit 4) naming the variable, the path and the reason.
namespace parashade {

void check_pocl_cache_dir();

}  // namespace parashade
