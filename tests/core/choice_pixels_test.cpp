// Visible pixels per chosen method (choice_pixels.hpp): counted by the visible triangle's method, pixels
// without a triangle left out, a visible triangle without a choice refused.
#include <stdexcept>

#include <gtest/gtest.h>

#include "parashade/choice_pixels.hpp"

namespace parashade {
namespace {

std::vector<TriangleShading> methods(std::initializer_list<TriangleMethod> m) {
  std::vector<TriangleShading> out;
  for (TriangleMethod x : m) out.push_back({x, 0u, 0.0f});
  return out;
}

TEST(ChoicePixels, CountsEachVisiblePixelByItsTrianglesMethod) {
  const auto choice = methods({TriangleMethod::phong, TriangleMethod::gouraud, TriangleMethod::segments,
                               TriangleMethod::gouraud});
  // Triangle 3 is chosen but hidden: it counts nowhere.
  const std::vector<std::int32_t> visible = {-1, 0, 1, 1, 2, -1, 2, 2, 0, 1};
  const ChoicePixels p = visible_pixels_by_method(visible, choice);
  EXPECT_EQ(p.phong, 2u);
  EXPECT_EQ(p.gouraud, 3u);
  EXPECT_EQ(p.segments, 3u);
}

TEST(ChoicePixels, EmptyImageHasNoPixels) {
  const ChoicePixels p = visible_pixels_by_method({-1, -1}, {});
  EXPECT_EQ(p.phong + p.gouraud + p.segments, 0u);
}

TEST(ChoicePixels, VisibleTriangleWithoutChoiceIsRefused) {
  EXPECT_THROW(visible_pixels_by_method({0, 2}, methods({TriangleMethod::phong, TriangleMethod::gouraud})),
               std::invalid_argument);
}

}  // namespace
}  // namespace parashade
