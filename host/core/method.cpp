#include "parashade/method.hpp"

#include "parashade/errors.hpp"

namespace parashade {

Method parse_method(const std::string& name) {
  if (name == "flat") return Method::flat;
  if (name == "gouraud") return Method::gouraud;
  if (name == "phong") return Method::phong;
  throw UsageError("unknown method '" + name + "' (valid: flat, gouraud, phong)");
}

const char* method_name(Method m) {
  switch (m) {
    case Method::flat: return "flat";
    case Method::gouraud: return "gouraud";
    case Method::phong: return "phong";
  }
  return "?";
}

}  // namespace parashade
