#pragma once
// One entry of the tune cache (tune_cache.hpp) checked before it is used: a hand or another program may
// have broken it, and a broken entry was used and printed as if valid (work_items -1), refused as a usage
// error, or ended `tune` with an internal error (a string where a number belongs). An entry with a fault
// is set aside: not used, counted in one warning, kept in the file.
#include <string>

#include <nlohmann/json.hpp>

namespace parashade {

// "" when `entry` is a whole, valid entry of the format the cache writes; else its first fault, e.g.
// "params.work_items is -1, not a count of work-items".
std::string tune_entry_fault(const nlohmann::json& entry);

}  // namespace parashade
