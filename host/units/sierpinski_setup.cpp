#include "parashade/sierpinski_setup.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <stdexcept>
#include <vector>

#include "parashade/parallel.hpp"
#include "parashade/setup.hpp"

namespace parashade {
namespace {

using i64 = std::int64_t;
using v2 = glm::i64vec2;

// A sub-triangle of ABC at depth D, in the slot order of A, B, C: sign * S_D + t + T, where T is the top
// vertex and S_D the shaded sub-triangle's shape relative to it. Corner children keep the sign, the middle
// child flips it ([Malovanyi 2019, parallel Gouraud] ch. 3: AKM, KBL, MLC translated, LMK rotated by 180°).
struct Leaf {
  int sign;
  v2 t;  // sub-pixels, relative to the top vertex
};

// Half of a whole-pixel offset (sub-pixels), for the unit's grid: exact, or rounded toward zero (touch)
// or away from it (overlap) to whole pixels.
i64 half(i64 c, SierpinskiGrid grid) {
  if (grid == SierpinskiGrid::even || grid == SierpinskiGrid::odd) {
    if (c % (2 * i64(kSubpixel)) != 0) throw std::logic_error("sierpinski: geometry not normalized for this depth");
    return c / 2;
  }
  const i64 px = c / kSubpixel;
  const i64 halved = grid == SierpinskiGrid::touch ? px / 2 : (px + (px > 0) - (px < 0)) / 2;  // / truncates
  return halved * kSubpixel;
}

// shape[l][s]: the level-l sub-triangle's vertex s relative to the top vertex (shape[0] = ABC - T).
using Shapes = std::vector<std::array<v2, 3>>;

// Depth-first, the corner at the top vertex first, so that leaf 0 is the shaded sub-triangle. A corner
// child starts at the rounded midpoint (exact, touch) or ends at its own vertex (overlap); the middle
// child's corners are the top child's midpoints.
void collect(const Shapes& shape, int top, int level, int depth, SierpinskiGrid grid, Leaf node, std::vector<Leaf>& out) {
  if (level == depth) {
    out.push_back(node);
    return;
  }
  const auto& whole = shape[std::size_t(level)];
  const auto& halves = shape[std::size_t(level) + 1];
  const int order[3] = {top, (top + 1) % 3, (top + 2) % 3};
  for (int slot : order) {
    const v2 corner = grid == SierpinskiGrid::overlap ? whole[slot] - halves[slot] : halves[slot];
    collect(shape, top, level + 1, depth, grid, {node.sign, node.t + i64(node.sign) * corner}, out);
  }
  const v2 sum = halves[0] + halves[1] + halves[2];
  collect(shape, top, level + 1, depth, grid, {-node.sign, node.t + i64(node.sign) * sum}, out);
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
    if (!g.face.empty()) g.face[kept] = g.face[t];
    ++kept;
  }
  const std::uint64_t dropped = g.triangles.size() - kept;
  g.triangles.resize(kept);
  if (!g.material.empty()) g.material.resize(kept);
  if (!g.flat_color.empty()) g.flat_color.resize(kept);
  if (!g.face.empty()) g.face.resize(kept);
  return dropped;
}

std::uint64_t snap_sierpinski_vertices(ScreenGeometry& g, const UnitConfig& unit) {
  switch (unit.grid) {
    case SierpinskiGrid::even: return normalize_vertex_parity(g, unit.depth, false);
    case SierpinskiGrid::odd: return normalize_vertex_parity(g, unit.depth, true);
    case SierpinskiGrid::touch:
    case SierpinskiGrid::overlap: return normalize_vertex_parity(g, 0, false);
  }
  return 0;
}

std::uint64_t split_sierpinski(const ScreenGeometry& g, const UnitConfig& unit, const TriangleGeometry* in,
                               const float* attr_in, const FixedPlanes* fixed_in, TriangleGeometry* out,
                               float* attr_out, FixedPlanes* fixed_out, SierpinskiLeaf* leaf_out) {
  const int depth = unit.depth;
  const bool seal = unit.seal;
  const std::size_t leaves = std::size_t(1) << (2 * depth);
  std::atomic<std::uint64_t> degenerate{0};
  parallel_for_ranges(g.triangles.size(), 1024, [&](std::size_t first, std::size_t last) {
    std::vector<Leaf> sub;
    Shapes shape(std::size_t(depth) + 1);
    for (std::size_t t = first; t < last; ++t) {
      const glm::uvec3 tri = g.triangles[t];
      const v2 v[3] = {v2(g.xy[tri.x]), v2(g.xy[tri.y]), v2(g.xy[tri.z])};
      const TriangleGeometry& r = in[t];
      const float* a = attr_in + t * GOURAUD_ATTR_FLOATS;
      const int top = int(std::min_element(v, v + 3, [](v2 p, v2 q) { return p.y < q.y || (p.y == q.y && p.x < q.x); }) - v);
      const v2 apex = v[top];
      for (int k = 0; k < 3; ++k) shape[0][k] = v[k] - apex;
      for (int l = 1; l <= depth; ++l)
        for (int k = 0; k < 3; ++k)
          shape[std::size_t(l)][k] = v2(half(shape[std::size_t(l) - 1][k].x, unit.grid), half(shape[std::size_t(l) - 1][k].y, unit.grid));
      const auto& s_d = shape[std::size_t(depth)];
      const i64 area2 = (s_d[1].x - s_d[0].x) * (s_d[2].y - s_d[0].y) - (s_d[1].y - s_d[0].y) * (s_d[2].x - s_d[0].x);
      sub.clear();
      collect(shape, top, 0, depth, unit.grid, {1, v2(0)}, sub);
      Edge edge[3];
      v2 q[3];
      for (int k = 0; k < 3; ++k) q[k] = s_d[k] + apex;  // the shaded sub-triangle (leaf 0: t = 0)
      for (int e = 0; e < 3; ++e) {
        const v2 qi = q[e], qj = q[(e + 1) % 3];
        edge[e] = {qj.x - qi.x, qj.y - qi.y, qi.x, qi.y, edge_bias(glm::ivec2(qi), glm::ivec2(qj))};
      }

      if (area2 <= 0 && r.x0 <= r.x1) {
        // Too small to halve (remedy (b) rounds a short edge's half to nothing): the unit shades it whole,
        // as one record with a zero adder constant; the other records stay empty.
        degenerate.fetch_add(1, std::memory_order_relaxed);
        const std::size_t o = t * leaves;
        out[o] = r;
        std::copy(a, a + GOURAUD_ATTR_FLOATS, attr_out + o * GOURAUD_ATTR_FLOATS);
        if (fixed_out) fixed_out[o] = fixed_in[t];
        leaf_out[o] = SierpinskiLeaf{};
        leaf_out[o].sign = 1;
        leaf_out[o].shaded = 1;
        for (std::size_t k = 1; k < leaves; ++k) {
          out[o + k] = TriangleGeometry{};
          out[o + k].x0 = 1;  // empty box
          out[o + k].x1 = 0;
          if (fixed_out) fixed_out[o + k] = FixedPlanes{};
          leaf_out[o + k] = SierpinskiLeaf{};
        }
        continue;
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
        const v2 shift = leaf.sign > 0 ? leaf.t : leaf.t + i64(2) * apex;  // D, or C + (1, 1), in sub-pixels
        if (shift.x % kSubpixel != 0 || shift.y % kSubpixel != 0)
          throw std::logic_error("sierpinski: a sub-triangle is not a whole-pixel copy");
        const v2 shift_px = shift / i64(kSubpixel);
        i64 xmin = INT64_MAX, xmax = INT64_MIN, ymin = INT64_MAX, ymax = INT64_MIN;
        for (int s = 0; s < 3; ++s) {
          const v2 n = i64(leaf.sign) * s_d[s] + leaf.t + apex;
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
  return degenerate.load();
}

}  // namespace parashade
