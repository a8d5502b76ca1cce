// The planner's load for a scene, host only (scene_plans.hpp).
#include "parashade/scene_plans.hpp"

#include "parashade/frame_pipeline.hpp"

namespace parashade {

ScenePlans plan_scene(const Scene& scene, const FrameConfig& config, const std::vector<PlanOptions>& plans) {
  FramePipeline pipeline(config);
  const PreparedFrame& frame = pipeline.prepare_frame(scene);
  ScenePlans out;
  out.screen_triangles = frame.records;
  out.bin_entries = frame.bin_entries();
  for (const PlanOptions& o : plans)
    out.reports.push_back(make_plan(frame.arrays.triangles, frame.records, frame.bins(), config.unit(), o).report);
  return out;
}

}  // namespace parashade
