// An image from values in levels (image.hpp): the reference's double values as a writable picture.
#include <algorithm>
#include <cmath>

#include "parashade/errors.hpp"
#include "parashade/image.hpp"

namespace parashade {

RenderedImage levels_image(const std::vector<glm::dvec3>& levels, int width, int height) {
  if (width < 1 || height < 1 || levels.size() != std::size_t(width) * std::size_t(height))
    throw InputError("levels_image: " + std::to_string(levels.size()) + " values for a " + std::to_string(width) +
                     "x" + std::to_string(height) + " image");
  RenderedImage image;
  image.width = width;
  image.height = height;
  image.rgba.resize(4 * levels.size());
  image.rgb_float.resize(3 * levels.size());
  for (std::size_t p = 0; p < levels.size(); ++p) {
    for (int c = 0; c < 3; ++c) {
      const double v = std::clamp(levels[p][c], 0.0, 255.0);
      image.rgba[4 * p + c] = std::uint8_t(std::floor(v + 0.5));  // nearest level, halves up
      image.rgb_float[3 * p + c] = float(levels[p][c]);
    }
    image.rgba[4 * p + 3] = 255;
  }
  return image;
}

}  // namespace parashade
