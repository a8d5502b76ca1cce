#include "parashade/combined_kernel.hpp"

#include <algorithm>
#include <sstream>

namespace parashade {

std::string combined_kernel_options(const CombinedConfig& c) {
  std::ostringstream opt;
  opt << " -D SEG_AUTO=" << (c.automatic ? 1 : 0) << " -D SEG_K=" << c.k << " -D SEG_K_MAX=" << kCombinedMaxK
      << " -D HIGHLIGHT_TEST=" << (uses_highlight_mask(c) ? 1 : 0) << " -D COMBINED_MIN_WIDTH=" << combined_min_width(c)
      << " -D TRIANGLE_CHOICE=" << (c.rule != TriangleRule::none ? 1 : 0);
  return opt.str();
}


void set_combined_limits(const Scene& s, const CombinedConfig& c, std::vector<cl_float4>& materials) {
  for (std::size_t m = 0; m < s.materials.size() && 3 * m + 2 < materials.size(); ++m)
    materials[3 * m + 2].s[3] =
        c.automatic && c.rule == TriangleRule::none ? float(psi_limit(s, s.materials[m], combined_shading_budget(c))) : 0.0f;
}

}  // namespace parashade
