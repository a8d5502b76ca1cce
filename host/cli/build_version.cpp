#include "build_version.hpp"

namespace parashade::cli {

std::string build_version() {
  std::string v = PARASHADE_VERSION;
#ifdef PARASHADE_GIT_HASH
  if (*PARASHADE_GIT_HASH) v += std::string("+") + PARASHADE_GIT_HASH;
#endif
  return v;
}

}  // namespace parashade::cli
