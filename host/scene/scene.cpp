// Scene queries and the resolution limit every scene source shares.
#include <regex>
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

std::optional<std::pair<int, int>> parse_size(const std::string& size) {
  if (size.empty()) return std::nullopt;
  std::smatch m;
  if (!std::regex_match(size, m, std::regex(R"((\d{1,9})x(\d{1,9}))")))
    throw UsageError("--size '" + size + "' is not of the form WIDTHxHEIGHT, e.g. 1920x1080");
  return std::make_pair(std::stoi(m[1]), std::stoi(m[2]));
}

}  // namespace parashade
