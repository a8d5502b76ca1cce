#pragma once
// The planner's per-unit load and how the units' depth pass was mapped, as text (render's summary and
// `parashade plan`).
#include <cstdio>

#include "parashade/frame_stats.hpp"
#include "parashade/planner.hpp"

namespace parashade {

// The per-unit load and its summary.
void print_plan(const PlanReport& r, bool per_unit, std::FILE* out = stdout);

// How the units' depth pass was mapped (work-items of one device, or which sub-device ran which units)
// with each share's pass time.
void print_unit_mapping(const FrameStats& s, const FrameTimings& t, std::FILE* out = stdout);

}  // namespace parashade
