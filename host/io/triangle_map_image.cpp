// An ID buffer of the exact reference's visibility (image.hpp): which triangle each pixel shows, for
// studies that need the pixels grouped by triangle (scripts/mix_oracle.py).
#include <algorithm>
#include <cctype>
#include <string>

#include "parashade/errors.hpp"
#include "parashade/image.hpp"

namespace parashade {

RenderedImage triangle_map_image(const std::vector<std::int32_t>& triangle, int width, int height) {
  if (width < 1 || height < 1 || triangle.size() != std::size_t(width) * std::size_t(height))
    throw InputError("triangle_map_image: " + std::to_string(triangle.size()) + " indices for a " +
                     std::to_string(width) + "x" + std::to_string(height) + " image");
  constexpr std::int32_t kLargest = (1 << 24) - 2;  // plus one must fit in 24 bits
  RenderedImage image;
  image.width = width;
  image.height = height;
  image.rgba.resize(4 * triangle.size());
  for (std::size_t p = 0; p < triangle.size(); ++p) {
    const std::int32_t t = triangle[p];
    if (t > kLargest)
      throw InputError("--triangle-map: triangle " + std::to_string(t) + " does not fit the map's 24 bits");
    const std::uint32_t id = t < 0 ? 0u : std::uint32_t(t) + 1u;
    image.rgba[4 * p] = std::uint8_t(id >> 16);
    image.rgba[4 * p + 1] = std::uint8_t(id >> 8);
    image.rgba[4 * p + 2] = std::uint8_t(id);
    image.rgba[4 * p + 3] = 255;
  }
  return image;
}

void check_triangle_map_destination(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (ext != ".png" && ext != ".tif" && ext != ".tiff" && ext != ".ppm")
    throw InputError("cannot write " + path.string() +
                     ": a triangle map needs a lossless 8-bit format (png, tif, ppm)");
  check_image_destination(path);
}

}  // namespace parashade
