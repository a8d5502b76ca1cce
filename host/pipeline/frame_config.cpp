#include "parashade/frame_config.hpp"

#include "parashade/combinations.hpp"

namespace parashade {

void check_frame_config(const FrameConfig& c, DeviceMode devices) {
  // Powers of two from one vector row (TILE_MIN) to TILE_MAX: 16, 32 or 64.
  if (c.tile_size < TILE_MIN || c.tile_size > TILE_MAX || (c.tile_size & (c.tile_size - 1)) != 0)
    throw UsageError("tile size " + std::to_string(c.tile_size) + " is not supported (16, 32 or 64)");
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
