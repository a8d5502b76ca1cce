#pragma once
// The tuner's cache, in the spirit of Kernel Tuner's cache files: one JSON file of entries, each with
// the device (name and driver), the problem (scene, size, method, unit), the parameters, the measured
// times and the objective (median frame ms). Rewritten whole (atomically) after every candidate, so
// an interrupted `tune` resumes where it stopped.
#include <filesystem>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "parashade/device.hpp"
#include "parashade/renderer.hpp"

namespace parashade::cli {

// The problem a tuned configuration is for.
struct TuneProblem {
  std::string scene;  // the scene's name
  int width = 0, height = 0;
  std::string method, unit;  // unit: "float" or the unit and arithmetic of --units/--arith
  nlohmann::json to_json() const;
};

// $PARASHADE_TUNE_CACHE, else $XDG_CACHE_HOME/parashade/tune.json, else ~/.cache/parashade/tune.json.
std::filesystem::path default_tune_cache();

class TuneCache {
 public:
  // Reads `path` when it exists; a file that is not a tune cache is an InputError naming it.
  explicit TuneCache(std::filesystem::path path);
  bool has(const DeviceInfo& d, const TuneProblem& p, const nlohmann::json& params) const;
  // Appends an entry and rewrites the file.
  void add(const DeviceInfo& d, const TuneProblem& p, const nlohmann::json& params, const std::vector<double>& times,
           double objective, bool verified);
  // The verified entry with the least objective for this device and problem.
  std::optional<nlohmann::json> best(const DeviceInfo& d, const TuneProblem& p) const;
  const std::filesystem::path& path() const { return path_; }

 private:
  bool matches(const nlohmann::json& e, const DeviceInfo& d, const TuneProblem& p) const;
  std::filesystem::path path_;
  nlohmann::json doc_;
};

// The parameters of an entry as render options (tile, work-items, plan).
void apply_tuned_params(const nlohmann::json& params, RenderOptions& o);
// A configuration's parameters as the cache stores them.
nlohmann::json tuned_params(const RenderOptions& o);

}  // namespace parashade::cli
