#include "register_events_report.hpp"

#include <string>

namespace parashade {

nlohmann::json register_events_json(const RegisterEvents& e) {
  return {{"spans", e.spans},
          {"span_pixels", e.span_pixels},
          {"wrapped_pixels", e.wrapped_pixels},
          {"wrapped_spans", e.wrapped_spans},
          {"saturated_loads", e.saturated_loads},
          {"note", "counted on the host by the units' golden models over the frame's spans (hidden pixels "
                   "included); a wrapped pixel's register lost a carry: it is off by about 2^I levels"}};
}

void warn_register_events(const RegisterEvents& e, const Arithmetic& a, std::ostream& err) {
  const std::string format = arith_name(a);
  if (e.wrapped_pixels > 0)
    err << "parashade: warning: " << format << " span registers wrapped around on " << e.wrapped_pixels << " of "
        << e.span_pixels << " span pixels (" << e.wrapped_spans << " spans): those pixels are off by about 2^"
        << a.int_bits << " levels; more integer bits (fixed:I.F with a larger I) avoid it\n";
  if (e.saturated_loads > 0)
    err << "parashade: warning: " << format << ": " << e.saturated_loads
        << " span register loads saturated (a value or increment beyond the " << a.int_bits
        << " integer bits)\n";
}

}  // namespace parashade
