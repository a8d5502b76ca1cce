// The error map's pictures (error_map.hpp): the map at the image's size, and its scale, a colour bar with
// labelled ticks, as a picture of its own.
#include "parashade/error_map.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>

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

// The values a bar may label below its top: on a linear scale evenly spaced steps (tick_step); on gamma and
// log, which stretch the small errors, 0 and 1, 2, 5 times the powers of ten from 0.1 up.
std::vector<std::pair<double, std::string>> tick_candidates(double top, const ErrorScale& scale) {
  std::vector<std::pair<double, std::string>> ticks;
  if (scale.kind == ErrorScale::linear) {
    const double step = tick_step(top);
    const int decimals = std::max(0, -int(std::floor(std::log10(step) + 1e-9)));
    for (int k = 0; k * step < top * (1 - 1e-9); ++k) ticks.push_back({k * step, label(k * step, decimals)});
    return ticks;
  }
  ticks.push_back({0.0, "0"});
  for (double power = 0.1; power < top; power *= 10)
    for (double m : {1.0, 2.0, 5.0})
      if (m * power < top * (1 - 1e-9)) ticks.push_back({m * power, label(m * power, power < 0.5 ? 1 : 0)});
  return ticks;
}

}  // namespace

ErrorScale parse_error_scale(const std::string& text, const std::string& option) {
  if (text == "linear") return {ErrorScale::linear, 1.0};
  if (text == "log") return {ErrorScale::log, 1.0};
  if (text == "gamma") return {ErrorScale::gamma, 0.4};
  if (text.rfind("gamma:", 0) == 0) {
    const std::string g = text.substr(6);
    char* end = nullptr;
    const double v = g.empty() ? 0.0 : std::strtod(g.c_str(), &end);
    if (end && *end == '\0' && v > 0 && v <= 4) return {ErrorScale::gamma, v};
    throw UsageError(option + " gamma:G needs 0 < G <= 4, not '" + g + "'");
  }
  throw UsageError(option + " must be linear, gamma, gamma:G or log, not '" + text + "'");
}

std::string error_scale_name(const ErrorScale& scale) {
  if (scale.kind == ErrorScale::linear) return "linear";
  if (scale.kind == ErrorScale::log) return "log";
  char buf[32];
  std::snprintf(buf, sizeof buf, "gamma %g", scale.exponent);
  return buf;
}

double error_scale_position(double error, double top, const ErrorScale& scale) {
  const double t = std::clamp(error / top, 0.0, 1.0);
  if (scale.kind == ErrorScale::gamma) return std::pow(t, scale.exponent);
  if (scale.kind == ErrorScale::log) return std::clamp(std::log1p(std::max(error, 0.0)) / std::log1p(top), 0.0, 1.0);
  return t;
}

double error_scale_top(const std::vector<double>& errors) {
  double top = 1.0;
  for (double e : errors)
    if (std::isfinite(e)) top = std::max(top, e);
  return top;
}

int error_colour_index(double error, double top, const ErrorScale& scale) {
  return int(std::clamp(std::lround(255.0 * error_scale_position(error, top, scale)), 0L, 255L));
}

void check_picture_size(const char* what, std::size_t values, int width, int height) {
  if (width < 1 || height < 1 || values != std::size_t(width) * std::size_t(height))
    throw InputError(std::string(what) + ": " + std::to_string(values) + " values for a " + std::to_string(width) + "x" +
                     std::to_string(height) + " image");
}

RenderedImage error_map_image(const std::vector<double>& errors, int width, int height, const ErrorScale& scale) {
  const double top = error_scale_top(errors);
  return value_picture("error map", errors.size(), width, height, [&](std::size_t p) {
    const double e = errors[p];
    return std::isnan(e) ? kWhite : kViridis[std::size_t(error_colour_index(e, top, scale))].data();
  });
}

RenderedImage error_legend_image(double top, bool top_is_max, const ErrorScale& scale, int height) {
  const int s = std::clamp((height + 199) / 300, 1, 4);  // font and bar scale: readable at 256 and at 4096 rows
  const std::vector<std::pair<double, std::string>> candidates = tick_candidates(top, scale);
  const std::string top_text = top_label(top, top_is_max);
  int label_width = text_width(top_text, s);
  for (const auto& t : candidates) label_width = std::max(label_width, text_width(t.second, s));

  const std::string title = "levels", scale_name = error_scale_name(scale);
  const int bar_x0 = 4 * s + 1, bar_x1 = bar_x0 + 10 * s - 1, label_x = bar_x1 + 6 * s;
  const int bar_top = 2 * s + 2 * (kGlyphHeight + 2) * s + 3 * s;
  const int picture_height = std::max(height, bar_top + 48 * s);
  const int bar_bottom = picture_height - 1 - 4 * s;
  const int picture_width =
      std::max({label_x + label_width, bar_x0 + text_width(title, s), bar_x0 + text_width(scale_name, s)}) + 4 * s;

  RenderedImage picture;
  picture.width = picture_width;
  picture.height = picture_height;
  picture.rgba.assign(4 * std::size_t(picture_width) * std::size_t(picture_height), 255);

  // The bar, row by row from top (the top colour) to 0, framed in black: each row the colour of the error
  // whose position on the scale is the row's.
  const int span = bar_bottom - bar_top;
  fill(picture, bar_x0 - s, bar_top - s, bar_x1 + s, bar_bottom + s, kBlack);
  for (int y = bar_top; y <= bar_bottom; ++y) {
    const int index = int(std::lround(255.0 * double(bar_bottom - y) / double(span)));
    fill(picture, bar_x0, y, bar_x1, y, kViridis[std::size_t(index)].data());
  }
  draw_text(picture, bar_x0, 2 * s, title, s, kBlack);
  draw_text(picture, bar_x0, 2 * s + (kGlyphHeight + 2) * s, scale_name, s, kBlack);
  const auto row_of = [&](double v) { return bar_bottom - int(std::lround(error_scale_position(v, top, scale) * span)); };
  const auto tick = [&](double v, const std::string& text) {
    const int y = row_of(v);
    fill(picture, bar_x1 + s, y - (s - 1) / 2, bar_x1 + 4 * s, y + s / 2, kBlack);
    draw_text(picture, label_x, y - (kGlyphHeight * s) / 2, text, s, kBlack);
  };
  // From 0 up, a tick where its label clears the last one drawn and the top's.
  const int min_gap = (kGlyphHeight + 3) * s;
  int last = bar_bottom + min_gap;
  for (const auto& t : candidates) {
    const int y = row_of(t.first);
    if (last - y >= min_gap && y - bar_top >= min_gap) {
      tick(t.first, t.second);
      last = y;
    }
  }
  tick(top, top_text);
  return picture;
}

}  // namespace parashade
