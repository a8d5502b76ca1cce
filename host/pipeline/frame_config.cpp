#include "parashade/frame_config.hpp"

#include "parashade/combinations.hpp"

namespace parashade {

void check_frame_config(const FrameConfig& c, DeviceMode devices) {
  if (c.tile_size != 16 && c.tile_size != 32 && c.tile_size != 64)
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
