#pragma once
// The host memory a render's frame takes beyond the scene's own budget (memory_budget.hpp), judged once the
// scene is loaded and before any frame buffer is allocated: the per-pixel extras the options ask for
// (--float, --flip, the pictures), FLIP's bands of rows, and the triangle records the frame holds at once
// (all of them, or a band's when the frame streams: --band-mib).
#include "parashade/memory_budget.hpp"
#include "parashade/render_step.hpp"

namespace parashade {

// What `request` keeps beyond the frame it shades, for a `scene` of `triangles` triangles.
FrameExtras frame_extras(const RenderRequest& request, int width, int height, std::uint64_t triangles);

// Throws InputError (check_host_memory's message, naming the options) when the loaded scene's objects and
// frame with the extras exceed the host memory limit.
void check_frame_memory(const Scene& scene, const RenderRequest& request);

}  // namespace parashade
