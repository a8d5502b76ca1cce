#pragma once
// tune's search space (docs/tuning.md): named parameters, each with a list of values, the space their
// product. Layout parameters (tile, work_items, kernel_shape, work_group_size, partition, units, batch) never change
// the image (the lanes shape's float Phong may differ from the vector shape's in the last bits on a device whose
// one-lane and sixteen-lane builtins differ: such a point is measured but not verified); shading
// parameters (method, unit, normalize, specular) do. A point the table of combinations refuses
// (combinations.hpp) is skipped and counted; so is a point that varies units or batch where nothing
// reads them (no plan, or a static partition for batch).
#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "parashade/renderer.hpp"

namespace parashade::cli {

struct TuneSpace {
  std::vector<std::string> names;                  // tune_param_names(), in that order
  std::vector<std::vector<std::string>> values;    // per parameter, canonical names (parsed back, named)
};

// One point: an index into each parameter's values.
using TunePoint = std::vector<int>;

// The parameters `--param` takes, in the order of the space (and of Kernel Tuner's cache keys): each is
// named as the render option it sets (tile --tile, work_items --work-items, kernel_shape --kernel-shape,
// work_group_size --work-group-size, partition, cu, batch, method, units, normalize, specular).
const std::vector<std::string>& tune_param_names();
// The layout parameters among them (the cache's params; the image must not change along them).
bool is_layout_param(const std::string& name);
// The parameters whose values are numbers (the others are names).
bool is_number_param(const std::string& name);

// The default space: tile over tile_sizes(); work_items 0, CU, 4 CU, 64 CU; kernel_shape vector and work_group_size
// 0 (the lanes shape is searched when asked: --param kernel_shape=vector,lanes); partition none and every
// strategy; units CU, 2 CU, 4 CU, 16; batch 16, 64, 256; method `method`; unit none; exact normalize and
// specular.
TuneSpace default_tune_space(const std::string& method, int compute_units);

// `--param NAME=V1,V2,...`: NAME's values replaced. A usage error names the parameter and its valid
// values (an unknown name lists the names).
void set_tune_param(TuneSpace& space, const std::string& assignment);

// `base` with the point's parameters applied.
RenderOptions options_at(const TuneSpace& space, const TunePoint& point, const RenderOptions& base);

struct TunePoints {
  std::vector<TunePoint> valid;      // in odometer order, the last parameter fastest
  std::size_t refused = 0;           // refused by the table of combinations
  // units or batch varied where nothing reads them, work_items in the lanes shape (a work-group per tile), or a
  // lanes work-group larger than the tile's pixels
  std::size_t not_applicable = 0;
  std::string refusal_example;       // one refused point and the table's reason, for the summary
};
// Every point of the space, sorted into the three kinds. A point whose values the frame checks refuse
// outside the table (check_frame_config) is a usage error naming the parameters.
TunePoints enumerate_points(const TuneSpace& space, const RenderOptions& base);

// The point's parameters by name, every one: a layout parameter nothing reads is "-".
nlohmann::json point_params(const TuneSpace& space, const TunePoint& point);
// The point of the space with base's own values (the default configuration), or empty when the space
// does not hold them.
TunePoint default_point(const TuneSpace& space, const RenderOptions& base);
// Product of the value counts.
std::size_t space_size(const TuneSpace& space);

// A point's parameters (point_params) as the render options that give it: each parameter is the render
// option of its name (work_items: --work-items), so this is the same text for every parameter; a parameter
// at its "the device's" value (work_items or work_group_size 0) is left out, as render's default.
std::string render_flags(const nlohmann::json& params);

}  // namespace parashade::cli
