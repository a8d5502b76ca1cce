#include "parashade/dda_coverage.hpp"

#include <algorithm>

#include "parashade/edge_dda.hpp"
#include "parashade/setup.hpp"

namespace parashade {

DdaRowTable apply_dda_coverage(const ScreenGeometry& g, TriangleGeometry* records, float* attrs, FixedPlanes* fixed) {
  DdaRowTable table;
  table.first.resize(g.triangles.size());
  for (std::size_t t = 0; t < g.triangles.size(); ++t) {
    table.first[t] = std::uint32_t(table.rows.size() / 2);
    TriangleGeometry& r = records[t];
    if (r.x0 > r.x1) continue;  // no pixel centre: setup made no planes
    const glm::uvec3 tri = g.triangles[t];
    const auto address = [&](std::uint32_t v) {
      return glm::ivec2(int(floor_div(g.xy[v].x, kSubpixel)), int(floor_div(g.xy[v].y, kSubpixel)));
    };
    const DdaSpans spans = dda_spans(address(tri.x), address(tri.y), address(tri.z));
    // Clamp to the screen and find the new box.
    int x0 = g.width, x1 = -1, y0 = -1, y1 = -1;
    for (std::size_t i = 0; i < spans.rows.size(); ++i) {
      const int y = spans.y0 + int(i);
      const int xl = std::max(0, spans.rows[i].x), xr = std::min(g.width - 1, spans.rows[i].y);
      if (y < 0 || y >= g.height || xl > xr) continue;
      if (y0 < 0) y0 = y;
      y1 = y;
      x0 = std::min(x0, xl);
      x1 = std::max(x1, xr);
    }
    if (y0 < 0) {
      r.x0 = 1;  // empty box
      r.x1 = 0;
      continue;
    }
    const TriangleGeometry before = r;
    float* a = attrs + t * GOURAUD_ATTR_FLOATS;
    float attr_before[GOURAUD_ATTR_FLOATS];
    std::copy(a, a + GOURAUD_ATTR_FLOATS, attr_before);
    const FixedPlanes fixed_before = fixed ? fixed[t] : FixedPlanes{};
    move_plane_anchor(before, attr_before, fixed ? &fixed_before : nullptr, x0, y0, r, a, fixed ? &fixed[t] : nullptr);
    r.x0 = ps_short(x0), r.y0 = ps_short(y0), r.x1 = ps_short(x1), r.y1 = ps_short(y1);
    // The row table replaces the edge functions: zero ones make binning take every tile of the box.
    for (int e = 0; e < 3; ++e) {
      r.edge_c[e] = 0;
      r.edge_a[e] = r.edge_b[e] = 0;
    }
    for (int y = y0; y <= y1; ++y) {
      const glm::ivec2 s = spans.rows[std::size_t(y - spans.y0)];
      const int xl = std::max(0, s.x), xr = std::min(g.width - 1, s.y);
      table.rows.push_back(xl <= xr ? xl - x0 : 1);
      table.rows.push_back(xl <= xr ? xr - x0 : 0);
    }
  }
  return table;
}

}  // namespace parashade
