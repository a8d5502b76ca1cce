#pragma once
// The screen tile edge a frame gets when none is asked for (`parashade render` without --tile or a tuned
// entry, bench_llvmpipe). 64-pixel tiles repeat each triangle's per-tile work (record loads, span search) in
// fewer tiles and bin fewer entries: for Gouraud and flat frames this paid since the kernel shades 4x4 stamps
// (bench/README.md, run Q), for Phong and the combined method since they defer tiles and walk the stamps (run
// AA: 1.03-1.09x). A frame streamed in bands keeps TILE_DEFAULT: a band of 64-pixel tile rows holds too few tiles
// for the work-items (sphere_2m's kernel 1.32x slower); so do per-span normalization and the paths whose spans
// or counters follow the tiles (units, plans, split bands).
#include <cstddef>

#include "parashade/frame_config.hpp"
#include "parashade/scene.hpp"

namespace parashade {

// TILE_MAX for a whole plain frame (Gouraud, flat, Phong without per-span normalization, combined) whose records
// stay within the streaming threshold, else TILE_DEFAULT. Runs the geometry
// stage once to count the frame's screen triangles (FramePipeline's streaming rule, records_exceed), so it
// costs about one frame's geometry: call it once per scene, not per frame. band_record_bytes as
// RenderOptions' (kBandBytesByFrame: the frame's default budget).
int default_tile_size(const Scene& scene, const FrameConfig& config, std::size_t band_record_bytes);

}  // namespace parashade
