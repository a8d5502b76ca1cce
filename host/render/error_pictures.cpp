#include "error_pictures.hpp"

#include <cstdio>

#include "parashade/error_map.hpp"
#include "parashade/metrics.hpp"

namespace parashade {

StagedFile stage_error_map(const std::filesystem::path& path, const RenderedImage& image,
                           const std::vector<std::uint8_t>& covered, const std::vector<glm::dvec3>& reference,
                           const std::vector<std::uint8_t>& flipped, std::vector<std::string>& lines) {
  const std::vector<double> errors = pixel_errors(image, covered, reference, flipped);
  StagedFile file = stage_image(path, error_map_image(errors, image.width, image.height));
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.2f", error_scale_top(errors));
  lines.push_back("error map " + path.string() + ": scale 0.." + buf + " levels (its top is the largest error, at least 1)");
  return file;
}

}  // namespace parashade
