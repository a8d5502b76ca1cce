// A render's result as the summary printed on the terminal and its warnings (render_report.hpp).
#include <algorithm>

#include "parashade/combined.hpp"
#include "parashade/distributed.hpp"
#include "parashade/render_report.hpp"
#include "parashade/statistics.hpp"
#include "parashade/unit_table.hpp"
#include "plan_summary.hpp"
#include "register_events_report.hpp"
#include "vanishing_warnings.hpp"

namespace parashade {
namespace {

using ull = unsigned long long;

// The kernel's layout, each setting with where it came from (option, tune cache, device properties, frame).
void print_layout(const RenderResult& r, std::FILE* out) {
  const LayoutSources& s = r.sources;
  std::fprintf(out, "layout: %s kernel shape (%s), work-groups of %d (%s), %d work-items (%s), tile %d (%s)\n",
               kernel_shape_name(r.options.kernel_shape), s.kernel_shape.c_str(), r.options.group_size(),
               s.work_group_size.c_str(), r.work_items, s.work_items.c_str(), r.options.tile_size, s.tile.c_str());
}

void print_frame(const RenderResult& r, std::FILE* out) {
  const FrameTimings& m = r.medians;
  const double pixels = double(r.width) * r.height, triangles = double(r.stats.geometry.triangles_in);
  std::fprintf(out, "%s: %dx%d, %llu triangles (%llu after culling and clipping), method %s\n", r.scene_name.c_str(),
               r.width, r.height, ull(r.stats.geometry.triangles_in), ull(r.stats.geometry.triangles_out),
               r.options.method == Method::combined ? combined_name(r.options.combined).c_str()
                                                    : method_name(r.options.method));
  const DeviceInfo& dev = r.devices.front();
  std::fprintf(out, "device: %s (%s), %d compute units\n", dev.name.c_str(), dev.platform.c_str(), dev.compute_units);
  print_layout(r, out);
  // The stages add up to the frame: launch is the kernels from enqueue to completion on the host's clock
  // (kernel, the device's own time, is part of it), and other is what no stage covers (buffers, arguments;
  // from medians, so it may be slightly negative).
  const double other = m.total_ms - (m.geometry_ms + m.setup_ms + m.binning_ms + m.launch_ms + m.readback_ms);
  std::fprintf(out,
               "frame: %.3f ms (median of %d after %d warm-up; geometry %.3f, setup %.3f, binning %.3f, launch %.3f "
               "(kernel %.3f of it), read-back %.3f, other %.3f) = %.1f fps, %.1f Mpixel/s, %.2f Mtriangle/s\n",
               m.total_ms, r.frames, r.warmup, m.geometry_ms, m.setup_ms, m.binning_ms, m.launch_ms, m.kernel_ms,
               m.readback_ms, other, 1e3 / m.total_ms, pixels / (m.total_ms * 1e3), triangles / (m.total_ms * 1e3));
  if (m.choice_ms > 0.0) std::fprintf(out, "setup includes the per-triangle method choice: %.3f ms\n", m.choice_ms);
  if (const auto& a = r.against) {
    const bool device = !a->device.empty();
    std::fprintf(out,
                 "against %s%s: %.3f ms; this %s %.3fx as fast (median of %zu pairs' ratios, p10 %.3f, p90 %.3f; "
                 "kernel %.3fx)\n",
                 device ? "device " : "", (device ? a->device : a->method).c_str(), a->medians.total_ms,
                 device ? "device" : "method", median(a->frame_ratios), a->frame_ratios.size(),
                 quantile(a->frame_ratios, 0.1), quantile(a->frame_ratios, 0.9), median(a->kernel_ratios));
  }
}

void print_hardware(const RenderResult& r, bool per_unit, std::FILE* out) {
  const RenderOptions& o = r.options;
  if (o.unit_path()) {
    const ModeledClocks& c = r.stats.clocks;
    std::fprintf(out,
                 "unit %s, %s arithmetic, span increment %s: %llu modeled clocks (%llu spans, %llu span pixels, %.3f "
                 "pixels per clock)\n",
                 unit_name(o.unit()).c_str(), arith_name(o.arith).c_str(), division_name(o.division).c_str(),
                 ull(c.clocks), ull(c.spans), ull(c.pixels), c.clocks ? double(c.pixels) / double(c.clocks) : 0.0);
    if (const auto& e = r.registers)
      std::fprintf(out, "registers: %llu of %llu span pixels wrapped around, %llu span register loads saturated\n",
                   ull(e->wrapped_pixels), ull(e->span_pixels), ull(e->saturated_loads));
  }
  if (r.stats.plan) {
    print_plan(*r.stats.plan, per_unit, out);
    std::fprintf(out, "planned frame: planning %.3f ms, units' depth pass %.3f ms, resolve kernel %.3f ms (medians)\n",
                 r.medians.planning_ms, r.medians.unit_pass_ms, r.medians.kernel_ms);
    print_unit_mapping(r.stats, r.medians, out);
  }
}

void print_shading(const RenderResult& r, std::FILE* out) {
  const RenderOptions& o = r.options;
  const FrameStats& s = r.stats;
  if (o.span_normalize() || o.specular.kind != SpecularKind::exact) {
    const std::string steps =
        s.normalize_sequential_steps ? ", " + std::to_string(s.normalize_sequential_steps) + " sequential steps" : "";
    std::fprintf(out, "phong: normals %s (%llu span setups, %llu fell back to the exact normal%s), specular %s\n",
                 normalize_name(o.normalize).c_str(), ull(s.normalize_span_setups), ull(s.normalize_fallback_spans),
                 steps.c_str(), specular_name(o.specular).c_str());
  }
  if (const auto& c = s.choice)
    std::fprintf(out,
                 "triangle choice %s: of %llu triangles %llu by Gouraud (largest expected error %.2f levels), %llu by "
                 "segments, %llu by Phong per pixel; %llu where a terminator may cross\n",
                 triangle_rule_name(o.combined).c_str(), ull(c->triangles), ull(c->gouraud), c->largest_expected_levels,
                 ull(c->segments), ull(c->triangles - c->gouraud - c->segments), ull(c->terminator));
  if (r.errors && r.errors->choice_pixels) {
    const ChoicePixels& p = *r.errors->choice_pixels;
    const double all = std::max(1.0, double(p.gouraud + p.segments + p.phong));
    std::fprintf(out,
                 "visible pixels by the choice (exact reference's visibility): %.1f %% Gouraud, %.1f %% segments, "
                 "%.1f %% Phong per pixel, of %llu\n",
                 100.0 * double(p.gouraud) / all, 100.0 * double(p.segments) / all, 100.0 * double(p.phong) / all,
                 ull(p.gouraud + p.segments + p.phong));
  }
  if (o.method == Method::combined && uses_highlight_mask(o.combined))
    std::fprintf(out,
                 "highlight test: %llu of %llu triangles without a highlight, %llu (triangle, light) specular terms "
                 "skipped\n",
                 ull(s.highlight.without_highlight), ull(s.highlight.triangles), ull(s.highlight.light_terms_skipped));
}

void print_errors(const RenderResult& r, std::FILE* out) {
  if (!r.errors) return;
  for (const ErrorMetrics* m : {&r.errors->implementation, &r.errors->method})
    std::fprintf(out, "error vs %s: %s\n", m->reference.c_str(), describe_error(*m).c_str());
}

void print_split(const RenderResult& r, std::FILE* out) {
  std::fprintf(out, "%s: %dx%d split across devices, frame %.3f ms (median of %d)\n", r.scene_name.c_str(), r.width,
               r.height, median(r.frame_ms), r.frames);
  for (const DeviceShare& s : r.shares) {
    if (s.failed)
      std::fprintf(out, "  %-40s FAILED, dropped (--keep-going)\n", s.device.c_str());
    else
      std::fprintf(out, "  %-40s tile rows %4d..%4d (%d rows) %9.3f ms\n", s.device.c_str(), s.first_row,
                   s.first_row + s.rows - 1, s.rows, s.frame_ms);
  }
}

void print_distributed(const RenderResult& r, std::FILE* out) {
  const DistributedFigures& d = *r.distributed;
  const bool sort_last = d.mode == Distribute::sort_last;
  std::fprintf(out, "%s: %dx%d, %llu faces, method %s, %s over %d ranks (%d threads each)\n", r.scene_name.c_str(),
               r.width, r.height, ull(d.faces), method_name(r.options.method), distribute_name(d.mode), d.ranks,
               d.threads_per_rank);
  std::fprintf(out, "frame: %.3f ms (median of %d after %d warm-up, barrier to barrier)\n", median(r.frame_ms), r.frames,
               r.warmup);
  std::fprintf(out, "rank  %s  records  pixels  prepare_ms  render_ms  composite_ms  bytes_sent  peak_rss_mib\n",
               sort_last ? "faces" : "band ");
  const std::vector<RankFigures> m = d.rank_medians();
  std::vector<double> render, prepare;
  for (int k = 0; k < d.ranks; ++k) {
    const RankFigures& f = m[k];
    const std::string share = sort_last ? std::to_string((long long)f.faces)
                                        : std::to_string(int(f.band_first)) + "+" + std::to_string(int(f.band_rows));
    std::fprintf(out, "%4d  %s  %7.0f  %6.0f  %10.3f  %9.3f  %12.3f  %10.0f  %11.1f\n", k, share.c_str(), f.records,
                 f.pixels, f.prepare_ms, f.render_ms, f.composite_ms, f.bytes_sent, d.peak_rss_mib[k]);
    render.push_back(f.render_ms), prepare.push_back(f.prepare_ms);
  }
  const auto imbalance = [](const std::vector<double>& v) {
    double mean = 0;
    for (double x : v) mean += x / double(v.size());
    return mean > 0 ? *std::max_element(v.begin(), v.end()) / mean : 1.0;
  };
  std::fprintf(out, "imbalance (max/mean): render %.3f, prepare %.3f\n", imbalance(render), imbalance(prepare));
}

}  // namespace

void print_render_summary(const RenderResult& r, const std::vector<std::string>& lines,
                          const std::vector<std::string>& written, bool per_unit, std::FILE* out) {
  if (r.distributed) {
    print_distributed(r, out);
  } else if (r.mode == DeviceMode::bands) {
    print_split(r, out);
  } else {
    print_frame(r, out);
    print_hardware(r, per_unit, out);
    print_shading(r, out);
  }
  print_errors(r, out);
  for (const std::string& l : lines) std::fprintf(out, "%s\n", l.c_str());
  std::string files;
  for (std::size_t i = 0; i < written.size(); ++i) files += (i ? " and " : "") + written[i];
  std::fprintf(out, "wrote %s\n", files.c_str());
}

void print_render_warnings(const RenderResult& r, std::ostream& err) {
  for (const std::string& w : r.warnings) {
    err << "parashade: warning: " << w;
    if (w.empty() || w.back() != '\n') err << "\n";
  }
  if (r.mode == DeviceMode::bands || r.distributed) return;
  warn_vanishing(r.stats, r.image, err);
  if (r.registers) warn_register_events(*r.registers, r.options.arith, err);
}

}  // namespace parashade
