#include "parashade/tile_choice.hpp"

#include "parashade/frame_pipeline.hpp"
#include "parashade/geometry_stage.hpp"

namespace parashade {

int default_tile_size(const Scene& scene, const FrameConfig& config, std::size_t band_record_bytes) {
  // Phong keeps TILE_DEFAULT: 64-pixel tiles were mixed for it (the spheres 0.86-0.98x, the teapot 1.01-1.08x).
  if (!frame_can_stream(config) || (config.method != Method::gouraud && config.method != Method::flat))
    return TILE_DEFAULT;
  ScreenGeometry g;
  build_screen_geometry(scene, {config.method, false}, g);
  const RecordBudget budget = record_budget(band_record_bytes, scene.width, scene.height);
  return frame_streams(config, g.triangles.size(), budget.stream_above) ? TILE_DEFAULT : TILE_MAX;
}

}  // namespace parashade
