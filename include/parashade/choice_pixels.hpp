#pragma once
// Visible pixels per method of the combined method's per-triangle choice: the share of the image each
// method shades. The kernel's cost follows the pixels, not the triangles (a few large triangles under a
// highlight can hold a third of the image), so this is what a model of the combined frame needs
// (scripts/combined_study.py's ceiling, docs/triangle-choice.md §7).
#include <cstdint>
#include <vector>

#include "parashade/triangle_choice.hpp"

namespace parashade {

struct ChoicePixels {
  std::uint64_t gouraud = 0;
  std::uint64_t segments = 0;
  std::uint64_t phong = 0;  // Phong per pixel
};

// Counts the pixels whose visible triangle (`visible`: a screen triangle index per pixel, -1 where none,
// as ReferenceImage::triangle) the choice gives to each method. Throws std::invalid_argument when an index
// has no choice (the visibility and the choice come from different geometry).
ChoicePixels visible_pixels_by_method(const std::vector<std::int32_t>& visible,
                                      const std::vector<TriangleShading>& choice);

}  // namespace parashade
