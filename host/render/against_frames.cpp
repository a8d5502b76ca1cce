#include "against_frames.hpp"

#include "frame_medians.hpp"
#include "parashade/tile_choice.hpp"

namespace parashade {
namespace {

RenderOptions against_options(const Scene& scene, Method method, std::size_t band_record_bytes) {
  RenderOptions o;
  o.method = method;
  o.band_record_bytes = band_record_bytes;
  o.tile_size = default_tile_size(scene, o, band_record_bytes);
  return o;
}

}  // namespace

AgainstFrames::AgainstFrames(Device& device, const Scene& scene, Method method, std::size_t band_record_bytes)
    : method_(method_name(method)), renderer_(device, against_options(scene, method, band_record_bytes)) {}

AgainstFrames::AgainstFrames(const ResolvedRender& other)
    : method_(method_name(other.options.method)),
      device_(other.devices.front()->info().name),
      renderer_(*other.devices.front(), other.options) {}

AgainstSummary AgainstFrames::summary(const std::vector<FrameTimings>& method) const {
  AgainstSummary s;
  s.method = method_;
  s.device = device_;
  for (std::size_t i = 0; i < method.size() && i < timings_.size(); ++i) {
    s.frame_ratios.push_back(timings_[i].total_ms / method[i].total_ms);
    if (method[i].kernel_ms > 0) s.kernel_ratios.push_back(timings_[i].kernel_ms / method[i].kernel_ms);
  }
  s.medians = median_timings(timings_);
  for (const FrameTimings& t : timings_) s.samples_ms.push_back(t.total_ms);
  return s;
}

}  // namespace parashade
