// LDR-FLIP (flip.hpp), from the paper's definition. The filters are separable: the achromatic and red-green
// channels' contrast sensitivity is one Gaussian each, the blue-yellow one the sum of two, filtered as two
// separable passes whose sum is the 2D filter; the feature detectors are the first and second derivatives of a
// Gaussian, split into an x and a y pass. The frame goes in bands of rows, each band read with the rows its
// filters reach above and below (clamped at the image's edges), so memory is a few bands, not frames.
#include "parashade/flip.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "parashade/errors.hpp"
#include "parashade/error_map.hpp"
#include "parashade/parallel.hpp"

namespace parashade {
namespace {

constexpr double kPi = 3.14159265358979323846;
// The paper's constants: colour difference exponent q_c, its remapping's p_c and p_t, the feature detectors'
// width w (degrees) and the feature difference's exponent q_f.
constexpr float kQc = 0.7f, kPc = 0.4f, kPt = 0.95f, kQf = 0.5f;
constexpr double kFeatureWidthDegrees = 0.082;
// Contrast sensitivity as Gaussians a sqrt(pi / b) exp(-pi^2 x^2 / b), x in degrees, per YCxCz channel; the
// blue-yellow channel (Cz) is the sum of two.
constexpr double kA1[3] = {1.0, 1.0, 34.1}, kB1[3] = {0.0047, 0.0053, 0.04};
constexpr double kA2Cz = 13.5, kB2Cz = 0.025;

using Mat3 = std::array<std::array<float, 3>, 3>;

struct Colour {
  float x, y, z;
};

Colour apply(const Mat3& m, Colour c) {
  return {m[0][0] * c.x + m[0][1] * c.y + m[0][2] * c.z, m[1][0] * c.x + m[1][1] * c.y + m[1][2] * c.z,
          m[2][0] * c.x + m[2][1] * c.y + m[2][2] * c.z};
}

// Linear sRGB to CIE XYZ (D65) from the sRGB primaries and white point, in double, and its inverse.
struct ColourSpaces {
  Mat3 rgb_to_xyz{}, xyz_to_rgb{};
  Colour white{};  // XYZ of linear RGB (1, 1, 1)
  ColourSpaces() {
    const double xy[3][2] = {{0.64, 0.33}, {0.30, 0.60}, {0.15, 0.06}}, wx = 0.3127, wy = 0.3290;
    glm::dmat3 p;  // columns: the primaries' XYZ at Y = 1
    for (int i = 0; i < 3; ++i) p[i] = glm::dvec3(xy[i][0] / xy[i][1], 1.0, (1 - xy[i][0] - xy[i][1]) / xy[i][1]);
    const glm::dvec3 scale = glm::inverse(p) * glm::dvec3(wx / wy, 1.0, (1 - wx - wy) / wy);
    glm::dmat3 m;
    for (int i = 0; i < 3; ++i) m[i] = p[i] * scale[i];
    const glm::dmat3 inv = glm::inverse(m);
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) {
        rgb_to_xyz[r][c] = float(m[c][r]);
        xyz_to_rgb[r][c] = float(inv[c][r]);
      }
    white = apply(rgb_to_xyz, {1, 1, 1});
  }
};

const ColourSpaces& spaces() {
  static const ColourSpaces s;
  return s;
}

float srgb_to_linear(float v) {
  v = std::clamp(v, 0.0f, 1.0f);
  return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

// YCxCz (a linearized CIELab): 116 Y/Yn - 16, 500 (X/Xn - Y/Yn), 200 (Y/Yn - Z/Zn).
Colour linear_to_ycxcz(Colour rgb) {
  const ColourSpaces& s = spaces();
  const Colour v = apply(s.rgb_to_xyz, rgb);
  const float x = v.x / s.white.x, y = v.y / s.white.y, z = v.z / s.white.z;
  return {116.0f * y - 16.0f, 500.0f * (x - y), 200.0f * (y - z)};
}

Colour ycxcz_to_linear(Colour c) {
  const ColourSpaces& s = spaces();
  const float y = (c.x + 16.0f) / 116.0f;
  return apply(s.xyz_to_rgb, {(y + c.y / 500.0f) * s.white.x, y * s.white.y, (y - c.z / 200.0f) * s.white.z});
}

// CIELab of linear RGB with the Hunt adjustment (a and b scaled by 0.01 L).
Colour hunt_lab(Colour rgb) {
  const ColourSpaces& s = spaces();
  const Colour v = apply(s.rgb_to_xyz, rgb);
  constexpr float d = 6.0f / 29.0f;
  const auto f = [](float t) { return t > d * d * d ? std::cbrt(t) : t / (3.0f * d * d) + 4.0f / 29.0f; };
  const float fx = f(v.x / s.white.x), fy = f(v.y / s.white.y), fz = f(v.z / s.white.z);
  const float l = 116.0f * fy - 16.0f;
  return {l, 0.01f * l * 500.0f * (fx - fy), 0.01f * l * 200.0f * (fy - fz)};
}

float hyab(Colour a, Colour b) {
  return std::abs(a.x - b.x) + std::sqrt((a.y - b.y) * (a.y - b.y) + (a.z - b.z) * (a.z - b.z));
}

// Everything that depends on the observer only: the 1D filters and the colour difference's maximum.
struct Filters {
  int spatial_radius = 0, feature_radius = 0;
  std::vector<float> y, cx, cz1, cz2;  // contrast sensitivity, 2 * spatial_radius + 1 taps each
  std::vector<float> g, dg, ddg;       // Gaussian and its derivatives, 2 * feature_radius + 1 taps each
  float cmax = 0;                      // HyAB(green, blue)^q_c: the largest colour difference

  explicit Filters(double ppd) {
    spatial_radius = int(std::ceil(3.0 * std::sqrt(kB1[2] / (2.0 * kPi * kPi)) * ppd));  // b = 0.04 is the widest
    const int n = 2 * spatial_radius + 1;
    std::vector<double> w[4];
    for (int i = 0; i < n; ++i) {
      const double x = (i - spatial_radius) / ppd, x2 = x * x;
      for (int c = 0; c < 2; ++c) w[c].push_back(std::exp(-kPi * kPi * x2 / kB1[c]));
      // The sum of two Gaussians as the sum of two separable ones: each 1D tap the square root of its 2D weight.
      w[2].push_back(std::sqrt(kA1[2] * std::sqrt(kPi / kB1[2])) * std::exp(-kPi * kPi * x2 / kB1[2]));
      w[3].push_back(std::sqrt(kA2Cz * std::sqrt(kPi / kB2Cz)) * std::exp(-kPi * kPi * x2 / kB2Cz));
    }
    double sum[4] = {};
    for (int c = 0; c < 4; ++c)
      for (double v : w[c]) sum[c] += v;
    const double cz_norm = std::sqrt(sum[2] * sum[2] + sum[3] * sum[3]);  // the 2D filter's sum is 1
    for (int i = 0; i < n; ++i) {
      y.push_back(float(w[0][i] / sum[0]));
      cx.push_back(float(w[1][i] / sum[1]));
      cz1.push_back(float(w[2][i] / cz_norm));
      cz2.push_back(float(w[3][i] / cz_norm));
    }
    feature_filters(ppd);
    cmax = std::pow(hyab(hunt_lab({0, 1, 0}), hunt_lab({0, 0, 1})), kQc);
  }

  // The Gaussian sums to 1; the derivatives' positive taps to 1 and their negative taps to -1.
  void feature_filters(double ppd) {
    const double sigma = 0.5 * kFeatureWidthDegrees * ppd;
    feature_radius = int(std::ceil(3.0 * sigma));
    std::vector<double> w0, w1, w2;
    double s0 = 0, pos1 = 0, neg1 = 0, pos2 = 0, neg2 = 0;
    for (int i = -feature_radius; i <= feature_radius; ++i) {
      const double gauss = std::exp(-double(i) * i / (2 * sigma * sigma));
      w0.push_back(gauss);
      w1.push_back(-i * gauss);
      w2.push_back((double(i) * i / (sigma * sigma) - 1) * gauss);
      s0 += gauss;
      (w1.back() > 0 ? pos1 : neg1) += std::abs(w1.back());
      (w2.back() > 0 ? pos2 : neg2) += std::abs(w2.back());
    }
    for (std::size_t i = 0; i < w0.size(); ++i) {
      g.push_back(float(w0[i] / s0));
      dg.push_back(float(w1[i] / (w1[i] > 0 ? pos1 : neg1)));
      ddg.push_back(float(w2[i] / (w2[i] > 0 ? pos2 : neg2)));
    }
  }
};

// `in` (w values) convolved with `k` (odd length), the edge value repeated past either end.
void convolve_row(const float* in, float* out, int w, const std::vector<float>& k) {
  const int r = int(k.size()) / 2;
  const int lo = std::min(r, w), hi = std::max(lo, w - r);  // [lo, hi): every tap inside
  for (int x = lo; x < hi; ++x) out[x] = 0;
  for (int t = 0; t <= 2 * r; ++t) {
    const float kt = k[std::size_t(t)];
    const float* src = in + (t - r);
    for (int x = lo; x < hi; ++x) out[x] += kt * src[x];
  }
  const auto edge = [&](int x) {
    float s = 0;
    for (int t = 0; t <= 2 * r; ++t) s += k[std::size_t(t)] * in[std::clamp(x + t - r, 0, w - 1)];
    out[x] = s;
  };
  for (int x = 0; x < lo; ++x) edge(x);
  for (int x = hi; x < w; ++x) edge(x);
}

// Planes of a band: `rows` rows of `width` floats each, one after another.
struct Planes {
  int width = 0, rows = 0;
  std::vector<float> data;
  Planes(int count, int w, int r) : width(w), rows(r), data(std::size_t(count) * std::size_t(w) * std::size_t(r)) {}
  float* row(int plane, int y) { return &data[(std::size_t(plane) * std::size_t(rows) + std::size_t(y)) * std::size_t(width)]; }
};

// out[x] = sum over t of k[t] * plane(row0 + t)[x]: one output row of a vertical pass.
void convolve_column(Planes& p, int plane, int row0, const std::vector<float>& k, float* out) {
  std::fill(out, out + p.width, 0.0f);
  for (std::size_t t = 0; t < k.size(); ++t) {
    const float kt = k[t];
    const float* src = p.row(plane, row0 + int(t));
    for (int x = 0; x < p.width; ++x) out[x] += kt * src[x];
  }
}

struct FlipJob {
  const std::vector<float>* images[2];  // reference, test
  int width, height;
  const Filters* f;
  float* out;
};

// Rows [y0, y1) of the FLIP map. The band holds the rows from y0 - R to y1 + R (R the larger filter radius),
// each image row clamped into the image: per image its YCxCz (3 planes), their horizontal contrast
// sensitivity passes (Y, Cx, Cz twice: 4) and the grey's horizontal feature passes (dg, ddg, g: 3).
class Band {
 public:
  Band(const FlipJob& job, int y0, int y1)
      : job_(job), f_(*job.f), y0_(y0), r_(std::max(f_.spatial_radius, f_.feature_radius)),
        n_(y1 - y0 + 2 * r_), ycc_(6, job.width, n_), spatial_(8, job.width, n_), feature_(6, job.width, n_),
        v_(std::size_t(job.width) * 14) {
    for (int k = 0; k < n_; ++k) {
      for (int i = 0; i < 2; ++i) convert_row(i, k);
      for (int i = 0; i < 2; ++i) horizontal(i, k);
    }
  }

  // One row of the map: the vertical passes, then the colour and feature differences and their product.
  void row(int y) {
    const int w = job_.width;
    for (int i = 0; i < 2; ++i) vertical(i, y);
    const float cmax = f_.cmax, pccmax = kPc * f_.cmax;
    float* out = job_.out + std::size_t(y) * std::size_t(w);
    for (int x = 0; x < w; ++x) {
      Colour lab[2];
      for (int i = 0; i < 2; ++i) {
        Colour rgb = ycxcz_to_linear({slot(7 * i)[x], slot(7 * i + 1)[x], slot(7 * i + 2)[x]});
        rgb = {std::clamp(rgb.x, 0.0f, 1.0f), std::clamp(rgb.y, 0.0f, 1.0f), std::clamp(rgb.z, 0.0f, 1.0f)};
        lab[i] = hunt_lab(rgb);
      }
      float colour = std::pow(hyab(lab[0], lab[1]), kQc);
      colour = colour < pccmax ? colour * (kPt / pccmax) : kPt + (colour - pccmax) / (cmax - pccmax) * (1.0f - kPt);
      const float edge = std::abs(slot(3)[x] - slot(10)[x]), point = std::abs(slot(4)[x] - slot(11)[x]);
      const float feature = std::pow(std::max(edge, point) / std::sqrt(2.0f), kQf);
      out[x] = std::pow(colour, 1.0f - feature);
    }
  }

 private:
  float* slot(int s) { return &v_[std::size_t(s) * std::size_t(job_.width)]; }

  void convert_row(int i, int k) {
    const int w = job_.width, y = std::clamp(y0_ - r_ + k, 0, job_.height - 1);
    const float* src = &(*job_.images[i])[3 * std::size_t(y) * std::size_t(w)];
    float *py = ycc_.row(3 * i, k), *pcx = ycc_.row(3 * i + 1, k), *pcz = ycc_.row(3 * i + 2, k);
    for (int x = 0; x < w; ++x) {
      const Colour c =
          linear_to_ycxcz({srgb_to_linear(src[3 * x]), srgb_to_linear(src[3 * x + 1]), srgb_to_linear(src[3 * x + 2])});
      py[x] = c.x;
      pcx[x] = c.y;
      pcz[x] = c.z;
    }
  }

  void horizontal(int i, int k) {
    const int w = job_.width;
    convolve_row(ycc_.row(3 * i, k), spatial_.row(4 * i, k), w, f_.y);
    convolve_row(ycc_.row(3 * i + 1, k), spatial_.row(4 * i + 1, k), w, f_.cx);
    convolve_row(ycc_.row(3 * i + 2, k), spatial_.row(4 * i + 2, k), w, f_.cz1);
    convolve_row(ycc_.row(3 * i + 2, k), spatial_.row(4 * i + 3, k), w, f_.cz2);
    float* grey = slot(13);  // a scratch row: the vertical passes start after construction
    const float* py = ycc_.row(3 * i, k);
    for (int x = 0; x < w; ++x) grey[x] = (py[x] + 16.0f) / 116.0f;  // Y / Yn, in [0, 1]
    convolve_row(grey, feature_.row(3 * i, k), w, f_.dg);
    convolve_row(grey, feature_.row(3 * i + 1, k), w, f_.ddg);
    convolve_row(grey, feature_.row(3 * i + 2, k), w, f_.g);
  }

  // Image i's filtered Y, Cx, Cz in slots 7i..7i+2; its edge and point strengths in 7i+3 and 7i+4.
  void vertical(int i, int y) {
    const int w = job_.width, ks = y - y0_ + r_ - f_.spatial_radius, kf = y - y0_ + r_ - f_.feature_radius;
    float *s = slot(7 * i), *extra = slot(7 * i + 5), *extra2 = slot(7 * i + 6);
    convolve_column(spatial_, 4 * i, ks, f_.y, s);
    convolve_column(spatial_, 4 * i + 1, ks, f_.cx, s + w);
    convolve_column(spatial_, 4 * i + 2, ks, f_.cz1, s + 2 * w);
    convolve_column(spatial_, 4 * i + 3, ks, f_.cz2, extra);
    for (int x = 0; x < w; ++x) s[2 * w + x] += extra[x];
    // Edges: the x derivative smoothed in y and the y derivative of the x-smoothed grey; points likewise.
    convolve_column(feature_, 3 * i, kf, f_.g, s + 3 * w);      // dx
    convolve_column(feature_, 3 * i + 1, kf, f_.g, s + 4 * w);  // ddx
    convolve_column(feature_, 3 * i + 2, kf, f_.dg, extra);     // dy
    convolve_column(feature_, 3 * i + 2, kf, f_.ddg, extra2);   // ddy
    for (int x = 0; x < w; ++x) {
      s[3 * w + x] = std::sqrt(s[3 * w + x] * s[3 * w + x] + extra[x] * extra[x]);
      s[4 * w + x] = std::sqrt(s[4 * w + x] * s[4 * w + x] + extra2[x] * extra2[x]);
    }
  }

  const FlipJob& job_;
  const Filters& f_;
  int y0_, r_, n_;
  Planes ycc_, spatial_, feature_;
  std::vector<float> v_;  // 14 rows: per image 7 (Y, Cx, Cz, edge, point, 2 scratch)
};

// Rows of one band of ldr_flip's: about four bands a host thread, 32 to 256 rows each.
std::size_t band_rows(int height) { return balanced_chunk(std::size_t(height), 32, 256); }

}  // namespace

std::uint64_t ldr_flip_working_bytes(int width, int height, double ppd) {
  if (width < 1 || height < 1 || !(ppd > 0 && ppd < 1e4)) return 0;
  const Filters f(ppd);
  const std::uint64_t rows = band_rows(height), bands = (std::uint64_t(height) + rows - 1) / rows;
  const std::uint64_t in_flight = std::min<std::uint64_t>(bands, host_threads());
  const std::uint64_t reach = 2 * std::uint64_t(std::max(f.spatial_radius, f.feature_radius));
  // Band's planes: YCxCz 6, the spatial passes 8, the feature passes 6; and its 14 rows (v_).
  const std::uint64_t per_band = (20 * (std::min<std::uint64_t>(rows, std::uint64_t(height)) + reach) + 14) *
                                 std::uint64_t(width) * sizeof(float);
  return in_flight * per_band;
}

std::vector<float> ldr_flip(const std::vector<float>& reference, const std::vector<float>& test, int width, int height,
                            double ppd) {
  const std::size_t n = std::size_t(std::max(width, 0)) * std::size_t(std::max(height, 0));
  if (width < 1 || height < 1 || reference.size() != 3 * n || test.size() != 3 * n)
    throw InputError("FLIP: " + std::to_string(reference.size()) + " and " + std::to_string(test.size()) +
                     " values for a " + std::to_string(width) + "x" + std::to_string(height) + " RGB image");
  if (!(ppd > 0 && ppd < 1e4)) throw InputError("FLIP: pixels per degree must be positive, not " + std::to_string(ppd));
  const Filters filters(ppd);
  std::vector<float> map(n);
  const FlipJob job{{&reference, &test}, width, height, &filters, map.data()};
  parallel_for_ranges(std::size_t(height), band_rows(height), [&](std::size_t y0, std::size_t y1) {
    Band b(job, int(y0), int(y1));
    for (std::size_t y = y0; y < y1; ++y) b.row(int(y));
  });
  return map;
}

FlipFigures flip_figures(const std::vector<float>& map, double ppd) {
  FlipFigures f;
  f.ppd = ppd;
  double sum = 0;
  for (float v : map) {
    sum += v;
    f.max = std::max(f.max, double(v));
  }
  f.mean = map.empty() ? 0.0 : sum / double(map.size());
  return f;
}

std::vector<float> flip_input(const RenderedImage& image) {
  const std::size_t n = std::size_t(image.width) * std::size_t(image.height);
  const bool have_float = image.rgb_float.size() == 3 * n;
  std::vector<float> v(3 * n);
  for (std::size_t p = 0; p < n; ++p)
    for (int c = 0; c < 3; ++c)
      v[3 * p + c] = have_float ? std::clamp(image.rgb_float[3 * p + c], 0.0f, 255.0f) / 255.0f
                                : float(image.rgba[4 * p + c]) / 255.0f;
  return v;
}

std::vector<float> flip_input(const std::vector<glm::dvec3>& levels) {
  std::vector<float> v(3 * levels.size());
  for (std::size_t p = 0; p < levels.size(); ++p)
    for (int c = 0; c < 3; ++c) v[3 * p + c] = float(std::clamp(levels[p][c], 0.0, 255.0) / 255.0);
  return v;
}

RenderedImage flip_map_image(const std::vector<float>& map, int width, int height) {
  return value_picture("FLIP map", map.size(), width, height, [&](std::size_t p) {
    const float e = std::isnan(map[p]) ? 0.0f : std::clamp(map[p], 0.0f, 1.0f);
    return kMagma[std::lround(255.0f * e)];
  });
}

}  // namespace parashade
