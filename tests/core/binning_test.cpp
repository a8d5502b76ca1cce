// Binning (binning.hpp): the tile lists do not depend on the thread count nor on whether the count pass
// ran in one call (count) or range by range as setup writes the records (begin, count_range, finish);
// each list holds, in primitive order, the triangles whose box lies within the tile, or overlaps it with
// no edge excluding it. The expected lists come from a direct test of every tile (no chunks, no keys).
#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "parashade/binning.hpp"
#include "parashade/parallel.hpp"
#include "parashade/screen_geometry.hpp"

namespace parashade {
namespace {

constexpr int kWidth = 300, kHeight = 170;

// A triangle record with exact edge functions (the fields binning reads), as setup makes them.
TriangleGeometry record(glm::ivec2 a, glm::ivec2 b, glm::ivec2 c) {
  const glm::i64vec2 p[3] = {glm::i64vec2(a), glm::i64vec2(b), glm::i64vec2(c)};
  const std::int64_t area2 = (p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[1].y - p[0].y) * (p[2].x - p[0].x);
  glm::i64vec2 q[3] = {p[0], p[1], p[2]};
  if (area2 < 0) std::swap(q[1], q[2]);
  TriangleGeometry r{};
  const std::int64_t xmin = std::min({q[0].x, q[1].x, q[2].x}), xmax = std::max({q[0].x, q[1].x, q[2].x});
  const std::int64_t ymin = std::min({q[0].y, q[1].y, q[2].y}), ymax = std::max({q[0].y, q[1].y, q[2].y});
  const PixelBox box = centre_box(xmin, xmax, ymin, ymax, kWidth, kHeight);
  if (box.x0 > box.x1 || box.y0 > box.y1) {
    r.x0 = 1;
    r.x1 = 0;
    return r;
  }
  r.x0 = std::int16_t(box.x0), r.y0 = std::int16_t(box.y0), r.x1 = std::int16_t(box.x1), r.y1 = std::int16_t(box.y1);
  const std::int64_t cx = kSubpixel * box.x0 + kSubpixel / 2, cy = kSubpixel * box.y0 + kSubpixel / 2;
  for (int e = 0; e < 3; ++e) {
    const glm::i64vec2 vi = q[e], vj = q[(e + 1) % 3];
    const std::int64_t dx = vj.x - vi.x, dy = vj.y - vi.y;
    r.edge_c[e] = dx * (cy - vi.y) - dy * (cx - vi.x) - edge_bias(glm::ivec2(vi), glm::ivec2(vj));
    r.edge_a[e] = std::int32_t(-dy * kSubpixel);
    r.edge_b[e] = std::int32_t(dx * kSubpixel);
  }
  return r;
}

std::vector<TriangleGeometry> random_records(std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> x(-20 * kSubpixel, (kWidth + 20) * kSubpixel), y(-20 * kSubpixel, (kHeight + 20) * kSubpixel);
  std::uniform_int_distribution<int> small(-6 * kSubpixel, 6 * kSubpixel), kind(0, 9);
  std::vector<TriangleGeometry> out;
  while (out.size() < n) {
    const glm::ivec2 a(x(rng), y(rng));
    glm::ivec2 b, c;
    if (kind(rng) < 7) {  // small, mostly inside one tile
      b = a + glm::ivec2(small(rng), small(rng));
      c = a + glm::ivec2(small(rng), small(rng));
    } else {
      b = {x(rng), y(rng)};
      c = {x(rng), y(rng)};
    }
    const std::int64_t area2 = std::int64_t(b.x - a.x) * (c.y - a.y) - std::int64_t(b.y - a.y) * (c.x - a.x);
    if (area2 != 0) out.push_back(record(a, b, c));
  }
  return out;
}

// Tile k's expected list, in order: a triangle whose box lies within one tile is in that tile's list;
// another is in the list of every tile its box overlaps where no edge is negative at all four corners
// of the overlap (binning's conservative test).
std::vector<std::vector<std::uint32_t>> expected_lists(const std::vector<TriangleGeometry>& tris, int tile) {
  const int tiles_x = (kWidth + tile - 1) / tile, tiles_y = (kHeight + tile - 1) / tile;
  std::vector<std::vector<std::uint32_t>> lists(std::size_t(tiles_x) * tiles_y);
  for (std::size_t i = 0; i < tris.size(); ++i) {
    const TriangleGeometry& t = tris[i];
    if (t.x0 > t.x1) continue;
    if (t.x0 / tile == t.x1 / tile && t.y0 / tile == t.y1 / tile) {  // a box within one tile: no edge test
      lists[std::size_t(t.y0 / tile) * tiles_x + t.x0 / tile].push_back(std::uint32_t(i));
      continue;
    }
    for (int ty = 0; ty < tiles_y; ++ty)
      for (int tx = 0; tx < tiles_x; ++tx) {
        const int x0 = std::max<int>(tx * tile, t.x0), x1 = std::min<int>(tx * tile + tile - 1, t.x1);
        const int y0 = std::max<int>(ty * tile, t.y0), y1 = std::min<int>(ty * tile + tile - 1, t.y1);
        if (x0 > x1 || y0 > y1) continue;
        bool outside = false;
        for (int e = 0; e < 3; ++e) {
          std::int64_t best = INT64_MIN;
          for (int cx : {x0, x1})
            for (int cy : {y0, y1})
              best = std::max(best, t.edge_c[e] + std::int64_t(t.edge_a[e]) * (cx - t.x0) + std::int64_t(t.edge_b[e]) * (cy - t.y0));
          outside = outside || best < 0;
        }
        if (!outside) lists[std::size_t(ty) * tiles_x + tx].push_back(std::uint32_t(i));
      }
  }
  return lists;
}

std::vector<std::vector<std::uint32_t>> lists_of(const Binner& b, const std::vector<std::uint32_t>& out) {
  std::vector<std::vector<std::uint32_t>> lists(std::size_t(b.tiles_x()) * b.tiles_y());
  for (std::size_t k = 0; k < lists.size(); ++k)
    lists[k].assign(out.begin() + b.tile_start()[k], out.begin() + b.tile_start()[k + 1]);
  return lists;
}

TEST(Binning, ListsInPrimitiveOrderWhateverTheThreadsAndTheCountingSteps) {
  const unsigned before = host_threads();
  // 16, 32, 64: the renderer's sizes (a shift); 24: any other size (a division).
  for (const auto& [n, tile] : {std::pair<std::size_t, int>{0, 16}, {5, 16}, {1000, 16}, {9000, 16}, {40000, 16},
                                 {9000, 32}, {9000, 64}, {9000, 24}}) {
    const std::vector<TriangleGeometry> tris = random_records(n, unsigned(n) + 3);
    const auto expected = expected_lists(tris, tile);
    for (unsigned threads : {1u, 2u, 3u}) {
      set_host_threads(threads);
      Binner whole;  // reused across the cases, as the pipeline keeps it across frames
      for (int pass = 0; pass < 2; ++pass) {
        whole.count(tris.data(), tris.size(), kWidth, kHeight, tile);
        std::vector<std::uint32_t> out(whole.entries());
        whole.fill(out.data());
        ASSERT_EQ(lists_of(whole, out), expected) << n << " triangles, tile " << tile << ", " << threads << " threads";
      }
      Binner steps;
      steps.begin(tris.data(), tris.size(), kWidth, kHeight, tile);
      parallel_for(steps.chunks(), [&](std::size_t c) {
        for (std::size_t first = steps.chunk_first(c); first < steps.chunk_first(c + 1); first += 97)
          steps.count_range(c, first, std::min(steps.chunk_first(c + 1), first + 97));
      });
      steps.finish();
      std::vector<std::uint32_t> out(steps.entries());
      steps.fill(out.data());
      ASSERT_EQ(lists_of(steps, out), expected) << n << " triangles, tile " << tile << ", " << threads << " threads, in steps";
    }
  }
  set_host_threads(before);
}

}  // namespace
}  // namespace parashade
