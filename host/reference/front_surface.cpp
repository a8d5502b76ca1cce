// Which front surface the image shows where float depth cannot settle it (reference.hpp, depth_ties).
#include <algorithm>

#include "parashade/metrics.hpp"
#include "parashade/reference.hpp"

namespace parashade {

std::vector<std::uint8_t> front_surface_flips(const RenderedImage& image, const ReferenceImage& ref) {
  std::vector<std::uint8_t> flipped;
  if (ref.depth_ties.empty()) return flipped;
  flipped.assign(ref.ideal.size(), 0);
  const auto largest = [](const glm::dvec3& e) { return std::max({e.x, e.y, e.z}); };
  for (const ReferenceImage::DepthTie& tie : ref.depth_ties) {
    const std::size_t p = tie.pixel;
    if (p >= flipped.size() || !image.covered(p) || ref.covered[p] == 0) continue;
    // The image is nearer the other surface's ideal than the visible one's: it kept the other surface.
    if (largest(channel_errors(image, p, tie.ideal)) < largest(channel_errors(image, p, ref.ideal[p]))) flipped[p] = 1;
  }
  return flipped;
}

}  // namespace parashade
