#pragma once
// `tune --export-kt FILE`: the searched space as a Kernel Tuner cache file (its cache schema 1.1.0:
// device_name, kernel_name, problem_size, tune_params_keys, tune_params, objective, and "cache" keyed by the
// comma-joined parameter values), so that Kernel Tuner's own tools (its simulation mode, its cache readers
// and dashboards) read parashade's results. Every point of tune_params' product has an entry, because
// Kernel Tuner's simulation mode refuses a cache that lacks one: a point tune did not measure, or may not
// pick, carries Kernel Tuner's mark of a configuration it could not use, "InvalidConfig" in the objective
// (and in "__error__", where Kernel Tuner 1.5 writes it), and parashade's "status" says why.
// `tune --export-t4 FILE`: the measured candidates in the Tuning Tools Interoperability's T4 results format
// (schema 1.0.0, as Kernel Tuner writes it). docs/tuning.md has both.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tune_space.hpp"

namespace parashade::cli {

// A point of the searched space as the export sees it.
struct ExportPoint {
  nlohmann::json params;     // point_params: every parameter by name, "-" where the point does not read it
  nlohmann::json candidate;  // its result in the tune report's form (params, frame_ms, timing.samples_ms,
                             // compile_ms, verify_ms, timestamp, verified, max_abs, nmse, within_budget), or null
  bool restricted = false;   // excluded by --restrict (never measured)
};

struct ExportHeader {
  std::string device_name, kernel_name;
  int width = 0, height = 0;
  std::vector<std::string> restrictions;  // --restrict as Python (TuneRestriction::python)
};

// Why an entry is what it is: measured, over_budget, image_differs (both measured, not eligible),
// not_measured (a point of the space the budget did not reach), restricted, not_a_point (a combination of
// tune_params' values that is no point of the space: refused by the table of combinations, or "-" where
// a value is read, or a value where "-" is).
const std::vector<std::string>& export_statuses();

// Kernel Tuner reads its cache files as files it may append to: "cache" must be the last key and the text
// must end with "}\n}" (dump(1) gives that), hence an ordered object.
nlohmann::ordered_json kernel_tuner_cache(const TuneSpace& space, const ExportHeader& header,
                                          const std::vector<ExportPoint>& points);

// The T4 results: one per measured point, "invalidity" "correct" or "correctness" (the image differs, or
// the error is over the budget), measurements time (ms), max_error (levels) and nmse.
nlohmann::ordered_json t4_results(const std::vector<ExportPoint>& points);

}  // namespace parashade::cli
