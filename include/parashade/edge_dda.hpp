#pragma once
// The sources' edge-walking rasterization ([Malovanyi 2019, parallel Gouraud] §2.2, §4.3): vertices at integer
// pixel addresses, each edge walked by the line interpolator of the Obidnyk–Petukh algorithm (one pixel
// per clock along the major axis; the evaluation function OF starts at floor(BP/2), gains MP each clock,
// and a minor step is taken when it reaches BP), spans filled between the two chains, intensities
// carried along the edges by the edge increment dI = (I_end - I_start) / BP.
// A host-side study: its coverage is compared with the pixel-centre top-left rule, and its edge
// intensities with the plane through the vertices (the error delta_E of [Malovanyi 2019, parallel Gouraud] §2.2).
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace parashade {

// The pixels of the segment a -> b, a first and b last (BP + 1 of them), with each one's clock index.
std::vector<glm::ivec2> dda_segment(glm::ivec2 a, glm::ivec2 b);

// The triangle's spans filled the sources' way: every pixel of its three edges, and on each row the
// pixels between the leftmost and the rightmost edge pixel of that row: rows[i] = (xl, xr) of row y0 + i.
struct DdaSpans {
  int y0 = 0;
  std::vector<glm::ivec2> rows;
};
DdaSpans dda_spans(glm::ivec2 a, glm::ivec2 b, glm::ivec2 c);

// The same as pixels, row-major, each pixel once.
std::vector<glm::ivec2> dda_fill(glm::ivec2 a, glm::ivec2 b, glm::ivec2 c);

// delta_E along one edge a -> b of the triangle (a, b, c) with vertex intensities ia, ib, ic: the largest
// |edge interpolator value - plane value| over the edge's pixels, and the sources' bound
// |I_b - I_a| / (2 MP_ab).
struct EdgeIntensityError {
  double max_error = 0.0;
  double source_bound = 0.0;
  double plane_bound = 0.0;  // ours: |plane gradient along the minor axis| / 2
  int major = 0, minor = 0;  // BP, MP
};
EdgeIntensityError edge_intensity_error(glm::ivec2 a, glm::ivec2 b, glm::ivec2 c, double ia, double ib, double ic);

}  // namespace parashade
