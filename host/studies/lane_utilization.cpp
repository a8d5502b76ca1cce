#include "parashade/lane_utilization.hpp"

#include <algorithm>

#include "parashade/parallel.hpp"
#include "parashade/planner.hpp"

namespace parashade {
namespace {

constexpr int kLanes = VEC;  // a row segment's pixels, and a stamp's (4 x 4)
constexpr int kStamp = 4;

struct Count {
  std::uint64_t covered = 0, row_lanes = 0, stamp_lanes = 0;
};

// One triangle in one tile, as render_tiles.cl walks it.
void walk(const TriangleGeometry& t, int tile_x, int tile_y, int tile, Count& c) {
  const int x0 = t.x0, y0 = t.y0;
  const int row_first = std::max(tile_y, y0), row_last = std::min(tile_y + tile - 1, int(t.y1));
  const int lo = std::max(tile_x, x0) - x0, hi = std::min(tile_x + tile - 1, int(t.x1)) - x0;
  if (row_first > row_last || lo > hi) return;
  const bool small = (t.flags & TRIANGLE_SMALL) != 0;
  // Each row's covered span within the window [lo, hi] (relative to x0); empty where l > h.
  int span_l[TILE_MAX], span_h[TILE_MAX];
  for (int py = row_first; py <= row_last; ++py) {
    int l, h;
    if (!record_row_span(t, py - y0, l, h)) l = 1, h = 0;
    l = std::max(l, lo);
    h = std::min(h, hi);
    span_l[py - tile_y] = l;
    span_h[py - tile_y] = h;
    if (l <= h) c.covered += std::uint64_t(h - l + 1);
  }
  // Row segments: a small triangle's every row of its box, segments of the box; a large one's rows with a
  // span, the segments the span meets.
  for (int py = row_first; py <= row_last; ++py) {
    const int l = small ? lo : span_l[py - tile_y], h = small ? hi : span_h[py - tile_y];
    if (l > h) continue;
    c.row_lanes += std::uint64_t(kLanes) * std::uint64_t((h + x0 - tile_x) / kLanes - (l + x0 - tile_x) / kLanes + 1);
  }
  // Stamps: a small triangle's every stamp of its box; a large one's, per stamp row, the stamps between
  // the leftmost and rightmost covered pixel of its four rows.
  for (int sy = (row_first - tile_y) / kStamp; sy <= (row_last - tile_y) / kStamp; ++sy) {
    int l = hi + 1, h = lo - 1;
    for (int j = 0; j < kStamp; ++j) {
      const int py = tile_y + sy * kStamp + j;
      if (py < row_first || py > row_last) continue;
      const int rl = small ? lo : span_l[py - tile_y], rh = small ? hi : span_h[py - tile_y];
      if (rl > rh) continue;
      l = std::min(l, rl);
      h = std::max(h, rh);
    }
    if (l > h) continue;
    c.stamp_lanes += std::uint64_t(kLanes) * std::uint64_t((h + x0 - tile_x) / kStamp - (l + x0 - tile_x) / kStamp + 1);
  }
}

}  // namespace

LaneUtilization lane_utilization(const PreparedFrame& frame) {
  const int tiles = frame.tiles();
  std::vector<Count> per_tile(std::size_t(std::max(tiles, 0)));
  parallel_for(std::size_t(std::max(tiles, 0)), [&](std::size_t k) {
    const int tile_x = int(k % std::size_t(frame.tiles_x)) * frame.tile_size;
    const int tile_y = int(k / std::size_t(frame.tiles_x)) * frame.tile_size;
    for (std::uint32_t i = frame.tile_start[k]; i < frame.tile_start[k + 1]; ++i)
      walk(frame.arrays.triangles[frame.tile_list[i]], tile_x, tile_y, frame.tile_size, per_tile[k]);
  });
  LaneUtilization u;
  for (const Count& c : per_tile) {
    u.covered += c.covered;
    u.row_lanes += c.row_lanes;
    u.stamp_lanes += c.stamp_lanes;
  }
  return u;
}

}  // namespace parashade
