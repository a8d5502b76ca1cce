// Scene queries and the resolution limit every scene source shares.
#include <string>

#include "parashade/errors.hpp"
#include "parashade/scene.hpp"

namespace parashade {

std::size_t Scene::triangle_count() const {
  std::size_t n = 0;
  for (const Object& o : objects)
    if (o.mesh) n += o.mesh->triangles.size();
  return n;
}

void check_resolution(int width, int height, const std::string& what) {
  const auto check = [&](int value, const char* axis) {
    if (value < 1) throw InputError(what + ": " + axis + " " + std::to_string(value) + " must be at least 1");
    if (value > kMaxResolution)
      throw InputError(what + ": " + axis + " " + std::to_string(value) +
                       " is larger than the 12-bit screen address limit " + std::to_string(kMaxResolution));
  };
  check(width, "width");
  check(height, "height");
}

}  // namespace parashade
