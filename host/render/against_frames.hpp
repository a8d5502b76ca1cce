#pragma once
// `render --against METHOD`: a second renderer of the same scene on the same device, whose frames alternate
// with the rendered method's, one pair at a time (the against frame first in even pairs, second in odd
// ones). `render --against-device D`: the same request on device D, resolved there (its own layout). On a
// shared host whose speed drifts, or changes from one process to the next, both sides of a pair see the same
// host: the speed figure is the median of the pairs' ratios (bench/README.md, run AE).
#include <vector>

#include "parashade/device.hpp"
#include "parashade/method.hpp"
#include "parashade/render_step.hpp"
#include "parashade/renderer.hpp"
#include "parashade/scene.hpp"

namespace parashade {

class AgainstFrames {
 public:
  // `method` (flat, gouraud or phong) with render's defaults for it: the default tile, no tuned entry.
  AgainstFrames(Device& device, const Scene& scene, Method method, std::size_t band_record_bytes);
  // The request as resolved on the other device (ResolvedRender::against_device).
  explicit AgainstFrames(const ResolvedRender& other);

  static bool first_in_pair(int pair) { return pair % 2 == 0; }
  void warm_up(const Scene& scene) { renderer_.render(scene); }
  void frame(const Scene& scene) { timings_.push_back(renderer_.render(scene).timings); }

  // The against method's medians and the pairs' ratios (against / this method's frame, > 1: this method
  // faster), frame and kernel. `method` holds this method's frames, pair by pair.
  AgainstSummary summary(const std::vector<FrameTimings>& method) const;

 private:
  std::string method_, device_;  // AgainstSummary's
  Renderer renderer_;
  std::vector<FrameTimings> timings_;
};

}  // namespace parashade
