// The --distribute values; compiled with or without MPI.
#include "parashade/distributed.hpp"

#include "parashade/errors.hpp"

namespace parashade {

Distribute parse_distribute(const std::string& name) {
  if (name == "sort-last") return Distribute::sort_last;
  if (name == "sort-first") return Distribute::sort_first;
  throw UsageError("unknown --distribute '" + name + "' (valid: sort-last, sort-first)");
}

const char* distribute_name(Distribute d) { return d == Distribute::sort_last ? "sort-last" : "sort-first"; }

DeviceMode distribute_device_mode(Distribute d) {
  return d == Distribute::sort_last ? DeviceMode::ranks_sort_last : DeviceMode::ranks_sort_first;
}

}  // namespace parashade
