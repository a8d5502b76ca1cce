#pragma once
// One frame on an OpenCL device: vertex stage and primitive assembly, triangle setup, binning (host,
// "software"), then the shading kernel (the modeled hardware units), then read-back.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <CL/opencl.hpp>

#include "parashade/binning.hpp"
#include "parashade/combined.hpp"
#include "parashade/dda_coverage.hpp"
#include "parashade/device.hpp"
#include "parashade/highlight.hpp"
#include "parashade/image.hpp"
#include "parashade/method.hpp"
#include "parashade/planner.hpp"
#include "parashade/normalization.hpp"
#include "parashade/scene.hpp"
#include "parashade/screen_geometry.hpp"
#include "parashade/specular_models.hpp"
#include "parashade/triangle_choice.hpp"
#include "parashade/units.hpp"
#include "kernels/constants.h"

namespace parashade {

struct RenderOptions {
  Method method = Method::gouraud;
  bool float_output = false;  // also read back unclamped float RGB (for EXR and exact error figures)
  int tile_size = TILE_DEFAULT;  // screen tile edge in pixels: 16, 32 or 64 (kernels/constants.h)
  int work_items = 0;            // kernel work-items, each rendering every G-th tile; 0: WORK_ITEMS_PER_COMPUTE_UNIT per CU
  // Gouraud through a modeled shading unit (units.hpp): set by `--units`, or classic with a fixed `arith`.
  // Every triangle then goes by whole spans and the frame's modeled clocks are counted.
  std::optional<UnitConfig> units;
  Arithmetic arith;
  SpanDivision division;  // fixed point: the span increment by a division per span (--div)
  bool dda_coverage = false;  // the sources' edge-walking coverage instead of pixel centres (--coverage dda)
  // --cu / --partition: the frame by U modeled units from the planner's work lists, then a resolve pass
  // (docs/planner.md); the image is the same bytes as without.
  std::optional<PlanOptions> plan;
  // Only tile rows [band_first, band_first + band_rows) are shaded, the rest is background (a device's
  // share of a frame split across devices, split_renderer.hpp); band_rows < 0: the whole frame.
  int band_first = 0, band_rows = -1;
  SpecularModel specular;     // Phong: the specular model (--specular, kernels/specular_models.h)
  NormalizeMethod normalize;  // Phong: unit normals per span (--normalize, kernels/normalize_span.h)
  bool span_normalize() const { return method == Method::phong && normalize.kind != NormalizeKind::exact; }
  CombinedConfig combined;    // Method::combined: segment length or auto with its error budget
  bool unit_path() const { return units.has_value() || arith.fixed || dda_coverage; }
  UnitConfig unit() const { return units.value_or(UnitConfig{}); }
};

// Milliseconds. Host stages by the host clock; kernel_ms from the OpenCL profiling event.
struct FrameTimings {
  double geometry_ms = 0;  // vertex stage + clipping, culling, snapping
  double setup_ms = 0;     // triangle setup (edge functions, planes, dI_G)
  double choice_ms = 0;    // of setup_ms: the per-triangle method choice (combined with --triangle-choice)
  double binning_ms = 0;   // sort-middle binning into tiles, upload
  double kernel_ms = 0;    // shading kernel on the device (profiling event)
  double launch_ms = 0;    // enqueue to completion on the host clock (kernel_ms + launch overhead)
  double readback_ms = 0;  // map the frame and copy it out
  double total_ms = 0;     // the whole frame
  double planning_ms = 0;  // with a plan: costs, assignment and work lists (host)
  double unit_pass_ms = 0; // with a plan: the units' depth pass (profiling events); kernel_ms is the resolve
  // On sub-devices: unit_pass_ms from the first share's start to the last one's end; each share's own
  // pass (as FrameStats::unit_pass, 0 for a share without units) and the min-merge of their keys.
  std::vector<double> unit_pass_share_ms;
  double key_merge_ms = 0;
};

// Which device ran which modeled units in the units' depth pass (docs/planner.md): the device itself
// (U work-items of work-group size 1), or one share per sub-device (a contiguous block of units).
struct UnitPassShare {
  std::string device;
  int compute_units = 0;
  int first_unit = 0, units = 0;      // units [first_unit, first_unit + units), a work-item each
  int first_packet = 0, packets = 0;  // the work lists' packets they run (static: one per unit; dynamic: batches)
};

struct FrameStats {
  GeometryStats geometry;
  std::uint64_t triangles_without_pixels = 0;
  std::uint64_t bin_entries = 0;
  int tiles = 0;
  ModeledClocks clocks;  // on the unit path only (RenderOptions::unit_path)
  // Per-span normalization: span setups (per span and tile), those that fell back to the exact normal,
  // and a sequential method's unit steps (the recurrence: pixels stepped, including those before a tile).
  std::uint64_t normalize_span_setups = 0, normalize_fallback_spans = 0, normalize_sequential_steps = 0;
  std::uint64_t parity_dropped = 0;  // sierpinski: triangles degenerate after vertex parity normalization
  std::uint64_t sierpinski_whole = 0;  // sierpinski :touch/:overlap: too small to halve, shaded whole
  std::optional<PlanReport> plan;    // with a plan: the modeled per-unit load
  std::vector<UnitPassShare> unit_pass;  // with a plan: how the units were mapped onto the device(s)
  bool unit_pass_on_sub_devices = false;
  HighlightMarks highlight;          // combined with the highlight-presence test
  std::optional<TriangleChoiceStats> choice;  // combined with a per-triangle method choice
};

struct Frame {
  RenderedImage image;
  FrameTimings timings;
  FrameStats stats;
};

class Renderer {
 public:
  // unit_devices (with a plan only): sub-devices of `device`, in its context (sub_devices.hpp), over
  // which the units' depth pass is spread; empty: the units run as work-items of `device`.
  Renderer(Device& device, RenderOptions options, std::vector<Device*> unit_devices = {});
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;
  // Renders one frame. The result stays valid until the next render() (its memory is reused).
  const Frame& render(const Scene& scene);
  // Per pixel (row-major, width x height), how many triangles cover its centre, ignoring depth:
  // the same geometry, tiles and span computation as render(). For watertightness tests.
  std::vector<std::uint32_t> coverage_counts(const Scene& scene);
  // The screen geometry of the last render() or coverage_counts().
  const ScreenGeometry& geometry() const { return geometry_; }
  const RenderOptions& options() const { return options_; }
  // Work-items the kernel runs with for a frame of `tiles` tiles.
  int work_items(int tiles) const;

 private:
  void prepare(const Scene& scene, FrameTimings& t, FrameStats& s);  // geometry, setup, binning
  void release_frame();  // unmaps the last frame's image
  // planned_frame.cpp: the plan of a frame (in prepare), and the units' pass before the resolve kernel.
  void plan_frame(const TriangleGeometry* tris, std::size_t n, const std::uint32_t* tile_list, FrameTimings& t, FrameStats& s);
  struct UnitPassEvents {
    std::vector<cl::Event> share;  // per FrameStats::unit_pass entry (none for a share without units)
    std::vector<cl::Event> merge;  // sub-devices: the key merges
  };
  std::vector<UnitPassShare> unit_pass_shares() const;
  void enqueue_unit_pass(cl::Kernel& resolve, const std::vector<std::string>& files, const std::string& options,
                         cl_float4 viewer, cl_float4 background, const Scene& scene,
                         const std::vector<UnitPassShare>& shares, UnitPassEvents& events);
  void unit_pass_times(const UnitPassEvents& events, FrameTimings& t) const;
  cl::Buffer& ensure(cl::Buffer& buffer, std::size_t& capacity, std::size_t bytes, cl_mem_flags flags);
  // render_tiles' arguments 0..18 (the frame's buffers, with these tile lists): the plain kernel, the
  // resolve and the units' pass share them.
  void set_tile_kernel_args(cl::Kernel& k, const cl::Buffer& tile_start, const cl::Buffer& tile_list, cl_float4 viewer,
                            cl_float4 background, const Scene& scene);

  Device& device_;
  RenderOptions options_;
  std::vector<Device*> unit_devices_;
  ScreenGeometry geometry_;
  std::vector<TriangleShading> choice_;  // combined: the per-triangle method choice of this frame
  Frame frame_;
  Binner binner_;
  cl::Buffer tris_, attrs_, tile_start_, tile_tris_, lights_, materials_, out_rgba_, out_float_, counts_, fixed_,
      tile_clocks_, leaves_, dda_first_, dda_rows_;
  Plan plan_;
  std::vector<std::uint32_t> band_start_;  // tile_start with the tiles outside the band emptied
  cl::Buffer keys_, plan_packets_, plan_vtiles_, plan_starts_, plan_list_, plan_counter_;
  std::vector<cl::Buffer> share_keys_, share_counters_;  // sub-devices: each one's keys and batch counter
  std::vector<std::size_t> share_keys_cap_, share_counters_cap_;
  std::size_t keys_cap_ = 0, plan_packets_cap_ = 0, plan_vtiles_cap_ = 0, plan_starts_cap_ = 0, plan_list_cap_ = 0,
              plan_counter_cap_ = 0;
  DdaRowTable dda_;  // the last frame's row table (uploaded without waiting: it must outlive the copy)
  // sierpinski: setup's whole-triangle records before the split (kept to reuse their memory)
  std::vector<TriangleGeometry> whole_;
  std::vector<float> whole_attr_;
  std::vector<FixedPlanes> whole_fixed_;
  void* mapped_rgba_ = nullptr;   // the last frame's image, mapped for the host until the next render
  void* rgba_host_ = nullptr;       // the memory out_rgba_ was created on (frame_.image.rgba)
  std::size_t tris_cap_ = 0, attrs_cap_ = 0, start_cap_ = 0, list_cap_ = 0, lights_cap_ = 0, materials_cap_ = 0,
              float_cap_ = 0, counts_cap_ = 0, fixed_cap_ = 0,
              tile_clocks_cap_ = 0, leaves_cap_ = 0,
              dda_first_cap_ = 0, dda_rows_cap_ = 0;
};

}  // namespace parashade
