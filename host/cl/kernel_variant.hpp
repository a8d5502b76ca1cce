#pragma once
// Which build of render_tiles.cl a frame needs (DESIGN: specialize, don't branch): every compile-time
// choice as a field, turned into the -D options in one place. The program cache is keyed by the options.
#include <string>

#include "parashade/renderer.hpp"
#include "parashade/scene.hpp"

namespace parashade {

struct KernelVariant {
  Method method = Method::gouraud;
  int tile = 16;
  int num_lights = 0;
  unsigned point_lights = 0;  // bit i: light i is a point light
  bool local_viewer = false;
  bool need_position = false;  // point lights or a local viewer: per-pixel positions
  bool float_output = false;
  // Phong's specular model (0: exact) and per-span normalization (0: exact per pixel)
  SpecularModel specular;
  bool span_normalize = false;
  NormalizeMethod normalize;
  // combined
  bool combined = false;
  CombinedConfig combined_config;
  // the unit path
  bool unit_path = false;
  UnitConfig unit;
  Arithmetic arith;
  SpanDivision division;
  bool dda_coverage = false;
  // planned frames: 1 the units' depth pass, 2 the resolve; dynamic: units pull batches from a counter
  int plan_pass = 0;
  bool plan_dynamic = false;
  bool stamps = false;  // asked for; used where the kernel has them (stamps_apply)
  int defer_min_triangles = 0;  // Phong's and the combined method's stamps: RenderOptions::deferral_threshold()
  std::string kernel_defines;  // RenderOptions::kernel_defines, appended to the build options

  // 4x4 stamps: the plain path only (no unit, per-span normalization, plan or float read-back), for Phong,
  // Gouraud, flat and the combined method (its segment walk reads and writes the stamps a row at a time), where
  // they pay (docs/pipeline.md).
  bool stamps_apply() const;
  // Phong and the combined method on the stamps shade a tile of at least defer_min_triangles triangles after its
  // walk (the combined method's Gouraud and segment triangles in the walk, its Phong ones after).
  bool defers_tiles() const;

  std::string build_options() const;
};

KernelVariant kernel_variant(const Scene& s, const RenderOptions& o);
// The kernel sources of a variant, in include order.
std::vector<std::string> kernel_files(const KernelVariant& v);

}  // namespace parashade
