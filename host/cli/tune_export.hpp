#pragma once
// `tune --export-kt FILE`: the run's candidates as a Kernel Tuner cache file (its cache schema 1.1.0:
// device_name, kernel_name, problem_size, tune_params_keys, tune_params, objective, and "cache" keyed
// by the comma-joined parameter values), so that Kernel Tuner's own tools (its simulation mode, its
// cache readers and dashboards) read parashade's results. docs/tuning.md has a worked example.
#include <string>

#include <nlohmann/json.hpp>

#include "tune_space.hpp"

namespace parashade::cli {

// Kernel Tuner reads its cache files as files it may append to: "cache" must be the last key and the
// text must end with "}\n}" (dump(1) gives that), hence an ordered object.
// `candidates`: the tune report's candidates (params, frame_ms, timing.samples_ms, compile_ms,
// verify_ms, timestamp, verified, max_abs, nmse, within_budget), one cache entry each.
nlohmann::ordered_json kernel_tuner_cache(const TuneSpace& space, const std::string& device_name, const std::string& kernel_name,
                                  int width, int height, const nlohmann::json& candidates);

}  // namespace parashade::cli
