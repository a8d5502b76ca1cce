#include "kernel_variant.hpp"

#include <sstream>

namespace parashade {
namespace {

const char* method_header(Method m) {
  switch (m) {
    case Method::flat: return "method_flat.h";
    case Method::gouraud: return "method_gouraud.h";
    case Method::phong: return "method_phong.h";
    case Method::combined: return "method_combined.h";
  }
  return "";
}

// Per-span normalization's method and its parameters.
std::string normalize_defines(const NormalizeMethod& n) {
  std::ostringstream opt;
  switch (n.kind) {
    case NormalizeKind::slerp: opt << " -D NORMALIZE_METHOD=1"; break;
    case NormalizeKind::quadratic: opt << " -D NORMALIZE_METHOD=2 -D NORMALIZE_MID=" << int(n.mid); break;
    case NormalizeKind::dichotomy:
      opt << " -D NORMALIZE_METHOD=3 -D NORMALIZE_BISECTOR=" << int(n.bisector)
          << " -D NORMALIZE_SEGMENT_LOG2=" << n.segment_log2 << " -D NORMALIZE_EXTRAPOLATE=" << (n.extrapolate_last ? 1 : 0);
      break;
    case NormalizeKind::recurrence:
      opt << " -D NORMALIZE_METHOD=4 -D NORMALIZE_ARCCOS=" << int(n.arccos) << " -D NORMALIZE_REANCHOR=" << n.reanchor
          << " -D NORMALIZE_DIFFERENCE=" << (n.difference_form ? 1 : 0);
      break;
    case NormalizeKind::exact: break;
  }
  return opt.str();
}

}  // namespace

KernelVariant kernel_variant(const RenderOptions& o) {
  KernelVariant v;
  v.options = o;
  return v;
}

bool KernelVariant::set_scene(const Scene& s) {
  unsigned point = 0;
  for (std::size_t i = 0; i < s.lights.size(); ++i)
    if (s.lights[i].type == LightType::point) point |= 1u << i;
  const bool local = s.viewer_is_local(), changed = num_lights != int(s.lights.size()) || point_lights != point ||
                                                    local_viewer != local;
  num_lights = int(s.lights.size());
  point_lights = point;
  local_viewer = local;
  return changed;
}

KernelVariant kernel_variant(const Scene& s, const RenderOptions& o) {
  KernelVariant v = kernel_variant(o);
  v.set_scene(s);
  return v;
}

std::vector<std::string> kernel_files(const KernelVariant& v) {
  return {"common.h", "triangle_record.h", method_header(v.options.method),
          v.options.kernel_shape == KernelShape::lanes ? "render_lanes.cl" : "render_tiles.cl"};
}

bool KernelVariant::defers_tiles() const {
  return stamps_apply() && (options.method == Method::phong || options.method == Method::combined);
}

bool KernelVariant::stamps_apply() const {
  // Every method has them on the plain path (the combined method's segment walk reads and writes the stamps'
  // lanes a row at a time, combined_walk.h); the lanes shape has a layout of its own.
  return options.stamps && plain_frame() && options.kernel_shape == KernelShape::vector;
}

std::string KernelVariant::build_options() const {
  const RenderOptions& o = options;
  std::ostringstream opt;
  opt << "-D TILE=" << o.tile_size << " -D NUM_LIGHTS=" << num_lights << " -D POINT_LIGHTS=" << point_lights
      << " -D LOCAL_VIEWER=" << (local_viewer ? 1 : 0) << " -D NEED_POSITION=" << (need_position() ? 1 : 0)
      << " -D OUTPUT_FLOAT=" << (o.float_output ? 1 : 0) << " -D UNIT_PATH=" << (o.unit_path() ? 1 : 0);
  if (o.specular.kind != SpecularKind::exact) {
    const int model = o.specular.kind == SpecularKind::quadratic  ? 3
                      : o.specular.kind == SpecularKind::sevenths ? 4
                                                                  : 1;
    opt << " -D SPECULAR_MODEL=" << model << " -D SPECULAR_K=" << o.specular.k << " -D SPECULAR_P="
        << std::to_string(o.specular.p) << "f -D SPECULAR_P_IS_2=" << (o.specular.p == 2.0 ? 1 : 0);
  }
  if (o.span_normalize()) opt << normalize_defines(o.normalize);
  if (o.method == Method::combined) {
    const CombinedConfig& c = o.combined;
    opt << " -D SEG_AUTO=" << (c.automatic ? 1 : 0) << " -D SEG_K=" << c.k << " -D SEG_K_MAX=" << kCombinedMaxK
        << " -D HIGHLIGHT_TEST=" << (uses_highlight_mask(c) ? 1 : 0)
        << " -D COMBINED_MIN_WIDTH=" << combined_min_width(c)
        << " -D TRIANGLE_CHOICE=" << (c.rule != TriangleRule::none ? 1 : 0);
  }
  if (o.unit_path()) {
    const UnitConfig unit = o.unit();
    opt << " -D UNIT_KIND=" << int(unit.kind) << " -D UNIT_LANES=" << unit.lanes
        << " -D UNIT_OWN_STEP=" << (unit.own_step ? 1 : 0) << " -D FIXED=" << (o.arith.fixed ? 1 : 0)
        << " -D FRAC_BITS=" << o.arith.frac_bits << " -D REG_BITS=" << o.arith.width()
        << " -D SPAN_DIV=" << o.division.mode << " -D DIV_BITS=" << o.division.bits
        << " -D DIV_NEAREST=" << (o.division.nearest ? 1 : 0) << " -D DDA_COVERAGE=" << (o.dda_coverage ? 1 : 0)
        << " -D UNIT_REGISTER_COLOUR=" << (o.method == Method::gouraud ? 1 : 0);
  }
  if (stamps_apply()) opt << " -D STAMPS=1";
  if (defers_tiles()) opt << " -D DEFER_STAMPS=1 -D DEFER_MIN_TRIANGLES=" << o.deferral_threshold();
  if (plan_pass == 1) opt << " -D PLAN_PASS=1 -D PLAN_DYNAMIC=" << (plan_dynamic ? "1" : "0");
  if (plan_pass == 2) opt << " -D PLAN_PASS=2";
  // The shape, and the local size where it is not the vector shape's 1 (kept out of the default build's options).
  if (o.kernel_shape == KernelShape::lanes) opt << " -D KERNEL_SHAPE=1";
  if (o.kernel_shape == KernelShape::lanes || o.group_size() != 1) opt << " -D WORK_GROUP_SIZE=" << o.group_size();
  if (!o.kernel_defines.empty()) opt << " " << o.kernel_defines;
  return opt.str();
}

}  // namespace parashade
