// A render's result as its JSON report (render_report.hpp): one function per section, one place per key.
#include <algorithm>
#include <numeric>

#include "parashade/combined.hpp"
#include "parashade/distributed.hpp"
#include "parashade/frame_pipeline.hpp"
#include "parashade/render_report.hpp"
#include "parashade/report.hpp"
#include "parashade/report_header.hpp"
#include "parashade/statistics.hpp"
#include "parashade/unit_table.hpp"
#include "register_events_report.hpp"

namespace parashade {
namespace {

std::string method_text(const RenderOptions& o) {
  return o.method == Method::combined ? combined_name(o.combined) : method_name(o.method);
}

// What every render report holds, whatever rendered it.
nlohmann::json common_keys(const RenderResult& r, const std::filesystem::path& image) {
  return {{"scene", r.scene_name},  {"scene_file", r.scene_file.string()},  {"image", image.string()},
          {"width", r.width},       {"height", r.height},                   {"frame_ms", median(r.frame_ms)},
          {"timing", timing_json(r.frame_ms, r.warmup)}};
}

nlohmann::json error_json(const RenderResult& r) {
  if (!r.errors) return nlohmann::json::object();
  return {{"implementation", to_json(r.errors->implementation)}, {"method", to_json(r.errors->method)}};
}

nlohmann::json ratios(const std::vector<double>& v) {
  return {{"median", median(v)}, {"p10", quantile(v, 0.1)}, {"p90", quantile(v, 0.9)}};
}

nlohmann::json against_json(const AgainstSummary& s) {
  nlohmann::json j = {{"method", s.method},
          {"pairs", s.frame_ratios.size()},
          {"frame_ms", s.medians.total_ms},
          {"samples_ms", s.samples_ms},
          {"stages_ms", to_json(s.medians)},
          {"frame_ratio", ratios(s.frame_ratios)},
          {"kernel_ratio", ratios(s.kernel_ratios)},
          {"note", "each pair one frame of each renderer in one process, the against frame first in even pairs; "
                   "ratio = against ms / this method's ms (> 1: this method faster)"}};
  if (!s.device.empty()) {
    j["device"] = s.device;
    j["note"] = "each pair one frame on each device in one process, the against device's first in even pairs; "
                "ratio = against device's ms / this device's ms (> 1: this device faster)";
  }
  return j;
}

int band_mib(const RenderResult& r) {
  const std::size_t bytes = r.options.band_record_bytes;
  if (bytes == kBandBytesByFrame) return default_band_mib(r.width, r.height);
  return bytes == SIZE_MAX ? 0 : int(bytes >> 20);
}

// The shading: method, Phong's normals and specular model, the combined method's choices.
void shading_keys(const RenderResult& r, nlohmann::json& report) {
  const RenderOptions& o = r.options;
  report["method"] = method_text(o);
  report["specular"] = specular_name(o.specular);
  report["normalize"] = {{"method", normalize_name(o.normalize)},
                         {"span_setups", r.stats.normalize_span_setups},
                         {"fallback_spans", r.stats.normalize_fallback_spans},
                         {"sequential_steps", r.stats.normalize_sequential_steps}};
  if (o.method != Method::combined) return;
  if (o.combined.automatic) report["max_error"] = o.combined.max_error;
  report["combined_min_width"] = combined_min_width(o.combined);
  report["highlight_test"] = uses_highlight_mask(o.combined);
  report["triangle_choice_rule"] = triangle_rule_name(o.combined);
  if (r.errors && r.errors->choice_pixels) {
    const ChoicePixels& p = *r.errors->choice_pixels;
    report["stats"]["triangle_choice"]["visible_pixels"] = {
        {"gouraud", p.gouraud}, {"segments", p.segments}, {"phong", p.phong}};
  }
}

// The modeled hardware: the unit and its clocks, the registers' events, the plan of modeled units.
void hardware_keys(const RenderResult& r, nlohmann::json& report) {
  const RenderOptions& o = r.options;
  if (o.unit_path()) {
    report["units"] = unit_name(o.unit());
    report["arith"] = arith_name(o.arith);
    report["span_division"] = division_name(o.division);
    report["coverage"] = o.dda_coverage ? "dda" : "centre";
    report["modeled_clocks"] = to_json(r.stats.clocks);
    if (r.registers) report["registers"] = register_events_json(*r.registers);
  }
  if (r.stats.plan) {
    report["plan"] = to_json(*r.stats.plan);
    report["plan"]["measured_frame_ms"] = r.medians.total_ms;
    report["plan"]["mapping"] = unit_mapping_json(r.stats, r.medians);
  }
}

// The kernel's layout and where each setting came from (device_layout.hpp's LayoutSources).
nlohmann::json layout_json(const RenderResult& r) {
  const LayoutSources& s = r.sources;
  return {{"kernel_shape", kernel_shape_name(r.options.kernel_shape)},
          {"work_group_size", r.options.group_size()},
          {"sources",
           {{"kernel_shape", s.kernel_shape}, {"work_group_size", s.work_group_size}, {"work_items", s.work_items},
            {"tile", s.tile}}}};
}

nlohmann::json one_device_report(const RenderResult& r, const std::filesystem::path& image) {
  nlohmann::json report = common_keys(r, image);
  const double ms = r.medians.total_ms, pixels = double(r.width) * r.height;
  report["device"] = to_json(r.devices.front());
  report["tile"] = r.options.tile_size;
  report["band_mib"] = band_mib(r);
  report["tuned"] = r.tuned;
  report["work_items"] = r.work_items;
  report["layout"] = layout_json(r);
  report["defer_min_triangles"] = r.deferral ? nlohmann::json(*r.deferral) : nlohmann::json(nullptr);
  report["kernel_build"] = r.kernel_build;
  report["triangles"] = {{"in", r.stats.geometry.triangles_in}, {"after_culling", r.stats.geometry.triangles_out}};
  report["mesh"] = {{"vertices", r.mesh_vertices},
                    {"triangles", r.mesh_triangles},
                    {"bytes", 24 * r.mesh_vertices + 12 * r.mesh_triangles}};
  report["frame_ms"] = ms;
  report["frame_ms_note"] = frame_ms_note(r.frames, r.warmup, "frames", std::string("; ") + kWholeFrame);
  report["stages_ms"] = to_json(r.medians);
  report["mpixel_per_s"] = pixels / (ms * 1e3);
  report["mtriangle_per_s"] = double(r.stats.geometry.triangles_in) / (ms * 1e3);
  report["stats"] = to_json(r.stats);
  report["error"] = error_json(r);
  if (r.against) report["against"] = against_json(*r.against);
  shading_keys(r, report);
  hardware_keys(r, report);
  return report;
}

nlohmann::json split_report(const RenderResult& r, const std::filesystem::path& image) {
  nlohmann::json report = common_keys(r, image);
  report["frame_ms_note"] = frame_ms_note(r.frames, r.warmup, "split frames", "; every device's band, host clock");
  report["device_info"] = nlohmann::json::array();
  for (const DeviceInfo& d : r.devices) report["device_info"].push_back(to_json(d));
  report["devices"] = nlohmann::json::array();
  for (const DeviceShare& s : r.shares)
    report["devices"].push_back({{"device", s.device}, {"first_tile_row", s.first_row}, {"tile_rows", s.rows},
                                 {"band_ms", s.frame_ms}, {"failed", s.failed}, {"error", s.error}});
  return report;
}

double imbalance(const std::vector<double>& v) {
  const double mean = std::accumulate(v.begin(), v.end(), 0.0) / double(v.size());
  return mean > 0 ? *std::max_element(v.begin(), v.end()) / mean : 1.0;
}

nlohmann::json rank_json(const DistributedFigures& d, const RankFigures& f, int rank) {
  nlohmann::json j = {{"rank", rank},           {"records", f.records},           {"record_bytes", f.record_bytes},
                      {"pixels", f.pixels},     {"prepare_ms", f.prepare_ms},     {"render_ms", f.render_ms},
                      {"rank_frame_ms", f.frame_ms}, {"composite_ms", f.composite_ms}, {"gather_ms", f.gather_ms},
                      {"pack_ms", f.pack_ms},   {"bytes_sent", f.bytes_sent},     {"peak_rss_mib", d.peak_rss_mib[rank]}};
  if (d.mode == Distribute::sort_last) {
    j["faces"] = f.faces;
    j["won_pixels"] = f.won_pixels;
    j["modeled_clocks"] = f.modeled_clocks;
  } else {
    j["band_first_row"] = f.band_first;
    j["band_tile_rows"] = f.band_rows;
  }
  j["frames"] = nlohmann::json::array();
  for (const auto& frame : d.frames) {
    const RankFigures& g = frame[rank];
    j["frames"].push_back({{"prepare_ms", g.prepare_ms}, {"render_ms", g.render_ms}, {"pack_ms", g.pack_ms},
                           {"composite_ms", g.composite_ms}, {"gather_ms", g.gather_ms},
                           {"rank_frame_ms", g.frame_ms}});
  }
  return j;
}

nlohmann::json distributed_report(const RenderResult& r, const std::filesystem::path& image) {
  const DistributedFigures& d = *r.distributed;
  const bool sort_last = d.mode == Distribute::sort_last;
  nlohmann::json report = common_keys(r, image);
  report["distribute"] = distribute_name(d.mode);
  report["ranks"] = d.ranks;
  report["threads_per_rank"] = d.threads_per_rank;
  report["device"] = to_json(r.devices.front());
  report["method"] = method_name(r.options.method);
  report["tile"] = r.options.tile_size;
  report["faces"] = d.faces;
  report["read_scene"] = d.scatter_scene ? "rank-0" : "every-rank";
  report["float_output"] = r.options.float_output;
  report["frame_ms_note"] = frame_ms_note(r.frames, r.warmup, "frames",
                                          ", rank 0's clock from a barrier before the frame to one after the "
                                          "composite; compare ratios within one run");
  report["error"] = error_json(r);
  const std::vector<RankFigures> m = d.rank_medians();
  std::vector<double> render, prepare, frame, clocks;
  report["per_rank"] = nlohmann::json::array();
  for (int k = 0; k < d.ranks; ++k) {
    report["per_rank"].push_back(rank_json(d, m[k], k));
    render.push_back(m[k].render_ms), prepare.push_back(m[k].prepare_ms), frame.push_back(m[k].frame_ms);
    clocks.push_back(m[k].modeled_clocks);
  }
  report["imbalance"] = {{"render_ms", imbalance(render)}, {"prepare_ms", imbalance(prepare)},
                         {"rank_frame_ms", imbalance(frame)}};
  if (sort_last) {
    report["rank_partition"] = partition_name(d.rank_partition);
    report["planning_ms"] = d.planning_ms;
    report["composite"] = "MPI_Alltoall + MPI_Reduce_local (min of (depth, scene face) keys) + MPI_Gather to rank 0";
    report["imbalance"]["modeled_clocks"] = imbalance(clocks);
  } else {
    report["composite"] = "MPI_Gatherv of the bands to rank 0";
  }
  return report;
}

}  // namespace

RenderReport render_report(const RenderResult& r, const std::filesystem::path& image) {
  if (r.distributed) return {"render-distributed", distributed_report(r, image)};
  if (r.mode == DeviceMode::bands) return {"render-split", split_report(r, image)};
  return {"render", one_device_report(r, image)};
}

}  // namespace parashade
