#pragma once
// What combines: one table of the modeled combinations of method x unit x arithmetic x coverage x span
// division x normalization x specular model x combined choices x plan x device mode x kernel shape. Every choice is a
// value on an axis; the table lists the refused patterns, each with its reason, and everything it does
// not refuse is modeled. check_frame_config checks a configuration against it once; `parashade
// combinations` prints it (the CLI's help says where to look).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "parashade/errors.hpp"

namespace parashade {

struct FrameConfig;

enum class Axis { method, unit, arith, coverage, division, normalize, specular, choice, highlight, plan, devices, shape };
constexpr int kAxes = 12;

// How a frame is spread over devices: one device; bands of tile rows over a device list or over
// sub-devices (split_renderer.hpp); or the units' depth pass of a plan over sub-devices (docs/planner.md);
// or MPI ranks, sort-first (bands) or sort-last (shares of the triangles, depth keys composited;
// docs/distributed.md).
enum class DeviceMode { one, bands, unit_sub_devices, ranks_sort_first, ranks_sort_last };

// A configuration as a point on the axes: per axis the index of its value (axis_values).
struct Combination {
  std::uint8_t value[kAxes] = {};
};

Combination combination_of(const FrameConfig& c, DeviceMode devices = DeviceMode::one);

// A refused pattern: per axis a mask of the values it covers (bit i: value i); a combination matches when
// every axis's value is in the mask.
struct Refusal {
  std::uint32_t mask[kAxes];
  const char* reason;
};

const std::vector<Refusal>& refused_combinations();
const char* axis_name(Axis a);
const std::vector<std::string>& axis_values(Axis a);  // value names, by index

// The first refusal matching `c`, or null.
const Refusal* find_refusal(const Combination& c);

// A combination the table refuses. Names the values at fault (in the library's words, not command-line
// flags) and which axes they are on, so a front end can name its own options.
struct ConfigError : UsageError {
  ConfigError(const std::string& message, std::vector<Axis> axes) : UsageError(message), axes(std::move(axes)) {}
  std::vector<Axis> axes;
};

// Throws ConfigError if the table refuses `c`: "unit sierpinski:1 with coverage dda: the copies need ...",
// naming each value by `names` where given (the configuration's own spelling, e.g. "sierpinski:1"), else
// by its axis value.
using ValueNames = std::array<std::string, kAxes>;
void check_combination(const Combination& c, const ValueNames* names = nullptr);

// The table as text: the axes with their values, then each refused pattern and its reason, then how many
// of the combinations are modeled.
std::string describe_combinations();

}  // namespace parashade
