#include "parashade/highlight.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>

#include "parashade/light_bounds.hpp"
#include "parashade/parallel.hpp"

namespace parashade {

double negligible_cosine(const Light& l, const Material& m, double negligible_levels) {
  double peak = 0.0;
  for (int c = 0; c < 3; ++c) peak = std::max(peak, 255.0 * double(l.color[c]) * double(m.specular[c]));
  if (!(peak > negligible_levels)) return 1.0;
  return std::pow(negligible_levels / peak, 1.0 / double(m.shininess));
}

std::vector<double> negligible_cosines(const Scene& s, double negligible_levels) {
  std::vector<double> out;
  for (const Material& m : s.materials)
    for (const Light& l : s.lights) out.push_back(negligible_cosine(l, m, negligible_levels));
  return out;
}

HighlightMarks mark_highlights(const Scene& s, const ScreenGeometry& g, float* attributes, std::size_t stride, int slot,
                               double negligible_levels) {
  const std::vector<double> thresholds = negligible_cosines(s, negligible_levels);
  std::atomic<std::uint64_t> without{0}, skipped{0};
  parallel_for_ranges(g.triangles.size(), 2048, [&](std::size_t first, std::size_t last) {
    std::uint64_t range_without = 0, range_skipped = 0;
    for (std::size_t t = first; t < last; ++t) {
      const TriangleFrame f = triangle_frame(s, g, t);
      const double* threshold = &thresholds[g.material[t] * s.lights.size()];
      unsigned mask = 0;
      for (std::size_t i = 0; i < s.lights.size(); ++i) {
        if (light_bounds(f, s.lights[i], threshold[i]).max_n_dot_h > threshold[i]) mask |= 1u << i;
        else ++range_skipped;
      }
      attributes[t * stride + slot] = float(mask);
      range_without += mask == 0;
    }
    without += range_without;
    skipped += range_skipped;
  });
  return {g.triangles.size(), without.load(), skipped.load()};
}

}  // namespace parashade
