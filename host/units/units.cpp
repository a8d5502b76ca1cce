// The span arithmetic and division specs (--arith, --div); the units' specs are the unit table's.
#include "parashade/units.hpp"

#include <regex>

#include "parashade/errors.hpp"
#include "parashade/kernels/constants.h"
#include "parashade/shift_add_division.hpp"

namespace parashade {

SpanDivision parse_division(const std::string& spec) {
  if (spec == "constant") return {DIV_CONSTANT, 8, true};
  if (spec == "exact") return {DIV_EXACT, 8, true};
  std::smatch m;
  if (!std::regex_match(spec, m, std::regex(R"(shiftadd:(\d{1,2})(:trunc)?)")))
    throw UsageError("unknown span division '" + spec + "' (valid: constant, exact, shiftadd:N, shiftadd:N:trunc)");
  const int bits = std::stoi(m[1]);
  if (bits < 1 || bits > kMaxShiftAddBits)
    throw UsageError("span division '" + spec + "': N = " + m[1].str() + " digits is not in 1.." + std::to_string(kMaxShiftAddBits));
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
  if (i < REGISTER_MIN_INT_BITS)
    throw UsageError("arithmetic '" + spec + "': I = " + m[1].str() + " integer bits cannot hold 255 and a sign (I >= " +
                     std::to_string(REGISTER_MIN_INT_BITS) + ")");
  if (f < 1) throw UsageError("arithmetic '" + spec + "': F must be at least 1 fraction bit");
  if (i + f > REGISTER_MAX_BITS)
    throw UsageError("arithmetic '" + spec + "': I + F = " + std::to_string(i + f) + " bits exceeds the " +
                     std::to_string(REGISTER_MAX_BITS) + "-bit register");
  return {true, i, f};
}

std::string arith_name(const Arithmetic& a) {
  return a.fixed ? "fixed:" + std::to_string(a.int_bits) + "." + std::to_string(a.frac_bits) : "float";
}

}  // namespace parashade
