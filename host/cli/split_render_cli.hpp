#pragma once
// `render --device all|A,B`: the frame split across devices (split_renderer.hpp); image, summary and
// report (per-device bands and times). No error figures in this mode.
#include <string>

#include "parashade/renderer.hpp"
#include "parashade/scene.hpp"

namespace parashade::cli {

struct SplitRenderArgs {
  std::string devices, device_origin, output, report, scene_file;  // device_origin: device_option.hpp
  int frames = 5, warmup = 1;
  bool keep_going = false, quiet = false;
};

int run_split_render(const Scene& scene, const RenderOptions& options, const SplitRenderArgs& a);

}  // namespace parashade::cli
