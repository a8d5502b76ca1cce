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

}  // namespace

KernelVariant kernel_variant(const Scene& s, const RenderOptions& o) {
  KernelVariant v;
  v.method = o.method;
  v.tile = o.tile_size;
  v.num_lights = int(s.lights.size());
  for (std::size_t i = 0; i < s.lights.size(); ++i)
    if (s.lights[i].type == LightType::point) v.point_lights |= 1u << i;
  v.local_viewer = s.viewer_is_local();
  v.need_position = v.local_viewer || v.point_lights != 0;
  v.float_output = o.float_output;
  v.specular = o.specular;
  v.span_normalize = o.span_normalize();
  v.normalize = o.normalize;
  v.combined = o.method == Method::combined;
  v.combined_config = o.combined;
  v.unit_path = o.unit_path();
  v.unit = o.unit();
  v.arith = o.arith;
  v.division = o.division;
  v.dda_coverage = o.dda_coverage;
  v.stamps = o.stamps;
  v.defer_min_triangles = o.deferral_threshold();
  v.kernel_defines = o.kernel_defines;
  return v;
}

std::vector<std::string> kernel_files(const KernelVariant& v) {
  return {"common.h", "triangle_record.h", method_header(v.method), "render_tiles.cl"};
}

bool KernelVariant::defers_tiles() const { return stamps_apply() && (method == Method::phong || combined); }

bool KernelVariant::stamps_apply() const {
  // Every method has them on the plain path (the combined method's segment walk reads and writes the stamps'
  // lanes a row at a time, combined_walk.h).
  return stamps && !unit_path && !span_normalize && plan_pass == 0 && !float_output;
}

std::string KernelVariant::build_options() const {
  std::ostringstream opt;
  opt << "-D TILE=" << tile << " -D NUM_LIGHTS=" << num_lights << " -D POINT_LIGHTS=" << point_lights
      << " -D LOCAL_VIEWER=" << (local_viewer ? 1 : 0) << " -D NEED_POSITION=" << (need_position ? 1 : 0)
      << " -D OUTPUT_FLOAT=" << (float_output ? 1 : 0) << " -D UNIT_PATH=" << (unit_path ? 1 : 0);
  if (specular.kind != SpecularKind::exact) {
    const int model = specular.kind == SpecularKind::quadratic  ? 3
                      : specular.kind == SpecularKind::sevenths ? 4
                                                                : 1;
    opt << " -D SPECULAR_MODEL=" << model << " -D SPECULAR_K=" << specular.k << " -D SPECULAR_P="
        << std::to_string(specular.p) << "f -D SPECULAR_P_IS_2=" << (specular.p == 2.0 ? 1 : 0);
  }
  if (span_normalize) {
    switch (normalize.kind) {
      case NormalizeKind::slerp: opt << " -D NORMALIZE_METHOD=1"; break;
      case NormalizeKind::quadratic: opt << " -D NORMALIZE_METHOD=2 -D NORMALIZE_MID=" << int(normalize.mid); break;
      case NormalizeKind::dichotomy:
        opt << " -D NORMALIZE_METHOD=3 -D NORMALIZE_BISECTOR=" << int(normalize.bisector)
            << " -D NORMALIZE_SEGMENT_LOG2=" << normalize.segment_log2
            << " -D NORMALIZE_EXTRAPOLATE=" << (normalize.extrapolate_last ? 1 : 0);
        break;
      case NormalizeKind::recurrence:
        opt << " -D NORMALIZE_METHOD=4 -D NORMALIZE_ARCCOS=" << int(normalize.arccos)
            << " -D NORMALIZE_REANCHOR=" << normalize.reanchor
            << " -D NORMALIZE_DIFFERENCE=" << (normalize.difference_form ? 1 : 0);
        break;
      case NormalizeKind::exact: break;
    }
  }
  if (combined) {
    const CombinedConfig& c = combined_config;
    opt << " -D SEG_AUTO=" << (c.automatic ? 1 : 0) << " -D SEG_K=" << c.k << " -D SEG_K_MAX=" << kCombinedMaxK
        << " -D HIGHLIGHT_TEST=" << (uses_highlight_mask(c) ? 1 : 0)
        << " -D COMBINED_MIN_WIDTH=" << combined_min_width(c)
        << " -D TRIANGLE_CHOICE=" << (c.rule != TriangleRule::none ? 1 : 0);
  }
  if (unit_path) {
    opt << " -D UNIT_KIND=" << int(unit.kind) << " -D UNIT_LANES=" << unit.lanes
        << " -D UNIT_OWN_STEP=" << (unit.own_step ? 1 : 0) << " -D FIXED=" << (arith.fixed ? 1 : 0)
        << " -D FRAC_BITS=" << arith.frac_bits << " -D REG_BITS=" << arith.width() << " -D SPAN_DIV=" << division.mode
        << " -D DIV_BITS=" << division.bits << " -D DIV_NEAREST=" << (division.nearest ? 1 : 0)
        << " -D DDA_COVERAGE=" << (dda_coverage ? 1 : 0)
        << " -D UNIT_REGISTER_COLOUR=" << (method == Method::gouraud ? 1 : 0);
  }
  if (stamps_apply()) opt << " -D STAMPS=1";
  if (defers_tiles())
    opt << " -D DEFER_STAMPS=1 -D DEFER_MIN_TRIANGLES=" << defer_min_triangles;
  if (plan_pass == 1) opt << " -D PLAN_PASS=1 -D PLAN_DYNAMIC=" << (plan_dynamic ? "1" : "0");
  if (plan_pass == 2) opt << " -D PLAN_PASS=2";
  if (!kernel_defines.empty()) opt << " " << kernel_defines;
  return opt.str();
}

}  // namespace parashade
