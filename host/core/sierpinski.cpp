#include "parashade/sierpinski.hpp"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "parashade/parallel.hpp"
#include "parashade/setup.hpp"

namespace parashade {
namespace {

using i64 = std::int64_t;
using v2 = glm::i64vec2;

// A sub-triangle of ABC at depth D, in the slot order of A, B, C: sign * (ABC) / 2^D + t. Corner children
// keep the sign, the middle child flips it (SEEDS §4: AKM, KBL, MLC translated, LMK rotated by 180°).
struct Leaf {
  int sign;
  v2 t;  // sub-pixels
};

v2 exact_half_power(v2 v, int shift) {
  const i64 d = i64(1) << shift;
  if (v.x % d != 0 || v.y % d != 0) throw std::logic_error("sierpinski: geometry not normalized for this depth");
  return v / d;
}

// Depth-first, the corner at the top vertex first, so that leaf 0 is the shaded sub-triangle.
void collect(const v2 v[3], int top, int level, int depth, Leaf node, std::vector<Leaf>& out) {
  if (level == depth) {
    out.push_back(node);
    return;
  }
  const int order[3] = {top, (top + 1) % 3, (top + 2) % 3};
  for (int slot : order)
    collect(v, top, level + 1, depth, {node.sign, node.t + i64(node.sign) * exact_half_power(v[slot], level + 1)}, out);
  const v2 sum = v[0] + v[1] + v[2];
  collect(v, top, level + 1, depth, {-node.sign, node.t + i64(node.sign) * exact_half_power(sum, level + 1)}, out);
}

// The shaded sub-triangle's edge e: E(q) = dx (qy - yi) - dy (qx - xi), q in sub-pixels, and its
// top-left bias. A point reflection keeps the winding and E(C - p) is the reflected edge's own edge
// function; the reflected edge runs the other way, so its own bias is the other one.
struct Edge {
  i64 dx, dy, xi, yi, bias;
  i64 at(v2 q) const { return dx * (q.y - yi) - dy * (q.x - xi); }
};

i64 snap(i64 c, i64 period, i64 residue) { return floor_div(c - residue + period / 2, period) * period + residue; }

}  // namespace

std::uint64_t normalize_vertex_parity(ScreenGeometry& g, int depth, bool odd) {
  const i64 period = i64(kSubpixel) << depth, residue = odd ? kSubpixel : 0;
  for (glm::ivec2& p : g.xy) p = glm::ivec2(int(snap(p.x, period, residue)), int(snap(p.y, period, residue)));
  std::size_t kept = 0;
  for (std::size_t t = 0; t < g.triangles.size(); ++t) {
    const glm::uvec3 tri = g.triangles[t];
    const v2 a(g.xy[tri.x]), b(g.xy[tri.y]), c(g.xy[tri.z]);
    const i64 area2 = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);  // E01(V2), > 0 before snapping
    if (area2 <= 0) continue;
    g.triangles[kept] = tri;
    if (!g.material.empty()) g.material[kept] = g.material[t];
    if (!g.flat_color.empty()) g.flat_color[kept] = g.flat_color[t];
    ++kept;
  }
  const std::uint64_t dropped = g.triangles.size() - kept;
  g.triangles.resize(kept);
  if (!g.material.empty()) g.material.resize(kept);
  if (!g.flat_color.empty()) g.flat_color.resize(kept);
  return dropped;
}

void split_sierpinski(const ScreenGeometry& g, int depth, bool seal, const TriangleGeometry* in, const float* attr_in,
                      const FixedPlanes* fixed_in, TriangleGeometry* out, float* attr_out, FixedPlanes* fixed_out,
                      SierpinskiLeaf* leaf_out) {
  const std::size_t leaves = std::size_t(1) << (2 * depth);
  parallel_for_ranges(g.triangles.size(), 1024, [&](std::size_t first, std::size_t last) {
    std::vector<Leaf> sub;
    for (std::size_t t = first; t < last; ++t) {
      const glm::uvec3 tri = g.triangles[t];
      const v2 v[3] = {v2(g.xy[tri.x]), v2(g.xy[tri.y]), v2(g.xy[tri.z])};
      const TriangleGeometry& r = in[t];
      const float* a = attr_in + t * GOURAUD_ATTR_FLOATS;
      const int top = int(std::min_element(v, v + 3, [](v2 p, v2 q) { return p.y < q.y || (p.y == q.y && p.x < q.x); }) - v);
      sub.clear();
      collect(v, top, 0, depth, {1, v2(0)}, sub);
      const v2 t0 = sub[0].t;
      Edge edge[3];
      v2 q[3];
      for (int k = 0; k < 3; ++k) q[k] = exact_half_power(v[k], depth) + t0;  // the shaded sub-triangle
      for (int e = 0; e < 3; ++e) {
        const v2 qi = q[e], qj = q[(e + 1) % 3];
        edge[e] = {qj.x - qi.x, qj.y - qi.y, qi.x, qi.y, edge_bias(glm::ivec2(qi), glm::ivec2(qj))};
      }

      for (std::size_t k = 0; k < leaves; ++k) {
        const std::size_t o = t * leaves + k;
        TriangleGeometry& lr = out[o];
        const Leaf& leaf = sub[k];
        SierpinskiLeaf& info = leaf_out[o];
        info = SierpinskiLeaf{};
        info.sign = leaf.sign;
        info.shaded = k == 0;
        // The map from this sub-triangle's pixels to the shaded one's: P - D, or C - P (pixel indices).
        const v2 shift = leaf.sign > 0 ? leaf.t - t0 : leaf.t + t0;  // D, or C + (1, 1), in sub-pixels
        if (shift.x % kSubpixel != 0 || shift.y % kSubpixel != 0)
          throw std::logic_error("sierpinski: a sub-triangle is not a whole-pixel copy");
        const v2 shift_px = shift / i64(kSubpixel);
        i64 xmin = INT64_MAX, xmax = INT64_MIN, ymin = INT64_MAX, ymax = INT64_MIN;
        for (int s = 0; s < 3; ++s) {
          const v2 n = i64(leaf.sign) * exact_half_power(v[s], depth) + leaf.t;
          xmin = std::min(xmin, n.x), xmax = std::max(xmax, n.x), ymin = std::min(ymin, n.y), ymax = std::max(ymax, n.y);
        }
        const auto [x0, y0, x1, y1] = centre_box(xmin, xmax, ymin, ymax, g.width, g.height);
        if (r.x0 > r.x1 || x0 > x1 || y0 > y1) {
          lr = TriangleGeometry{};
          lr.x0 = 1;  // empty box
          lr.x1 = 0;
          if (fixed_out) fixed_out[o] = FixedPlanes{};
          continue;
        }
        lr.x0 = ps_short(x0), lr.y0 = ps_short(y0), lr.x1 = ps_short(x1), lr.y1 = ps_short(y1);
        lr.flags = 0;
        const v2 corner(i64(kSubpixel) * x0 + kSubpixel / 2, i64(kSubpixel) * y0 + kSubpixel / 2);
        for (int e = 0; e < 3; ++e) {
          const Edge& E = edge[e];
          const i64 bias = leaf.sign < 0 && seal ? 1 - E.bias : E.bias;
          lr.edge_c[e] = (leaf.sign > 0 ? E.at(corner - shift) : E.at(shift - corner)) - bias;
          lr.edge_a[e] = ps_int(-leaf.sign * E.dy * kSubpixel);
          lr.edge_b[e] = ps_int(leaf.sign * E.dx * kSubpixel);
          lr.edge_inv_a[e] = lr.edge_a[e] != 0 ? 1.0f / float(lr.edge_a[e]) : 0.0f;
        }
        // Depth and the float planes: the triangle's own, at this record's corner (the ideal values).
        move_plane_anchor(r, a, nullptr, int(x0), int(y0), lr, attr_out + o * GOURAUD_ATTR_FLOATS, nullptr);
        if (!fixed_out) continue;
        // Fixed planes seen through the map, and the copy's adder constant (modular 64-bit, exact).
        const FixedPlanes& p = fixed_in[t];
        FixedPlanes& lp = fixed_out[o];
        // Pixel indices of this record's corner in the original record's box, mapped to the shaded one.
        const i64 mx = leaf.sign > 0 ? x0 - shift_px.x : shift_px.x - 1 - x0;
        const i64 my = leaf.sign > 0 ? y0 - shift_px.y : shift_px.y - 1 - y0;
        for (int c = 0; c < 3; ++c) {
          const auto u = [](i64 x) { return std::uint64_t(x); };
          lp.ref[c] = plane_value(p.ref[c], p.ddx[c], p.ddy[c], ps_int(mx - r.x0), ps_int(my - r.y0));
          lp.ddx[c] = leaf.sign > 0 ? p.ddx[c] : i64(0 - u(p.ddx[c]));
          lp.ddy[c] = leaf.sign > 0 ? p.ddy[c] : i64(0 - u(p.ddy[c]));
          if (leaf.sign > 0)  // I(P) - I(P - D)
            info.offset[c] = i64(u(p.ddx[c]) * u(shift_px.x) + u(p.ddy[c]) * u(shift_px.y));
          else  // I(P) + I(C - P), C = shift_px - (1, 1)
            info.offset[c] = i64(2 * u(p.ref[c]) + u(p.ddx[c]) * u(shift_px.x - 1 - 2 * r.x0) +
                                 u(p.ddy[c]) * u(shift_px.y - 1 - 2 * r.y0));
        }
      }
    }
  });
}

}  // namespace parashade
