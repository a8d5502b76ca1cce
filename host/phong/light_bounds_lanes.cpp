#include "parashade/light_bounds_lanes.hpp"

#include "parashade/lane_vectors.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>

#include <glm/glm.hpp>

namespace parashade {
namespace {

__attribute__((always_inline)) inline float lmin(float a, float b) { return a < b ? a : b; }
__attribute__((always_inline)) inline float lmax(float a, float b) { return a > b ? a : b; }
// sqrt(max(0, x)) without a select: GCC splits sqrt(select) into a branch around the sqrt, which stops the
// loop's vectorization. Clearing x when its sign bit is set is an integer mask instead.
__attribute__((always_inline)) inline float sqrt0(float x) {
  std::int32_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  bits &= ~(bits >> 31);
  std::memcpy(&x, &bits, sizeof x);
  return std::sqrt(x);
}

// Squared distance from the origin to the segment a + t (b - a), t in [0, 1].
__attribute__((always_inline)) inline float segment_distance2(float ax, float ay, float az, float bx, float by, float bz) {
  const float ex = bx - ax, ey = by - ay, ez = bz - az;
  const float e2 = ex * ex + ey * ey + ez * ez;
  const float t = e2 > 0.0f ? lmin(1.0f, lmax(0.0f, -(ax * ex + ay * ey + az * ez) / e2)) : 0.0f;
  const float px = ax + t * ex, py = ay + t * ey, pz = az + t * ez;
  return px * px + py * py + pz * pz;
}

}  // namespace

// Cloned for AVX2 (picked at load time where the CPU has it): three-operand vector instructions spare the
// register copies of SSE2, ~1.2x on the whole choice (bench_triangle_choice).
__attribute__((target_clones("avx2", "default"))) void frame_lanes(const Scene& s, const ScreenGeometry& g, std::size_t first, int count, FrameLanes& f) {
  const bool distant_viewer = !s.viewer_is_local();
  const bool have_world = g.world.size() == g.normal.size();
  f.count = count;
  for (int j = 0; j < kLanes; ++j) {  // gather (lanes past count repeat the first triangle)
    const std::size_t t = first + std::size_t(j < count ? j : 0);
    const glm::uvec3 idx = g.triangles[t];
    f.material[j] = g.material[t];
    const std::uint32_t vid[3] = {idx.x, idx.y, idx.z};
    bool usable = distant_viewer || have_world;
    for (int k = 0; k < 3; ++k) {
      glm::vec3 n = g.normal[vid[k]];
      const float len2 = glm::dot(n, n);
      usable = usable && len2 > 1e-24f && std::isfinite(len2);
      // Scene vertices carry unit normals (to float precision); clip-made ones are interpolations.
      if (std::abs(len2 - 1.0f) > 1e-6f && len2 > 0.0f) n *= 1.0f / std::sqrt(len2);
      const glm::vec3 w = vid[k] < g.world.size() ? g.world[vid[k]] : glm::vec3(0.0f);
      for (int c = 0; c < 3; ++c) {
        f.n[k][c][j] = usable ? n[c] : (c == 2 ? 1.0f : 0.0f);
        f.w[k][c][j] = w[c];
      }
    }
    f.usable[j] = usable ? 1.0f : 0.0f;
  }
  const glm::vec3 eye = s.camera.position, view_dir = glm::normalize(s.camera.position - s.camera.target);
#pragma omp simd
  for (int j = 0; j < kLanes; ++j) {
    float dot01 = 0, dot12 = 0, dot20 = 0, sum[3], cen[3];
    for (int c = 0; c < 3; ++c) {
      dot01 += f.n[0][c][j] * f.n[1][c][j];
      dot12 += f.n[1][c][j] * f.n[2][c][j];
      dot20 += f.n[2][c][j] * f.n[0][c][j];
      sum[c] = f.n[0][c][j] + f.n[1][c][j] + f.n[2][c][j];
      cen[c] = (f.w[0][c][j] + f.w[1][c][j] + f.w[2][c][j]) * (1.0f / 3.0f);
    }
    f.cos_spread[j] = lmin(dot01, lmin(dot12, dot20)) - 4e-7f;  // float dots of float unit vectors: a few ulps
    const float len = std::sqrt(sum[0] * sum[0] + sum[1] * sum[1] + sum[2] * sum[2]);
    const float inv = len > 1e-12f ? 1.0f / len : 0.0f;
    float c0 = 0, c1 = 0, c2 = 0, r2 = 0;
    for (int c = 0; c < 3; ++c) {
      f.normal_centre[c][j] = sum[c] * inv;
      c0 += f.normal_centre[c][j] * f.n[0][c][j];
      c1 += f.normal_centre[c][j] * f.n[1][c][j];
      c2 += f.normal_centre[c][j] * f.n[2][c][j];
      f.centroid[c][j] = cen[c];
    }
    const float cos_half = len > 1e-12f ? lmin(c0, lmin(c1, c2)) - 1e-6f : -1.0f;
    f.cos_half[j] = cos_half;
    f.sin_half[j] = sqrt0((1.0f - cos_half * cos_half));
    for (int k = 0; k < 3; ++k) {
      const float dx = f.w[k][0][j] - cen[0], dy = f.w[k][1][j] - cen[1], dz = f.w[k][2][j] - cen[2];
      r2 = lmax(r2, dx * dx + dy * dy + dz * dz);
    }
    f.radius[j] = std::sqrt(r2) * 1.00001f;
    // The viewer: a constant direction, or the eye's direction at the centroid within a chord.
    const float vx = eye.x - cen[0], vy = eye.y - cen[1], vz = eye.z - cen[2];
    const float dist = std::sqrt(vx * vx + vy * vy + vz * vz);
    const float vinv = dist > 0.0f ? 1.0f / dist : 0.0f;
    f.view[0][j] = distant_viewer ? view_dir.x : vx * vinv;
    f.view[1][j] = distant_viewer ? view_dir.y : vy * vinv;
    f.view[2][j] = distant_viewer ? view_dir.z : vz * vinv;
    f.view_chord[j] = distant_viewer ? 0.0f : (dist > 0.0f ? lmin(2.0f, 2.0f * f.radius[j] * vinv) : 2.0f);
    // min |N'|: the origin's squared distance to the three edges and, when its projection falls inside,
    // to the plane of the normal tips.
    const float ax = f.n[0][0][j], ay = f.n[0][1][j], az = f.n[0][2][j];
    const float bx = f.n[1][0][j], by = f.n[1][1][j], bz = f.n[1][2][j];
    const float cx = f.n[2][0][j], cy = f.n[2][1][j], cz = f.n[2][2][j];
    float d2 = lmin(segment_distance2(ax, ay, az, bx, by, bz),
                    lmin(segment_distance2(bx, by, bz, cx, cy, cz), segment_distance2(cx, cy, cz, ax, ay, az)));
    const float ux = bx - ax, uy = by - ay, uz = bz - az, wx = cx - ax, wy = cy - ay, wz = cz - az;
    const float mx = uy * wz - uz * wy, my = uz * wx - ux * wz, mz = ux * wy - uy * wx;
    const float m2 = mx * mx + my * my + mz * mz, am = ax * mx + ay * my + az * mz;
    // The origin projects inside when it sees the three edges turning the same way as m.
    const float s0 = mx * (ay * bz - az * by) + my * (az * bx - ax * bz) + mz * (ax * by - ay * bx);
    const float s1 = mx * (by * cz - bz * cy) + my * (bz * cx - bx * cz) + mz * (bx * cy - by * cx);
    const float s2 = mx * (cy * az - cz * ay) + my * (cz * ax - cx * az) + mz * (cx * ay - cy * ax);
    const bool inside = (m2 > 1e-20f) & (((s0 >= 0) & (s1 >= 0) & (s2 >= 0)) | ((s0 <= 0) & (s1 <= 0) & (s2 <= 0)));
    d2 = inside ? lmin(d2, am * am / (m2 > 0.0f ? m2 : 1.0f)) : d2;
    f.min_normal[j] = lmax(0.0f, std::sqrt(d2) - 1e-6f);
  }
}

namespace {

// The per-light bounds are written on GCC's vector types (lane_vectors.hpp) rather than left to the
// auto-vectorizer: with its many selects GCC gave up on the loop ("control flow in loop"). W lanes a vector.
template <int W>
struct LightLanesOf : lanes::Lanes<W> {
  PARASHADE_USING_LANES(W);

  // cone_gap on lanes (light_bounds.cpp, by cosines): largest N.D over the normals' cone (cos_n, sin_n,
  // centre c) and D within the angle beta (sin beta = s) of the unit d.
  static PARASHADE_LANE vf cone_gap(vf cos_n, vf sin_n, vf dx, vf dy, vf dz, vf cx, vf cy, vf cz, vf s) {
    const vf cos_b = vsqrt0(1.0f - s * s);
    const vf cos_r = cos_n * cos_b - sin_n * s, sin_r = sin_n * cos_b + cos_n * s;
    const vf cos_t = cx * dx + cy * dy + cz * dz, sin_t = vsqrt0(1.0f - cos_t * cos_t);
    const vi gap = (cos_n > 0.0f) & (s < 1.0f) & (cos_t < cos_r);
    return gap ? vmin(splat(1.0f), cos_t * cos_r + sin_t * sin_r + 1e-5f) : splat(1.0f);
  }

  template <bool directional>
  static PARASHADE_LANE void of(const FrameLanes& f, const glm::vec3 dir, const glm::vec3 pos, LightLanes& out) {
    for (int at = 0; at < kLanes; at += kWidth) {
      const vf radius = load(f.radius, at);
      // L at the centroid, within a chord over the triangle (light_bounds.hpp).
      const vf dx = pos.x - load(f.centroid[0], at), dy = pos.y - load(f.centroid[1], at), dz = pos.z - load(f.centroid[2], at);
      const vf dist = vsqrt(dx * dx + dy * dy + dz * dz);
      const vf inv = dist > 0.0f ? 1.0f / dist : splat(0.0f);
      const vi near = directional ? vi{} : ~(dist > 2.0f * radius);  // also where dist is NaN
      const vf lx = directional ? splat(dir.x) : dx * inv, ly = directional ? splat(dir.y) : dy * inv,
               lz = directional ? splat(dir.z) : dz * inv;
      const vf chord = directional ? splat(0.0f) : (near ? splat(2.0f) : 2.0f * radius * inv * 1.00001f);
      store(out.chord, at, chord);
      const vf ch = load(f.cos_half, at), sh = load(f.sin_half, at);
      const vf ncx = load(f.normal_centre[0], at), ncy = load(f.normal_centre[1], at), ncz = load(f.normal_centre[2], at);
      const vi usable = (load(f.usable, at) > 0.0f) & ~near;
      const vf max_n_dot_l = usable ? cone_gap(ch, sh, lx, ly, lz, ncx, ncy, ncz, chord * vsqrt0(1.0f - 0.25f * chord * chord))
                                    : splat(1.0f);
      // H within asin(ratio) of normalize(c_L + c_V).
      const vf hx = lx + load(f.view[0], at), hy = ly + load(f.view[1], at), hz = lz + load(f.view[2], at);
      const vf hl = vsqrt(hx * hx + hy * hy + hz * hz);
      const vi h_ok = hl > 0.0f;
      const vf hinv = h_ok ? 1.0f / hl : splat(0.0f);
      const vf ratio = h_ok ? (chord + load(f.view_chord, at)) * hinv * 1.00001f : splat(1.0f);
      const vi h_bounded = usable & (ratio < 1.0f);
      store(out.sin_h_radius, at, h_bounded ? ratio : splat(1.0f));
      // |L + V| >= |c_L + c_V| - chord_L - chord_V, rounded down.
      store(out.half_min, at, h_bounded ? vmax(splat(0.0f), hl * (1.0f - ratio) * 0.9999f - 1e-6f) : splat(0.0f));
      store(out.max_n_dot_h, at, h_bounded ? cone_gap(ch, sh, hx * hinv, hy * hinv, hz * hinv, ncx, ncy, ncz, vmin(ratio, splat(1.0f)))
                                       : splat(1.0f));
      // The terminator: N'.D' = sum b_i b_j n_i.d_j is positive (negative) where every pair is; float
      // rounding is kept out by a margin relative to |d|.
      vf n[3][3];
      for (int k = 0; k < 3; ++k)
        for (int c = 0; c < 3; ++c) n[k][c] = load(f.n[k][c], at);
      vf low_c = splat(1.0f), high_c = splat(-1.0f);
      for (int k = 0; k < 3; ++k) {
        const vf v = n[k][0] * lx + n[k][1] * ly + n[k][2] * lz;
        low_c = vmin(low_c, v);
        high_c = vmax(high_c, v);
      }
      vf lo = low_c, hi = high_c;
      if (!directional) {  // n_i.(P - w_k) for the nine pairs
        lo = splat(1e30f);
        hi = splat(-1e30f);
        for (int w = 0; w < 3; ++w) {
          const vf qx = pos.x - load(f.w[w][0], at), qy = pos.y - load(f.w[w][1], at), qz = pos.z - load(f.w[w][2], at);
          for (int k = 0; k < 3; ++k) {
            const vf v = n[k][0] * qx + n[k][1] * qy + n[k][2] * qz;
            lo = vmin(lo, v);
            hi = vmax(hi, v);
          }
        }
      }
      const vf margin = directional ? splat(1e-5f) : 1e-5f * (dist + radius + 1.0f);
      const vi lit = usable & (lo > margin), dark = usable & (hi < -margin) & ~lit;
      const vf lit_w = weight(lit), dark_w = weight(dark);
      store(out.state, at, 2.0f - 2.0f * lit_w - dark_w);
      // Lit: the three terms of docs/triangle-choice.md §2 (Gouraud - Phong), rounded up.
      const vf c_n = vsqrt0(2.0f - 2.0f * load(f.cos_spread, at));
      const vf c_l = vmin(splat(2.0f), 2.0f * chord);
      const vf rho = directional ? splat(1.0f) : (dist + radius) / vmax(splat(1e-30f), dist - radius);
      const vf min_light = vsqrt(vmax(splat(1e-6f), 1.0f - c_l * c_l / 3.0f));
      const vf bound = c_n * c_l / 3.0f + (1.0f - load(f.min_normal, at)) * vmin(splat(1.0f), vmax(splat(0.0f), max_n_dot_l)) +
                       (1.0f - min_light) + (rho - 1.0f) * c_l / min_light;
      // Where the weights are 0 the products must not be NaN: vmin(x, 1) is 1 for a NaN x, vmax(x, 0) is 0.
      store(out.diffuse, at, lit_w * vmin(bound * 1.0001f + 1e-6f, splat(1.0f)) + (1.0f - lit_w - dark_w));
      store(out.terminator_distance, at, lit_w * vmax(low_c - chord, splat(0.0f)) + dark_w * vmax(-high_c - chord, splat(0.0f)));
    }
  }

  static PARASHADE_LANE void run(const FrameLanes& f, const Light& l, LightLanes& out) {
    if (l.type == LightType::directional) of<true>(f, -glm::normalize(l.direction), glm::vec3(0.0f), out);
    else of<false>(f, glm::vec3(0.0f), l.position, out);
  }
};

__attribute__((target("avx2"))) void light_lanes_avx2(const FrameLanes& f, const Light& l, LightLanes& out) {
  LightLanesOf<8>::run(f, l, out);
}

void light_lanes_sse(const FrameLanes& f, const Light& l, LightLanes& out) { LightLanesOf<4>::run(f, l, out); }

std::atomic<bool> four_only{false};

}  // namespace

void four_float_lanes_only(bool only) { four_only = only; }

bool lanes::avx2_lanes() {
  static const bool cpu = __builtin_cpu_supports("avx2");
  return cpu && !four_only.load(std::memory_order_relaxed);
}

void light_lanes(const FrameLanes& f, const Light& l, LightLanes& out) {
  if (lanes::avx2_lanes()) light_lanes_avx2(f, l, out);
  else light_lanes_sse(f, l, out);
}

}  // namespace parashade
