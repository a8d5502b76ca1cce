#include "tune_space.hpp"

#include <algorithm>
#include <cstdlib>

#include "cli_args.hpp"
#include "parashade/combinations.hpp"
#include "parashade/combined.hpp"
#include "parashade/errors.hpp"
#include "parashade/unit_table.hpp"

namespace parashade::cli {
namespace {

int parse_int(const std::string& text) {
  char* end = nullptr;
  const long v = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || v < 0 || v > 1 << 30)
    throw UsageError("'" + text + "' is not a non-negative integer");
  return int(v);
}

std::string partition_values() {
  std::string s = "none";
  for (Partition p : {Partition::round_robin, Partition::lpt, Partition::tiles, Partition::dynamic})
    s += ", " + partition_name(p);
  return s;
}

// The method axis of the table of combinations, with combined's forms spelled out.
std::string method_values() {
  std::string s;
  for (const std::string& m : axis_values(Axis::method))
    s += (s.empty() ? "" : ", ") +
         (m == "combined" ? "combined:K (K = 0.." + std::to_string(kCombinedMaxK) + "), combined:auto" : m);
  return s;
}

// One parameter: how a value is checked and named (the name parses back to the same value), and what
// the valid values are, from the project's own tables and parsers.
struct ParamDef {
  const char* name;
  std::string (*canonical)(const std::string& text);  // throws UsageError
  std::string (*valid)();
};

const std::vector<ParamDef>& param_defs() {
  static const std::vector<ParamDef> defs = {
      {"tile",
       [](const std::string& t) {
         const int v = parse_int(t);
         const std::vector<int> sizes = tile_sizes();
         if (std::find(sizes.begin(), sizes.end(), v) == sizes.end()) throw UsageError("tile " + t + " is not supported");
         return std::to_string(v);
       },
       [] { return tile_sizes_text(); }},
      {"work_items", [](const std::string& t) { return std::to_string(parse_int(t)); },
       [] { return std::string("0 (the device's default) or a positive number of work-items"); }},
      {"kernel_shape", [](const std::string& t) { return std::string(kernel_shape_name(parse_kernel_shape(t))); },
       [] { return std::string("vector, lanes"); }},
      {"work_group_size",
       [](const std::string& t) {
         RenderOptions o;  // the size alone (its limits with the tile and the device: per point, per render)
         o.work_group_size = parse_int(t);
         o.tile_size = 0;
         check_work_group_size(o);
         return std::to_string(o.work_group_size);
       },
       [] { return "0 (the shape's default) or a power of two up to " + std::to_string(MAX_WORK_GROUP_SIZE); }},
      {"partition",
       [](const std::string& t) { return t == "none" ? t : partition_name(parse_partition(t)); },
       partition_values},
      {"cu",
       [](const std::string& t) {
         PlanOptions plan;
         plan.units = parse_int(t);
         check_plan_options(plan);
         return std::to_string(plan.units);
       },
       [] { return "1.." + std::to_string(MAX_MODELED_UNITS) + " modeled units (0: the device's compute units)"; }},
      {"batch",
       [](const std::string& t) {
         const int v = parse_int(t);
         if (v < 1) throw UsageError("batch " + t + " must be at least 1 triangle");
         return std::to_string(v);
       },
       [] { return std::string("a positive number of triangles (read by the dynamic partition)"); }},
      {"method",
       [](const std::string& t) {
         const Method m = parse_method(t);
         return m == Method::combined ? combined_name(parse_combined(t)) : std::string(method_name(m));
       },
       method_values},
      {"units", [](const std::string& t) { return t == "none" ? t : unit_name(parse_units(t)); },
       [] { return "none, " + unit_specs_help(); }},
      {"normalize", [](const std::string& t) { return normalize_name(parse_normalize(t)); },
       [] { return std::string("as render --normalize takes them"); }},
      {"specular", [](const std::string& t) { return specular_name(parse_specular(t)); },
       [] { return std::string("as render --specular takes them"); }},
  };
  return defs;
}

int index_of(const TuneSpace& s, const char* name) {
  return int(std::find(s.names.begin(), s.names.end(), name) - s.names.begin());
}

const ParamDef& param_def(const std::string& name) {
  return *std::find_if(param_defs().begin(), param_defs().end(), [&](const ParamDef& d) { return name == d.name; });
}

}  // namespace

const std::vector<std::string>& tune_param_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const ParamDef& d : param_defs()) n.push_back(d.name);
    return n;
  }();
  return names;
}

bool is_number_param(const std::string& name) {
  return name == "tile" || name == "work_items" || name == "work_group_size" || name == "cu" || name == "batch";
}

bool is_layout_param(const std::string& name) {
  return name == "tile" || name == "work_items" || name == "kernel_shape" || name == "work_group_size" ||
         name == "partition" || name == "cu" || name == "batch";
}

TuneSpace default_tune_space(const std::string& method, int compute_units) {
  const int cu = std::max(1, compute_units);
  const auto distinct = [](std::vector<int> v) {
    std::vector<std::string> out;
    for (int x : v)
      if (std::find(out.begin(), out.end(), std::to_string(x)) == out.end()) out.push_back(std::to_string(x));
    return out;
  };
  TuneSpace s;
  s.names = tune_param_names();
  std::vector<std::string> tiles;
  for (int t : tile_sizes()) tiles.push_back(std::to_string(t));
  std::vector<std::string> partitions = {"none"};
  for (Partition p : {Partition::round_robin, Partition::lpt, Partition::tiles, Partition::dynamic})
    partitions.push_back(partition_name(p));
  s.values = {tiles,
              distinct({0, cu, 16 * cu, 64 * cu}),
              {"vector"},
              {"0"},
              partitions,
              distinct({cu, 2 * cu, 4 * cu, 16}),
              {"16", "64", "256"},
              {for_option("--method", [&] { return param_def("method").canonical(method); })},
              {"none"},
              {"exact"},
              {"exact"}};
  return s;
}

void set_tune_param(TuneSpace& space, const std::string& assignment) {
  const std::size_t eq = assignment.find('=');
  std::string name = assignment.substr(0, eq);
  std::replace(name.begin(), name.end(), '-', '_');  // work-items as the render option spells it
  const auto def = std::find_if(param_defs().begin(), param_defs().end(), [&](const ParamDef& d) { return name == d.name; });
  if (def == param_defs().end()) {
    std::string names;
    for (const std::string& n : tune_param_names()) names += (names.empty() ? "" : ", ") + n;
    throw UsageError("--param: unknown parameter '" + assignment.substr(0, eq) + "' (valid: " + names + ")");
  }
  if (eq == std::string::npos || eq + 1 == assignment.size())
    throw UsageError("--param " + name + ": expected " + name + "=V1,V2,... (valid values: " + def->valid() + ")");
  const std::string option = "--param " + name;
  std::vector<std::string> values;
  for (const std::string& text : split_list(assignment.substr(eq + 1), option)) {
    std::string v;
    try {
      v = def->canonical(text);
    } catch (const UsageError& e) {
      throw UsageError(option + ": " + e.what() + " (valid: " + def->valid() + ")");
    }
    if (std::find(values.begin(), values.end(), v) != values.end())
      throw UsageError(option + " lists '" + text + "' twice (as " + v + ")");
    values.push_back(v);
  }
  space.values[std::size_t(def - param_defs().begin())] = values;
}

RenderOptions options_at(const TuneSpace& s, const TunePoint& p, const RenderOptions& base) {
  const auto value = [&](const char* name) -> const std::string& {
    const int i = index_of(s, name);
    return s.values[i][p[i]];
  };
  RenderOptions o = base;
  o.tile_size = std::stoi(value("tile"));
  o.work_items = std::stoi(value("work_items"));
  o.kernel_shape = parse_kernel_shape(value("kernel_shape"));
  o.work_group_size = std::stoi(value("work_group_size"));
  if (value("partition") == "none") {
    o.plan.reset();
  } else {
    PlanOptions plan;
    plan.partition = parse_partition(value("partition"));
    plan.units = std::stoi(value("cu"));
    if (plan.partition == Partition::dynamic) plan.batch = std::stoi(value("batch"));
    o.plan = plan;
  }
  o.method = parse_method(value("method"));
  o.combined = o.method == Method::combined ? parse_combined(value("method")) : CombinedConfig{};
  if (value("units") == "none") o.units.reset();
  else o.units = parse_units(value("units"));
  o.normalize = parse_normalize(value("normalize"));
  o.specular = parse_specular(value("specular"));
  return o;
}

TunePoints enumerate_points(const TuneSpace& s, const RenderOptions& base) {
  TunePoints out;
  const int partition = index_of(s, "partition"), units = index_of(s, "cu"), batch = index_of(s, "batch");
  const int items = index_of(s, "work_items");
  TunePoint p(s.names.size(), 0);
  if (space_size(s) == 0) return out;
  for (;;) {
    const std::string& part = s.values[partition][p[partition]];
    const bool reads_units = part != "none", reads_batch = part == "dynamic";
    const RenderOptions shaped = options_at(s, p, base);
    const bool lanes = shaped.kernel_shape == KernelShape::lanes;  // a work-group per tile: no work_items to read
    const bool group_fits = !lanes || shaped.group_size() <= shaped.tile_size * shaped.tile_size;
    if ((!reads_units && p[units] != 0) || (!reads_batch && p[batch] != 0) || (lanes && p[items] != 0) ||
        !group_fits) {
      ++out.not_applicable;
    } else {
      const RenderOptions o = options_at(s, p, base);
      if (const Refusal* r = find_refusal(combination_of(o))) {
        if (out.refusal_example.empty()) out.refusal_example = point_params(s, p).dump() + ": " + r->reason;
        ++out.refused;
      } else {
        try {
          check_render_options(o, DeviceMode::one);
        } catch (const Error& e) {
          throw UsageError("--param: the point " + point_params(s, p).dump() + " is not a valid frame: " + e.what());
        }
        out.valid.push_back(p);
      }
    }
    int d = int(p.size()) - 1;
    while (d >= 0 && ++p[d] == int(s.values[d].size())) p[d--] = 0;
    if (d < 0) break;
  }
  return out;
}

nlohmann::json point_params(const TuneSpace& s, const TunePoint& p) {
  nlohmann::json j = nlohmann::json::object();
  const std::string& part = s.values[index_of(s, "partition")][p[index_of(s, "partition")]];
  for (std::size_t i = 0; i < s.names.size(); ++i) {
    const std::string& n = s.names[i];
    const std::string& v = s.values[i][p[i]];
    const bool lanes = s.values[index_of(s, "kernel_shape")][p[index_of(s, "kernel_shape")]] == "lanes";
    const bool unread = (n == "cu" && part == "none") || (n == "batch" && part != "dynamic") || (n == "work_items" && lanes);
    if (unread) j[n] = "-";
    else if (is_number_param(n)) j[n] = std::stoi(v);
    else j[n] = v;
  }
  return j;
}

TunePoint default_point(const TuneSpace& s, const RenderOptions& base) {
  TunePoint p(s.names.size(), 0);
  const auto pick = [&](const char* name, const std::string& v) {
    const int i = index_of(s, name);
    const auto at = std::find(s.values[i].begin(), s.values[i].end(), v);
    if (at == s.values[i].end()) return false;
    p[i] = int(at - s.values[i].begin());
    return true;
  };
  const std::string method = base.method == Method::combined ? combined_name(base.combined) : method_name(base.method);
  if (pick("tile", std::to_string(base.tile_size)) && pick("work_items", std::to_string(base.work_items)) &&
      pick("kernel_shape", kernel_shape_name(base.kernel_shape)) &&
      pick("work_group_size", std::to_string(base.work_group_size)) && pick("partition", "none") && pick("method", method) && pick("units", "none") &&
      pick("normalize", normalize_name(base.normalize)) && pick("specular", specular_name(base.specular)))
    return p;
  return {};
}

std::size_t space_size(const TuneSpace& s) {
  std::size_t n = 1;
  for (const auto& v : s.values) n *= v.size();
  return n;
}

std::string render_flags(const nlohmann::json& params) {
  std::string flags;
  std::vector<std::string> names;  // the shading first, then the layout
  for (const std::string& n : tune_param_names())
    if (!is_layout_param(n)) names.push_back(n);
  for (const std::string& n : tune_param_names())
    if (is_layout_param(n)) names.push_back(n);
  for (const std::string& name : names) {
    const nlohmann::json& v = params.at(name);
    const std::string text = v.is_string() ? v.get<std::string>() : v.dump();
    // "-": nothing reads it at this point; "none": the option's absence (no plan, no unit); a work-group or
    // work-items of 0, the device's: the option's absence too, which render resolves alike (device_layout.hpp).
    if (text == "-" || text == "none" || (text == "0" && (name == "work_group_size" || name == "work_items"))) continue;
    std::string option = name;
    std::replace(option.begin(), option.end(), '_', '-');
    flags += (flags.empty() ? "--" : " --") + option + " " + text;
  }
  return flags;
}

}  // namespace parashade::cli
