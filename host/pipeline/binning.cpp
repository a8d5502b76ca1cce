#include "parashade/binning.hpp"

#include <algorithm>

#include "parashade/parallel.hpp"

namespace parashade {
namespace {

// Pixel column or row (>= 0) -> tile column or row: a shift for the power-of-two tile sizes the renderer
// allows (an integer division per box corner cost more than the rest of a small triangle's binning).
struct TileOf {
  explicit TileOf(int tile_size)
      : size(tile_size), shift((tile_size & (tile_size - 1)) == 0 ? __builtin_ctz(unsigned(tile_size)) : -1) {}
  int operator()(int pixel) const { return shift >= 0 ? pixel >> shift : pixel / size; }
  int size, shift;
};

constexpr std::size_t kFillAhead = 32;  // records

}  // namespace

template <typename Visit>
void Binner::for_each_tile_of(const TriangleGeometry& t, Visit visit) const {
  if (t.x0 > t.x1) return;
  const TileOf tile_of(tile_size_);
  const int tx0 = tile_of(t.x0), tx1 = tile_of(t.x1), ty0 = tile_of(t.y0), ty1 = tile_of(t.y1);
  if (tx0 == tx1 && ty0 == ty1) {
    visit(ty0 * tiles_x_ + tx0);
    return;
  }
  for (int ty = ty0; ty <= ty1; ++ty) {
    const std::int64_t dy_lo = std::max<int>(ty * tile_size_, t.y0) - t.y0;
    const std::int64_t dy_hi = std::min<int>(ty * tile_size_ + tile_size_ - 1, t.y1) - t.y0;
    for (int tx = tx0; tx <= tx1; ++tx) {
      const std::int64_t dx_lo = std::max<int>(tx * tile_size_, t.x0) - t.x0;
      const std::int64_t dx_hi = std::min<int>(tx * tile_size_ + tile_size_ - 1, t.x1) - t.x0;
      // Skip the tile when some edge is negative at every pixel centre of it (max over the corners < 0).
      bool outside = false;
      for (int e = 0; e < 3 && !outside; ++e) {
        const std::int64_t a = t.edge_a[e], b = t.edge_b[e];
        const std::int64_t best = t.edge_c[e] + std::max(a * dx_lo, a * dx_hi) + std::max(b * dy_lo, b * dy_hi);
        outside = best < 0;
      }
      if (!outside) visit(ty * tiles_x_ + tx);
    }
  }
}

void Binner::begin(const TriangleGeometry* tris, std::size_t n, int width, int height, int tile_size,
                   std::size_t min_chunk) {
  tris_ = tris;
  n_ = n;
  tile_size_ = tile_size;
  tiles_x_ = (width + tile_size - 1) / tile_size;
  tiles_y_ = (height + tile_size - 1) / tile_size;
  const std::size_t tiles = std::size_t(tiles_x_) * tiles_y_;
  // Chunks are contiguous ranges of triangles; their lists are concatenated in chunk order per tile,
  // so the result is in primitive order whatever the number of threads. About four per thread (a
  // thread slowed by other work leaves its share to the others), each of at least min_chunk triangles
  // (the per-chunk counters, tiles x 4 bytes, are summed over all chunks; setup runs in these chunks
  // too, ~50 ns a triangle, and a chunk must be worth waking a thread for).
  const std::size_t chunks = std::max<std::size_t>(
      1, std::min<std::size_t>(4 * std::size_t(host_threads()), n / std::max<std::size_t>(1, min_chunk)));
  chunk_first_.resize(chunks + 1);
  for (std::size_t c = 0; c <= chunks; ++c) chunk_first_[c] = n * c / chunks;
  chunk_cursor_.assign(chunks * tiles, 0);
  tile_of_.resize(n);
}

void Binner::count_range(std::size_t chunk, std::size_t first, std::size_t last) {
  const std::size_t tiles = std::size_t(tiles_x_) * tiles_y_;
  std::uint32_t* counts = &chunk_cursor_[chunk * tiles];
  const TileOf tile_of(tile_size_);
  for (std::size_t i = first; i < last; ++i) {
    const TriangleGeometry& t = tris_[i];
    std::uint32_t key;
    if (t.x0 > t.x1) {
      key = kNoTile;
    } else if (const int tx = tile_of(t.x0), ty = tile_of(t.y0); tx == tile_of(t.x1) && ty == tile_of(t.y1)) {
      key = std::uint32_t(ty * tiles_x_ + tx);
      ++counts[key];
    } else {
      key = kSeveralTiles;
      for_each_tile_of(t, [counts](int tile) { ++counts[tile]; });
    }
    tile_of_[i] = key;
  }
}

void Binner::finish() {
  const std::size_t tiles = std::size_t(tiles_x_) * tiles_y_;
  const std::size_t chunks = chunk_first_.size() - 1;
  start_.resize(tiles + 1);
  std::uint32_t total = 0;
  for (std::size_t k = 0; k < tiles; ++k) {
    start_[k] = total;
    for (std::size_t c = 0; c < chunks; ++c) {
      const std::uint32_t cnt = chunk_cursor_[c * tiles + k];
      chunk_cursor_[c * tiles + k] = total;
      total += cnt;
    }
  }
  start_[tiles] = total;
}

void Binner::count(const TriangleGeometry* tris, std::size_t n, int width, int height, int tile_size) {
  begin(tris, n, width, height, tile_size);
  parallel_for(chunks(), [&](std::size_t c) { count_range(c, chunk_first_[c], chunk_first_[c + 1]); });
  finish();
}

void Binner::fill(std::uint32_t* out) {
  const std::size_t tiles = std::size_t(tiles_x_) * tiles_y_;
  // The fill alone is worth a second thread only where its records are (chunks may be smaller, for setup).
  parallel_for_if(n_ >= 2 * kMinChunk, chunks(), [&](std::size_t c) {
    std::uint32_t* cursor = &chunk_cursor_[c * tiles];
    const std::size_t last = chunk_first_[c + 1];
    for (std::size_t i = chunk_first_[c]; i < last; ++i) {
      // A record of several tiles is read again (its tiles and edges), long after setup wrote it: fetched
      // ahead, as its key says it will be.
      if (i + kFillAhead < last && tile_of_[i + kFillAhead] == kSeveralTiles) {
        const char* ahead = reinterpret_cast<const char*>(&tris_[i + kFillAhead]);
        __builtin_prefetch(ahead);
        __builtin_prefetch(ahead + sizeof(TriangleGeometry) - 1);
      }
      const std::uint32_t key = tile_of_[i];
      if (key < kSeveralTiles)
        out[cursor[key]++] = std::uint32_t(i);
      else if (key == kSeveralTiles)
        for_each_tile_of(tris_[i], [&](int tile) { out[cursor[tile]++] = std::uint32_t(i); });
    }
  });
}

}  // namespace parashade
