#pragma once
// Sort-middle binning: each non-empty triangle record goes into the list of every screen tile its
// bounding box overlaps (and that no edge excludes), in primitive order. A tile is then shaded by one
// work-group that walks its list in order, so depth testing is race-free and the image deterministic.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "parashade/kernels/triangle_record.h"

namespace parashade {

class Binner {
 public:
  // Counts the entries of every tile; tile_start() is valid afterwards.
  void count(const TriangleGeometry* tris, std::size_t n, int width, int height, int tile_size);
  // Writes the triangle indices, tile after tile, to out[0 .. entries()) (once after each count).
  void fill(std::uint32_t* out);

  // count() in steps, for a caller that counts each range of records right after writing it:
  // begin(), then count_range() over consecutive ranges covering every chunk (a chunk's ranges in order,
  // by one thread at a time; different chunks on any threads), then finish(). `tris` must hold the
  // records of a range by the time it is counted, and all of them at fill().
  // Chunks hold at least min_chunk records (each is worth waking a thread for: kMinChunk for setup alone).
  static constexpr std::size_t kMinChunk = 2048;
  void begin(const TriangleGeometry* tris, std::size_t n, int width, int height, int tile_size,
             std::size_t min_chunk = kMinChunk);
  std::size_t chunks() const { return chunk_first_.size() - 1; }
  std::size_t chunk_first(std::size_t chunk) const { return chunk_first_[chunk]; }  // chunk_first(chunks()) == n
  void count_range(std::size_t chunk, std::size_t first, std::size_t last);
  void finish();

  int tiles_x() const { return tiles_x_; }
  int tiles_y() const { return tiles_y_; }
  int tile_size() const { return tile_size_; }
  std::size_t entries() const { return start_.empty() ? 0 : start_.back(); }
  // tile_start()[k] .. tile_start()[k+1] index the entries of tile k (row-major); size tiles + 1.
  const std::vector<std::uint32_t>& tile_start() const { return start_; }

 private:
  template <typename Visit>
  void for_each_tile_of(const TriangleGeometry& t, Visit visit) const;

  const TriangleGeometry* tris_ = nullptr;
  std::size_t n_ = 0;
  int tiles_x_ = 0, tiles_y_ = 0, tile_size_ = TILE_DEFAULT;
  std::vector<std::size_t> chunk_first_;        // first triangle of each chunk (+ end)
  std::vector<std::uint32_t> chunk_cursor_;     // per chunk x tile: where the chunk's entries of the tile start
  std::vector<std::uint32_t> start_;
  // Per record, counted: its only tile, kSeveralTiles (fill tests its tiles again) or kNoTile.
  static constexpr std::uint32_t kNoTile = 0xffffffffu, kSeveralTiles = 0xfffffffeu;
  std::vector<std::uint32_t> tile_of_;
};

}  // namespace parashade
