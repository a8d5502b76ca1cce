#include "parashade/frame_pipeline.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <optional>

#include "parashade/combined.hpp"
#include "parashade/geometry_stage.hpp"
#include "parashade/highlight.hpp"
#include "parashade/host_clock.hpp"
#include "parashade/parallel.hpp"
#include "parashade/setup.hpp"
#include "parashade/sierpinski_setup.hpp"

namespace parashade {

FrameRecords FramePipeline::HostStorage::records(std::size_t n, std::size_t attribute_floats, bool fixed, bool leaves) {
  triangles_.resize(n);
  attributes_.resize(n * attribute_floats);
  fixed_.resize(fixed ? n : 0);
  leaves_.resize(leaves ? n : 0);
  return {triangles_.data(), attributes_.data(), fixed ? fixed_.data() : nullptr, leaves ? leaves_.data() : nullptr};
}

std::uint32_t* FramePipeline::HostStorage::tile_list(std::size_t entries) {
  list_.resize(std::max<std::size_t>(entries, 1));
  return list_.data();
}

bool frame_can_stream(const FrameConfig& config) {
  return config.whole_plain_frame() && config.method != Method::combined;
}

std::size_t triangle_record_bytes(Method method) {
  return sizeof(TriangleGeometry) + attribute_floats(method) * sizeof(float);
}

int default_band_mib(int width, int height) {
  const std::size_t frame_bytes = std::size_t(std::max(width, 0)) * std::size_t(std::max(height, 0)) * 8;
  return 16 + int((frame_bytes + (std::size_t(1) << 20) - 1) >> 20);
}

RecordBudget record_budget(std::size_t record_bytes, int width, int height) {
  if (record_bytes != kBandBytesByFrame) return {record_bytes, record_bytes};
  return {std::size_t(default_band_mib(width, height)) << 20, kDefaultBandBytes};
}

bool records_exceed(Method method, std::size_t screen_triangles, std::size_t record_bytes) {
  return screen_triangles > record_bytes / triangle_record_bytes(method);
}

bool frame_streams(const FrameConfig& config, std::size_t screen_triangles, std::size_t record_bytes) {
  return frame_can_stream(config) && records_exceed(config.method, screen_triangles, record_bytes);
}

FramePipeline::FramePipeline(const FrameConfig& config) : config_(config) { check_frame_config(config_); }

void FramePipeline::set_band(int first, int rows) {
  if (first < 0 || rows < -1)
    throw UsageError("a band is tile rows [first, first + rows) with first >= 0 and rows >= 0, or rows -1 for the "
                     "whole frame (got first " + std::to_string(first) + ", rows " + std::to_string(rows) + ")");
  config_.band_first = first;
  config_.band_rows = rows;
}

const PreparedFrame& FramePipeline::prepare_frame(const Scene& scene) { return prepare_frame(scene, host_); }

const PreparedFrame& FramePipeline::prepare_frame(const Scene& scene, FrameStorage& storage) {
  begin_frame(scene, SIZE_MAX);
  return prepare_band(scene, storage, 0);
}

int FramePipeline::begin_frame(const Scene& scene, std::size_t record_bytes) {
  const FrameConfig& config = config_;
  check_resolution(scene.width, scene.height, "scene '" + scene.name + "'");
  auto t0 = Clock::now();
  build_screen_geometry(scene, {config.method, false, config.chooses_per_triangle()}, geometry_);
  // The extra-triangulation unit needs its midpoints on pixel corners: vertex parity normalization.
  parity_dropped_ = config.splits_triangles() ? snap_sierpinski_vertices(geometry_, config.unit()) : 0;
  geometry_ms_ = ms_since(t0);
  const RecordBudget budget = record_budget(record_bytes, scene.width, scene.height);
  band_rows_.clear();
  banding_ms_ = 0;
  banding_empty_ = 0;
  if (!frame_streams(config, geometry_.triangles.size(), budget.stream_above)) return 1;
  t0 = Clock::now();
  plan_bands(std::max<std::size_t>(1, budget.band / triangle_record_bytes(config.method)));
  banding_ms_ = ms_since(t0);
  return int(band_rows_.size()) - 1;
}

namespace {
constexpr std::uint32_t kNoRows = 0xffffffffu;
}  // namespace

// Bands of consecutive tile rows, each overlapped by at most max_records triangles unless one row alone
// is; then each band's triangles in primitive order. Two passes over the triangles, on all threads.
void FramePipeline::plan_bands(std::size_t max_records) {
  const FrameConfig& config = config_;
  const ScreenGeometry& g = geometry_;
  const std::size_t n = g.triangles.size();
  const int tile = config.tile_size, rows = (g.height + tile - 1) / tile;
  int tile_shift = 0;
  while ((1 << tile_shift) < tile) ++tile_shift;  // tile sizes are powers of two
  const std::size_t chunk = balanced_chunk(n, 8192, 65536), ranges = (n + chunk - 1) / chunk;
  triangle_rows_.resize(n);
  // Pass 1: each triangle's tile rows (its pixel-centre box, centre_box, as setup computes it), and per
  // range how many triangles start and end in each row.
  std::vector<std::uint32_t> starts(ranges * std::size_t(rows), 0), ends(ranges * std::size_t(rows), 0);
  std::vector<std::uint64_t> empty(ranges, 0);
  parallel_for(ranges, [&](std::size_t r) {
    std::uint32_t* start = starts.data() + r * std::size_t(rows);
    std::uint32_t* end_row = ends.data() + r * std::size_t(rows);
    for (std::size_t t = r * chunk, end = std::min(n, t + chunk); t < end; ++t) {
      const glm::uvec3 tri = g.triangles[t];
      const glm::ivec2 a = g.xy[tri.x], b = g.xy[tri.y], c = g.xy[tri.z];
      const auto [x0, y0, x1, y1] = centre_box(std::min({a.x, b.x, c.x}), std::max({a.x, b.x, c.x}),
                                               std::min({a.y, b.y, c.y}), std::max({a.y, b.y, c.y}), g.width, g.height);
      if (x0 > x1 || y0 > y1) {
        triangle_rows_[t] = kNoRows;
        ++empty[r];
        continue;
      }
      const std::uint32_t first = std::uint32_t(y0 >> tile_shift), last = std::uint32_t(y1 >> tile_shift);
      triangle_rows_[t] = first << 16 | last;
      ++start[first];
      ++end_row[last];
    }
  });
  for (std::uint64_t e : empty) banding_empty_ += e;
  // The bands, greedily, from the triangles overlapping each row (started by it, not ended before it).
  std::vector<int> band_of_row(rows);
  band_rows_.assign(1, 0);
  std::size_t in_band = 0, open = 0;
  for (int row = 0; row < rows; ++row) {
    std::size_t started = 0, ended = 0;
    for (std::size_t r = 0; r < ranges; ++r) {
      started += starts[r * std::size_t(rows) + std::size_t(row)];
      ended += ends[r * std::size_t(rows) + std::size_t(row)];
    }
    if (row > band_rows_.back() && in_band + started > max_records) {  // a new band takes the open ones too
      band_rows_.push_back(row);
      in_band = open;
    }
    in_band += started;
    open += started;
    open -= ended;
    band_of_row[row] = int(band_rows_.size()) - 1;
  }
  band_rows_.push_back(rows);
  const std::size_t bands = band_rows_.size() - 1;
  // Where each range's triangles go in each band: a band holds the triangles whose first row's band is
  // not after it and whose last row's band is not before it.
  std::vector<std::uint32_t> cursor(ranges * bands);
  band_start_list_.assign(bands + 1, 0);
  std::uint32_t at = 0;
  band_records_ = 0;
  std::vector<std::uint32_t> open_in(ranges, 0);  // per range: triangles started in earlier bands still open
  for (std::size_t b = 0; b < bands; ++b) {
    band_start_list_[b] = at;
    for (std::size_t r = 0; r < ranges; ++r) {
      std::uint32_t started = 0, ended = 0;
      for (int row = band_rows_[b]; row < band_rows_[b + 1]; ++row) {
        started += starts[r * std::size_t(rows) + std::size_t(row)];
        ended += ends[r * std::size_t(rows) + std::size_t(row)];
      }
      cursor[r * bands + b] = at;
      at += open_in[r] + started;
      open_in[r] += started - ended;
    }
    band_records_ = std::max<std::size_t>(band_records_, at - band_start_list_[b]);
  }
  band_start_list_[bands] = at;
  // Pass 2: the lists, each range's triangles after the previous ranges' (primitive order).
  band_list_.resize(at);
  std::uint32_t* list = band_list_.data();
  const std::uint32_t* rows_of = triangle_rows_.data();
  parallel_for(ranges, [&](std::size_t r) {
    std::uint32_t* next = cursor.data() + r * bands;
    // The cursor of the band the last triangle went to stays in a register: neighbours mostly share a
    // band, and a cursor incremented in memory made each store wait for the previous one (sphere_2m:
    // this pass 1.6-2.0 ms, 0.5-0.9 without the wait).
    int band = 0;
    std::uint32_t band_at = next[0];
    for (std::size_t t = r * chunk, end = std::min(n, t + chunk); t < end; ++t) {
      const std::uint32_t v = rows_of[t];
      if (v == kNoRows) continue;
      const int first = band_of_row[v >> 16], last = band_of_row[v & 0xffffu];
      if (first == band && last == band) {
        list[band_at++] = std::uint32_t(t);
        continue;
      }
      next[band] = band_at;
      for (int b = first; b <= last; ++b) list[next[b]++] = std::uint32_t(t);
      band = last;
      band_at = next[band];
    }
    next[band] = band_at;
  });
}

const PreparedFrame& FramePipeline::prepare_band(const Scene& scene, FrameStorage& storage, int band) {
  const FrameConfig& config = config_;
  const bool streamed = !band_rows_.empty();
  frame_ = PreparedFrame{};
  FrameTimings& t = frame_.timings;
  FrameStats& s = frame_.stats;
  if (band == 0) {
    t.geometry_ms = geometry_ms_;
    t.binning_ms = banding_ms_;
    s.parity_dropped = parity_dropped_;
  }
  s.geometry = geometry_.stats;
  frame_.geometry = &geometry_;

  auto t0 = Clock::now();
  const std::uint32_t* order = streamed ? band_list_.data() + band_start_list_[std::size_t(band)] : nullptr;
  const std::size_t triangles =
      streamed ? band_start_list_[std::size_t(band) + 1] - band_start_list_[std::size_t(band)] : geometry_.triangles.size();
  frame_.records = config.splits_triangles() ? triangles << (2 * config.unit().depth) : triangles;  // sub-triangles when split
  frame_.arrays = storage.records(streamed ? band_records_ : frame_.records, attribute_floats(config.method),
                                  config.arith.fixed, config.splits_triangles());
  setup(scene, frame_.arrays, order);
  if (streamed && band == 0) s.triangles_without_pixels += banding_empty_;
  t.setup_ms = ms_since(t0);

  t0 = Clock::now();
  bin(scene, storage);
  t.binning_ms += ms_since(t0);
  frame_.first_tile = streamed ? band_rows_[std::size_t(band)] * frame_.tiles_x : 0;
  frame_.end_tile = streamed ? band_rows_[std::size_t(band) + 1] * frame_.tiles_x : frame_.tiles();
  parallel_rest();  // the device's kernel comes next, on the same cores
  return frame_;
}

void FramePipeline::setup(const Scene& scene, const FrameRecords& out, const std::uint32_t* order) {
  const FrameConfig& config = config_;
  FrameTimings& t = frame_.timings;
  FrameStats& s = frame_.stats;
  const Method method = config.method;
  const auto setup_started = Clock::now();
  counted_ = false;
  if (config.splits_triangles()) {
    // Setup per triangle, then each record split into its sub-triangles' records.
    const std::size_t triangles = geometry_.triangles.size();
    whole_.resize(triangles);
    whole_attr_.resize(triangles * GOURAUD_ATTR_FLOATS);
    whole_fixed_.resize(out.fixed ? triangles : 0);
    FixedPlanes* whole_fixed = out.fixed ? whole_fixed_.data() : nullptr;
    s.triangles_without_pixels =
        setup_triangles(geometry_, method, whole_.data(), whole_attr_.data(), whole_fixed).without_pixels;
    s.sierpinski_whole = split_sierpinski(geometry_, config.unit(), whole_.data(), whole_attr_.data(), whole_fixed,
                                         out.triangles, out.attributes, out.fixed, out.leaves);
    return;
  }
  const bool choose = config.chooses_per_triangle();  // never with streamed bands: records are the triangles
  const double budget = combined_shading_budget(config.combined);
  counted_ = !config.dda_coverage;  // DDA coverage changes the boxes after setup
  if (counted_) {
    // Binning's count pass runs on each range of records right after its setup, while they are in cache,
    // and the per-triangle choice right before it: one wake-up of the host threads for all three.
    std::optional<TriangleChooser> chooser;
    if (choose) chooser.emplace(scene, geometry_, config.combined, budget, choice_);
    const TriangleShading* gouraud = choose ? choice_.data() : nullptr;
    const std::size_t n = frame_.records;
    // A chunk is worth waking a thread for at ~0.1 ms of work: the choice costs about twice setup's ~50 ns a
    // triangle (bench_triangle_choice).
    binner_.begin(out.triangles, n, scene.width, scene.height, config.tile_size,
                  chooser ? Binner::kMinChunk / 3 : Binner::kMinChunk);
    std::atomic<std::uint64_t> empty{0}, choosing_ns{0}, working_ns{0};
    parallel_for(binner_.chunks(), [&](std::size_t c) {
      constexpr std::size_t kRange = 512;  // records in L1/L2 between setup and counting
      std::uint64_t e = 0;
      const auto c0 = Clock::now();
      std::chrono::nanoseconds in_choice{0};  // timed only with a choice, for choice_ms
      for (std::size_t first = binner_.chunk_first(c), end = binner_.chunk_first(c + 1); first < end; first += kRange) {
        const std::size_t last = std::min(end, first + kRange);
        if (chooser) {
          const auto r0 = Clock::now();
          chooser->choose(first, last);
          in_choice += Clock::now() - r0;
        }
        e += setup_triangle_range(geometry_, method, out.triangles, out.attributes, out.fixed, gouraud, first, last, order);
        if (chooser) apply_triangle_choice(choice_, out.attributes, PHONG_ATTR_FLOATS, first, last);
        binner_.count_range(c, first, last);
      }
      empty += e;
      if (chooser) {
        choosing_ns += std::uint64_t(in_choice.count());
        working_ns += std::uint64_t(std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now() - c0).count());
      }
    });
    s.triangles_without_pixels = empty.load();
    if (chooser) {
      s.choice = chooser->stats();
      // The choice's share of the threads' time in this loop, as a share of setup's wall time so far.
      t.choice_ms = working_ns ? ms_since(setup_started) * double(choosing_ns) / double(working_ns) : 0.0;
    }
  } else {
    if (choose) {
      const auto c0 = Clock::now();
      s.choice = choose_triangle_methods(scene, geometry_, config.combined, budget, choice_);
      t.choice_ms = ms_since(c0);
    }
    s.triangles_without_pixels =
        setup_triangles(geometry_, method, out.triangles, out.attributes, out.fixed, choose ? choice_.data() : nullptr)
            .without_pixels;
    if (choose) apply_triangle_choice(choice_, out.attributes, PHONG_ATTR_FLOATS, 0, choice_.size());
  }
  if (choose) {
    if (uses_highlight_mask(config.combined))
      s.highlight = {s.choice->triangles, s.choice->without_highlight, s.choice->light_terms_skipped};
  } else if (method == Method::combined && config.combined.highlight_test) {
    s.highlight = mark_highlights(scene, geometry_, out.attributes, PHONG_ATTR_FLOATS, PHONG_HIGHLIGHT_SLOT,
                                  dropped_specular_levels(config.combined, budget, scene.lights.size()));
  }
  if (config.dda_coverage) {
    dda_ = apply_dda_coverage(geometry_, out.triangles, out.attributes, out.fixed);
    frame_.dda = &dda_;
  }
}

void FramePipeline::bin(const Scene& scene, FrameStorage& storage) {
  const FrameConfig& config = config_;
  const std::size_t n = frame_.records;
  if (counted_)  // setup counted the records
    binner_.finish();
  else
    binner_.count(frame_.arrays.triangles, n, scene.width, scene.height, config.tile_size);
  const std::vector<std::uint32_t>* start = &binner_.tile_start();
  if (config.band_rows >= 0) {  // empty every tile outside the band: tile k holds start[k] .. start[k + 1]
    band_start_ = binner_.tile_start();
    const std::size_t tiles = band_start_.size() - 1, tx = std::size_t(binner_.tiles_x());
    const std::size_t lo = std::min(tiles, tx * std::size_t(config.band_first));
    const std::size_t hi = std::min(tiles, tx * std::size_t(config.band_first + config.band_rows));
    for (std::size_t k = 0; k < lo; ++k) band_start_[k] = band_start_[lo];
    for (std::size_t k = hi + 1; k <= tiles; ++k) band_start_[k] = band_start_[hi];
    start = &band_start_;
  }
  std::uint32_t* list = storage.tile_list(binner_.entries());
  binner_.fill(list);
  frame_.tile_start = start->data();
  frame_.tile_list = list;
  frame_.tiles_x = binner_.tiles_x();
  frame_.tiles_y = binner_.tiles_y();
  frame_.tile_size = config.tile_size;
  frame_.stats.bin_entries = binner_.entries();
  frame_.stats.tiles = frame_.tiles();
  if (config.plan) {
    const auto t0 = Clock::now();
    // The planner costs every triangle over the full bins (a band's plan is not modeled: the table refuses it).
    const TileBins bins{binner_.tile_start().data(), list, binner_.tiles_x(), binner_.tiles_y(), binner_.tile_size()};
    plan_ = make_plan(frame_.arrays.triangles, n, bins, config.unit(), *config.plan);
    frame_.plan = &plan_;
    frame_.stats.plan = plan_.report;
    frame_.timings.planning_ms = ms_since(t0);
  }
}

}  // namespace parashade
