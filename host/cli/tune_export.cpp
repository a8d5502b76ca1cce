#include "tune_export.hpp"

#include <algorithm>
#include <numeric>

namespace parashade::cli {

namespace {

// Kernel Tuner's key: str() of each value, joined by commas.
std::string key_of(const nlohmann::json& params, const std::vector<std::string>& names) {
  std::string key;
  for (const std::string& n : names) {
    const nlohmann::json& v = params.at(n);
    key += (key.empty() ? "" : ",") + (v.is_string() ? v.get<std::string>() : v.dump());
  }
  return key;
}

}  // namespace

nlohmann::ordered_json kernel_tuner_cache(const TuneSpace& space, const std::string& device_name, const std::string& kernel_name,
                                  int width, int height, const nlohmann::json& candidates) {
  nlohmann::ordered_json tune_params = nlohmann::ordered_json::object();
  for (std::size_t i = 0; i < space.names.size(); ++i) {
    nlohmann::ordered_json values = nlohmann::ordered_json::array();
    const bool numeric = is_number_param(space.names[i]);
    for (const std::string& v : space.values[i])
      values.push_back(numeric ? nlohmann::ordered_json(std::stoi(v)) : nlohmann::ordered_json(v));
    // "-": a layout parameter nothing reads at that point (cu without a plan, batch of a static one).
    for (const auto& c : candidates)
      if (c["params"][space.names[i]] == "-" && std::find(values.begin(), values.end(), "-") == values.end())
        values.push_back("-");
    tune_params[space.names[i]] = values;
  }
  nlohmann::ordered_json cache = nlohmann::ordered_json::object();
  for (const auto& c : candidates) {
    nlohmann::ordered_json e;
    for (const std::string& n : space.names) e[n] = c["params"][n];
    const std::vector<double> times = c.value("timing", nlohmann::json::object()).value("samples_ms", std::vector<double>{});
    e["time"] = c["frame_ms"];
    e["times"] = times;
    e["compile_time"] = c.value("compile_ms", 0.0);
    e["verification_time"] = c.value("verify_ms", 0.0);
    e["benchmark_time"] = std::accumulate(times.begin(), times.end(), 0.0);
    e["strategy_time"] = 0.0;
    e["framework_time"] = 0.0;
    e["timestamp"] = c.value("timestamp", "");
    // parashade's own observables, beside Kernel Tuner's: filter on them for the error budget.
    for (const char* k : {"verified", "nmse", "within_budget"}) e[k] = c.value(k, nlohmann::json());
    e["max_error"] = c.value("max_abs", nlohmann::json());  // the report's max_abs, under the export's own name
    cache[key_of(c["params"], space.names)] = e;
  }
  return nlohmann::ordered_json{{"schema_version", "1.1.0"},
          {"device_name", device_name},
          {"kernel_name", kernel_name},
          {"problem_size", {width, height}},
          {"tune_params_keys", space.names},
          {"tune_params", tune_params},
          {"objective", "time"},
          {"objective_higher_is_better", false},
          {"cache", cache}};
}

}  // namespace parashade::cli
