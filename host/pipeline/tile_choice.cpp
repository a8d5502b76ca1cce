#include "parashade/tile_choice.hpp"

#include "parashade/frame_pipeline.hpp"
#include "parashade/geometry_stage.hpp"

namespace parashade {

int default_tile_size(const Scene& scene, const FrameConfig& config, std::size_t band_record_bytes) {
  // Per-span normalization walks rows, which 64-pixel tiles were not measured on.
  if (!config.whole_plain_frame() || config.span_normalize()) return TILE_DEFAULT;
  ScreenGeometry g;
  build_screen_geometry(scene, {config.method, false}, g);
  const RecordBudget budget = record_budget(band_record_bytes, scene.width, scene.height);
  // Records past the streaming threshold: the frame streams, or (the combined method, which does not) is as
  // large as Phong's streamed frames with records as large.
  return records_exceed(config.method, g.triangles.size(), budget.stream_above) ? TILE_DEFAULT : TILE_MAX;
}

}  // namespace parashade
