#include "parashade/choice_pixels.hpp"

#include <stdexcept>
#include <string>

namespace parashade {

ChoicePixels visible_pixels_by_method(const std::vector<std::int32_t>& visible,
                                      const std::vector<TriangleShading>& choice) {
  ChoicePixels p;
  for (const std::int32_t t : visible) {
    if (t < 0) continue;
    if (std::size_t(t) >= choice.size())
      throw std::invalid_argument("visible triangle " + std::to_string(t) + " has no method choice (" +
                                  std::to_string(choice.size()) + " triangles chosen)");
    switch (choice[std::size_t(t)].method) {
      case TriangleMethod::gouraud: ++p.gouraud; break;
      case TriangleMethod::segments: ++p.segments; break;
      case TriangleMethod::phong: ++p.phong; break;
    }
  }
  return p;
}

}  // namespace parashade
