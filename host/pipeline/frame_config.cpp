#include "parashade/frame_config.hpp"

#include <algorithm>

#include "parashade/combinations.hpp"

namespace parashade {

const char* kernel_shape_name(KernelShape s) { return s == KernelShape::lanes ? "lanes" : "vector"; }

int shape_work_group_size(KernelShape shape, int tile) {
  return shape == KernelShape::lanes ? std::min(LANES_WORK_GROUP_DEFAULT, std::max(1, tile * tile)) : 1;
}

KernelShape parse_kernel_shape(const std::string& text) {
  if (text == "vector") return KernelShape::vector;
  if (text == "lanes") return KernelShape::lanes;
  throw UsageError("unknown kernel shape '" + text + "' (valid: vector, lanes)");
}

std::vector<int> tile_sizes() {
  std::vector<int> sizes;
  for (int t = TILE_MIN; t <= TILE_MAX; t *= 2) sizes.push_back(t);
  return sizes;
}

std::string tile_sizes_text() {
  const std::vector<int> sizes = tile_sizes();
  std::string text;
  for (std::size_t i = 0; i < sizes.size(); ++i)
    text += (i == 0 ? "" : i + 1 == sizes.size() ? " or " : ", ") + std::to_string(sizes[i]);
  return text;
}

void check_frame_config(const FrameConfig& c, DeviceMode devices) {
  const std::vector<int> sizes = tile_sizes();
  if (std::find(sizes.begin(), sizes.end(), c.tile_size) == sizes.end())
    throw UsageError("tile size " + std::to_string(c.tile_size) + " is not supported (" + tile_sizes_text() + ")");
  if (c.plan) check_plan_options(*c.plan);
  ValueNames names;
  names[int(Axis::method)] = c.method == Method::combined ? combined_name(c.combined) : method_name(c.method);
  if (c.unit_path()) names[int(Axis::unit)] = unit_name(c.unit());
  names[int(Axis::arith)] = arith_name(c.arith);
  names[int(Axis::division)] = division_name(c.division);
  names[int(Axis::normalize)] = normalize_name(c.normalize);
  names[int(Axis::specular)] = specular_name(c.specular);
  if (c.combined.rule != TriangleRule::none) names[int(Axis::choice)] = triangle_rule_name(c.combined);
  check_combination(combination_of(c, devices), &names);
}

}  // namespace parashade
