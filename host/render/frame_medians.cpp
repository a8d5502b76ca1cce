#include "frame_medians.hpp"

#include "parashade/statistics.hpp"

namespace parashade {

FrameTimings median_timings(const std::vector<FrameTimings>& f) {
  const auto med = [&](double FrameTimings::*field) {
    std::vector<double> v;
    for (const auto& t : f) v.push_back(t.*field);
    return median(v);
  };
  FrameTimings m;
  m.geometry_ms = med(&FrameTimings::geometry_ms);
  m.setup_ms = med(&FrameTimings::setup_ms);
  m.choice_ms = med(&FrameTimings::choice_ms);
  m.binning_ms = med(&FrameTimings::binning_ms);
  m.kernel_ms = med(&FrameTimings::kernel_ms);
  m.launch_ms = med(&FrameTimings::launch_ms);
  m.readback_ms = med(&FrameTimings::readback_ms);
  m.total_ms = med(&FrameTimings::total_ms);
  m.planning_ms = med(&FrameTimings::planning_ms);
  m.unit_pass_ms = med(&FrameTimings::unit_pass_ms);
  m.key_merge_ms = med(&FrameTimings::key_merge_ms);
  for (std::size_t k = 0; !f.empty() && k < f.front().unit_pass_share_ms.size(); ++k) {
    std::vector<double> v;
    for (const auto& t : f) v.push_back(k < t.unit_pass_share_ms.size() ? t.unit_pass_share_ms[k] : 0.0);
    m.unit_pass_share_ms.push_back(median(v));
  }
  return m;
}

}  // namespace parashade
