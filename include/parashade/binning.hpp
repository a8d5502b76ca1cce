#pragma once
// Sort-middle binning: each non-empty triangle record goes into the list of every screen tile its
// bounding box overlaps (and that no edge excludes), in primitive order. A tile is then shaded by one
// work-group that walks its list in order, so depth testing is race-free and the image deterministic.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "kernels/triangle_record.h"

namespace parashade {

class Binner {
 public:
  // Counts the entries of every tile; tile_start() is valid afterwards.
  void count(const TriangleGeometry* tris, std::size_t n, int width, int height, int tile_size);
  // Writes the triangle indices, tile after tile, to out[0 .. entries()).
  void fill(std::uint32_t* out) const;

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
};

}  // namespace parashade
