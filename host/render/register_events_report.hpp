#pragma once
// What `render` says about a fixed-point frame's register wraps and saturations (register_events.hpp):
// the report's "registers" section and a warning on stderr when there are any.
#include <ostream>

#include <nlohmann/json.hpp>

#include "parashade/register_events.hpp"
#include "parashade/units.hpp"

namespace parashade {

nlohmann::json register_events_json(const RegisterEvents& e);
// One "parashade: warning:" line per kind of event that happened; nothing when none did.
void warn_register_events(const RegisterEvents& e, const Arithmetic& a, std::ostream& err);

}  // namespace parashade
