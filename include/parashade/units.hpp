#pragma once
// The modeled shading units ([Malovanyi 2019, parallel Gouraud] ch. 3) and their arithmetic: what `--units` and `--arith` select.
// A unit decides how many intensities a clock produces and, in fixed point, which values are
// quantized where (kernels/fixed_point.h, docs/units.md). Units apply to Gouraud's code interpolators.
#include <cstdint>
#include <string>

#include "parashade/kernels/span_division.h"
#include "parashade/kernels/unit_cost.h"
#include "parashade/unit_kinds.hpp"  // UnitKind: one member per kernels/units/<unit>.h (cmake/unit_kinds.cmake)

namespace parashade {

// How the extra triangulation gets its midpoints onto pixel corners ([Malovanyi 2019, parallel Gouraud] ch. 3, the sources' two remedies).
enum class SierpinskiGrid {
  even,     // (a) every vertex to the nearest pixel corner = 0 (mod 2^D): exact midpoints
  odd,      // (a) the same with corners = 1 (mod 2^D)
  touch,    // (b) vertices to the nearest pixel corner; each edge from two equal halves of floor(d/2) pixels
  overlap,  // (b) the same with halves of ceil(d/2) pixels, overlapping by one where d is odd
};

struct UnitConfig {
  UnitKind kind = UnitKind::classic;
  int lanes = 1;          // intensities per clock: classic 1, counter 2, interleave and pipelined M (1..16), segment P (2..64), sierpinski 4^D
  bool own_step = false;  // interleave: M*dI quantized from setup's plane on its own (else M times the quantized dI)
  int depth = 0;          // sierpinski: subdivision depth D (1..3)
  SierpinskiGrid grid = SierpinskiGrid::even;  // sierpinski: the parity remedy
  bool seal = false;      // sierpinski: reflected copies take pixel centres on their edges by their own
                          // top-left rule instead of mirroring the shaded sub-triangle's (no holes)
};

// "classic", "counter", "interleave:M[:own]", "segment:P", "sierpinski[:D][:even|:odd|:touch|:overlap][:seal]"
// (D = 1, even by default): each unit parses its own (unit_table.hpp). Throws UsageError naming the value.
UnitConfig parse_units(const std::string& spec);
std::string unit_name(const UnitConfig& u);
const char* sierpinski_grid_name(SierpinskiGrid g);

// Span register format I.F (kernels/fixed_point.h), or float.
struct Arithmetic {
  bool fixed = false;
  int int_bits = 12;   // including the sign bit
  int frac_bits = 12;
  int width() const { return int_bits + frac_bits; }
};

// "float" or "fixed:I.F" (9 <= I, 1 <= F, I + F <= 32; "fixed" alone is fixed:12.12). Throws UsageError.
Arithmetic parse_arith(const std::string& spec);
std::string arith_name(const Arithmetic& a);

// How a span gets its increment (kernels/span_division.h): the constant dI_G once per triangle, or a
// division per span of its end registers' difference, exact or by shifts and adds with n digits.
struct SpanDivision {
  int mode = 0;          // DIV_CONSTANT, DIV_EXACT, DIV_SHIFT_ADD
  int bits = 8;          // shiftadd: n digits of 1/k (1..30)
  bool nearest = true;   // shiftadd: digits rounded to nearest (the source's Table 1) or truncated
};

// "constant", "exact", "shiftadd:N" or "shiftadd:N:trunc". Throws UsageError naming the value.
SpanDivision parse_division(const std::string& spec);
std::string division_name(const SpanDivision& d);

// Modeled clocks of one frame: every span costs SPAN_LOAD_CLOCKS plus the unit's span_clocks (unit_table.hpp).
// Triangle setup is the host's ("software") work and is timed, not modeled.
struct ModeledClocks {
  std::uint64_t spans = 0;
  std::uint64_t pixels = 0;  // shaded span pixels, hidden ones included (the unit shades before the depth test)
  std::uint64_t clocks = 0;
};

}  // namespace parashade
