// The 5x7 label font (bitmap_font.hpp), drawn by hand in the style of the classic HD44780 character set.
#include "bitmap_font.hpp"

#include <array>
#include <cstddef>

namespace parashade {
namespace {

struct Glyph {
  char c;
  std::array<const char*, kGlyphHeight> rows;  // '#' set, '.' clear
};

constexpr Glyph kGlyphs[] = {
    {'0', {".###.", "#...#", "#..##", "#.#.#", "##..#", "#...#", ".###."}},
    {'1', {"..#..", ".##..", "..#..", "..#..", "..#..", "..#..", ".###."}},
    {'2', {".###.", "#...#", "....#", "...#.", "..#..", ".#...", "#####"}},
    {'3', {"#####", "...#.", "..#..", "...#.", "....#", "#...#", ".###."}},
    {'4', {"...#.", "..##.", ".#.#.", "#..#.", "#####", "...#.", "...#."}},
    {'5', {"#####", "#....", "####.", "....#", "....#", "#...#", ".###."}},
    {'6', {"..##.", ".#...", "#....", "####.", "#...#", "#...#", ".###."}},
    {'7', {"#####", "....#", "...#.", "..#..", ".#...", ".#...", ".#..."}},
    {'8', {".###.", "#...#", "#...#", ".###.", "#...#", "#...#", ".###."}},
    {'9', {".###.", "#...#", "#...#", ".####", "....#", "...#.", ".##.."}},
    {'.', {".....", ".....", ".....", ".....", ".....", ".##..", ".##.."}},
    {'-', {".....", ".....", ".....", "#####", ".....", ".....", "....."}},
    {' ', {".....", ".....", ".....", ".....", ".....", ".....", "....."}},
    {'a', {".....", ".....", ".###.", "....#", ".####", "#...#", ".####"}},
    {'e', {".....", ".....", ".###.", "#...#", "#####", "#....", ".###."}},
    {'g', {".....", ".....", ".####", "#...#", ".####", "....#", ".###."}},
    {'i', {"..#..", ".....", ".##..", "..#..", "..#..", "..#..", ".###."}},
    {'l', {".##..", "..#..", "..#..", "..#..", "..#..", "..#..", ".###."}},
    {'m', {".....", ".....", "##.#.", "#.#.#", "#.#.#", "#...#", "#...#"}},
    {'n', {".....", ".....", "#.##.", "##..#", "#...#", "#...#", "#...#"}},
    {'o', {".....", ".....", ".###.", "#...#", "#...#", "#...#", ".###."}},
    {'r', {".....", ".....", "#.##.", "##..#", "#....", "#....", "#...."}},
    {'s', {".....", ".....", ".####", "#....", ".###.", "....#", "####."}},
    {'v', {".....", ".....", "#...#", "#...#", "#...#", ".#.#.", "..#.."}},
    {'x', {".....", ".....", "#...#", ".#.#.", "..#..", ".#.#.", "#...#"}},
};

const Glyph* glyph_for(char c) {
  for (const Glyph& g : kGlyphs)
    if (g.c == c) return &g;
  return nullptr;
}

}  // namespace

int text_width(const std::string& text, int scale) {
  return text.empty() ? 0 : scale * (kGlyphAdvance * int(text.size()) - (kGlyphAdvance - kGlyphWidth));
}

void draw_text(RenderedImage& image, int x, int y, const std::string& text, int scale, const std::uint8_t rgb[3]) {
  for (std::size_t i = 0; i < text.size(); ++i) {
    const Glyph* g = glyph_for(text[i]);
    const int left = x + int(i) * kGlyphAdvance * scale;
    for (int gy = 0; gy < kGlyphHeight * scale; ++gy)
      for (int gx = 0; gx < kGlyphWidth * scale; ++gx) {
        const int px = left + gx, py = y + gy;
        if (px < 0 || py < 0 || px >= image.width || py >= image.height) continue;
        if (g && g->rows[std::size_t(gy / scale)][gx / scale] != '#') continue;
        std::uint8_t* p = &image.rgba[4 * (std::size_t(py) * std::size_t(image.width) + std::size_t(px))];
        p[0] = rgb[0];
        p[1] = rgb[1];
        p[2] = rgb[2];
        p[3] = 255;
      }
  }
}

}  // namespace parashade
