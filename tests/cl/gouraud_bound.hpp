#pragma once
// The float Gouraud kernel's error bound against its double-precision ideal (docs/error-bounds.md), per
// frame: the largest over the screen triangles. Shared by the kernel and hard-case tests.
#include <algorithm>
#include <cmath>

#include "parashade/screen_geometry.hpp"

namespace parashade::testing_support {

// Gouraud: each channel is ref + ddy*dy + ddx*dx in float from float coefficients, so
// |I - I*| <= 8u (max|I_v| + |ddx| w + |ddy| h) over the triangle's box (docs/error-bounds.md).
inline double gouraud_bound(const ScreenGeometry& g) {
  double worst = 0.0;
  for (const glm::uvec3& t : g.triangles) {
    const glm::dvec2 p[3] = {glm::dvec2(g.xy[t.x]) / double(kSubpixel), glm::dvec2(g.xy[t.y]) / double(kSubpixel),
                             glm::dvec2(g.xy[t.z]) / double(kSubpixel)};
    const double w = std::max({p[0].x, p[1].x, p[2].x}) - std::min({p[0].x, p[1].x, p[2].x}) + 1.0;
    const double h = std::max({p[0].y, p[1].y, p[2].y}) - std::min({p[0].y, p[1].y, p[2].y}) + 1.0;
    for (int c = 0; c < 3; ++c) {
      const double i0 = g.color[t.x][c], i1 = g.color[t.y][c], i2 = g.color[t.z][c];
      const double det = (p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[2].x - p[0].x) * (p[1].y - p[0].y);
      const double ddx = ((i1 - i0) * (p[2].y - p[0].y) - (i2 - i0) * (p[1].y - p[0].y)) / det;
      const double ddy = ((i2 - i0) * (p[1].x - p[0].x) - (i1 - i0) * (p[2].x - p[0].x)) / det;
      const double imax = std::max({std::abs(i0), std::abs(i1), std::abs(i2)});
      worst = std::max(worst, 8.0 * (1.0 / (1 << 24)) * (imax + std::abs(ddx) * w + std::abs(ddy) * h));
    }
  }
  return worst;
}

}  // namespace parashade::testing_support
