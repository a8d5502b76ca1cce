#pragma once
// The planner's per-unit load for a scene without a device (`parashade plan`): the frame prepared as
// render prepares it, then one plan per strategy and unit count asked for.
#include <cstddef>
#include <vector>

#include "parashade/frame_config.hpp"
#include "parashade/planner.hpp"
#include "parashade/scene.hpp"

namespace parashade {

struct ScenePlans {
  std::size_t screen_triangles = 0, bin_entries = 0;
  std::vector<PlanReport> reports;  // one per plan asked for, in order
};

// `config` without a plan (checked as FramePipeline checks it); `plans` with their units resolved.
ScenePlans plan_scene(const Scene& scene, const FrameConfig& config, const std::vector<PlanOptions>& plans);

}  // namespace parashade
