#pragma once
// LDR-FLIP (ꟻLIP): NVIDIA's perceptual difference of two low-dynamic-range images, per pixel in [0, 1]
// (Andersson, Nilsson, Akenine-Möller, Oskarsson, Åström and Fairchild, "FLIP: A Difference Evaluator for
// Alternating Images", HPG 2020), written here from the paper's definition: the images in YCxCz, filtered by
// the contrast sensitivity functions of an observer at `ppd` pixels per degree, compared in Hunt-adjusted
// CIELab by the HyAB distance (colour pipeline), and their edges and points compared by Gaussian derivative
// filters (feature pipeline); the error is colour^(1 - feature). Border pixels repeat the edge (as the
// reference implementation does). Checked against NVIDIA's `flip-evaluator` package (tests/scripts/
// flip_agreement_test.py; docs/pictures.md gives the figures). Render and compare report its mean.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "parashade/image.hpp"

namespace parashade {

// FLIP's default observer: a 0.7 m wide monitor of 3840 pixels seen from 0.7 m, in pixels per degree.
constexpr double kFlipDefaultPpd = 0.7 * (3840.0 / 0.7) * (3.14159265358979323846 / 180.0);  // 67.02

// Per pixel, the LDR-FLIP error in [0, 1] of `test` against `reference`: width x height pixels, 3
// sRGB-encoded values in [0, 1] each (row 0 at the top; values outside [0, 1] are clamped). Float
// arithmetic, in bands of rows on the host threads (parallel.hpp). Throws InputError when a size differs
// from width x height x 3 or `ppd` is not positive.
std::vector<float> ldr_flip(const std::vector<float>& reference, const std::vector<float>& test, int width, int height,
                            double ppd = kFlipDefaultPpd);

// Bytes ldr_flip allocates beyond its inputs and its map for a width x height image: its bands of rows in
// flight at once (one per host thread, parallel.hpp, each of 20 float planes over the band and its filters'
// reach, and 14 float rows), from the same band height and filter radius ldr_flip takes. For the host memory
// budget (memory_budget.hpp): 4096 wide on 2 threads about 180 MB, on 16 threads about 1.3 GB.
std::uint64_t ldr_flip_working_bytes(int width, int height, double ppd = kFlipDefaultPpd);

// The figures a report gives of a FLIP map: its mean (summed in double) and largest value.
struct FlipFigures {
  double mean = 0.0;
  double max = 0.0;
  double ppd = kFlipDefaultPpd;
};
FlipFigures flip_figures(const std::vector<float>& map, double ppd = kFlipDefaultPpd);

// FLIP's inputs: an image's display values / 255 (its float values, clamped to [0, 255], when present,
// else the 8-bit ones, as the metrics read it), or values in levels (a reference), clamped likewise.
std::vector<float> flip_input(const RenderedImage& image);
std::vector<float> flip_input(const std::vector<glm::dvec3>& levels);

// Magma (matplotlib's, CC0), the colour map FLIP's own tools draw their maps in: entry round(255 x error).
extern const std::uint8_t kMagma[256][3];

// An RGB picture of a FLIP map (alpha 255): magma, linear from 0 to 1, the map's own size.
RenderedImage flip_map_image(const std::vector<float>& map, int width, int height);

}  // namespace parashade
