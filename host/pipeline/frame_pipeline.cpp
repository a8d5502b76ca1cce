#include "parashade/frame_pipeline.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>

#include "parashade/combined.hpp"
#include "parashade/geometry_stage.hpp"
#include "parashade/highlight.hpp"
#include "parashade/parallel.hpp"
#include "parashade/setup.hpp"
#include "parashade/sierpinski_setup.hpp"

namespace parashade {
namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

}  // namespace

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

const PreparedFrame& FramePipeline::prepare_frame(const Scene& scene, const FrameConfig& config) {
  return prepare_frame(scene, config, host_);
}

const PreparedFrame& FramePipeline::prepare_frame(const Scene& scene, const FrameConfig& config, FrameStorage& storage) {
  check_frame_config(config);
  check_resolution(scene.width, scene.height, "scene '" + scene.name + "'");
  frame_ = PreparedFrame{};
  FrameTimings& t = frame_.timings;
  FrameStats& s = frame_.stats;

  auto t0 = Clock::now();
  build_screen_geometry(scene, {config.method, false, config.chooses_per_triangle()}, geometry_);
  // The extra-triangulation unit needs its midpoints on pixel corners: vertex parity normalization.
  const bool split = config.splits_triangles();
  if (split) s.parity_dropped = snap_sierpinski_vertices(geometry_, config.unit());
  t.geometry_ms = ms_since(t0);
  s.geometry = geometry_.stats;
  frame_.geometry = &geometry_;

  t0 = Clock::now();
  const std::size_t triangles = geometry_.triangles.size();
  frame_.records = split ? triangles << (2 * config.unit().depth) : triangles;  // sub-triangles when split
  frame_.arrays = storage.records(frame_.records, attribute_floats(config.method), config.arith.fixed, split);
  setup(scene, config, frame_.arrays);
  t.setup_ms = ms_since(t0);

  t0 = Clock::now();
  bin(scene, config, storage);
  t.binning_ms = ms_since(t0);
  parallel_rest();  // the device's kernel comes next, on the same cores
  return frame_;
}

void FramePipeline::setup(const Scene& scene, const FrameConfig& config, const FrameRecords& out) {
  FrameTimings& t = frame_.timings;
  FrameStats& s = frame_.stats;
  const Method method = config.method;
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
  const bool choose = config.chooses_per_triangle();
  if (choose) {
    const auto c0 = Clock::now();
    s.choice = choose_triangle_methods(scene, geometry_, config.combined, combined_shading_budget(config.combined),
                                       choice_);
    t.choice_ms = ms_since(c0);
  }
  const TriangleShading* gouraud = choose ? choice_.data() : nullptr;
  counted_ = !config.dda_coverage;  // DDA coverage changes the boxes after setup
  if (counted_) {
    // Binning's count pass runs on each range of records right after its setup, while they are in cache.
    const std::size_t n = geometry_.triangles.size();
    binner_.begin(out.triangles, n, scene.width, scene.height, config.tile_size);
    std::atomic<std::uint64_t> empty{0};
    parallel_for(binner_.chunks(), [&](std::size_t c) {
      constexpr std::size_t kRange = 512;  // records in L1/L2 between setup and counting
      std::uint64_t e = 0;
      for (std::size_t first = binner_.chunk_first(c), end = binner_.chunk_first(c + 1); first < end; first += kRange) {
        const std::size_t last = std::min(end, first + kRange);
        e += setup_triangle_range(geometry_, method, out.triangles, out.attributes, out.fixed, gouraud, first, last);
        binner_.count_range(c, first, last);
      }
      empty += e;
    });
    s.triangles_without_pixels = empty.load();
  } else {
    s.triangles_without_pixels =
        setup_triangles(geometry_, method, out.triangles, out.attributes, out.fixed, gouraud).without_pixels;
  }
  if (choose) {
    apply_triangle_choice(choice_, out.attributes, PHONG_ATTR_FLOATS);
    if (uses_highlight_mask(config.combined))
      s.highlight = {s.choice->triangles, s.choice->without_highlight, s.choice->light_terms_skipped};
  } else if (method == Method::combined && config.combined.highlight_test) {
    s.highlight = mark_highlights(scene, geometry_, out.attributes, PHONG_ATTR_FLOATS, PHONG_HIGHLIGHT_SLOT,
                                  config.combined.negligible_specular);
  }
  if (config.dda_coverage) {
    dda_ = apply_dda_coverage(geometry_, out.triangles, out.attributes, out.fixed);
    frame_.dda = &dda_;
  }
}

void FramePipeline::bin(const Scene& scene, const FrameConfig& config, FrameStorage& storage) {
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
