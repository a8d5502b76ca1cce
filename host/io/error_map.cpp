// The error map's picture (error_map.hpp): the map, then a colour bar with labelled ticks.
#include "parashade/error_map.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "bitmap_font.hpp"
#include "parashade/errors.hpp"

namespace parashade {
namespace {

constexpr std::uint8_t kWhite[3] = {255, 255, 255};
constexpr std::uint8_t kBlack[3] = {0, 0, 0};

void put(RenderedImage& image, int x, int y, const std::uint8_t rgb[3]) {
  if (x < 0 || y < 0 || x >= image.width || y >= image.height) return;
  std::uint8_t* p = &image.rgba[4 * (std::size_t(y) * std::size_t(image.width) + std::size_t(x))];
  p[0] = rgb[0];
  p[1] = rgb[1];
  p[2] = rgb[2];
  p[3] = 255;
}

void fill(RenderedImage& image, int x0, int y0, int x1, int y1, const std::uint8_t rgb[3]) {  // inclusive
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) put(image, x, y, rgb);
}

// A value as a tick label: `decimals` places, trailing zeros kept so the labels of one bar align.
std::string label(double v, int decimals) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

// The top's label: two decimals at most, trailing zeros dropped ("124.37", "12.5", "1"), and "max" when
// it is the largest error (not the 1-level floor).
std::string top_label(double top, bool is_max) {
  std::string s = label(top, 2);
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return is_max ? s + " max" : s;
}

// Evenly spaced ticks below the top: steps of 1, 2 or 5 times a power of ten, at most 5 of them.
double tick_step(double top) {
  const double power = std::pow(10.0, std::floor(std::log10(top / 5.0)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (top / (m * power) <= 5.0) return m * power;
  return 10.0 * power;
}

}  // namespace

double error_scale_top(const std::vector<double>& errors) {
  double top = 1.0;
  for (double e : errors)
    if (std::isfinite(e)) top = std::max(top, e);
  return top;
}

int error_colour_index(double error, double top) {
  return int(std::clamp(std::lround(255.0 * error / top), 0L, 255L));
}

RenderedImage error_map_image(const std::vector<double>& errors, int width, int height) {
  if (width < 1 || height < 1 || errors.size() != std::size_t(width) * std::size_t(height))
    throw InputError("error map: " + std::to_string(errors.size()) + " errors for a " + std::to_string(width) + "x" +
                     std::to_string(height) + " image");
  const double top = error_scale_top(errors);
  bool top_is_max = false;
  for (double e : errors) top_is_max = top_is_max || e == top;
  const int s = std::clamp((height + 199) / 300, 1, 4);  // font and bar scale: readable at 256 and at 4096 rows

  // Ticks: 0, step, 2 step, ... and the top, leaving out one too close to the top's label.
  const double step = tick_step(top);
  const int decimals = std::max(0, -int(std::floor(std::log10(step) + 1e-9)));
  std::vector<std::pair<double, std::string>> ticks;
  for (int k = 0; k * step < top * (1 - 1e-9); ++k) ticks.push_back({k * step, label(k * step, decimals)});
  int label_width = text_width(top_label(top, top_is_max), s);
  for (const auto& t : ticks) label_width = std::max(label_width, text_width(t.second, s));

  const std::string title = "levels";
  const int bar_x0 = width + 8 * s, bar_x1 = bar_x0 + 10 * s - 1, label_x = bar_x1 + 6 * s;
  const int bar_top = 2 * s + kGlyphHeight * s + 5 * s;
  const int picture_height = std::max(height, bar_top + 48 * s);
  const int bar_bottom = picture_height - 1 - 4 * s;
  const int picture_width = std::max(label_x + label_width, bar_x0 + text_width(title, s)) + 4 * s;

  RenderedImage picture;
  picture.width = picture_width;
  picture.height = picture_height;
  picture.rgba.assign(4 * std::size_t(picture_width) * std::size_t(picture_height), 255);

  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const double e = errors[std::size_t(y) * std::size_t(width) + std::size_t(x)];
      put(picture, x, y, std::isnan(e) ? kWhite : kViridis[std::size_t(error_colour_index(e, top))].data());
    }

  // The bar, row by row from top (the top colour) to 0, framed in black.
  const int span = bar_bottom - bar_top;
  fill(picture, bar_x0 - s, bar_top - s, bar_x1 + s, bar_bottom + s, kBlack);
  for (int y = bar_top; y <= bar_bottom; ++y) {
    const double v = top * double(bar_bottom - y) / double(span);
    fill(picture, bar_x0, y, bar_x1, y, kViridis[std::size_t(error_colour_index(v, top))].data());
  }
  draw_text(picture, bar_x0, 2 * s, title, s, kBlack);
  const auto tick = [&](double v, const std::string& text) {
    const int y = bar_bottom - int(std::lround(v / top * span));
    fill(picture, bar_x1 + s, y - (s - 1) / 2, bar_x1 + 4 * s, y + s / 2, kBlack);
    draw_text(picture, label_x, y - (kGlyphHeight * s) / 2, text, s, kBlack);
  };
  const int min_gap = (kGlyphHeight + 3) * s;  // label rows between two ticks
  for (const auto& t : ticks)
    if (span * (top - t.first) / top >= min_gap) tick(t.first, t.second);
  tick(top, top_label(top, top_is_max));
  return picture;
}

}  // namespace parashade
