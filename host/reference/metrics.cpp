// Image error against a reference (metrics.hpp). Two passes over the commonly covered pixels: the
// per-channel means of the reference first, then the sums, so the NMSE denominator is computed stably.
#include "parashade/metrics.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstddef>
#include <limits>
#include <string>

#include "parashade/errors.hpp"

namespace parashade {
namespace {

// The image's value at a pixel in levels: the unquantized output when present (clamped as the 8-bit
// image would be), else the 8-bit channels.
glm::dvec3 image_value(const RenderedImage& image, std::size_t p) {
  if (!image.rgb_float.empty()) {
    const glm::dvec3 v(image.rgb_float[3 * p], image.rgb_float[3 * p + 1], image.rgb_float[3 * p + 2]);
    return glm::clamp(v, glm::dvec3(0.0), glm::dvec3(255.0));
  }
  return glm::dvec3(image.rgba[4 * p], image.rgba[4 * p + 1], image.rgba[4 * p + 2]);
}

void check_sizes(const RenderedImage& image, const std::vector<std::uint8_t>& ref_covered,
                 const std::vector<glm::dvec3>& ref_values, const std::string& reference_name) {
  const std::size_t pixels = std::size_t(std::max(image.width, 0)) * std::size_t(std::max(image.height, 0));
  if (image.rgba.size() != 4 * pixels || (!image.rgb_float.empty() && image.rgb_float.size() != 3 * pixels) ||
      ref_covered.size() != pixels || ref_values.size() != pixels) {
    throw InputError("compare_to_reference: the image (" + std::to_string(image.width) + "x" +
                     std::to_string(image.height) + ") and the reference '" + reference_name +
                     "' differ in size");
  }
}

bool is_flipped(const std::vector<std::uint8_t>& flipped, std::size_t p) { return !flipped.empty() && flipped[p] != 0; }

// ", FLIP 0.0123 (LDR-FLIP mean; max 0.410)" when FLIP was computed.
std::string flip_note(const ErrorMetrics& e) {
  if (!e.flip) return "";
  char buf[96];
  std::snprintf(buf, sizeof buf, ", FLIP %.4g (LDR-FLIP mean; max %.3g)", e.flip->mean, e.flip->max);
  return buf;
}

// ", 4 front-surface flips (float depth ties, not compared)" when there are any.
std::string front_surface_note(const ErrorMetrics& e) {
  if (e.front_surface_mismatch == 0) return "";
  return ", " + std::to_string(e.front_surface_mismatch) + " front-surface flips (float depth ties, not compared)";
}

}  // namespace

const char* metrics_status_name(MetricsStatus s) {
  switch (s) {
    case MetricsStatus::identical: return "identical";
    case MetricsStatus::nothing_compared: return "nothing compared";
    case MetricsStatus::compared: break;
  }
  return "compared";
}

std::string describe_error(const ErrorMetrics& e) {
  char buf[320];
  if (e.status == MetricsStatus::nothing_compared) {
    std::snprintf(buf, sizeof buf, "no pixel covered by both (NMSE, PSNR, max and mean undefined), %llu coverage mismatches",
                  (unsigned long long)e.coverage_mismatch);
    return buf + front_surface_note(e) + flip_note(e);
  }
  char psnr[32];
  if (e.status == MetricsStatus::identical) std::snprintf(psnr, sizeof psnr, "exact");
  else std::snprintf(psnr, sizeof psnr, "%.2f dB", e.psnr_db);
  std::snprintf(buf, sizeof buf, "NMSE %.3g, PSNR %s, max %.2f, mean %.3f levels, %llu px > 1 level, %llu coverage mismatches",
                e.nmse, psnr, e.max_abs, e.mean_abs, (unsigned long long)e.pixels_over_1_level,
                (unsigned long long)e.coverage_mismatch);
  return buf + front_surface_note(e) + flip_note(e);
}

glm::dvec3 channel_errors(const RenderedImage& image, std::size_t pixel, const glm::dvec3& reference) {
  return glm::abs(reference - image_value(image, pixel));
}

std::vector<double> pixel_errors(const RenderedImage& image, const std::vector<std::uint8_t>& ref_covered,
                                 const std::vector<glm::dvec3>& ref_values, const std::vector<std::uint8_t>& flipped) {
  check_sizes(image, ref_covered, ref_values, "per-pixel error");
  std::vector<double> errors(ref_values.size(), std::numeric_limits<double>::quiet_NaN());
  for (std::size_t p = 0; p < errors.size(); ++p) {
    if (!image.covered(p) || ref_covered[p] == 0 || is_flipped(flipped, p)) continue;
    const glm::dvec3 e = channel_errors(image, p, ref_values[p]);
    errors[p] = std::max({e.x, e.y, e.z});
  }
  return errors;
}

ErrorMetrics compare_to_reference(const RenderedImage& image, const std::vector<std::uint8_t>& ref_covered,
                                  const std::vector<glm::dvec3>& ref_values, const std::string& reference_name,
                                  const std::vector<std::uint8_t>& flipped) {
  check_sizes(image, ref_covered, ref_values, reference_name);
  const std::size_t pixels = ref_values.size();
  if (!flipped.empty() && flipped.size() != pixels)
    throw InputError("compare_to_reference: the front-surface flips and the reference '" + reference_name + "' differ in size");

  ErrorMetrics m;
  m.reference = reference_name;
  glm::dvec3 ref_sum(0.0), ref_first(0.0);
  bool ref_constant = true;  // decided exactly, not from a rounded spread
  // Compared: covered by both and showing the reference's front surface.
  const auto compared = [&](std::size_t p) { return image.covered(p) && ref_covered[p] != 0 && !is_flipped(flipped, p); };
  for (std::size_t p = 0; p < pixels; ++p) {
    const bool in_image = image.covered(p), in_ref = ref_covered[p] != 0;
    if (in_image != in_ref) ++m.coverage_mismatch;
    if (in_image && in_ref && is_flipped(flipped, p)) ++m.front_surface_mismatch;
    if (compared(p)) {
      if (m.pixels_compared++ == 0) ref_first = ref_values[p];
      ref_constant = ref_constant && ref_values[p] == ref_first;
      ref_sum += ref_values[p];
    }
  }
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  constexpr double inf = std::numeric_limits<double>::infinity();
  if (m.pixels_compared == 0) {  // nothing to compare: every statistic is undefined
    m.status = MetricsStatus::nothing_compared;
    m.nmse = m.psnr_db = m.max_abs = m.mean_abs = nan;
    return m;
  }

  const glm::dvec3 ref_mean = ref_sum / double(m.pixels_compared);
  double error_sq = 0.0, spread_sq = 0.0, abs_sum = 0.0;
  for (std::size_t p = 0; p < pixels; ++p) {
    if (!compared(p)) continue;
    const glm::dvec3 diff = ref_values[p] - image_value(image, p);
    const glm::dvec3 spread = ref_values[p] - ref_mean;
    const glm::dvec3 abs_diff = channel_errors(image, p, ref_values[p]);
    error_sq += glm::dot(diff, diff);
    spread_sq += glm::dot(spread, spread);
    abs_sum += abs_diff.x + abs_diff.y + abs_diff.z;
    const double worst = std::max({abs_diff.x, abs_diff.y, abs_diff.z});
    m.max_abs = std::max(m.max_abs, worst);
    if (worst > 1.0) ++m.pixels_over_1_level;
  }

  const double samples = 3.0 * double(m.pixels_compared);
  const double mse = error_sq / samples;
  m.mean_abs = abs_sum / samples;
  // A constant reference has no spread (decided exactly); a near-uniform one is floored (metrics.hpp).
  if (ref_constant) spread_sq = 0.0;
  m.nmse = error_sq / std::max(spread_sq, samples * kNmseSpreadFloor);
  m.psnr_db = mse > 0.0 ? 10.0 * std::log10(255.0 * 255.0 / mse) : inf;
  if (error_sq == 0.0) m.status = MetricsStatus::identical;
  return m;
}

}  // namespace parashade
