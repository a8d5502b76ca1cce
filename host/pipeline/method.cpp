#include "parashade/method.hpp"

#include "parashade/combined.hpp"
#include "parashade/errors.hpp"

namespace parashade {

Method parse_method(const std::string& name) {
  if (name == "flat") return Method::flat;
  if (name == "gouraud") return Method::gouraud;
  if (name == "phong") return Method::phong;
  if (name.compare(0, 9, "combined:") == 0) {
    parse_combined(name);  // validates K
    return Method::combined;
  }
  throw UsageError("unknown method '" + name + "' (valid: flat, gouraud, phong, combined:K (K = 0.." +
                   std::to_string(kCombinedMaxK) + "), combined:auto)");
}

const char* method_name(Method m) {
  switch (m) {
    case Method::flat: return "flat";
    case Method::gouraud: return "gouraud";
    case Method::phong: return "phong";
    case Method::combined: return "combined";
  }
  return "?";
}

}  // namespace parashade
