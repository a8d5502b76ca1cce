#pragma once
// Numbers in the scene loaders' messages: three significant digits ("3e+38", "1.41e+38", "0.05").
#include <sstream>
#include <string>

namespace parashade {

inline std::string short_number(double v) {
  std::ostringstream s;
  s.precision(3);
  s << v;
  return s.str();
}

}  // namespace parashade
