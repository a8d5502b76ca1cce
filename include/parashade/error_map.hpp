#pragma once
// A picture of an image's error: per-pixel error in 8-bit levels (pixel_errors in metrics.hpp) as a
// colour map, with its scale drawn in. Written by `render --error-map` and `compare --diff`
// (docs/pictures.md).
#include <array>
#include <cstdint>
#include <vector>

#include "parashade/image.hpp"

namespace parashade {

// Viridis (viridis.cpp names its origin): entry 0 is the colour of no error, entry 255 of the scale's top.
extern const std::array<std::array<std::uint8_t, 3>, 256> kViridis;

// The top of the scale: the largest error (NaN entries skipped), never clipped, at least 1 level.
double error_scale_top(const std::vector<double>& errors);

// The colour entry of `error` on the scale 0..top: round(255 * error / top), within 0..255.
int error_colour_index(double error, double top);

// An RGB picture (alpha 255) of `errors` (width x height, row 0 at the top; NaN: not compared): the map
// at the top left, pixel by pixel kViridis[error_colour_index(e, top)] with top = error_scale_top(errors)
// and white where nothing was compared; to its right a colour bar from 0 (bottom) to top, ticks labelled
// in levels ("levels" above; the top tick reads "<top> max", or "1" when every error is below 1 level). The picture is at least as tall as the
// scale needs, so it can be taller than the map (white below). Throws InputError on a size mismatch.
RenderedImage error_map_image(const std::vector<double>& errors, int width, int height);

}  // namespace parashade
