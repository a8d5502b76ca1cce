#include "tune_cache.hpp"

#include <cstdlib>
#include <fstream>

#include "parashade/errors.hpp"
#include "parashade/report.hpp"

namespace parashade::cli {

nlohmann::json TuneProblem::to_json() const {
  return {{"scene", scene}, {"width", width}, {"height", height}, {"method", method}, {"unit", unit}};
}

std::filesystem::path default_tune_cache() {
  if (const char* p = std::getenv("PARASHADE_TUNE_CACHE"); p && *p) return p;
  if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x) return std::filesystem::path(x) / "parashade" / "tune.json";
  if (const char* h = std::getenv("HOME"); h && *h) return std::filesystem::path(h) / ".cache" / "parashade" / "tune.json";
  return "parashade-tune.json";
}

TuneCache::TuneCache(std::filesystem::path path) : path_(std::move(path)) {
  doc_ = {{"format", "parashade tune cache 1"}, {"objective", "frame_ms (median, lower is better)"},
          {"tune_params_keys", {"tile", "work_items", "partition", "units", "batch"}},
          {"entries", nlohmann::json::array()}};
  std::error_code ec;
  if (!std::filesystem::exists(path_, ec)) return;
  std::ifstream in(path_);
  nlohmann::json read;
  try {
    in >> read;
  } catch (const nlohmann::json::exception& e) {
    throw InputError("tune cache '" + path_.string() + "' is not valid JSON: " + e.what());
  }
  if (!read.is_object() || !read.contains("entries") || !read["entries"].is_array())
    throw InputError("tune cache '" + path_.string() + "' has no \"entries\" array");
  doc_["entries"] = read["entries"];
}

bool TuneCache::matches(const nlohmann::json& e, const DeviceInfo& d, const TuneProblem& p) const {
  return e.value("device_name", "") == d.name && e.value("driver_version", "") == d.driver &&
         e.contains("problem") && e["problem"] == p.to_json();
}

bool TuneCache::has(const DeviceInfo& d, const TuneProblem& p, const nlohmann::json& params) const {
  for (const auto& e : doc_["entries"])
    if (matches(e, d, p) && e.contains("params") && e["params"] == params) return true;
  return false;
}

void TuneCache::add(const DeviceInfo& d, const TuneProblem& p, const nlohmann::json& params,
                    const std::vector<double>& times, double objective, bool verified) {
  doc_["entries"].push_back({{"device_name", d.name},
                             {"driver_version", d.driver},
                             {"platform", d.platform},
                             {"compute_units", d.compute_units},
                             {"problem", p.to_json()},
                             {"params", params},
                             {"times_ms", times},
                             {"objective", objective},
                             {"verified", verified}});
  std::error_code ec;
  if (path_.has_parent_path()) std::filesystem::create_directories(path_.parent_path(), ec);
  write_text_atomically(path_, doc_.dump(1) + "\n");
}

std::optional<nlohmann::json> TuneCache::best(const DeviceInfo& d, const TuneProblem& p) const {
  std::optional<nlohmann::json> out;
  for (const auto& e : doc_["entries"])
    if (matches(e, d, p) && e.value("verified", false) && e.contains("objective") && e["objective"].is_number() &&
        (!out || e["objective"].get<double>() < (*out)["objective"].get<double>()))
      out = e;
  return out;
}

nlohmann::json tuned_params(const RenderOptions& o) {
  nlohmann::json p = {{"tile", o.tile_size}, {"work_items", o.work_items}};
  if (o.plan) {
    p["partition"] = partition_name(o.plan->partition);
    p["units"] = o.plan->units;
    p["batch"] = o.plan->batch;
  } else {
    p["partition"] = "none";
  }
  return p;
}

void apply_tuned_params(const nlohmann::json& params, RenderOptions& o) {
  try {
    o.tile_size = params.at("tile").get<int>();
    o.work_items = params.at("work_items").get<int>();
    const std::string part = params.at("partition").get<std::string>();
    if (part == "none") {
      o.plan.reset();
    } else {
      PlanOptions plan;
      plan.partition = parse_partition(part);
      plan.units = params.at("units").get<int>();
      plan.batch = params.at("batch").get<int>();
      o.plan = plan;
    }
  } catch (const nlohmann::json::exception& e) {
    throw InputError(std::string("a tune cache entry's parameters are not usable: ") + e.what());
  }
}

}  // namespace parashade::cli
