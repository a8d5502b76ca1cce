#include "parashade/tile_choice.hpp"

#include "parashade/frame_pipeline.hpp"
#include "parashade/geometry_stage.hpp"

namespace parashade {

int default_tile_size(const Scene& scene, const FrameConfig& config, std::size_t band_record_bytes) {
  // The combined method does not stream, but its records are Phong's: a frame whose Phong records would stream
  // keeps TILE_DEFAULT as Phong's does. Per-span normalization walks rows, which 64-pixel tiles were not measured on.
  FrameConfig as_records = config;
  if (as_records.method == Method::combined) as_records.method = Method::phong;
  if (!frame_can_stream(as_records) || as_records.span_normalize()) return TILE_DEFAULT;
  ScreenGeometry g;
  build_screen_geometry(scene, {config.method, false}, g);
  const RecordBudget budget = record_budget(band_record_bytes, scene.width, scene.height);
  return frame_streams(as_records, g.triangles.size(), budget.stream_above) ? TILE_DEFAULT : TILE_MAX;
}

}  // namespace parashade
