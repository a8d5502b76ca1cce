#pragma once
// Highlight-presence test ([Dembitsky 2025, software/hardware rendering] ch. 3): may a triangle show a specular highlight? Its shaded normals are
// normalized interpolations of its vertex normals, so they lie in the spherical triangle of the unit
// vertex normals (for barycentric weights >= 0). With a directional light and a distant viewer H is
// constant, and the largest N.H over that spherical triangle bounds the specular term.
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "parashade/light_bounds.hpp"
#include "parashade/scene.hpp"
#include "parashade/screen_geometry.hpp"

namespace parashade {

struct HighlightMarks {
  std::uint64_t triangles = 0;           // triangles tested
  std::uint64_t without_highlight = 0;   // no light's specular term can reach `negligible` levels
  std::uint64_t light_terms_skipped = 0; // (triangle, light) pairs whose specular term is skipped
};

// For every screen triangle t, writes into attributes[t * stride + slot] the bit mask of the lights whose
// specular term must be evaluated: light l is left out when 255 * max_c(I_l,c k_s,c) * max(0, N.H)^n
// <= negligible_levels for every shaded normal N and halfway vector H of the triangle. For point lights
// and a local viewer H varies: it stays within a cone around H_c from the vertices' L and V cones
// (docs/combined.md §5).
HighlightMarks mark_highlights(const Scene& s, const ScreenGeometry& g, float* attributes, std::size_t stride, int slot,
                               double negligible_levels);

// The largest N.H at which light l's specular term on material m stays <= negligible_levels (8-bit
// levels, largest channel); 1 when it never exceeds them.
double negligible_cosine(const Light& l, const Material& m, double negligible_levels);
// negligible_cosine for every (material, light), light-major within a material: [m * lights + l].
std::vector<double> negligible_cosines(const Scene& s, double negligible_levels);

}  // namespace parashade
