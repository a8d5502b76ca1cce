#pragma once
// Golden models of the shading units: plain C++ that steps each unit's registers clock by clock, as
// the block diagrams of [Malovanyi 2019, parallel Gouraud] ch. 3 describe (slow, small, obviously right). In fixed point the kernels
// must reproduce them bit for bit (tests/cl/unit_golden_test.cpp). Each unit's model is in
// host/units/<unit>.cpp (unit_table.hpp); what they share (the span load, the adder) is here.
#include <cstdint>
#include <vector>

#include "parashade/units.hpp"
#include "parashade/kernels/fixed_point.h"
#include "parashade/kernels/sierpinski_leaf.h"

namespace parashade {

// What the line interpolators and setup hand a unit for one span, already in span-register format.
struct SpanLoad {
  std::int32_t start = 0;    // S: intensity at the span's left pixel (from setup's plane, rounded)
  std::int32_t end = 0;      // E: intensity at its right pixel, rounded on its own (the counter unit's right start)
  std::int32_t step = 0;     // dI: the constant span increment, rounded
  std::int32_t own_step = 0; // M*dI rounded from setup's plane on its own (interleave:M:own)
  int length = 0;            // pixels, >= 1
  // sierpinski: start and step are the shaded sub-triangle's span (the one this span is a copy of);
  // the copy's adder adds `offset` (sign +1) or subtracts from it (sign -1, pixels in reverse order).
  std::int32_t offset = 0;
  int sign = 1;
};

// Loads channel `c` of a triangle's planes for the span [xl, xr] of row dy (all relative to the
// triangle's box corner x0, y0). For the sierpinski unit, `leaf` is the record's sub-triangle data.
// With a per-span division, the step is (E - S) / (L - 1) (0 for one pixel) instead of the plane's dI_G.
SpanLoad load_span(const FixedPlanes& p, int c, int xl, int xr, int dy, const UnitConfig& unit, const Arithmetic& a,
                   const SierpinskiLeaf* leaf = nullptr, const SpanDivision& division = {});

// One W-bit adder of a unit: the carry out of the register is lost.
struct Adder {
  int width;
  std::int32_t operator()(std::int32_t a, std::int32_t b) const {
    return wrap_register(std::uint32_t(a) + std::uint32_t(b), width);
  }
};

struct SpanTrace {
  std::vector<std::int32_t> values;  // span register value per pixel, left to right
  std::vector<std::uint32_t> clock;  // per pixel, the clock (0 = the first after the load) that produced it
  std::uint64_t clocks = 0;          // clocks the unit took for the span's pixels (without the load)
};

// The segment unit's adders as its golden model builds them (host/units/segment.cpp): the multiples
// 2..P of dI (even ones are wired shifts of a smaller one, odd ones one adder each), one output adder
// per lane but the first, and the accumulator that steps the segment base by P*dI.
struct SegmentAdders {
  int multiples = 0, outputs = 0, accumulator = 0;
  int total() const { return multiples + outputs + accumulator; }
};
SegmentAdders segment_adders(int p);

// Runs the unit over one span, clock by clock. a.fixed must be true.
SpanTrace run_unit(const UnitConfig& unit, const Arithmetic& a, const SpanLoad& span);

}  // namespace parashade
