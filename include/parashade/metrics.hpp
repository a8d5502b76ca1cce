#pragma once
// Error of a rendered image against a reference, over the pixels both cover; coverage mismatches and
// front-surface flips (float depth ties, docs/error-bounds.md) are counted separately. Values in 8-bit levels, over the N = 3 x (pixels compared) channel samples:
//   MSE  = sum (I - O)^2 / N
//   NMSE = sum (I - O)^2 / max(sum (I - mean_c(I))^2, N x 1 level^2)   (mean per channel)
//   PSNR = 10 log10(255^2 / MSE)
// NMSE's denominator is the reference's spread, floored at one level^2 per sample: a reference flatter
// than one 8-bit step (an ambient-only box, a constant image) is normalized as if it varied by one level,
// so NMSE is then the MSE in levels^2 and stays finite (it used to be +inf or ~1e29). docs/error-bounds.md.
// Degenerate cases, told apart by `status`:
//   identical         MSE 0: nmse, max_abs, mean_abs 0; psnr_db +inf (unbounded; JSON null, printed "exact")
//   nothing_compared  no pixel covered by both: nmse, psnr_db, max_abs, mean_abs NaN (undefined; JSON null)
// Throws InputError when the image and reference sizes differ.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "parashade/flip.hpp"
#include "parashade/image.hpp"

namespace parashade {

enum class MetricsStatus { compared, identical, nothing_compared };
// "compared", "identical", "nothing compared"
const char* metrics_status_name(MetricsStatus s);

// NMSE's floor on the reference's spread, per channel sample: one 8-bit level, squared.
constexpr double kNmseSpreadFloor = 1.0;

struct ErrorMetrics {
  std::string reference;                 // "ideal <method>" or "exact phong"
  MetricsStatus status = MetricsStatus::compared;
  double nmse = 0.0;
  double psnr_db = 0.0;                  // dB; +inf when identical
  double max_abs = 0.0;                  // levels, largest channel difference
  double mean_abs = 0.0;                 // levels, per channel sample
  std::uint64_t pixels_compared = 0;
  std::uint64_t pixels_over_1_level = 0; // pixels with some channel more than 1 level off
  std::uint64_t coverage_mismatch = 0;   // pixels covered in one image only
  // Pixels where the image shows another front surface than the reference's, where float depth cannot
  // tell them apart (ReferenceImage::depth_ties, front_surface_flips): counted apart, not compared.
  std::uint64_t front_surface_mismatch = 0;
  // LDR-FLIP of the whole frames (flip.hpp), when asked for (render --flip, compare --flip).
  std::optional<FlipFigures> flip;
};

// Uses image.rgb_float when present (the unquantized output), else the 8-bit values.
// One line for people: "NMSE 0.0123, PSNR 40.12 dB, max ..."; never "nan" or "inf" ("PSNR exact",
// "no pixel compared").
std::string describe_error(const ErrorMetrics& e);

// `flipped` (empty, or 1 per pixel where the image kept another front surface than the reference's): those
// pixels are counted in front_surface_mismatch and left out of every other figure.
ErrorMetrics compare_to_reference(const RenderedImage& image, const std::vector<std::uint8_t>& ref_covered,
                                  const std::vector<glm::dvec3>& ref_values, const std::string& reference_name,
                                  const std::vector<std::uint8_t>& flipped = {});

// |reference - image| per channel at `pixel`, in levels, as compare_to_reference counts it (the image's
// float values clamped to [0, 255] when present, else its 8-bit values).
glm::dvec3 channel_errors(const RenderedImage& image, std::size_t pixel, const glm::dvec3& reference);

// Per pixel, the largest of channel_errors: compare_to_reference's max_abs is the largest of these.
// NaN where the image or the reference does not cover the pixel, or `flipped` marks it (not compared).
// Throws InputError when the sizes differ.
std::vector<double> pixel_errors(const RenderedImage& image, const std::vector<std::uint8_t>& ref_covered,
                                 const std::vector<glm::dvec3>& ref_values, const std::vector<std::uint8_t>& flipped = {});

}  // namespace parashade
