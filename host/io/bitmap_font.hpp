#pragma once
// A 5x7 pixel font for the few labels parashade draws into images (the error map's scale): digits, '.',
// '-', ' ' and the lower-case letters of "levels", "max" and the scales' names ("linear", "gamma", "log").
// Built in because OpenImageIO's render_text needs a TrueType font file, which a fresh machine may not have
// (Debian's OpenImageIO ships none), and so that the same run writes the same bytes on every machine.
#include <cstdint>
#include <string>

#include "parashade/image.hpp"

namespace parashade {

constexpr int kGlyphWidth = 5, kGlyphHeight = 7, kGlyphAdvance = 6;  // in font pixels

// Width in image pixels of `text` drawn at `scale` (each font pixel a scale x scale block).
int text_width(const std::string& text, int scale);

// Draws `text` with its top-left corner at (x, y) in `rgb` colour into the RGBA image, clipped to it.
// Characters without a glyph are drawn as a filled box, so a missing one shows instead of vanishing.
void draw_text(RenderedImage& image, int x, int y, const std::string& text, int scale, const std::uint8_t rgb[3]);

}  // namespace parashade
