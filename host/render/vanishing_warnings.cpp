#include "vanishing_warnings.hpp"

#include <cstddef>
#include <cstdint>

namespace parashade {

void warn_vanishing(const FrameStats& stats, const RenderedImage& image, std::ostream& err) {
  const std::uint64_t on_screen = stats.geometry.triangles_out;
  if (stats.parity_dropped > 0)
    err << "parashade: warning: the sierpinski unit's vertex snap made " << stats.parity_dropped << " of " << on_screen
        << " screen triangles degenerate: they are not drawn (a smaller depth, the :touch or :overlap grid, or "
           "larger triangles keep them)\n";
  const GeometryStats& g = stats.geometry;
  if (on_screen == 0 && g.triangles_in > 0) {
    // Nothing reached the screen: say why, so that an empty image is not taken for a rendered one (a mesh whose
    // vertices all coincide rendered an empty frame without a word: issue 46, item 17).
    err << "parashade: warning: nothing drawn: none of the " << g.triangles_in << " triangles reached the screen ("
        << g.zero_area << " of zero area, " << g.culled_backface << " culled as back faces, " << g.outside
        << " outside the view, " << g.non_finite << " with non-finite coordinates)\n";
    return;
  }
  if (on_screen == 0) return;
  const std::size_t pixels = std::size_t(image.width) * std::size_t(image.height);
  for (std::size_t p = 0; p < pixels; ++p)
    if (image.covered(p)) return;
  err << "parashade: warning: nothing drawn: " << on_screen << " triangles reached the screen and cover no pixel ("
      << stats.triangles_without_pixels << " of them contain no pixel centre";
  if (stats.parity_dropped > 0) err << ", " << stats.parity_dropped << " dropped by the vertex snap";
  err << ")\n";
}

}  // namespace parashade
