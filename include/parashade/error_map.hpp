#pragma once
// A picture of an image's error: per-pixel error in 8-bit levels (pixel_errors in metrics.hpp) as a
// colour map of the image's own size, so that it overlays the image pixel for pixel, and its scale (a colour
// bar with labelled ticks) as a picture of its own. Written by `render --error-map / --error-legend` and
// `compare --error-map / --error-legend` (docs/pictures.md).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "parashade/image.hpp"

namespace parashade {

// A picture of `values` per-pixel values of a width x height image (alpha 255), pixel p in the 3 bytes
// colour(p) points to: the error map's and the FLIP map's. Throws InputError "<what>: N values for a WxH
// image" when the counts differ (check_picture_size).
void check_picture_size(const char* what, std::size_t values, int width, int height);
template <typename Colour>
RenderedImage value_picture(const char* what, std::size_t values, int width, int height, Colour&& colour) {
  check_picture_size(what, values, width, height);
  RenderedImage picture;
  picture.width = width;
  picture.height = height;
  picture.rgba.assign(4 * values, 255);
  for (std::size_t p = 0; p < values; ++p) {
    const std::uint8_t* c = colour(p);
    for (int k = 0; k < 3; ++k) picture.rgba[4 * p + std::size_t(k)] = c[k];
  }
  return picture;
}

// Viridis (viridis.cpp names its origin): entry 0 is the colour of no error, entry 255 of the scale's top.
extern const std::array<std::array<std::uint8_t, 3>, 256> kViridis;

// How an error in 0..top becomes a position t in [0, 1] on the colour scale:
//   linear   t = e / top
//   gamma G  t = (e / top)^G            (default G = 0.4, as the bench report's error strips)
//   log      t = ln(1 + e) / ln(1 + top) (levels: 0 stays 0, one level is ln 2 / ln(1 + top))
// The default is gamma 0.4: a map whose largest error is 49 levels and whose mean is 0.31 shows its
// one-level pixels at colour 54 of 255, where a linear scale gives them 5, black to the eye.
struct ErrorScale {
  enum Kind { linear, gamma, log } kind = gamma;
  double exponent = 0.4;  // gamma's G
};

// "linear", "gamma" (G = 0.4), "gamma:G" (0 < G <= 4), "log"; throws UsageError naming `option` otherwise.
ErrorScale parse_error_scale(const std::string& text, const std::string& option = "--error-scale");
// "linear", "gamma 0.4", "log": as the legend and the summary name it.
std::string error_scale_name(const ErrorScale& scale);
// The position t of `error` on the scale 0..top, within [0, 1].
double error_scale_position(double error, double top, const ErrorScale& scale);

// The top of the scale: the largest error (NaN entries skipped), never clipped, at least 1 level.
double error_scale_top(const std::vector<double>& errors);

// The colour entry of `error` on the scale 0..top: round(255 t), within 0..255 (linear unless told).
int error_colour_index(double error, double top, const ErrorScale& scale = ErrorScale{ErrorScale::linear, 1.0});

// An RGB picture (alpha 255) of `errors` (width x height, row 0 at the top; NaN: not compared), exactly
// width x height: pixel by pixel kViridis[error_colour_index(e, top, scale)] with top = error_scale_top(errors),
// white where nothing was compared. Throws InputError on a size mismatch.
RenderedImage error_map_image(const std::vector<double>& errors, int width, int height, const ErrorScale& scale);

// The scale of such a map as a picture of its own: a colour bar from 0 (bottom) to `top`, ticks placed on
// `scale` and labelled in levels, under a title of two lines, "levels" and the scale's name; the top tick reads
// "<top> max" when `top_is_max`. At least `height` rows tall (the map's height, so that it stands beside the
// map), more when the bar needs them.
RenderedImage error_legend_image(double top, bool top_is_max, const ErrorScale& scale, int height);

}  // namespace parashade
