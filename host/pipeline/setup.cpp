#include "parashade/setup.hpp"

#include "parashade/parallel.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>

namespace parashade {
namespace {

struct Plane {
  double ref, ddx, ddy;
};

// Affine functions over one triangle: the geometry shared by all its attribute planes is computed once.
struct PlaneBasis {
  glm::dvec2 e1, e2;   // b - a, c - a
  glm::dvec2 at;       // evaluation point - a
  double inv_det;
  PlaneBasis(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, glm::dvec2 point)
      : e1(b - a), e2(c - a), at(point - a), inv_det(1.0 / (e1.x * e2.y - e2.x * e1.y)) {}
  // The plane through values va, vb, vc at a, b, c, evaluated at the point.
  Plane plane(double va, double vb, double vc) const {
    const double d1 = vb - va, d2 = vc - va;
    const double ddx = (d1 * e2.y - d2 * e1.y) * inv_det;
    const double ddy = (d2 * e1.x - d1 * e2.x) * inv_det;
    return {va + ddx * at.x + ddy * at.y, ddx, ddy};
  }
};

void store(float* dst, int slot, const Plane& p0, const Plane& p1, const Plane& p2) {
  dst[slot + 0] = float(p0.ref);
  dst[slot + 1] = float(p1.ref);
  dst[slot + 2] = float(p2.ref);
  dst[slot + 3] = float(p0.ddx);
  dst[slot + 4] = float(p1.ddx);
  dst[slot + 5] = float(p2.ddx);
  dst[slot + 6] = float(p0.ddy);
  dst[slot + 7] = float(p1.ddy);
  dst[slot + 8] = float(p2.ddy);
}

}  // namespace

std::size_t attribute_floats(Method method) {
  switch (method) {
    case Method::flat: return FLAT_ATTR_FLOATS;
    case Method::gouraud: return GOURAUD_ATTR_FLOATS;
    case Method::phong:
    case Method::combined: return PHONG_ATTR_FLOATS;
  }
  return 0;
}

double constant_span_increment(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, double ia, double ib, double ic) {
  return ConstantSpanIncrement(a, b, c)(ia, ib, ic);
}

ConstantSpanIncrement::ConstantSpanIncrement(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c)
    : dy_bc(c.y - b.y), dy_ac(c.y - a.y), inv_denominator(1.0 / ((c.x - a.x) * (c.y - b.y) - (c.x - b.x) * (c.y - a.y))) {}

double constant_span_increment_longest_span(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, double ia, double ib,
                                            double ic) {
  // Sort by y so that B is the middle vertex and H lies on AC at y = y_B.
  struct V {
    glm::dvec2 p;
    double i;
  } v[3] = {{a, ia}, {b, ib}, {c, ic}};
  std::sort(v, v + 3, [](const V& l, const V& r) { return l.p.y < r.p.y; });
  const V &A = v[0], &B = v[1], &C = v[2];
  const double t = (B.p.y - A.p.y) / (C.p.y - A.p.y);  // = BP_AH / BP_AC along AC (similar triangles)
  const double x_h = t * (C.p.x - A.p.x) + A.p.x;
  const double i_h = A.i + (C.i - A.i) * t;             // I_A + dI_AC * BP_AH
  return (i_h - B.i) / (x_h - B.p.x);
}

void move_plane_anchor(const TriangleGeometry& from, const float* attr, const FixedPlanes* fixed, int x0, int y0,
                       TriangleGeometry& to, float* attr_to, FixedPlanes* fixed_to) {
  const double dx = double(x0 - from.x0), dy = double(y0 - from.y0);
  to.z_ref = float(double(from.z_ref) + double(from.z_ddx) * dx + double(from.z_ddy) * dy);
  to.z_ddx = from.z_ddx;
  to.z_ddy = from.z_ddy;
  std::copy(attr, attr + GOURAUD_ATTR_FLOATS, attr_to);
  for (int c = 0; c < 3; ++c) attr_to[c] = float(double(attr[c]) + double(attr[3 + c]) * dx + double(attr[6 + c]) * dy);
  if (!fixed || !fixed_to) return;
  *fixed_to = *fixed;
  for (int c = 0; c < 3; ++c)
    fixed_to->ref[c] = plane_value(fixed->ref[c], fixed->ddx[c], fixed->ddy[c], x0 - from.x0, y0 - from.y0);
}

std::int64_t to_plane_register(double levels) {
  const double v = std::isnan(levels) ? 0.0 : std::clamp(levels, -kPlaneLimit, kPlaneLimit);
  // Times 2^PLANE_FRAC: a power of two, so the product is exact (ldexp gives the same, as a call).
  return std::llround(v * double(std::uint64_t(1) << PLANE_FRAC));
}

SetupStats setup_triangles(const ScreenGeometry& g, Method method, TriangleGeometry* geometry, float* attributes,
                           FixedPlanes* fixed, const TriangleShading* gouraud) {
  const std::size_t count = g.triangles.size();
  std::atomic<std::uint64_t> without_pixels{0};
  parallel_for_ranges(count, balanced_chunk(count, 2048, 4096), [&](std::size_t first, std::size_t last) {
    without_pixels += setup_triangle_range(g, method, geometry, attributes, fixed, gouraud, first, last);
  });
  return {std::uint64_t(count), without_pixels.load()};
}

std::uint64_t setup_triangle_range(const ScreenGeometry& g, Method method, TriangleGeometry* geometry,
                                   float* attributes, FixedPlanes* fixed, const TriangleShading* gouraud,
                                   std::size_t first, std::size_t last, const std::uint32_t* order) {
  const std::size_t stride = attribute_floats(method);
  const bool has_position = !g.world.empty();
  std::uint64_t empty = 0;
  for (std::size_t rec = first; rec < last; ++rec) {
    const std::size_t t = order ? order[rec] : rec;  // the screen triangle of this record
    const glm::uvec3 tri = g.triangles[t];
    const std::uint32_t vid[3] = {tri.x, tri.y, tri.z};
    const glm::i64vec2 p[3] = {glm::i64vec2(g.xy[tri.x]), glm::i64vec2(g.xy[tri.y]), glm::i64vec2(g.xy[tri.z])};
    TriangleGeometry& r = geometry[rec];
    float* attr = attributes + rec * stride;

    const std::int64_t half = kSubpixel / 2;
    const std::int64_t xmin = std::min({p[0].x, p[1].x, p[2].x}), xmax = std::max({p[0].x, p[1].x, p[2].x});
    const std::int64_t ymin = std::min({p[0].y, p[1].y, p[2].y}), ymax = std::max({p[0].y, p[1].y, p[2].y});
    const auto [x0, y0, x1, y1] = centre_box(xmin, xmax, ymin, ymax, g.width, g.height);
    if (x0 > x1 || y0 > y1) {
      r = TriangleGeometry{};
      r.x0 = 1;  // empty box
      r.x1 = 0;
      if (fixed) fixed[rec] = FixedPlanes{};
      ++empty;
      continue;
    }
    r.x0 = ps_short(x0);
    r.y0 = ps_short(y0);
    r.x1 = ps_short(x1);
    r.y1 = ps_short(y1);
    const bool small = xmax - xmin <= SMALL_EXTENT * kSubpixel && ymax - ymin <= SMALL_EXTENT * kSubpixel;
    r.flags = small ? TRIANGLE_SMALL : 0;
    const std::int64_t cx = kSubpixel * x0 + half, cy = kSubpixel * y0 + half;
    for (int e = 0; e < 3; ++e) {
      const glm::i64vec2 vi = p[e], vj = p[(e + 1) % 3];
      const std::int64_t dx = vj.x - vi.x, dy = vj.y - vi.y;
      r.edge_c[e] = dx * (cy - vi.y) - dy * (cx - vi.x) - edge_bias(glm::ivec2(vi), glm::ivec2(vj));
      r.edge_a[e] = ps_int(-dy * kSubpixel);
      r.edge_b[e] = ps_int(dx * kSubpixel);
    }

    const glm::dvec2 s[3] = {glm::dvec2(p[0]) / double(kSubpixel), glm::dvec2(p[1]) / double(kSubpixel),
                             glm::dvec2(p[2]) / double(kSubpixel)};
    const glm::dvec2 at(double(x0) + 0.5, double(y0) + 0.5);
    const PlaneBasis basis(s[0], s[1], s[2], at);
    const auto plane = [&](double a, double b, double c) { return basis.plane(a, b, c); };
    const Plane z = plane(g.depth[vid[0]], g.depth[vid[1]], g.depth[vid[2]]);
    r.z_ref = float(z.ref);
    r.z_ddx = float(z.ddx);
    r.z_ddy = float(z.ddy);

    // Gouraud's colour planes (also the combined method's triangles given to Gouraud).
    const auto colour_planes = [&] {
      std::array<Plane, 3> ch;
      const ConstantSpanIncrement span_increment(s[0], s[1], s[2]);
      for (int k = 0; k < 3; ++k) {
        const double ia = g.color[vid[0]][k], ib = g.color[vid[1]][k], ic = g.color[vid[2]][k];
        ch[k] = plane(ia, ib, ic);
        ch[k].ddx = span_increment(ia, ib, ic);  // dI_G, once per triangle (formula 2.16)
      }
      return ch;
    };
    switch (method) {
      case Method::flat: {
        const glm::vec3 c = g.flat_color[t];
        attr[0] = c.r;
        attr[1] = c.g;
        attr[2] = c.b;
        attr[3] = 0.0f;
        break;
      }
      case Method::gouraud: {
        const auto ch = colour_planes();
        store(attr, 0, ch[0], ch[1], ch[2]);
        if (fixed) {
          for (int k = 0; k < 3; ++k) {
            fixed[rec].ref[k] = to_plane_register(ch[k].ref);
            fixed[rec].ddx[k] = to_plane_register(ch[k].ddx);
            fixed[rec].ddy[k] = to_plane_register(ch[k].ddy);
          }
        }
        break;
      }
      case Method::phong:
      case Method::combined: {  // the same planes; the kernel shades differently
        attr[PHONG_MATERIAL_SLOT] = float(g.material[t]);
        // Filled later where the choice or the highlight test runs.
        attr[PHONG_HIGHLIGHT_SLOT] = attr[PHONG_METHOD_SLOT] = attr[PHONG_PSI_SLOT] = 0.0f;
        if (gouraud && gouraud[t].method == TriangleMethod::gouraud) {
          // The combined method's per-triangle choice: Gouraud's colour planes. Such a triangle is shaded from
          // them alone, in the walk, never by a deferred tile's winners: no normal or position planes (a quarter
          // of setup's time on the sphere).
          const auto ch = colour_planes();
          store(attr, 0, ch[0], ch[1], ch[2]);
          std::fill(attr + 9, attr + 18, 0.0f);
          break;
        }
        Plane n[3], q[3];
        for (int k = 0; k < 3; ++k) {
          n[k] = plane(g.normal[vid[0]][k], g.normal[vid[1]][k], g.normal[vid[2]][k]);
          q[k] = has_position ? plane(g.world[vid[0]][k], g.world[vid[1]][k], g.world[vid[2]][k]) : Plane{0, 0, 0};
        }
        store(attr, 0, n[0], n[1], n[2]);
        store(attr, 9, q[0], q[1], q[2]);
        if (fixed) {  // the normal's components for a unit's registers (fixed_point.h)
          for (int k = 0; k < 3; ++k) {
            fixed[rec].ref[k] = to_plane_register(NORMAL_REGISTER_LEVELS * n[k].ref);
            fixed[rec].ddx[k] = to_plane_register(NORMAL_REGISTER_LEVELS * n[k].ddx);
            fixed[rec].ddy[k] = to_plane_register(NORMAL_REGISTER_LEVELS * n[k].ddy);
          }
        }
        break;
      }
    }
  }
  return empty;
}

}  // namespace parashade
