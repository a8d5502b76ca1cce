#include "parashade/edge_dda.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <climits>
#include <cstdint>

namespace parashade {

std::vector<glm::ivec2> dda_segment(glm::ivec2 a, glm::ivec2 b) {
  const int dx = b.x - a.x, dy = b.y - a.y;
  const int sx = dx < 0 ? -1 : 1, sy = dy < 0 ? -1 : 1;
  const bool x_major = std::abs(dx) >= std::abs(dy);
  const int bp = std::max(std::abs(dx), std::abs(dy)), mp = std::min(std::abs(dx), std::abs(dy));
  std::vector<glm::ivec2> out;
  out.reserve(std::size_t(bp) + 1);
  glm::ivec2 p = a;
  int of = bp / 2;  // OF0 = floor(BP / 2)
  out.push_back(p);
  for (int i = 0; i < bp; ++i) {
    of += mp;
    const bool minor_step = of >= bp;
    if (minor_step) of -= bp;
    if (x_major) {
      p.x += sx;
      if (minor_step) p.y += sy;
    } else {
      p.y += sy;
      if (minor_step) p.x += sx;
    }
    out.push_back(p);
  }
  return out;
}

DdaSpans dda_spans(glm::ivec2 a, glm::ivec2 b, glm::ivec2 c) {
  DdaSpans s;
  s.y0 = std::min({a.y, b.y, c.y});
  const int y1 = std::max({a.y, b.y, c.y});
  s.rows.assign(std::size_t(y1 - s.y0) + 1, glm::ivec2(INT32_MAX, INT32_MIN));
  for (const auto& [p, q] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, a}}) {
    for (const glm::ivec2& px : dda_segment(p, q)) {
      glm::ivec2& row = s.rows[std::size_t(px.y - s.y0)];
      row = {std::min(row.x, px.x), std::max(row.y, px.x)};
    }
  }
  return s;  // every row between the top and bottom vertex holds an edge pixel: the edges are 8-connected
}

std::vector<glm::ivec2> dda_fill(glm::ivec2 a, glm::ivec2 b, glm::ivec2 c) {
  const DdaSpans s = dda_spans(a, b, c);
  std::vector<glm::ivec2> out;
  for (std::size_t i = 0; i < s.rows.size(); ++i)
    for (int x = s.rows[i].x; x <= s.rows[i].y; ++x) out.push_back({x, s.y0 + int(i)});
  return out;
}

EdgeIntensityError edge_intensity_error(glm::ivec2 a, glm::ivec2 b, glm::ivec2 c, double ia, double ib, double ic) {
  // The plane through the vertices (at their pixel addresses).
  const glm::dvec2 e1(b - a), e2(c - a);
  const double det = e1.x * e2.y - e2.x * e1.y;
  const double gx = ((ib - ia) * e2.y - (ic - ia) * e1.y) / det, gy = ((ic - ia) * e1.x - (ib - ia) * e2.x) / det;
  EdgeIntensityError r;
  const int dx = b.x - a.x, dy = b.y - a.y;
  r.major = std::max(std::abs(dx), std::abs(dy));
  r.minor = std::min(std::abs(dx), std::abs(dy));
  r.source_bound = r.minor > 0 ? std::abs(ib - ia) / (2.0 * r.minor) : 0.0;
  r.plane_bound = 0.5 * std::abs(std::abs(dx) >= std::abs(dy) ? gy : gx);
  if (r.major == 0) return r;
  const std::vector<glm::ivec2> px = dda_segment(a, b);
  const double step = (ib - ia) / r.major;  // the edge increment, one per clock
  for (std::size_t i = 0; i < px.size(); ++i) {
    const double edge = ia + step * double(i);
    const double plane = ia + gx * (px[i].x - a.x) + gy * (px[i].y - a.y);
    r.max_error = std::max(r.max_error, std::abs(edge - plane));
  }
  return r;
}

}  // namespace parashade
