#include "split_render_cli.hpp"

#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>

#include "cli_args.hpp"
#include "device_option.hpp"
#include "common_options.hpp"
#include "progress.hpp"

#include "parashade/image.hpp"
#include "parashade/output_file.hpp"
#include "parashade/report.hpp"
#include "parashade/report_header.hpp"
#include "parashade/split_renderer.hpp"
#include "parashade/statistics.hpp"

namespace parashade::cli {

int run_split_render(const Scene& scene, const RenderOptions& options, const SplitRenderArgs& a) {
  auto devices = for_device(a.device_origin, [&] { return open_devices(a.devices); });
  nlohmann::json device_info = nlohmann::json::array();
  for (const auto& d : devices) device_info.push_back(to_json(d->info()));
  SplitRenderer renderer(std::move(devices), options, a.keep_going);
  std::string warning;
  const auto warn = [&] {
    if (!warning.empty()) std::cerr << "parashade: warning: " << warning;
    warning.clear();
  };
  FrameProgress progress(a.warmup + a.frames, a.quiet);
  for (int i = 0; i < a.warmup; ++i) {
    renderer.render(scene, &warning);  // the first is the calibration frame (equal bands)
    warn();
    progress.step(i + 1);
  }
  std::vector<double> times;
  const Frame* f = nullptr;
  for (int i = 0; i < a.frames; ++i) {
    f = &renderer.render(scene, &warning);
    warn();
    times.push_back(f->timings.total_ms);
    progress.step(a.warmup + i + 1);
  }
  const double ms = median(times);
  StagedFile staged_image = stage_image(a.output, f->image);  // replaces the old image with the report
  nlohmann::json shares = nlohmann::json::array();
  for (const auto& s : renderer.shares())
    shares.push_back({{"device", s.device}, {"first_tile_row", s.first_row}, {"tile_rows", s.rows},
                      {"band_ms", s.frame_ms}, {"failed", s.failed}, {"error", s.error}});
  if (!a.report.empty()) {
    const nlohmann::json report = {{"scene", scene.name},   {"scene_file", a.scene_file}, {"image", a.output},
                                   {"width", scene.width},  {"height", scene.height},     {"frame_ms", ms},
                                   {"frame_ms_note", "median of " + std::to_string(a.frames) + " split frames"},
                                   {"timing", timing_json(times, a.warmup)},
                                   {"device_info", device_info},
                                   {"devices", shares}};
    StagedFile staged_report = stage_text(a.report, report_text(report, "render-split"));
    staged_image.commit();
    staged_report.commit();
  } else {
    staged_image.commit();
  }
  std::printf("%s: %dx%d split across devices, frame %.3f ms (median of %d)\n", scene.name.c_str(), scene.width,
              scene.height, ms, a.frames);
  for (const auto& s : renderer.shares()) {
    if (s.failed)
      std::printf("  %-40s FAILED, dropped (--keep-going)\n", s.device.c_str());
    else
      std::printf("  %-40s tile rows %4d..%4d (%d rows) %9.3f ms\n", s.device.c_str(), s.first_row,
                  s.first_row + s.rows - 1, s.rows, s.frame_ms);
  }
  std::printf("wrote %s%s%s\n", a.output.c_str(), a.report.empty() ? "" : " and ", a.report.c_str());
  return 0;
}

}  // namespace parashade::cli
