#pragma once
// The tuner's cache, in the spirit of Kernel Tuner's cache files: one JSON file of entries, each with
// the device (platform, name, driver, compute units), the parashade build (version and git commit, <parashade/version.hpp>), the problem (scene,
// size and the shading: method, unit, normalization, specular model), the layout parameters, the
// measured times, the objective (median frame ms) and the error against the exact reference. Rewritten
// whole (atomically) after every candidate, so an interrupted `tune` resumes where it stopped; each write
// holds a lock (flock on the cache's folder) and first takes in the entries other runs wrote meanwhile,
// so two runs on one cache keep each other's entries. An entry of another device or build is never used
// (stale_entries says how many there are and why); an entry with a fault is set aside (set_aside).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

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
// How the cache at `given` (--cache or --tune-cache, or empty) was named, for messages: the option, or
// PARASHADE_TUNE_CACHE when it chose the default; "" for parashade's own default, whose folder
// (~/.cache/parashade) parashade may make. A folder a user named must exist, like every output's.
std::string tune_cache_origin(const std::string& given, const std::string& option);

// One measured configuration as the cache keeps it.
struct TuneMeasurement {
  std::vector<double> times;  // the timed frames, ms
  double objective = 0;       // their median
  bool verified = false;      // the image is the bytes of the shading's default layout
  double max_error = 0, nmse = 0;  // against the exact reference (levels; normalized squared error)
};

class TuneCache {
 public:
  // Reads `path` when it exists; a file that is not a tune cache (not JSON, no "entries" array) is an
  // InputError naming it.
  explicit TuneCache(std::filesystem::path path);
  // The entry of this device, build, problem and parameters, if any.
  std::optional<nlohmann::json> find(const DeviceInfo& d, const TuneProblem& p, const nlohmann::json& params) const;
  bool has(const DeviceInfo& d, const TuneProblem& p, const nlohmann::json& params) const {
    return find(d, p, params).has_value();
  }
  // Appends an entry (in memory); write() rewrites the file with the entries written since it was read.
  void add(const DeviceInfo& d, const TuneProblem& p, const nlohmann::json& params, const TuneMeasurement& m);
  void write();
  // The verified entry with the least objective for this device, build and problem.
  std::optional<nlohmann::json> best(const DeviceInfo& d, const TuneProblem& p) const;
  // Why entries are not used here: "" when every entry (of `p`'s scene and size, when given) is of this
  // device and build, else one sentence with the counts of entries of another build and of another
  // device, and an example of each.
  std::string stale_entries(const DeviceInfo& d, const TuneProblem* p = nullptr) const;
  // "" when every entry is understood, else one sentence: how many entries are set aside (not used, kept in
  // the file) and the first one's fault (tune_cache_entry.hpp).
  std::string set_aside() const;
  const std::filesystem::path& path() const { return path_; }

 private:
  bool ours(const nlohmann::json& e, const DeviceInfo& d) const;  // this device and build
  // Appends `entries` (only_new: those whose device, build, problem and parameters are not held yet),
  // checking each (tune_cache_entry.hpp).
  void take(const nlohmann::json& entries, bool only_new);
  std::filesystem::path path_;
  nlohmann::json doc_;
  std::vector<bool> usable_;  // per entry of doc_["entries"]: understood
  std::vector<std::string> faults_;  // of the entries set aside, "entry N: fault"
};

// The parameters of an entry as render options (tile, work-items, plan).
void apply_tuned_params(const nlohmann::json& params, RenderOptions& o);
// A configuration's layout parameters as the cache stores them.
nlohmann::json tuned_params(const RenderOptions& o);

}  // namespace parashade
