#include "parashade/report.hpp"

#include <cmath>

#include "parashade/errors.hpp"
#include "parashade/output_file.hpp"

namespace parashade {

nlohmann::json to_json(const DeviceInfo& d) {
  return {{"index", d.index},          {"platform", d.platform},        {"name", d.name},
          {"vendor", d.vendor},        {"version", d.version},          {"driver", d.driver},
          {"type", d.type},            {"compute_units", d.compute_units}, {"global_memory", d.global_memory},
          {"max_allocation", d.max_allocation}};
}

nlohmann::json to_json(const ErrorMetrics& m) {
  nlohmann::json j = {{"reference", m.reference},
          {"status", metrics_status_name(m.status)},  // says why a figure is null: identical or nothing compared
          {"nmse", number_or_null(m.nmse)},
          {"psnr_db", number_or_null(m.psnr_db)},
          {"max_abs", number_or_null(m.max_abs)},
          {"mean_abs", number_or_null(m.mean_abs)},
          {"pixels_compared", m.pixels_compared},
          {"pixels_over_1_level", m.pixels_over_1_level},
          {"coverage_mismatch", m.coverage_mismatch},
          {"front_surface_mismatch", m.front_surface_mismatch}};  // float depth ties: counted apart, not compared
  if (m.flip) j["flip"] = {{"metric", "LDR-FLIP"}, {"mean", m.flip->mean}, {"max", m.flip->max}, {"ppd", m.flip->ppd}};
  return j;
}

nlohmann::json to_json(const FrameTimings& t) {
  return {{"geometry_ms", t.geometry_ms},   {"setup_ms", t.setup_ms},       {"choice_ms", t.choice_ms},
          {"binning_ms", t.binning_ms},     {"kernel_ms", t.kernel_ms},     {"launch_ms", t.launch_ms},
          {"readback_ms", t.readback_ms},   {"total_ms", t.total_ms},       {"planning_ms", t.planning_ms},
          {"unit_pass_ms", t.unit_pass_ms}, {"key_merge_ms", t.key_merge_ms}};
}

nlohmann::json to_json(const FrameStats& s) {
  return {{"triangles_in", s.geometry.triangles_in},
          {"culled_backface", s.geometry.culled_backface},
          {"zero_area", s.geometry.zero_area},
          {"outside", s.geometry.outside},
          {"clipped", s.geometry.clipped},
          {"non_finite", s.geometry.non_finite},
          {"screen_triangles", s.geometry.triangles_out},
          {"triangles_without_pixels", s.triangles_without_pixels},
          {"bin_entries", s.bin_entries},
          {"tiles", s.tiles},
          {"bands", s.bands},
          {"parity_dropped", s.parity_dropped}, {"sierpinski_whole", s.sierpinski_whole},
          {"highlight_test", {{"triangles", s.highlight.triangles},
                              {"without_highlight", s.highlight.without_highlight},
                              {"light_terms_skipped", s.highlight.light_terms_skipped}}},
          {"triangle_choice", s.choice ? nlohmann::json{{"triangles", s.choice->triangles},
                                                        {"gouraud", s.choice->gouraud},
                                                        {"segments", s.choice->segments},
                                                        {"phong", s.choice->triangles - s.choice->gouraud - s.choice->segments},
                                                        {"without_highlight", s.choice->without_highlight},
                                                        {"terminator", s.choice->terminator},
                                                        {"largest_expected_gouraud_levels", s.choice->largest_expected_levels}}
                                       : nlohmann::json(nullptr)}};
}

nlohmann::json to_json(const ModeledClocks& c) {
  return {{"spans", c.spans}, {"span_pixels", c.pixels}, {"clocks", c.clocks}};
}

nlohmann::json to_json(const PlanReport& r) {
  nlohmann::json units = nlohmann::json::array();
  for (const UnitLoad& l : r.load)
    units.push_back({{"triangles", l.triangles}, {"spans", l.spans}, {"pixels", l.pixels}, {"clocks", l.clocks}});
  return {{"partition", partition_name(r.partition)},
          {"units", r.units},
          {"tile", r.tile_size},
          {"batch", r.batch},
          {"setup_clocks", r.setup_clocks},
          {"modeled_frame_clocks", r.frame_clocks()},
          {"modeled_total_clocks", r.total_clocks()},
          {"imbalance", r.imbalance()},
          {"per_unit", units}};
}

nlohmann::json unit_mapping_json(const FrameStats& s, const FrameTimings& t) {
  nlohmann::json shares = nlohmann::json::array();
  for (std::size_t k = 0; k < s.unit_pass.size(); ++k) {
    const UnitPassShare& u = s.unit_pass[k];
    shares.push_back({{"device", u.device}, {"compute_units", u.compute_units}, {"first_unit", u.first_unit},
                      {"units", u.units}, {"first_packet", u.first_packet}, {"packets", u.packets},
                      {"pass_ms", k < t.unit_pass_share_ms.size() ? t.unit_pass_share_ms[k] : 0.0}});
  }
  nlohmann::json j = {{"kind", s.unit_pass_on_sub_devices ? "sub-devices" : "work-items"}, {"shares", shares},
                      {"unit_pass_ms", t.unit_pass_ms}};
  if (s.unit_pass_on_sub_devices) {
    j["note"] = "units in contiguous blocks in proportion to the sub-devices' compute units (dynamic: batches in "
                "proportion to their units), run concurrently on the sub-devices' queues into keys of their own, "
                "min-merged on the parent; unit_pass_ms from the first start to the last end";
    j["key_merge_ms"] = t.key_merge_ms;
  } else {
    j["note"] = "one work-item per unit (work-group size 1) of one kernel on the device";
  }
  return j;
}

void write_text_atomically(const std::filesystem::path& path, const std::string& text) {
  stage_text(path, text).commit();
}

}  // namespace parashade
