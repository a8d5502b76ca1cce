#include "against_frames.hpp"

#include <cstdio>

#include "cli_args.hpp"
#include "frame_medians.hpp"
#include "parashade/errors.hpp"
#include "parashade/method.hpp"
#include "parashade/report.hpp"
#include "parashade/statistics.hpp"
#include "parashade/tile_choice.hpp"

namespace parashade::cli {
namespace {

RenderOptions against_options(const Scene& scene, const std::string& method, std::size_t band_record_bytes) {
  RenderOptions o;
  o.method = AgainstFrames::check_method(method);
  o.band_record_bytes = band_record_bytes;
  o.tile_size = default_tile_size(scene, o, band_record_bytes);
  return o;
}

nlohmann::json ratios(const std::vector<double>& r) {
  return {{"median", median(r)}, {"p10", quantile(r, 0.1)}, {"p90", quantile(r, 0.9)}};
}

}  // namespace

Method AgainstFrames::check_method(const std::string& method) {
  const Method m = for_option("--against", [&] { return parse_method(method); });
  // A combined configuration would need options of its own; the baselines are the plain methods.
  if (m == Method::combined)
    throw UsageError("--against takes flat, gouraud or phong with render's defaults (got '" + method + "')");
  return m;
}

AgainstFrames::AgainstFrames(Device& device, const Scene& scene, const std::string& method,
                             std::size_t band_record_bytes)
    : name_(method), renderer_(device, against_options(scene, method, band_record_bytes)) {}

nlohmann::json AgainstFrames::summary(const std::vector<FrameTimings>& method) const {
  std::vector<double> frame, kernel;
  for (std::size_t i = 0; i < method.size() && i < timings_.size(); ++i) {
    frame.push_back(timings_[i].total_ms / method[i].total_ms);
    if (method[i].kernel_ms > 0) kernel.push_back(timings_[i].kernel_ms / method[i].kernel_ms);
  }
  const FrameTimings med = median_timings(timings_);
  std::vector<double> samples;
  for (const FrameTimings& t : timings_) samples.push_back(t.total_ms);
  return {{"method", name_},
          {"pairs", frame.size()},
          {"frame_ms", med.total_ms},
          {"samples_ms", samples},
          {"stages_ms", to_json(med)},
          {"frame_ratio", ratios(frame)},
          {"kernel_ratio", ratios(kernel)},
          {"note", "each pair one frame of each renderer in one process, the against frame first in even pairs; "
                   "ratio = against ms / this method's ms (> 1: this method faster)"}};
}

std::string AgainstFrames::line(const nlohmann::json& s) {
  char buf[320];
  const nlohmann::json& f = s.at("frame_ratio");
  std::snprintf(buf, sizeof buf,
                "against %s: %.3f ms; this method %.3fx as fast (median of %d pairs' ratios, p10 %.3f, p90 %.3f; "
                "kernel %.3fx)",
                s.at("method").get<std::string>().c_str(), s.at("frame_ms").get<double>(), f.at("median").get<double>(),
                s.at("pairs").get<int>(), f.at("p10").get<double>(), f.at("p90").get<double>(),
                s.at("kernel_ratio").at("median").get<double>());
  return buf;
}

}  // namespace parashade::cli
