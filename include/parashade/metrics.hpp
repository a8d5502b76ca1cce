#pragma once
// Error of a rendered image against a reference, over the pixels both cover; coverage mismatches
// are counted separately. Values in 8-bit levels. NMSE = sum (I - O)^2 / sum (I - mean_c(I))^2 over
// covered pixels and the three channels (mean per channel); PSNR = 10 log10(255^2 / MSE).
// Degenerate cases: no pixel covered by both -> nmse, psnr_db, max_abs and mean_abs are NaN (undefined;
// JSON null). A constant reference (every compared pixel equal) -> nmse 0 if the image equals it, +inf
// otherwise. MSE 0 -> psnr_db +inf. Throws InputError when the image and reference sizes differ.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "parashade/image.hpp"

namespace parashade {

struct ErrorMetrics {
  std::string reference;                 // "ideal <method>" or "exact phong"
  double nmse = 0.0;                     // +inf when the reference is constant and the image is not
  double psnr_db = 0.0;                  // dB; +inf when identical
  double max_abs = 0.0;                  // levels, largest channel difference
  double mean_abs = 0.0;                 // levels, per channel sample
  std::uint64_t pixels_compared = 0;
  std::uint64_t pixels_over_1_level = 0; // pixels with some channel more than 1 level off
  std::uint64_t coverage_mismatch = 0;   // pixels covered in one image only
};

// Uses image.rgb_float when present (the unquantized output), else the 8-bit values.
ErrorMetrics compare_to_reference(const RenderedImage& image, const std::vector<std::uint8_t>& ref_covered,
                                  const std::vector<glm::dvec3>& ref_values, const std::string& reference_name);

// |reference - image| per channel at `pixel`, in levels, as compare_to_reference counts it (the image's
// float values clamped to [0, 255] when present, else its 8-bit values).
glm::dvec3 channel_errors(const RenderedImage& image, std::size_t pixel, const glm::dvec3& reference);

// Per pixel, the largest of channel_errors: compare_to_reference's max_abs is the largest of these.
// NaN where the image or the reference does not cover the pixel (not compared). Throws InputError when
// the sizes differ.
std::vector<double> pixel_errors(const RenderedImage& image, const std::vector<std::uint8_t>& ref_covered,
                                 const std::vector<glm::dvec3>& ref_values);

}  // namespace parashade
