// A tune cache entry's fields checked against what the cache writes (tune_cache_entry.hpp).
#include "tune_cache_entry.hpp"

#include <cmath>

#include "parashade/combined.hpp"
#include "parashade/errors.hpp"
#include "parashade/frame_config.hpp"
#include "parashade/kernels/constants.h"
#include "parashade/method.hpp"
#include "parashade/scene.hpp"
#include "parashade/normalization.hpp"
#include "parashade/planner.hpp"
#include "parashade/specular_models.hpp"
#include "parashade/units.hpp"

namespace parashade {
namespace {

using json = nlohmann::json;

// The fault of `object[key]` under `where` ("params.tile"), "" when `ok` holds.
template <typename Ok>
std::string check(const json& object, const char* where, const char* key, const char* expected, Ok ok) {
  const std::string at = std::string(where) + (*where ? "." : "") + key;
  if (!object.contains(key)) return at + " is missing";
  const json& v = object[key];
  return ok(v) ? "" : at + " is " + v.dump() + ", not " + expected;
}

bool int_in(const json& v, long long lo, long long hi) {
  return v.is_number_integer() && v.get<long long>() >= lo && v.get<long long>() <= hi;
}

bool finite_at_least_zero(const json& v) { return v.is_number() && std::isfinite(v.get<double>()) && v.get<double>() >= 0; }

// True when `parse` accepts the string `v` (the parsers throw UsageError).
template <typename Parse>
bool parses(const json& v, Parse parse) {
  if (!v.is_string()) return false;
  try {
    parse(v.get<std::string>());
    return true;
  } catch (const Error&) {
    return false;
  }
}

bool is_tile(const json& v) {
  for (const int t : tile_sizes())
    if (v.is_number_integer() && v.get<long long>() == t) return true;
  return false;
}

std::string params_fault(const json& p) {
  if (!p.is_object()) return "params is " + p.dump() + ", not an object";
  std::string f = check(p, "params", "tile", "a tile size", is_tile);
  if (f.empty()) f = check(p, "params", "work_items", "a count of work-items", [](const json& v) { return int_in(v, 0, 1 << 20); });
  // The kernel's shape and work-group, written only where not the defaults (tuned_params).
  if (f.empty() && p.contains("kernel_shape"))
    f = check(p, "params", "kernel_shape", "vector or lanes",
              [](const json& v) { return parses(v, [](const std::string& s) { parse_kernel_shape(s); }); });
  if (f.empty() && p.contains("work_group_size"))
    f = check(p, "params", "work_group_size", "a work-group size",
              [](const json& v) { return int_in(v, 0, MAX_WORK_GROUP_SIZE); });
  if (f.empty())
    f = check(p, "params", "partition", "none or a partition", [](const json& v) {
      return v == "none" || parses(v, [](const std::string& s) { parse_partition(s); });
    });
  if (!f.empty() || p["partition"] == "none") return f;
  f = check(p, "params", "cu", "a count of modeled units", [](const json& v) { return int_in(v, 1, MAX_MODELED_UNITS); });
  if (f.empty() && p.contains("batch"))
    f = check(p, "params", "batch", "a batch of triangles", [](const json& v) { return int_in(v, 1, 1 << 30); });
  return f;
}

std::string problem_fault(const json& p) {
  if (!p.is_object()) return "problem is " + p.dump() + ", not an object";
  const auto text = [](const json& v) { return v.is_string(); };
  std::string f = check(p, "problem", "scene", "a name", text);
  if (f.empty()) f = check(p, "problem", "width", "a width", [](const json& v) { return int_in(v, 1, kMaxResolution); });
  if (f.empty()) f = check(p, "problem", "height", "a height", [](const json& v) { return int_in(v, 1, kMaxResolution); });
  if (f.empty())
    f = check(p, "problem", "method", "a method", [](const json& v) {
      return parses(v, [](const std::string& s) { s.rfind("combined", 0) == 0 ? (void)parse_combined(s) : (void)parse_method(s); });
    });
  if (f.empty())
    f = check(p, "problem", "units", "float or a unit", [](const json& v) {
      return v == "float" || parses(v, [](const std::string& s) { parse_units(s); });
    });
  if (f.empty())
    f = check(p, "problem", "normalize", "a normalization", [](const json& v) { return parses(v, [](const std::string& s) { parse_normalize(s); }); });
  if (f.empty())
    f = check(p, "problem", "specular", "a specular model", [](const json& v) { return parses(v, [](const std::string& s) { parse_specular(s); }); });
  return f;
}

std::string measurement_fault(const json& e) {
  std::string f = check(e, "", "objective", "a time in ms", finite_at_least_zero);
  if (f.empty()) f = check(e, "", "verified", "true or false", [](const json& v) { return v.is_boolean(); });
  if (f.empty()) f = check(e, "", "max_error", "a number of levels", finite_at_least_zero);
  if (f.empty()) f = check(e, "", "nmse", "a number or null", [](const json& v) { return v.is_null() || finite_at_least_zero(v); });
  if (f.empty())
    f = check(e, "", "times_ms", "a list of times", [](const json& v) {
      if (!v.is_array()) return false;
      for (const json& t : v)
        if (!finite_at_least_zero(t)) return false;
      return true;
    });
  return f;
}

}  // namespace

std::string tune_entry_fault(const json& e) {
  if (!e.is_object()) return "not an object";
  const auto text = [](const json& v) { return v.is_string(); };
  std::string f = check(e, "", "device_name", "a name", text);
  if (f.empty()) f = check(e, "", "driver_version", "a version", text);
  if (f.empty()) f = check(e, "", "version", "a version", text);
  if (f.empty()) f = check(e, "", "compute_units", "a count", [](const json& v) { return int_in(v, 1, 1 << 20); });
  if (f.empty()) f = problem_fault(e.value("problem", json()));
  if (f.empty()) f = params_fault(e.value("params", json()));
  if (f.empty()) f = measurement_fault(e);
  return f;
}

}  // namespace parashade
