#pragma once
// What one frame computes and how the modeled hardware computes it: the method, the shading unit and its
// arithmetic, coverage, the span increment, Phong's normalization and specular model, the combined
// method's choices, the plan of modeled units and the screen tiles. Device-free: the same configuration
// is prepared on the host (prepare_frame), rendered by any device, or only planned (`parashade plan`).
// Which of these combine is one table (combinations.hpp), checked by check_frame_config.
#include <optional>
#include <string>
#include <vector>

#include "parashade/combinations.hpp"
#include "parashade/combined.hpp"
#include "parashade/method.hpp"
#include "parashade/normalization.hpp"
#include "parashade/planner.hpp"
#include "parashade/specular_models.hpp"
#include "parashade/units.hpp"
#include "parashade/kernels/constants.h"

namespace parashade {

// The frame kernel's shape (docs/pipeline.md): vector, a work-item walks whole tiles with explicit 16-lane vectors
// (kernels/render_tiles.cl); lanes, a work-group per tile and a work-item per pixel lane, the lanes made by the
// device's implicit vectorizer or a GPU's wavefront (kernels/render_lanes.cl). The same image; an axis of the table
// of combinations, since the lanes shape has the plain frame's passes only.
enum class KernelShape { vector, lanes };
const char* kernel_shape_name(KernelShape s);
// The work-group `shape` takes when none is given, for tiles of `tile` pixels (0: not chosen yet): vector 1 (a
// work-item walks tiles of its own); lanes LANES_WORK_GROUP_DEFAULT within the tile's pixels. The one rule:
// RenderOptions::group_size and device_work_group_size (which also keeps it within the device's) read it.
int shape_work_group_size(KernelShape shape, int tile);
KernelShape parse_kernel_shape(const std::string& text);  // UsageError naming the valid values

struct FrameConfig {
  Method method = Method::gouraud;
  int tile_size = TILE_DEFAULT;  // screen tile edge in pixels: 16, 32 or 64 (kernels/constants.h)
  // A modeled shading unit (units.hpp): set by `--units`, or classic with a fixed `arith` or DDA coverage
  // (with_implied_unit). Every triangle then goes by whole spans and the frame's modeled clocks are counted.
  std::optional<UnitConfig> units;
  Arithmetic arith;
  SpanDivision division;      // fixed point: the span increment by a division per span
  bool dda_coverage = false;  // the sources' edge-walking coverage instead of pixel centres
  // The frame by U modeled units from the planner's work lists, then a resolve pass (docs/planner.md);
  // the image is the same bytes as without.
  std::optional<PlanOptions> plan;
  // Only tile rows [band_first, band_first + band_rows) are shaded, the rest is background (a device's
  // share of a frame split across devices); band_rows < 0: the whole frame.
  int band_first = 0, band_rows = -1;
  SpecularModel specular;     // Phong: the specular model (kernels/specular_models.h)
  NormalizeMethod normalize;  // Phong: unit normals per span (kernels/normalize_span.h)
  CombinedConfig combined;    // Method::combined: segment length or auto with its error budget
  KernelShape kernel_shape = KernelShape::vector;  // the kernel that shades the frame (--kernel-shape)

  bool span_normalize() const { return method == Method::phong && normalize.kind != NormalizeKind::exact; }
  // The unit path: spans through a modeled unit (explicit, or implied by fixed point or DDA coverage).
  bool unit_path() const { return units.has_value() || arith.fixed || dda_coverage; }
  UnitConfig unit() const { return units.value_or(UnitConfig{}); }
  // The whole frame by the plain path: no unit, plan or split band.
  bool whole_plain_frame() const { return !unit_path() && !plan && band_rows < 0; }
  // combined with a per-triangle choice between Gouraud, segments and Phong
  bool chooses_per_triangle() const { return method == Method::combined && combined.rule != TriangleRule::none; }
  // The sierpinski unit splits every triangle into 4^D sub-triangle records.
  bool splits_triangles() const { return unit_path() && unit().kind == UnitKind::sierpinski; }
};

// The supported screen tile sizes, the powers of two from TILE_MIN to TILE_MAX (kernels/constants.h), in
// increasing order; and as text for help and errors ("16, 32 or 64").
std::vector<int> tile_sizes();
std::string tile_sizes_text();

// Checks the values (tile size, plan limits) and the combination, on `devices`, against the table
// (combinations.hpp). Throws ConfigError naming the values at fault, never a command-line flag.
void check_frame_config(const FrameConfig& c, DeviceMode devices = DeviceMode::one);

}  // namespace parashade
