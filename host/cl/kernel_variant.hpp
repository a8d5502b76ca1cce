#pragma once
// Which build of render_tiles.cl a frame needs (DESIGN: specialize, don't branch): every compile-time
// choice as a field, turned into the -D options in one place. The program cache is keyed by the options.
#include <string>

#include "parashade/renderer.hpp"
#include "parashade/scene.hpp"

namespace parashade {

struct KernelVariant {
  // The renderer's options, the one copy of every knob the kernel reads: build_options turns each into
  // its -D (a new knob: its RenderOptions field and its line there).
  RenderOptions options;
  // The scene's part (set_scene): its lights and viewer.
  int num_lights = 0;
  unsigned point_lights = 0;  // bit i: light i is a point light
  bool local_viewer = false;
  // planned frames: 1 the units' depth pass, 2 the resolve; dynamic: units pull batches from a counter
  int plan_pass = 0;
  bool plan_dynamic = false;

  bool need_position() const { return local_viewer || point_lights != 0; }  // per-pixel positions
  // The plain frame: no unit, per-span normalization, plan pass or float read-back. The kernel derives the
  // same from its macros (PLAIN_FRAME, kernels/tile_paths.h) and refuses STAMPS off it; a test ties the two.
  bool plain_frame() const {
    return !options.unit_path() && !options.span_normalize() && plan_pass == 0 && !options.float_output;
  }
  // 4x4 stamps: the plain frame only, for Phong, Gouraud, flat and the combined method (its segment walk reads
  // and writes the stamps a row at a time), where they pay (docs/pipeline.md).
  bool stamps_apply() const;
  // Phong and the combined method on the stamps shade a tile of at least RenderOptions::deferral_threshold()
  // triangles after its walk (the combined method's Gouraud and segment triangles in the walk, its Phong ones
  // after).
  bool defers_tiles() const;

  std::string build_options() const;

  // The scene's part: its lights and viewer. Returns whether anything changed (the kernel must be rebuilt).
  bool set_scene(const Scene& s);
};

// The options' part of a renderer's variant, built once per renderer; set_scene adds the scene's.
KernelVariant kernel_variant(const RenderOptions& o);
// Both parts at once.
KernelVariant kernel_variant(const Scene& s, const RenderOptions& o);
// The kernel sources of a variant, in include order.
std::vector<std::string> kernel_files(const KernelVariant& v);

}  // namespace parashade
