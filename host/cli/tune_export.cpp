#include "tune_export.hpp"

#include <algorithm>
#include <map>
#include <numeric>

namespace parashade::cli {

namespace {

const char* const kInvalid = "InvalidConfig";  // Kernel Tuner's util.InvalidConfig, as its cache files spell it

// Kernel Tuner's key: str() of each value, joined by commas.
std::string key_of(const nlohmann::json& params, const std::vector<std::string>& names) {
  std::string key;
  for (const std::string& n : names) {
    const nlohmann::json& v = params.at(n);
    key += (key.empty() ? "" : ",") + (v.is_string() ? v.get<std::string>() : v.dump());
  }
  return key;
}

// A candidate's timed frames (the tune report's timing.samples_ms), none for no candidate.
std::vector<double> samples_of(const nlohmann::json& c) {
  if (c.is_null()) return {};
  return c.value("timing", nlohmann::json::object()).value("samples_ms", std::vector<double>{});
}

std::string status_of(const ExportPoint& p) {
  if (p.restricted) return "restricted";
  if (p.candidate.is_null()) return "not_measured";
  if (!p.candidate.value("verified", false)) return "image_differs";
  if (!p.candidate.value("within_budget", false)) return "over_budget";
  return "measured";
}

// tune_params: the space's values some point takes (cu's values are none of a space without a plan), and "-"
// for a parameter some point does not read: the product, and so the file, is no larger than it must be.
nlohmann::ordered_json tune_params_of(const TuneSpace& space, const std::vector<ExportPoint>& points) {
  nlohmann::ordered_json tune_params = nlohmann::ordered_json::object();
  for (std::size_t i = 0; i < space.names.size(); ++i) {
    const std::string& name = space.names[i];
    const auto taken = [&](const nlohmann::json& v) {
      return std::any_of(points.begin(), points.end(), [&](const ExportPoint& p) { return p.params[name] == v; });
    };
    nlohmann::ordered_json values = nlohmann::ordered_json::array();
    for (const std::string& v : space.values[i]) {
      const bool number = is_number_param(name);
      if (taken(number ? nlohmann::json(std::stoi(v)) : nlohmann::json(v)))
        values.push_back(number ? nlohmann::ordered_json(std::stoi(v)) : nlohmann::ordered_json(v));
    }
    if (taken("-")) values.push_back("-");
    tune_params[name] = values;
  }
  return tune_params;
}

// One cache entry: the parameters, Kernel Tuner's fields, parashade's own observables beside them.
nlohmann::ordered_json entry_of(const std::vector<std::string>& names, const nlohmann::ordered_json& params,
                                const ExportPoint* p) {
  nlohmann::ordered_json e;
  for (const std::string& n : names) e[n] = params[n];
  const nlohmann::json none;
  const nlohmann::json& c = p ? p->candidate : none;
  const std::string status = p ? status_of(*p) : "not_a_point";
  const std::vector<double> times = samples_of(c);
  e["time"] = status == "measured" ? nlohmann::ordered_json(c["frame_ms"]) : nlohmann::ordered_json(kInvalid);
  e["times"] = times;
  e["compile_time"] = c.is_null() ? 0.0 : c.value("compile_ms", 0.0);
  e["verification_time"] = c.is_null() ? 0.0 : c.value("verify_ms", 0.0);
  e["benchmark_time"] = std::accumulate(times.begin(), times.end(), 0.0);
  e["strategy_time"] = 0.0;
  e["framework_time"] = 0.0;
  e["timestamp"] = c.is_null() ? std::string() : c.value("timestamp", std::string());
  if (status != "measured") e["__error__"] = kInvalid;
  e["status"] = status;
  // parashade's own observables: an error budget is not Kernel Tuner's, so they are kept beside its fields.
  // The report's max_abs under the export's own name, max_error.
  static const std::pair<const char*, const char*> kOwn[] = {
      {"verified", "verified"}, {"max_error", "max_abs"}, {"nmse", "nmse"}, {"within_budget", "within_budget"}};
  for (const auto& [k, from] : kOwn)
    e[k] = c.is_null() ? nlohmann::ordered_json() : nlohmann::ordered_json(c.value(from, nlohmann::json()));
  return e;
}

}  // namespace

const std::vector<std::string>& export_statuses() {
  static const std::vector<std::string> s = {"measured",     "over_budget", "image_differs",
                                             "not_measured", "restricted",  "not_a_point"};
  return s;
}

nlohmann::ordered_json kernel_tuner_cache(const TuneSpace& space, const ExportHeader& header,
                                          const std::vector<ExportPoint>& points) {
  const nlohmann::ordered_json tune_params = tune_params_of(space, points);
  std::map<std::string, const ExportPoint*> by_key;
  for (const ExportPoint& p : points) by_key[key_of(p.params, space.names)] = &p;
  // Every combination of tune_params' values, the last parameter fastest (Kernel Tuner's product order).
  nlohmann::ordered_json cache = nlohmann::ordered_json::object();
  std::vector<std::size_t> at(space.names.size(), 0);
  for (bool more = true; more;) {
    nlohmann::ordered_json params = nlohmann::ordered_json::object();
    for (std::size_t i = 0; i < space.names.size(); ++i) params[space.names[i]] = tune_params[space.names[i]][at[i]];
    const std::string key = key_of(params, space.names);
    const auto found = by_key.find(key);
    cache[key] = entry_of(space.names, params, found == by_key.end() ? nullptr : found->second);
    more = false;
    for (std::size_t i = space.names.size(); i-- > 0 && !more;) {
      if (++at[i] < tune_params[space.names[i]].size()) more = true;
      else at[i] = 0;
    }
  }
  nlohmann::ordered_json restrictions = header.restrictions;
  return nlohmann::ordered_json{{"schema_version", "1.1.0"},
                                {"device_name", header.device_name},
                                {"kernel_name", header.kernel_name},
                                {"problem_size", {header.width, header.height}},
                                {"tune_params_keys", space.names},
                                {"tune_params", tune_params},
                                {"objective", "time"},
                                {"objective_higher_is_better", false},
                                {"restrictions", restrictions},
                                {"cache", cache}};
}

nlohmann::ordered_json t4_results(const std::vector<ExportPoint>& points) {
  nlohmann::ordered_json results = nlohmann::ordered_json::array();
  for (const ExportPoint& p : points) {
    if (p.candidate.is_null()) continue;
    const nlohmann::json& c = p.candidate;
    const std::vector<double> times = samples_of(c);
    const bool correct = status_of(p) == "measured";
    nlohmann::ordered_json configuration = nlohmann::ordered_json::object();  // in the space's order
    for (const std::string& n : tune_param_names())
      if (p.params.contains(n)) configuration[n] = p.params[n];
    nlohmann::ordered_json measurements = {
        {{"name", "time"}, {"value", c["frame_ms"]}, {"unit", "ms"}},
        {{"name", "max_error"}, {"value", c["max_abs"]}, {"unit", "levels"}}};
    if (c["nmse"].is_number()) measurements.push_back({{"name", "nmse"}, {"value", c["nmse"]}, {"unit", ""}});
    results.push_back({{"timestamp", c.value("timestamp", std::string())},
                       {"configuration", configuration},
                       {"objectives", {"time"}},
                       {"times",
                        {{"compilation_time", c.value("compile_ms", 0.0)},
                         {"runtimes", times},
                         {"framework", 0.0},
                         {"search_algorithm", 0.0},
                         {"validation", c.value("verify_ms", 0.0)}}},
                       {"invalidity", correct ? "correct" : "correctness"},
                       {"correctness", correct ? 1 : 0},
                       {"measurements", measurements}});
  }
  return {{"schema_version", "1.0.0"}, {"results", results}, {"metadata", {{"timeunit", "milliseconds"}}}};
}

}  // namespace parashade::cli
