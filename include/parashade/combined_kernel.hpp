#pragma once
// What the combined method's kernel (kernels/method_combined.h) needs from the host.
#include <string>
#include <vector>

#include <CL/opencl.hpp>

#include "parashade/combined.hpp"
#include "parashade/scene.hpp"

namespace parashade {

// -D options: SEG_AUTO, SEG_K, SEG_K_MAX, HIGHLIGHT_TEST, COMBINED_MIN_WIDTH.
std::string combined_kernel_options(const CombinedConfig& c);
// Triangles narrower than this (bounding box, pixels) are shaded by Phong per pixel.
int combined_min_width(const CombinedConfig& c);
// combined:auto: the limit on the relative normal change per segment of each material, from the
// error budget, into the spare .w of its specular entry (materials[3m+2].w of blinn_phong.h's table).
void set_combined_limits(const Scene& s, const CombinedConfig& c, std::vector<cl_float4>& materials);
// The shading error allowed to the segments: the budget minus the 8-bit image's rounding (0.5 level).
double combined_shading_budget(const CombinedConfig& c);

}  // namespace parashade
