#include "parashade/units.hpp"

#include <regex>

#include "parashade/errors.hpp"
#include "kernels/constants.h"

namespace parashade {

UnitConfig parse_units(const std::string& spec) {
  const std::string valid = " (valid: classic, counter, interleave:M[:own] with M = 1.." +
                            std::to_string(MAX_INTERLEAVE_LANES) + ", segment:P with P = 2, 4, ..., " +
                            std::to_string(MAX_SEGMENT_LANES) +
                            ", sierpinski[:D][:even|:odd|:touch|:overlap][:seal] with D = 1..3)";
  if (spec == "classic") return {UnitKind::classic, 1, false};
  if (spec == "counter") return {UnitKind::counter, 2, false};
  std::smatch m;
  if (std::regex_match(spec, m, std::regex(R"(interleave:(\d{1,3})(:own)?)"))) {
    const int lanes = std::stoi(m[1]);
    if (lanes < 1 || lanes > MAX_INTERLEAVE_LANES)
      throw UsageError("--units '" + spec + "': M = " + m[1].str() + " is not in 1.." + std::to_string(MAX_INTERLEAVE_LANES));
    return {UnitKind::interleave, lanes, m[2].matched};
  }
  if (std::regex_match(spec, m, std::regex(R"(segment:(\d{1,3}))"))) {
    const int lanes = std::stoi(m[1]);
    if (lanes < 2 || lanes > MAX_SEGMENT_LANES || (lanes & (lanes - 1)) != 0)
      throw UsageError("--units '" + spec + "': P = " + m[1].str() + " is not a power of two in 2.." +
                       std::to_string(MAX_SEGMENT_LANES));
    return {UnitKind::segment, lanes, false};
  }
  if (std::regex_match(spec, m, std::regex(R"(sierpinski(:(\d{1,2}))?(:(even|odd|touch|overlap))?(:seal)?)"))) {
    const int depth = m[2].matched ? std::stoi(m[2]) : 1;
    if (depth < 1 || depth > 3) throw UsageError("--units '" + spec + "': depth D = " + m[2].str() + " is not in 1..3");
    const std::string grid = m[4].matched ? m[4].str() : "even";
    const SierpinskiGrid g = grid == "odd"     ? SierpinskiGrid::odd
                             : grid == "touch" ? SierpinskiGrid::touch
                             : grid == "overlap" ? SierpinskiGrid::overlap
                                                 : SierpinskiGrid::even;
    return {UnitKind::sierpinski, 1 << (2 * depth), false, depth, g, m[5].matched};
  }
  throw UsageError("unknown unit '" + spec + "'" + valid);
}

const char* sierpinski_grid_name(SierpinskiGrid g) {
  switch (g) {
    case SierpinskiGrid::even: return "even";
    case SierpinskiGrid::odd: return "odd";
    case SierpinskiGrid::touch: return "touch";
    case SierpinskiGrid::overlap: return "overlap";
  }
  return "?";
}

std::string unit_name(const UnitConfig& u) {
  switch (u.kind) {
    case UnitKind::classic: return "classic";
    case UnitKind::counter: return "counter";
    case UnitKind::interleave: return "interleave:" + std::to_string(u.lanes) + (u.own_step ? ":own" : "");
    case UnitKind::segment: return "segment:" + std::to_string(u.lanes);
    case UnitKind::sierpinski:
      return "sierpinski:" + std::to_string(u.depth) + ":" + sierpinski_grid_name(u.grid) + (u.seal ? ":seal" : "");
  }
  return "?";
}

SpanDivision parse_division(const std::string& spec) {
  if (spec == "constant") return {DIV_CONSTANT, 8, true};
  if (spec == "exact") return {DIV_EXACT, 8, true};
  std::smatch m;
  if (!std::regex_match(spec, m, std::regex(R"(shiftadd:(\d{1,2})(:trunc)?)")))
    throw UsageError("unknown span division '" + spec + "' (valid: constant, exact, shiftadd:N, shiftadd:N:trunc)");
  const int bits = std::stoi(m[1]);
  if (bits < 1 || bits > 30) throw UsageError("--div '" + spec + "': N = " + m[1].str() + " digits is not in 1..30");
  return {DIV_SHIFT_ADD, bits, !m[2].matched};
}

std::string division_name(const SpanDivision& d) {
  if (d.mode == DIV_CONSTANT) return "constant";
  if (d.mode == DIV_EXACT) return "exact";
  return "shiftadd:" + std::to_string(d.bits) + (d.nearest ? "" : ":trunc");
}

Arithmetic parse_arith(const std::string& spec) {
  if (spec == "float") return {};
  if (spec == "fixed") return {true, 12, 12};
  std::smatch m;
  if (!std::regex_match(spec, m, std::regex(R"(fixed:(\d{1,2})\.(\d{1,2}))")))
    throw UsageError("unknown arithmetic '" + spec + "' (valid: float, fixed, fixed:I.F)");
  const int i = std::stoi(m[1]), f = std::stoi(m[2]);
  if (i < 9) throw UsageError("--arith '" + spec + "': I = " + m[1].str() + " integer bits cannot hold 255 and a sign (I >= 9)");
  if (f < 1) throw UsageError("--arith '" + spec + "': F must be at least 1 fraction bit");
  if (i + f > 32) throw UsageError("--arith '" + spec + "': I + F = " + std::to_string(i + f) + " bits exceeds the 32-bit register");
  return {true, i, f};
}

std::string arith_name(const Arithmetic& a) {
  return a.fixed ? "fixed:" + std::to_string(a.int_bits) + "." + std::to_string(a.frac_bits) : "float";
}

}  // namespace parashade
