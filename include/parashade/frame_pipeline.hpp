#pragma once
// One frame's host stages ("software" in the sources' split): vertex stage with clipping and culling, the
// extra triangulation's vertex snap, the per-triangle method choice, triangle setup, DDA coverage,
// binning into screen tiles and the plan of modeled units. Device-free: `parashade plan` prepares a frame
// without a device, and a device's renderer (renderer.hpp) only uploads, launches and reads back.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "parashade/binning.hpp"
#include "parashade/dda_coverage.hpp"
#include "parashade/frame_config.hpp"
#include "parashade/frame_stats.hpp"
#include "parashade/planner.hpp"
#include "parashade/scene.hpp"
#include "parashade/screen_geometry.hpp"
#include "parashade/triangle_choice.hpp"
#include "parashade/kernels/sierpinski_leaf.h"
#include "parashade/kernels/triangle_record.h"

namespace parashade {

// The record arrays of one frame (kernels/triangle_record.h): setup writes them, the kernels read them.
struct FrameRecords {
  TriangleGeometry* triangles = nullptr;
  float* attributes = nullptr;         // attribute_floats(method) per record
  FixedPlanes* fixed = nullptr;        // fixed point only
  SierpinskiLeaf* leaves = nullptr;    // the sierpinski unit only
};

// Where a frame's arrays live. The pipeline's own host arrays by default; a device's renderer hands out
// mapped buffers instead, so the kernel reads what setup wrote without a copy (a copy of the records
// costs 0.5-8 ms a frame here, a map 0.05-0.3 ms).
class FrameStorage {
 public:
  virtual ~FrameStorage() = default;
  // Room for `n` records of `attribute_floats` floats each, with fixed planes and leaves when asked.
  virtual FrameRecords records(std::size_t n, std::size_t attribute_floats, bool fixed, bool leaves) = 0;
  // Room for the tile lists' `entries` triangle indices.
  virtual std::uint32_t* tile_list(std::size_t entries) = 0;
};

// A prepared frame: records, bins and plan, valid until the pipeline's next prepare.
struct PreparedFrame {
  const ScreenGeometry* geometry = nullptr;
  std::size_t records = 0;  // sub-triangles with the sierpinski unit
  FrameRecords arrays;
  // Bins: tile k (row-major) holds tile_list[tile_start[k] .. tile_start[k + 1]); a band's tiles outside
  // it are empty.
  const std::uint32_t* tile_start = nullptr;  // tiles + 1 entries
  const std::uint32_t* tile_list = nullptr;
  int tiles_x = 0, tiles_y = 0, tile_size = 16;
  // The tiles [first_tile, end_tile) to shade: every tile, or a streamed band's (FramePipeline::begin_frame).
  int first_tile = 0, end_tile = 0;
  const DdaRowTable* dda = nullptr;  // dda coverage: the spans' row table
  const Plan* plan = nullptr;        // with a plan
  FrameTimings timings;              // the host stages'
  FrameStats stats;

  int tiles() const { return tiles_x * tiles_y; }
  std::size_t bin_entries() const { return tile_start ? tile_start[tiles()] : 0; }
  TileBins bins() const { return {tile_start, tile_list, tiles_x, tiles_y, tile_size}; }
};

// Whether a frame of this configuration may stream in bands: a plain frame (no unit, plan, split band or
// combined method).
bool frame_can_stream(const FrameConfig& config);
// Bytes of one triangle's record and attributes for `method` (what a band's budget counts).
std::size_t triangle_record_bytes(Method method);
// Whether `screen_triangles` records of `method` take more than `record_bytes`, whether or not the frame may stream.
bool records_exceed(Method method, std::size_t screen_triangles, std::size_t record_bytes);
// Whether a frame of `screen_triangles` (after the geometry stage) streams in bands when its records may
// take `record_bytes` (FramePipeline::begin_frame's rule).
bool frame_streams(const FrameConfig& config, std::size_t screen_triangles, std::size_t record_bytes);

// When none is given, a width x height frame streams only when its records would exceed this many MiB: 16
// plus the frame's colour and depth (8 bytes a pixel), rounded up; its bands then take at most
// kDefaultBandBytes. The banding passes cost a frame of many small triangles about a tenth of its time
// whatever the bands' size, the memory a frame may take grows with its pixels, and smaller bands stay in
// the last-level cache from setup to kernel (bench/README.md, run U).
int default_band_mib(int width, int height);
constexpr std::size_t kDefaultBandBytes = std::size_t(16) << 20;
// A records budget that means "by the frame" (default_band_mib, kDefaultBandBytes).
constexpr std::size_t kBandBytesByFrame = 0;
// begin_frame's and default_tile_size's record_bytes resolved: a frame streams when its records exceed
// `stream_above` bytes, in bands of at most `band` bytes (both record_bytes unless kBandBytesByFrame).
struct RecordBudget {
  std::size_t stream_above, band;
};
RecordBudget record_budget(std::size_t record_bytes, int width, int height);

class FramePipeline {
 public:
  // A pipeline for frames as `config` asks, checked here once against the table of combinations
  // (check_frame_config; a ConfigError names what is refused) and kept: every frame reads it unchanged.
  explicit FramePipeline(const FrameConfig& config);
  const FrameConfig& config() const { return config_; }
  // Shade only tile rows [first, first + rows) from the next frame on (rows -1: the whole frame); a split
  // frame's device moving its band. Throws UsageError for a band that is not one.
  void set_band(int first, int rows);

  // Prepares `scene` into the pipeline's own host arrays or into `storage`. A plan needs its units
  // resolved (PlanOptions::units >= 1).
  const PreparedFrame& prepare_frame(const Scene& scene);
  const PreparedFrame& prepare_frame(const Scene& scene, FrameStorage& storage);
  // The screen geometry of the last prepared frame.
  const ScreenGeometry& geometry() const { return geometry_; }

  // A frame in bands of tile rows, so that only one band's records exist at a time (peak memory,
  // bench/README.md). begin_frame runs the vertex stage and returns the number of bands: 1 when the
  // frame's records take at most `record_bytes` (record_budget: kBandBytesByFrame is the frame's
  // default) or the configuration does not stream (a plan, a unit, the combined method, a split frame's
  // band), else bands whose records take at most that much (or one
  // tile row each). prepare_band(b) then sets up and bins band b's triangles, in primitive order,
  // into `storage` (every band gets room for the largest band's records, so the buffers do not grow
  // from band to band); its tiles are PreparedFrame::first_tile .. end_tile. Triangles whose box holds
  // no pixel centre get no record when the frame streams. The geometry stage's time and stats come
  // with band 0; the other stats are the band's own.
  int begin_frame(const Scene& scene, std::size_t record_bytes);
  const PreparedFrame& prepare_band(const Scene& scene, FrameStorage& storage, int band);

 private:
  class HostStorage : public FrameStorage {
   public:
    FrameRecords records(std::size_t n, std::size_t attribute_floats, bool fixed, bool leaves) override;
    std::uint32_t* tile_list(std::size_t entries) override;

   private:
    std::vector<TriangleGeometry> triangles_;
    std::vector<float> attributes_;
    std::vector<FixedPlanes> fixed_;
    std::vector<SierpinskiLeaf> leaves_;
    std::vector<std::uint32_t> list_;
  };
  void setup(const Scene& scene, const FrameRecords& out, const std::uint32_t* order);
  void plan_bands(std::size_t max_records);
  void bin(const Scene& scene, FrameStorage& storage);

  FrameConfig config_;
  HostStorage host_;
  PreparedFrame frame_;
  ScreenGeometry geometry_;
  std::vector<TriangleShading> choice_;  // combined: the per-triangle method choice
  Binner binner_;
  bool counted_ = false;  // setup ran binning's count pass (Binner::begin, count_range) on this frame's records
  std::vector<std::uint32_t> band_start_;  // tile_start with the tiles outside the band emptied
  DdaRowTable dda_;
  // begin_frame: the vertex stage's time and dropped triangles, and the bands of a streamed frame.
  double geometry_ms_ = 0, banding_ms_ = 0;
  std::uint64_t parity_dropped_ = 0, banding_empty_ = 0;
  std::vector<int> band_rows_;                // band b: tile rows [band_rows_[b], band_rows_[b + 1])
  std::vector<std::uint32_t> band_start_list_;  // band b's triangles: band_list_[start[b] .. start[b + 1])
  std::vector<std::uint32_t> band_list_;
  std::vector<std::uint32_t> triangle_rows_;  // per screen triangle: first tile row << 16 | last; kNoRows: no pixel
  std::size_t band_records_ = 0;              // the largest band's triangles
  Plan plan_;
  // sierpinski: setup's whole-triangle records before the split (kept to reuse their memory)
  std::vector<TriangleGeometry> whole_;
  std::vector<float> whole_attr_;
  std::vector<FixedPlanes> whole_fixed_;
};

}  // namespace parashade
