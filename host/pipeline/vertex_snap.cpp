#include "parashade/vertex_snap.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "parashade/screen_geometry.hpp"
#include "parashade/vertex_lanes.hpp"

namespace parashade {

std::uint8_t outcode_of(const glm::vec4& c) {
  // One test for NaN or Inf in any coordinate (the sum is then NaN or Inf); finite coordinates so
  // large that their sum overflows (> 3e38) count as outside too.
  if (!std::isfinite(c.x + c.y + c.z + c.w)) return kNonFinite;
  const float g = kGuardBand * c.w;
  return std::uint8_t((c.z + c.w >= 0.0f ? 0 : kNear) | (c.w - c.z >= 0.0f ? 0 : kFar) |
                      (c.x + g >= 0.0f ? 0 : kLeft) | (g - c.x >= 0.0f ? 0 : kRight) |
                      (c.y + g >= 0.0f ? 0 : kBottom) | (g - c.y >= 0.0f ? 0 : kTop));
}

Snapped snap(const glm::vec4& c, int width, int height) {
  Snapped s{{0, 0}, 1.0f, 0.0f};
  if (!(c.w > 0.0f)) return s;
  const double inv_w = 1.0 / double(c.w);
  const double x = (double(c.x) * inv_w * 0.5 + 0.5) * width * kSubpixel;
  const double y = (0.5 - double(c.y) * inv_w * 0.5) * height * kSubpixel;
  constexpr double kLimit = double(1 << 30);
  s.xy = {int(std::lrint(std::clamp(x, -kLimit, kLimit))), int(std::lrint(std::clamp(y, -kLimit, kLimit)))};
  s.depth = float(double(c.z) * inv_w * 0.5 + 0.5);
  s.inv_w = float(inv_w);
  return s;
}

namespace {

using namespace vertex_lanes;
using Ints = Mask;  // the same lanes holding integers (outcodes, screen positions)

inline __attribute__((always_inline)) Doubles splat_double(double v) {
  Doubles r;
  for (int k = 0; k < kLanes; ++k) r[k] = v;
  return r;
}

// Per lane: the outcode bit where `inside` (a comparison) is false.
inline __attribute__((always_inline)) Ints outside(Mask inside, int bit) { return ~inside & bit; }

// std::lrint of doubles within +-2^30 (after the clamp): adding and subtracting 1.5 * 2^52 rounds to the
// nearest integer, ties to even, as lrint in the default rounding mode; then the exact conversion. NaN
// lanes give 0, as int(lrint(NaN)) on x86-64 (the low half of 0x8000000000000000).
inline __attribute__((always_inline)) Ints round_to_int(Doubles x) {
  const Doubles magic = splat_double(6755399441055744.0);
  const Doubles r = (x + magic) - magic;
  return __builtin_convertvector(r == r ? r : splat_double(0.0), Ints);
}

inline __attribute__((always_inline)) Doubles clamp(Doubles x, double limit) {
  const Doubles lo = splat_double(-limit), hi = splat_double(limit);
  return x < lo ? lo : (hi < x ? hi : x);  // std::clamp's order: NaN stays NaN
}

inline __attribute__((always_inline)) void transform_lanes(const glm::mat4& m, const glm::vec3* position, int width,
                                                           int height, std::size_t i, const SnappedVertices& out) {
  const Vec3s p = load3(position + i);
  Floats c[4];
  for (int j = 0; j < 4; ++j) c[j] = transform(m, p, j);
  const Floats sum = ((c[0] + c[1]) + c[2]) + c[3];
  const Mask finite = (sum - sum) == splat(0.0f);  // false for NaN and Inf
  const Floats g = splat(kGuardBand) * c[3], zero = splat(0.0f);
  const Ints planes = outside(c[2] + c[3] >= zero, kNear) | outside(c[3] - c[2] >= zero, kFar) |
                      outside(c[0] + g >= zero, kLeft) | outside(g - c[0] >= zero, kRight) |
                      outside(c[1] + g >= zero, kBottom) | outside(g - c[1] >= zero, kTop);
  const Ints code = (finite & planes) | (~finite & kNonFinite);

  const Mask valid = c[3] > zero;
  const Doubles inv = splat_double(1.0) / __builtin_convertvector(c[3], Doubles);
  const Doubles half = splat_double(0.5), sub = splat_double(double(kSubpixel));
  const Doubles cx = __builtin_convertvector(c[0], Doubles), cy = __builtin_convertvector(c[1], Doubles);
  const Doubles x = ((cx * inv * half + half) * splat_double(double(width))) * sub;
  const Doubles y = ((half - cy * inv * half) * splat_double(double(height))) * sub;
  constexpr double kLimit = double(1 << 30);
  const Ints xi = round_to_int(clamp(x, kLimit)) & valid, yi = round_to_int(clamp(y, kLimit)) & valid;
  const Floats depth = __builtin_convertvector(__builtin_convertvector(c[2], Doubles) * inv * half + half, Floats);
  const Floats inv_w = __builtin_convertvector(inv, Floats);
  const Floats depth_out = select(valid, depth, splat(1.0f)), inv_w_out = select(valid, inv_w, zero);

  if (out.clip)
    for (int k = 0; k < kLanes; ++k) out.clip[i + std::size_t(k)] = {c[0][k], c[1][k], c[2][k], c[3][k]};
  for (int k = 0; k < kLanes; ++k) {
    out.outcode[i + std::size_t(k)] = std::uint8_t(code[k]);
    out.xy[i + std::size_t(k)] = {xi[k], yi[k]};
  }
  std::memcpy(out.depth + i, &depth_out, sizeof depth_out);
  std::memcpy(out.inv_w + i, &inv_w_out, sizeof inv_w_out);
}

// Whole groups of kLanes vertices from the first. Clones for AVX-512 and AVX2 machines (8 lanes of doubles
// are one or two registers; SSE2 needs four and spills, so the baseline clone is not called:
// vertex_lanes::pay). The scalar tail stays outside the clones: GCC 12 left out the vzeroupper on a
// clone's return path through scalar code, and the dirty upper register state then slowed the SSE code
// that ran next on that thread (Phong's setup 1.5x).
__attribute__((target_clones("arch=x86-64-v4", "avx2", "default")))
void transform_groups(const glm::mat4& m, const glm::vec3* position, std::size_t groups, int width, int height,
                      const SnappedVertices& out) {
  for (std::size_t g = 0; g < groups; ++g) transform_lanes(m, position, width, height, g * kLanes, out);
}

}  // namespace

void transform_vertices(const glm::mat4& m, const glm::vec3* position, std::size_t count, int width, int height,
                        const SnappedVertices& out) {
  const std::size_t groups = vertex_lanes::pay() ? count / vertex_lanes::kLanes : 0;
  if (groups) transform_groups(m, position, groups, width, height, out);
  for (std::size_t i = groups * vertex_lanes::kLanes; i < count; ++i) {
    const glm::vec4 clip = m * glm::vec4(position[i], 1.0f);
    if (out.clip) out.clip[i] = clip;
    out.outcode[i] = outcode_of(clip);
    const Snapped s = snap(clip, width, height);
    out.xy[i] = s.xy;
    out.depth[i] = s.depth;
    out.inv_w[i] = s.inv_w;
  }
}

}  // namespace parashade
