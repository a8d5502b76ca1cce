// Wraps and saturations of the span registers over a prepared frame (register_events.hpp): each span of
// each record through its unit's golden model, as tests/cl/unit_golden_test.cpp checks the kernels against.
#include "parashade/register_events.hpp"

#include <cmath>
#include <cstdint>

#include "parashade/golden_units.hpp"
#include "parashade/planner.hpp"

namespace parashade {
namespace {

// A plane value (PLANE_FRAC fraction bits) rounded to the register's F fraction bits as load_register
// does, but not saturated: it saturated when this does not fit W bits.
bool load_saturates(std::int64_t v, const Arithmetic& a) {
  const int shift = PLANE_FRAC - a.frac_bits;
  const std::int64_t rounded = (v >> shift) + ((v >> (shift - 1)) & 1);
  return rounded != saturate_register(rounded, a.width());
}

// The exact value, in setup's plane format, that pixel dx of row dy of a record stands for: its plane, or
// for a sierpinski copy the shaded sub-triangle's plane through the copy's adder (sierpinski_leaf.h).
std::int64_t exact_plane_value(const FixedPlanes& p, int c, int dx, int dy, const SierpinskiLeaf* leaf) {
  const std::int64_t v = plane_value(p.ref[c], p.ddx[c], p.ddy[c], dx, dy);
  if (!leaf) return v;
  const std::uint64_t offset = std::uint64_t(leaf->offset[c]);
  return std::int64_t(leaf->sign < 0 ? offset - std::uint64_t(v) : offset + std::uint64_t(v));
}

class Counter {
 public:
  Counter(const FrameConfig& config) : unit_(config.unit()), arith_(config.arith), division_(config.division) {}

  void span(const FixedPlanes& p, const SierpinskiLeaf* leaf, int xl, int xr, int dy) {
    ++events_.spans;
    events_.span_pixels += std::uint64_t(xr - xl + 1);
    bool span_wrapped = false;
    wrapped_.assign(std::size_t(xr - xl + 1), 0);
    for (int c = 0; c < 3; ++c) {
      events_.saturated_loads += load_saturates(plane_value(p.ref[c], p.ddx[c], p.ddy[c], xl, dy), arith_);
      events_.saturated_loads += load_saturates(plane_value(p.ref[c], p.ddx[c], p.ddy[c], xr, dy), arith_);
      events_.saturated_loads += load_saturates(p.ddx[c], arith_);
      // A sierpinski copy's adder takes an offset register too (sierpinski_leaf.h: I(P) - I(P - D), or
      // I(P) + I(C - P) for a reflected copy, up to twice the span's values): saturated, every pixel of the
      // copy's span is off by what it lost, too little to count as a wrap (issue 46, item 16).
      if (leaf && !leaf->shaded) events_.saturated_loads += load_saturates(leaf->offset[c], arith_);
      const SpanTrace t = run_unit(unit_, arith_, load_span(p, c, xl, xr, dy, unit_, arith_, leaf, division_));
      for (int i = 0; i < int(t.values.size()); ++i) {
        const double exact = std::ldexp(double(exact_plane_value(p, c, xl + i, dy, leaf)), -PLANE_FRAC);
        const double value = std::ldexp(double(t.values[std::size_t(i)]), -arith_.frac_bits);
        if (std::fabs(value - exact) >= half_range_) wrapped_[std::size_t(i)] = 1, span_wrapped = true;
      }
    }
    for (const std::uint8_t w : wrapped_) events_.wrapped_pixels += w;
    events_.wrapped_spans += span_wrapped;
  }
  const RegisterEvents& events() const { return events_; }

 private:
  UnitConfig unit_;
  Arithmetic arith_;
  SpanDivision division_;
  double half_range_ = std::ldexp(1.0, arith_.int_bits - 1);  // levels
  RegisterEvents events_;
  std::vector<std::uint8_t> wrapped_;  // per pixel of the current span
};

}  // namespace

RegisterEvents count_register_events(const PreparedFrame& frame, const FrameConfig& config) {
  if (!config.arith.fixed || !frame.arrays.fixed) return {};
  Counter counter(config);
  for (std::size_t r = 0; r < frame.records; ++r) {
    const TriangleGeometry& t = frame.arrays.triangles[r];
    if (t.x0 > t.x1 || t.y0 > t.y1) continue;
    const FixedPlanes& planes = frame.arrays.fixed[r];
    const SierpinskiLeaf* leaf = frame.arrays.leaves ? &frame.arrays.leaves[r] : nullptr;
    const auto visit = [&](int dy, int xl, int xr) { counter.span(planes, leaf, xl, xr, dy); };
    if (frame.dda) {
      for (int dy = 0; dy <= t.y1 - t.y0; ++dy) {
        const std::size_t at = 2 * (std::size_t(frame.dda->first[r]) + std::size_t(dy));
        if (frame.dda->rows[at] <= frame.dda->rows[at + 1]) visit(dy, frame.dda->rows[at], frame.dda->rows[at + 1]);
      }
    } else {
      for_each_span(t, visit);
    }
  }
  return counter.events();
}

RegisterEvents count_register_events(const Scene& scene, const FrameConfig& config) {
  if (!config.arith.fixed) return {};
  FrameConfig host = config;
  host.plan.reset();
  FramePipeline pipeline(host);
  return count_register_events(pipeline.prepare_frame(scene), host);
}

}  // namespace parashade
