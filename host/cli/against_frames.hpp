#pragma once
// `render --against METHOD`: a second renderer of the same scene on the same device, whose frames alternate
// with the rendered method's, one pair at a time (the against frame first in even pairs, second in odd
// ones). On a shared host whose speed drifts, or changes from one process to the next, both sides of a pair
// see the same host: the speed figure is the median of the pairs' ratios (bench/README.md, run AE).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "parashade/device.hpp"
#include "parashade/method.hpp"
#include "parashade/renderer.hpp"
#include "parashade/scene.hpp"

namespace parashade::cli {

class AgainstFrames {
 public:
  // METHOD: flat, gouraud or phong, rendered with render's defaults for it (default tile, no tuned entry).
  AgainstFrames(Device& device, const Scene& scene, const std::string& method, std::size_t band_record_bytes);

  // METHOD as --against takes it; a usage error for any other.
  static Method check_method(const std::string& method);

  static bool first_in_pair(int pair) { return pair % 2 == 0; }
  void warm_up(const Scene& scene) { renderer_.render(scene); }
  void frame(const Scene& scene) { timings_.push_back(renderer_.render(scene).timings); }

  // The report's "against": the against method's medians and the pairs' ratios (against / this method's
  // frame, > 1: this method faster), frame and kernel. `method` holds this method's frames, pair by pair.
  nlohmann::json summary(const std::vector<FrameTimings>& method) const;
  // One line for the terminal, from summary().
  static std::string line(const nlohmann::json& summary);

 private:
  std::string name_;
  Renderer renderer_;
  std::vector<FrameTimings> timings_;
};

}  // namespace parashade::cli
