#pragma once
// What the combined method's kernel (kernels/method_combined.h) needs from the host.
#include <string>
#include <vector>

#include <CL/opencl.hpp>

#include "parashade/combined.hpp"
#include "parashade/scene.hpp"

namespace parashade {

// -D options: SEG_AUTO, SEG_K, SEG_K_MAX, HIGHLIGHT_TEST, COMBINED_MIN_WIDTH, TRIANGLE_CHOICE.
std::string combined_kernel_options(const CombinedConfig& c);
// combined:auto without a triangle choice: the limit on the relative normal change per segment of each
// material, from the error budget, into the spare .w of its specular entry (materials[3m+2].w of
// blinn_phong.h's table). With a choice the limit is per triangle (PHONG_PSI_SLOT).
void set_combined_limits(const Scene& s, const CombinedConfig& c, std::vector<cl_float4>& materials);

}  // namespace parashade
