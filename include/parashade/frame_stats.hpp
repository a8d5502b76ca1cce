#pragma once
// What a frame took and what it held: stage times and counts, filled by the pipeline's host stages
// (prepare_frame) and by the device that renders it. Device-free.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "parashade/highlight.hpp"
#include "parashade/planner.hpp"
#include "parashade/screen_geometry.hpp"
#include "parashade/triangle_choice.hpp"
#include "parashade/units.hpp"

namespace parashade {

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
  int bands = 1;  // bands of tile rows the frame streamed in (FramePipeline::begin_frame); 1: whole
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

}  // namespace parashade
