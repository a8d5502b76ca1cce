// The reference rasterizer's coverage: pixel-centre sampling with the top-left rule, watertight on
// shared edges and shared vertices, clamped to the screen.
#include <gtest/gtest.h>

#include <cstdint>
#include <stdexcept>
#include <vector>

#include "parashade/reference.hpp"
#include "screen_fixtures.hpp"

namespace parashade {
namespace {

using test_fixtures::centre;
using test_fixtures::coverage_counts;
using test_fixtures::GeometryBuilder;
using test_fixtures::simple_scene;

glm::ivec2 at_centre(int i, int j) { return {centre(i), centre(j)}; }

bool covered(const ReferenceImage& r, int x, int y) { return r.covered[std::size_t(y) * r.width + x] != 0; }

// Expects exactly one hit on [x0, x1) x [y0, y1) and none elsewhere.
void expect_covered_once_in(const std::vector<int>& hits, int width, int height, int x0, int x1, int y0,
                            int y1) {
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const bool inside = x >= x0 && x < x1 && y >= y0 && y < y1;
      EXPECT_EQ(hits[std::size_t(y) * width + x], inside ? 1 : 0) << "pixel (" << x << ", " << y << ")";
    }
}

TEST(ReferenceCoverage, SquareSplitAlongEitherDiagonalCoversEachPixelOnce) {
  // Corners on pixel centres: the diagonal and all four sides pass exactly through pixel centres.
  for (const bool main_diagonal : {true, false}) {
    GeometryBuilder b(10, 10);
    const auto p0 = b.vertex(at_centre(1, 1)), p1 = b.vertex(at_centre(8, 1));
    const auto p2 = b.vertex(at_centre(8, 8)), p3 = b.vertex(at_centre(1, 8));
    if (main_diagonal) {
      b.triangle(p0, p1, p2);
      b.triangle(p0, p2, p3);
    } else {
      b.triangle(p0, p1, p3);
      b.triangle(p1, p2, p3);
    }
    // Top and left sides belong to the square, bottom and right sides do not.
    expect_covered_once_in(coverage_counts(simple_scene(), b.geometry()), 10, 10, 1, 8, 1, 8);
  }
}

TEST(ReferenceCoverage, SharedEdgeOfSlopeOneHalfThroughCentresIsCoveredOnce) {
  // The shared edge (1,1) -> (9,5) passes through the centres (3,2), (5,3), (7,4).
  GeometryBuilder b(12, 8);
  const auto a = b.vertex(at_centre(1, 1)), c = b.vertex(at_centre(9, 5));
  b.triangle(a, c, b.vertex(at_centre(10, 0)));
  b.triangle(a, c, b.vertex(at_centre(0, 7)));
  const std::vector<int> hits = coverage_counts(simple_scene(), b.geometry());
  for (const int h : hits) EXPECT_LE(h, 1);
  for (const glm::ivec2& p : {glm::ivec2(3, 2), glm::ivec2(5, 3), glm::ivec2(7, 4)})
    EXPECT_EQ(hits[std::size_t(p.y) * 12 + p.x], 1)
        << "centre on the shared edge (" << p.x << ", " << p.y << ")";
}

TEST(ReferenceCoverage, JitteredGridIsWatertight) {
  // A 6x6-cell grid, cells 3 pixels wide; interior vertices jittered by multiples of half a pixel, so
  // many edges and vertices fall exactly on pixel centres. Diagonals alternate.
  constexpr int kCells = 6, kCellPx = 3, kSize = 24, kOrigin = 2;
  GeometryBuilder b(kSize, kSize);
  std::uint32_t state = 12345;
  auto jitter = [&state]() {
    state = state * 1664525u + 1013904223u;
    return int((state >> 16) % 5) - 2;  // -2 .. 2 half pixels
  };
  std::vector<std::uint32_t> id((kCells + 1) * (kCells + 1));
  for (int j = 0; j <= kCells; ++j)
    for (int i = 0; i <= kCells; ++i) {
      glm::ivec2 p = at_centre(kOrigin + kCellPx * i, kOrigin + kCellPx * j);
      if (i > 0 && i < kCells && j > 0 && j < kCells) p += glm::ivec2(jitter(), jitter()) * (kSubpixel / 2);
      id[j * (kCells + 1) + i] = b.vertex(p);
    }
  for (int j = 0; j < kCells; ++j)
    for (int i = 0; i < kCells; ++i) {
      const auto v00 = id[j * (kCells + 1) + i], v10 = id[j * (kCells + 1) + i + 1];
      const auto v01 = id[(j + 1) * (kCells + 1) + i], v11 = id[(j + 1) * (kCells + 1) + i + 1];
      if ((i + j) % 2 == 0) {
        b.triangle(v00, v10, v11);
        b.triangle(v00, v11, v01);
      } else {
        b.triangle(v00, v10, v01);
        b.triangle(v10, v11, v01);
      }
    }
  const int end = kOrigin + kCellPx * kCells;
  expect_covered_once_in(coverage_counts(simple_scene(), b.geometry()), kSize, kSize, kOrigin, end, kOrigin,
                         end);
}

TEST(ReferenceCoverage, FanAroundAVertexOnAPixelCentreCoversItOnce) {
  // Seven triangles around the centre of pixel (8, 8), irregular ring, some ring vertices off-lattice.
  GeometryBuilder b(16, 16);
  const auto hub = b.vertex(at_centre(8, 8));
  const std::vector<glm::ivec2> ring = {at_centre(13, 8),
                                        at_centre(11, 12) + glm::ivec2(37, 0),
                                        at_centre(7, 14),
                                        at_centre(3, 11) - glm::ivec2(0, 91),
                                        at_centre(2, 6),
                                        at_centre(6, 2),
                                        at_centre(12, 3) + glm::ivec2(5, 77)};
  std::vector<std::uint32_t> ids;
  for (const glm::ivec2& p : ring) ids.push_back(b.vertex(p));
  for (std::size_t k = 0; k < ids.size(); ++k) b.triangle(hub, ids[k], ids[(k + 1) % ids.size()]);
  const std::vector<int> hits = coverage_counts(simple_scene(), b.geometry());
  for (const int h : hits) EXPECT_LE(h, 1);
  for (int y = 7; y <= 9; ++y)
    for (int x = 7; x <= 9; ++x)
      EXPECT_EQ(hits[std::size_t(y) * 16 + x], 1) << "pixel (" << x << ", " << y << ")";
}

TEST(ReferenceCoverage, TopAndLeftEdgesAreInsideBottomAndRightEdgesAreNot) {
  const Scene scene = simple_scene();
  {
    // Top edge y = centre(1), left edge x = centre(1), hypotenuse (6,1)-(1,6) runs down-left: a right edge.
    GeometryBuilder b(8, 8);
    b.triangle(b.vertex(at_centre(1, 1)), b.vertex(at_centre(6, 1)), b.vertex(at_centre(1, 6)));
    const ReferenceImage r = render_reference(scene, b.geometry(), Method::flat);
    EXPECT_TRUE(covered(r, 3, 1)) << "centre on a top edge";
    EXPECT_TRUE(covered(r, 1, 3)) << "centre on a left edge";
    EXPECT_TRUE(covered(r, 1, 1)) << "vertex where top and left edges meet";
    EXPECT_FALSE(covered(r, 3, 4)) << "centre on a right edge";
    EXPECT_FALSE(covered(r, 6, 1)) << "vertex on a right edge";
    EXPECT_TRUE(covered(r, 2, 2)) << "interior";
  }
  {
    // Right edge x = centre(6), bottom edge y = centre(6); the hypotenuse (1,6)-(6,1) now is a left edge.
    GeometryBuilder b(8, 8);
    b.triangle(b.vertex(at_centre(6, 1)), b.vertex(at_centre(6, 6)), b.vertex(at_centre(1, 6)));
    const ReferenceImage r = render_reference(scene, b.geometry(), Method::flat);
    EXPECT_FALSE(covered(r, 6, 3)) << "centre on a right edge";
    EXPECT_FALSE(covered(r, 3, 6)) << "centre on a bottom edge";
    EXPECT_TRUE(covered(r, 3, 4)) << "centre on a left edge";
    EXPECT_TRUE(covered(r, 5, 3)) << "interior";
  }
}

TEST(ReferenceCoverage, CentresOffTheEdgeBySubpixelFollowTheEdgeFunctionSign) {
  // A near-horizontal top edge 1/256 pixel below row 2's centres: row 2 is outside, row 3 inside.
  GeometryBuilder b(8, 8);
  b.triangle(b.vertex({centre(0), centre(2) + 1}), b.vertex({centre(7), centre(2) + 1}),
             b.vertex(at_centre(0, 7)));
  const ReferenceImage r = render_reference(simple_scene(), b.geometry(), Method::flat);
  EXPECT_FALSE(covered(r, 2, 2));
  EXPECT_TRUE(covered(r, 2, 3));
}

TEST(ReferenceCoverage, TrianglesInTheGuardBandAreClampedToTheScreen) {
  GeometryBuilder b(7, 5);
  b.triangle(b.vertex({-7 * kSubpixel, -5 * kSubpixel}), b.vertex({4 * 7 * kSubpixel, -5 * kSubpixel}),
             b.vertex({-7 * kSubpixel, 4 * 5 * kSubpixel}));
  const ReferenceImage r = render_reference(simple_scene(), b.geometry(), Method::flat);
  for (const std::uint8_t c : r.covered) EXPECT_EQ(c, 1);
  for (const std::int32_t t : r.triangle) EXPECT_EQ(t, 0);
}

TEST(ReferenceCoverage, ZeroAreaCoversNothingAndWrongOrderIsRejected) {
  const Scene scene = simple_scene();
  GeometryBuilder flat(8, 8);
  flat.triangle(flat.vertex(at_centre(1, 1)), flat.vertex(at_centre(3, 3)), flat.vertex(at_centre(5, 5)));
  const ReferenceImage r = render_reference(scene, flat.geometry(), Method::flat);
  for (const std::uint8_t c : r.covered) EXPECT_EQ(c, 0);

  GeometryBuilder b(8, 8);
  b.triangle(b.vertex(at_centre(1, 1)), b.vertex(at_centre(6, 1)), b.vertex(at_centre(1, 6)));
  ScreenGeometry reversed = b.geometry();
  std::swap(reversed.triangles[0].y, reversed.triangles[0].z);
  EXPECT_THROW(render_reference(scene, reversed, Method::flat), std::invalid_argument);
}

}  // namespace
}  // namespace parashade
