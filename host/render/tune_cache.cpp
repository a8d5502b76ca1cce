#include "tune_cache.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <set>

#include "parashade/errors.hpp"
#include "parashade/json_number.hpp"
#include "parashade/report.hpp"
#include "parashade/version.hpp"
#include "tune_cache_entry.hpp"

namespace parashade {
namespace {

// The build an entry was measured with, "0.1.0+abc123def456": a timing from another build of the
// kernels or the host stages says nothing about this one.
std::string build_id() { return std::string(version) + "+" + git_hash; }

// The entries of the cache file at `path` (none when it does not exist); InputError when it is not a tune cache.
nlohmann::json read_entries(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return nlohmann::json::array();
  std::ifstream in(path);
  nlohmann::json read;
  try {
    in >> read;
  } catch (const nlohmann::json::exception& e) {
    throw InputError("tune cache '" + path.string() + "' is not valid JSON: " + e.what());
  }
  if (!read.is_object() || !read.contains("entries") || !read["entries"].is_array())
    throw InputError("tune cache '" + path.string() + "' has no \"entries\" array");
  return read["entries"];
}

// What makes two entries one measurement: the device, the build, the problem and the parameters.
std::string identity(const nlohmann::json& e) {
  if (!e.is_object()) return e.dump();
  nlohmann::json id = nlohmann::json::object();
  for (const char* key : {"platform", "device_name", "driver_version", "compute_units", "version", "problem", "params"})
    id[key] = e.value(key, nlohmann::json());
  return id.dump();
}

// An exclusive lock on the cache's folder while a write reads, merges and renames (flock on a folder
// descriptor: no lock file beside the cache). Without it (a file system without locks) the write goes on.
class FolderLock {
 public:
  explicit FolderLock(const std::filesystem::path& folder)
      : fd_(::open(folder.empty() ? "." : folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC)) {
    if (fd_ >= 0)
      while (::flock(fd_, LOCK_EX) != 0 && errno == EINTR) {
      }
  }
  ~FolderLock() {
    if (fd_ >= 0) ::close(fd_);  // releases the lock
  }
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

 private:
  int fd_;
};

}  // namespace

nlohmann::json TuneProblem::to_json() const {
  return {{"scene", scene}, {"width", width},         {"height", height},
          {"method", method}, {"units", unit}, {"normalize", normalize}, {"specular", specular}};
}

std::optional<TuneProblem> tune_problem(const Scene& scene, const RenderOptions& o) {
  if (o.arith.fixed || o.dda_coverage || o.division.mode != DIV_CONSTANT) return std::nullopt;
  TuneProblem p{scene.name, scene.width, scene.height, method_name(o.method)};
  if (o.method == Method::combined) {
    // Only what combined:K or combined:auto alone gives (the tuner's values of the method parameter).
    const CombinedConfig plain = parse_combined(combined_name(o.combined));
    const CombinedConfig& c = o.combined;
    if (c.rule != plain.rule || c.highlight_test != plain.highlight_test || c.min_width != plain.min_width ||
        c.max_error != plain.max_error)
      return std::nullopt;
    p.method = combined_name(c);
  }
  if (o.units) p.unit = unit_name(*o.units);
  p.normalize = normalize_name(o.normalize);
  p.specular = specular_name(o.specular);
  return p;
}

std::string tune_cache_origin(const std::string& given, const std::string& option) {
  if (!given.empty()) return option;
  if (const char* p = std::getenv("PARASHADE_TUNE_CACHE"); p && *p) return "PARASHADE_TUNE_CACHE";
  return "";
}

std::filesystem::path default_tune_cache() {
  if (const char* p = std::getenv("PARASHADE_TUNE_CACHE"); p && *p) return p;
  if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x) return std::filesystem::path(x) / "parashade" / "tune.json";
  if (const char* h = std::getenv("HOME"); h && *h) return std::filesystem::path(h) / ".cache" / "parashade" / "tune.json";
  return "parashade-tune.json";
}

TuneCache::TuneCache(std::filesystem::path path) : path_(std::move(path)) {
  doc_ = {{"format", "parashade tune cache 3"}, {"objective", "frame_ms (median, lower is better)"},
          {"tune_params_keys", {"tile", "work_items", "partition", "cu", "batch"}},
          {"entries", nlohmann::json::array()}};
  take(read_entries(path_), false);
}

void TuneCache::take(const nlohmann::json& entries, bool only_new) {
  std::set<std::string> held;
  if (only_new)
    for (const auto& e : doc_["entries"]) held.insert(identity(e));
  for (const auto& e : entries) {
    if (only_new && !held.insert(identity(e)).second) continue;
    const std::string fault = tune_entry_fault(e);
    doc_["entries"].push_back(e);
    usable_.push_back(fault.empty());
    if (!fault.empty()) faults_.push_back("entry " + std::to_string(doc_["entries"].size()) + ": " + fault);
  }
}

std::string TuneCache::set_aside() const {
  if (faults_.empty()) return "";
  const std::size_t n = faults_.size();
  return "tune cache '" + path_.string() + "': " + std::to_string(n) + (n == 1 ? " entry" : " entries") +
         " not understood, not used (" + faults_.front() + (n > 1 ? "; and more" : "") + ")";
}

namespace {

// The device an entry was measured on: platform, name, driver and compute units. Two implementations can
// name one CPU alike (PoCL's and Intel's runtimes), so the platform is part of it.
bool same_device(const nlohmann::json& e, const DeviceInfo& d) {
  return e.value("platform", "") == d.platform && e.value("device_name", "") == d.name &&
         e.value("driver_version", "") == d.driver && e.value("compute_units", -1) == d.compute_units;
}

// "PLATFORM / NAME, driver D, N compute units", as entries and devices are told apart.
std::string device_text(const std::string& platform, const std::string& name, const std::string& driver, int units) {
  return platform + " / " + name + ", driver " + driver + ", " + std::to_string(units) + " compute units";
}

}  // namespace

bool TuneCache::ours(const nlohmann::json& e, const DeviceInfo& d) const {
  return same_device(e, d) && e.value("version", "") == build_id();
}

std::optional<nlohmann::json> TuneCache::find(const DeviceInfo& d, const TuneProblem& p, const nlohmann::json& params) const {
  const nlohmann::json problem = p.to_json();
  const nlohmann::json& entries = doc_["entries"];
  for (std::size_t i = 0; i < entries.size(); ++i)
    if (usable_[i] && ours(entries[i], d) && entries[i]["problem"] == problem && entries[i]["params"] == params)
      return entries[i];
  return std::nullopt;
}

void TuneCache::add(const DeviceInfo& d, const TuneProblem& p, const nlohmann::json& params, const TuneMeasurement& m) {
  doc_["entries"].push_back({{"device_name", d.name},
                             {"driver_version", d.driver},
                             {"platform", d.platform},
                             {"compute_units", d.compute_units},
                             {"version", build_id()},
                             {"problem", p.to_json()},
                             {"params", params},
                             {"times_ms", m.times},
                             {"objective", m.objective},
                             {"verified", m.verified},
                             {"max_error", m.max_error},
                             {"nmse", number_or_null(m.nmse)}});
  usable_.push_back(true);
}

void TuneCache::write() {
  FolderLock lock(path_.parent_path());
  take(read_entries(path_), true);  // what other runs wrote since this one read the file
  write_text_atomically(path_, doc_.dump(1) + "\n");
}

std::optional<nlohmann::json> TuneCache::best(const DeviceInfo& d, const TuneProblem& p) const {
  const nlohmann::json problem = p.to_json();
  std::optional<nlohmann::json> out;
  const nlohmann::json& entries = doc_["entries"];
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const nlohmann::json& e = entries[i];
    if (usable_[i] && ours(e, d) && e["problem"] == problem && e["verified"].get<bool>() &&
        (!out || e["objective"].get<double>() < (*out)["objective"].get<double>()))
      out = e;
  }
  return out;
}

std::string TuneCache::stale_entries(const DeviceInfo& d, const TuneProblem* p) const {
  int other_build = 0, other_device = 0;
  std::string build_example, device_example;
  const nlohmann::json& entries = doc_["entries"];
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const nlohmann::json& e = entries[i];
    if (!usable_[i] || ours(e, d)) continue;
    if (p) {
      const nlohmann::json q = e.value("problem", nlohmann::json::object());
      if (q.value("scene", "") != p->scene || q.value("width", 0) != p->width || q.value("height", 0) != p->height)
        continue;
    }
    if (same_device(e, d)) {
      ++other_build;
      if (build_example.empty()) build_example = e.value("version", std::string("an unversioned build"));
    } else {
      ++other_device;
      if (device_example.empty())
        device_example = device_text(e.value("platform", std::string("no platform")), e.value("device_name", std::string("?")),
                                     e.value("driver_version", std::string("?")), e.value("compute_units", -1));
    }
  }
  if (!other_build && !other_device) return "";
  std::string s = "tune cache '" + path_.string() + "': ";
  if (other_build)
    s += std::to_string(other_build) + " entr" + (other_build == 1 ? "y" : "ies") + " of another parashade build (" +
         build_example + "; this is " + build_id() + ")";
  if (other_build && other_device) s += " and ";
  if (other_device)
    s += std::to_string(other_device) + " entr" + (other_device == 1 ? "y" : "ies") + " of another device (" +
         device_example + "; this is " + device_text(d.platform, d.name, d.driver, d.compute_units) + ")";
  return s + " not used";
}

nlohmann::json tuned_params(const RenderOptions& o) {
  nlohmann::json p = {{"tile", o.tile_size}, {"work_items", o.work_items}};
  // Only where not the defaults, so entries written before these knobs existed stay the same entries.
  if (o.kernel_shape != KernelShape::vector) p["kernel_shape"] = kernel_shape_name(o.kernel_shape);
  if (o.work_group_size != 0) p["work_group_size"] = o.work_group_size;
  if (o.plan) {
    p["partition"] = partition_name(o.plan->partition);
    p["cu"] = o.plan->units;
    if (o.plan->partition == Partition::dynamic) p["batch"] = o.plan->batch;
  } else {
    p["partition"] = "none";
  }
  return p;
}

void apply_tuned_params(const nlohmann::json& params, RenderOptions& o) {
  try {
    o.tile_size = params.at("tile").get<int>();
    o.work_items = params.at("work_items").get<int>();
    o.kernel_shape = parse_kernel_shape(params.value("kernel_shape", std::string("vector")));
    o.work_group_size = params.value("work_group_size", 0);
    const std::string part = params.at("partition").get<std::string>();
    if (part == "none") {
      o.plan.reset();
    } else {
      PlanOptions plan;
      plan.partition = parse_partition(part);
      plan.units = params.at("cu").get<int>();
      if (params.contains("batch")) plan.batch = params.at("batch").get<int>();
      o.plan = plan;
    }
  } catch (const nlohmann::json::exception& e) {
    throw InputError(std::string("a tune cache entry's parameters are not usable: ") + e.what());
  }
}

}  // namespace parashade
