#include "parashade/combinations.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "parashade/frame_config.hpp"
#include "parashade/unit_table.hpp"

namespace parashade {
namespace {

// The unit axis: no unit, then the unit table's values (a new unit is a new value without an edit here).
std::vector<std::string> unit_axis() {
  std::vector<std::string> values{"none"};
  for (std::string& v : unit_combination_values()) values.push_back(std::move(v));
  return values;
}

// Each axis's values, in index order; a value's bit in a mask is 1 << index.
const std::vector<std::string> kValues[kAxes] = {
    {"flat", "gouraud", "phong", "combined"},                                                    // method
    unit_axis(),                                                                                 // unit
    {"float", "fixed"},                                                                          // arith
    {"centre", "dda"},                                                                           // coverage
    {"constant", "per-span"},                                                                    // division
    {"exact", "per-span"},                                                                       // normalize
    {"exact", "model"},                                                                          // specular
    {"none", "per-triangle"},                                                                    // choice
    {"off", "on"},                                                                               // highlight
    {"none", "planned"},                                                                         // plan
    {"one", "bands", "unit-sub-devices", "ranks-sort-first", "ranks-sort-last"},                 // devices
    {"vector", "lanes"},                                                                         // shape
};
const char* const kAxisNames[kAxes] = {"method", "unit", "arith", "coverage", "division", "normalize",
                                       "specular", "choice", "highlight", "plan", "devices", "shape"};

constexpr std::uint32_t kAll = ~std::uint32_t(0);

// The bit of a unit axis value, by name (a refusal names the units it refuses).
std::uint32_t unit_bit(const std::string& name) {
  const std::vector<std::string>& v = kValues[int(Axis::unit)];
  const auto at = std::find(v.begin(), v.end(), name);
  if (at == v.end() || at - v.begin() >= 32) throw std::logic_error("no unit axis value '" + name + "' for a mask");
  return std::uint32_t(1) << (at - v.begin());
}

// Value bits, by axis.
constexpr std::uint32_t kFlat = 1, kGouraud = 2, kPhong = 4, kCombined = 8;
constexpr std::uint32_t kNoUnit = 1, kAnyUnit = kAll & ~kNoUnit;
const std::uint32_t kSierpinski = unit_bit("sierpinski"), kInterleaveOwn = unit_bit("interleave:own");
constexpr std::uint32_t kFloat = 1, kDda = 2, kPerSpan = 2, kModel = 2, kPerTriangle = 2, kOn = 2, kPlanned = 2;
constexpr std::uint32_t kNoPlan = 1, kBands = 2, kUnitSubDevices = 4, kRanksSortFirst = 8, kRanksSortLast = 16;
constexpr std::uint32_t kLanes = 2;

struct Pattern {
  Axis axis;
  std::uint32_t values;
};

Refusal refuse(std::initializer_list<Pattern> patterns, const char* reason) {
  Refusal r{};
  for (std::uint32_t& m : r.mask) m = kAll;
  for (const Pattern& p : patterns) r.mask[int(p.axis)] = p.values;
  r.reason = reason;
  return r;
}

// The table. A pattern not listed here is modeled; the tests render a sample of the modeled ones.
const std::vector<Refusal> kRefused = {
    refuse({{Axis::method, kFlat}, {Axis::unit, kAnyUnit}},
           "the shading units interpolate along spans; flat has nothing to interpolate"),
    refuse({{Axis::method, kPhong}, {Axis::unit, kSierpinski}},
           "sierpinski copies Gouraud intensities; phong shades every pixel of every copy, so it is modeled for "
           "gouraud only"),
    refuse({{Axis::unit, kSierpinski}, {Axis::coverage, kDda}}, "the copies need pixel-centre coverage"),
    refuse({{Axis::method, kAll & ~kPhong}, {Axis::specular, kModel}},
           "the lower-degree specular models are phong's (the other methods light on the host)"),
    refuse({{Axis::method, kAll & ~kPhong}, {Axis::normalize, kPerSpan}}, "per-span normals are phong's"),
    refuse({{Axis::normalize, kPerSpan}, {Axis::unit, kAnyUnit}},
           "the units normalize per pixel: per-span normals have no shading-unit model"),
    refuse({{Axis::method, kAll & ~kGouraud}, {Axis::coverage, kDda}}, "dda coverage is modeled for gouraud's units only"),
    refuse({{Axis::method, kCombined}, {Axis::unit, kAnyUnit}},
           "combined has no shading-unit model (gouraud or phong run through the units)"),
    refuse({{Axis::method, kAll & ~kCombined}, {Axis::choice, kPerTriangle}},
           "a per-triangle choice chooses between gouraud and the segments of combined:K|auto (combined:0 is phong)"),
    refuse({{Axis::method, kAll & ~kCombined}, {Axis::highlight, kOn}},
           "the highlight test is modeled in the combined method (combined:0 is phong)"),
    refuse({{Axis::division, kPerSpan}, {Axis::arith, kFloat}},
           "a division per span divides fixed-point span registers: it needs fixed arithmetic"),
    refuse({{Axis::division, kPerSpan}, {Axis::unit, kSierpinski | kInterleaveOwn}},
           "this unit's increments come from setup's plane, not from a division per span"),
    refuse({{Axis::plan, kPlanned}, {Axis::method, kCombined}},
           "combined's span walk has no planned depth pass"),
    refuse({{Axis::plan, kPlanned}, {Axis::coverage, kDda}}, "dda's spans come from a row table the plan does not carry"),
    refuse({{Axis::plan, kPlanned}, {Axis::unit, kSierpinski}},
           "the plan does not model the extra triangulation (its records are sub-triangle copies)"),
    refuse({{Axis::plan, kPlanned}, {Axis::devices, kBands}},
           "planned units run on one device, or on the sub-devices of one (sub:NAME:N), not in bands across devices"),
    refuse({{Axis::plan, kNoPlan}, {Axis::devices, kUnitSubDevices}},
           "sub-devices run a plan's units; without a plan, sub-devices take bands of the frame"),
    // MPI ranks (docs/distributed.md): sort-first ranks take bands of tile rows, sort-last ranks
    // composite the planned frame's depth keys of their share of the triangles.
    refuse({{Axis::plan, kPlanned}, {Axis::devices, kRanksSortFirst}},
           "sort-first ranks take bands of the frame, and a band's plan is not modeled (use --distribute sort-last)"),
    refuse({{Axis::method, kCombined}, {Axis::devices, kRanksSortLast}},
           "sort-last ranks composite the planned frame's depth keys, and combined's span walk has no planned depth "
           "pass (use --distribute sort-first)"),
    refuse({{Axis::coverage, kDda}, {Axis::devices, kRanksSortLast}},
           "sort-last ranks composite the planned frame's depth keys, and dda's row table has no planned depth pass "
           "(use --distribute sort-first)"),
    refuse({{Axis::unit, kSierpinski}, {Axis::devices, kRanksSortLast}},
           "sort-last ranks composite the planned frame's depth keys, and the extra triangulation's sub-triangle "
           "copies have none (use --distribute sort-first)"),
    // The lanes shape (kernels/render_lanes.cl) has the plain frame's passes: coverage, depth and shading per pixel.
    refuse({{Axis::shape, kLanes}, {Axis::unit, kAnyUnit}},
           "the modeled units step span registers along whole spans, and a lanes work-item owns pixels, not spans: "
           "the units (and fixed point, dda coverage and span division, which run on them) have the vector shape only"),
    refuse({{Axis::shape, kLanes}, {Axis::normalize, kPerSpan}},
           "per-span normals are set up once per span, and a lanes work-item owns pixels, not spans: the vector shape "
           "only"),
    refuse({{Axis::shape, kLanes}, {Axis::plan, kPlanned}},
           "the planned depth pass and its resolve are the vector shape's (the lanes shape has no planned pass)"),
    refuse({{Axis::shape, kLanes}, {Axis::devices, kRanksSortLast}},
           "sort-last ranks composite the planned frame's depth keys, which the lanes shape has no pass for (use "
           "--distribute sort-first)"),
};

std::uint8_t unit_value(const FrameConfig& c) { return c.unit_path() ? std::uint8_t(1 + unit_combination_value(c.unit())) : 0; }

}  // namespace

Combination combination_of(const FrameConfig& c, DeviceMode devices) {
  if (devices == DeviceMode::one && c.band_rows >= 0) devices = DeviceMode::bands;  // a device's band of a frame
  Combination k;
  k.value[int(Axis::method)] = std::uint8_t(c.method);
  k.value[int(Axis::unit)] = unit_value(c);
  k.value[int(Axis::arith)] = c.arith.fixed ? 1 : 0;
  k.value[int(Axis::coverage)] = c.dda_coverage ? 1 : 0;
  k.value[int(Axis::division)] = c.division.mode != DIV_CONSTANT ? 1 : 0;
  k.value[int(Axis::normalize)] = c.normalize.kind != NormalizeKind::exact ? 1 : 0;
  k.value[int(Axis::specular)] = c.specular.kind != SpecularKind::exact ? 1 : 0;
  k.value[int(Axis::choice)] = c.combined.rule != TriangleRule::none ? 1 : 0;
  k.value[int(Axis::highlight)] = c.combined.highlight_test ? 1 : 0;
  k.value[int(Axis::plan)] = c.plan ? 1 : 0;
  k.value[int(Axis::devices)] = std::uint8_t(devices);
  k.value[int(Axis::shape)] = std::uint8_t(c.kernel_shape);
  return k;
}

const std::vector<Refusal>& refused_combinations() { return kRefused; }
const char* axis_name(Axis a) { return kAxisNames[int(a)]; }
const std::vector<std::string>& axis_values(Axis a) { return kValues[int(a)]; }

const Refusal* find_refusal(const Combination& c) {
  for (const Refusal& r : kRefused) {
    bool match = true;
    for (int a = 0; a < kAxes && match; ++a) match = (r.mask[a] >> c.value[a]) & 1u;
    if (match) return &r;
  }
  return nullptr;
}

void check_combination(const Combination& c, const ValueNames* names) {
  const Refusal* r = find_refusal(c);
  if (!r) return;
  std::vector<Axis> axes;
  std::string values;
  for (int a = 0; a < kAxes; ++a) {
    if (r->mask[a] == kAll) continue;
    axes.push_back(Axis(a));
    const std::string& value = names && !(*names)[a].empty() ? (*names)[a] : kValues[a][c.value[a]];
    values += (values.empty() ? "" : " with ") + std::string(kAxisNames[a]) + " " + value;
  }
  throw ConfigError(values + ": " + r->reason, axes);
}

std::string describe_combinations() {
  std::ostringstream out;
  out << "Axes and their values:\n";
  for (int a = 0; a < kAxes; ++a) {
    out << "  " << kAxisNames[a] << ":";
    for (const std::string& v : kValues[a]) out << " " << v;
    out << "\n";
  }
  out << "\nRefused (every other combination is modeled):\n";
  for (const Refusal& r : kRefused) {
    std::string pattern;
    for (int a = 0; a < kAxes; ++a) {
      if (r.mask[a] == kAll) continue;
      std::string vals;
      for (std::size_t v = 0; v < kValues[a].size(); ++v)
        if ((r.mask[a] >> v) & 1u) vals += (vals.empty() ? "" : "|") + kValues[a][v];
      pattern += (pattern.empty() ? "" : ", ") + std::string(kAxisNames[a]) + " " + vals;
    }
    out << "  " << pattern << "\n      " << r.reason << "\n";
  }
  // Count the modeled points of the whole product (odometer over the axes); fixed point and dda coverage
  // imply a unit, so "no unit" with either is no point at all.
  std::uint64_t total = 0, modeled = 0;
  Combination c;
  for (;;) {
    const bool exists = !(c.value[int(Axis::unit)] == 0 && (c.value[int(Axis::arith)] || c.value[int(Axis::coverage)]));
    total += exists;
    if (exists && !find_refusal(c)) ++modeled;
    int a = 0;
    while (a < kAxes && ++c.value[a] == kValues[a].size()) c.value[a++] = 0;
    if (a == kAxes) break;
  }
  out << "\n" << modeled << " of " << total << " combinations are modeled.\n"
      << "Fixed-point arithmetic and dda coverage without a unit run on the classic unit.\n";
  return out.str();
}

}  // namespace parashade
