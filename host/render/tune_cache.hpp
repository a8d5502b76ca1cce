#pragma once
// The tuner's cache, in the spirit of Kernel Tuner's cache files: one JSON file of entries, each with
// the device (name, driver, compute units), the parashade build (version and git commit, <parashade/version.hpp>), the problem (scene,
// size and the shading: method, unit, normalization, specular model), the layout parameters, the
// measured times, the objective (median frame ms) and the error against the exact reference. Rewritten
// whole (atomically) after every candidate, so an interrupted `tune` resumes where it stopped. An entry
// of another device or build is never used (stale_entries says how many there are and why).
#include <filesystem>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "parashade/device.hpp"
#include "parashade/renderer.hpp"
#include "parashade/scene.hpp"

namespace parashade {

// The problem a tuned configuration is for: the scene at its size, shaded one way. The layout (tile,
// work-items, plan) never changes the image; the shading does, so it is part of the problem.
struct TuneProblem {
  std::string scene;  // the scene's name
  int width = 0, height = 0;
  std::string method;                                   // "gouraud", "combined:2", "combined:auto", ...
  std::string unit = "float";                           // "float" (no unit) or the unit's name
  std::string normalize = "exact", specular = "exact";  // Phong's (normalize_name, specular_name)
  nlohmann::json to_json() const;
};

// The problem of rendering `scene` with `o`; nullopt when `o` shades in a way the tuner does not search
// (fixed-point arithmetic, dda coverage, a division per span, combined's extra options), so that no
// entry is taken for it.
std::optional<TuneProblem> tune_problem(const Scene& scene, const RenderOptions& o);

// $PARASHADE_TUNE_CACHE, else $XDG_CACHE_HOME/parashade/tune.json, else ~/.cache/parashade/tune.json.
std::filesystem::path default_tune_cache();

// One measured configuration as the cache keeps it.
struct TuneMeasurement {
  std::vector<double> times;  // the timed frames, ms
  double objective = 0;       // their median
  bool verified = false;      // the image is the bytes of the shading's default layout
  double max_error = 0, nmse = 0;  // against the exact reference (levels; normalized squared error)
};

class TuneCache {
 public:
  // Reads `path` when it exists; a file that is not a tune cache is an InputError naming it.
  explicit TuneCache(std::filesystem::path path);
  // The entry of this device, build, problem and parameters, if any.
  std::optional<nlohmann::json> find(const DeviceInfo& d, const TuneProblem& p, const nlohmann::json& params) const;
  bool has(const DeviceInfo& d, const TuneProblem& p, const nlohmann::json& params) const {
    return find(d, p, params).has_value();
  }
  // Appends an entry (in memory); write() rewrites the file.
  void add(const DeviceInfo& d, const TuneProblem& p, const nlohmann::json& params, const TuneMeasurement& m);
  void write() const;
  // The verified entry with the least objective for this device, build and problem.
  std::optional<nlohmann::json> best(const DeviceInfo& d, const TuneProblem& p) const;
  // Why entries are not used here: "" when every entry (of `p`'s scene and size, when given) is of this
  // device and build, else one sentence with the counts of entries of another build and of another
  // device, and an example of each.
  std::string stale_entries(const DeviceInfo& d, const TuneProblem* p = nullptr) const;
  const std::filesystem::path& path() const { return path_; }

 private:
  bool ours(const nlohmann::json& e, const DeviceInfo& d) const;  // this device and build
  std::filesystem::path path_;
  nlohmann::json doc_;
};

// The parameters of an entry as render options (tile, work-items, plan).
void apply_tuned_params(const nlohmann::json& params, RenderOptions& o);
// A configuration's layout parameters as the cache stores them.
nlohmann::json tuned_params(const RenderOptions& o);

}  // namespace parashade
