// The extra-triangulation unit (kernels/units/sierpinski.h): the classic interpolator shades one of 4^D
// sub-triangles, one adder per copy gives the others. Its code for the unit table: spec, span load,
// golden model; its clocks are classic's (the copies cost none). No error bound: its copies are not span
// accumulators. Its setup (vertex snapping, sub-triangle records): sierpinski_setup.cpp.
#include <regex>
#include <stdexcept>

#include "parashade/errors.hpp"
#include "parashade/unit_table.hpp"
#include "parashade/kernels/constants.h"

namespace parashade {
namespace {

std::optional<UnitConfig> parse(const std::string& spec) {
  std::smatch m;
  if (!std::regex_match(spec, m, std::regex(R"(sierpinski(:(\d{1,2}))?(:(even|odd|touch|overlap))?(:seal)?)")))
    return std::nullopt;
  const int depth = m[2].matched ? std::stoi(m[2]) : 1;
  if (depth < 1 || depth > MAX_SIERPINSKI_DEPTH)
    throw UsageError("unit '" + spec + "': depth D = " + m[2].str() + " is not in 1.." + std::to_string(MAX_SIERPINSKI_DEPTH));
  const std::string grid = m[4].matched ? m[4].str() : "even";
  const SierpinskiGrid g = grid == "odd"       ? SierpinskiGrid::odd
                           : grid == "touch"   ? SierpinskiGrid::touch
                           : grid == "overlap" ? SierpinskiGrid::overlap
                                               : SierpinskiGrid::even;
  return UnitConfig{UnitKind::sierpinski, 1 << (2 * depth), false, depth, g, m[5].matched};
}

std::string name(const UnitConfig& u) {
  return "sierpinski:" + std::to_string(u.depth) + ":" + sierpinski_grid_name(u.grid) + (u.seal ? ":seal" : "");
}

// The shaded sub-triangle's span starts at this copy's left pixel, or at its right one when reflected.
SpanLoad load(const FixedPlanes& p, int c, int xl, int xr, int dy, const Arithmetic& a, const SierpinskiLeaf* leaf) {
  if (!leaf) throw std::invalid_argument("the sierpinski unit needs the sub-triangle's record");
  const int f = a.frac_bits, w = a.width();
  SpanLoad s;
  s.sign = leaf->sign;
  s.start = load_register(plane_value(p.ref[c], p.ddx[c], p.ddy[c], s.sign > 0 ? xl : xr, dy), f, w);
  s.step = load_register(s.sign > 0 ? p.ddx[c] : std::int64_t(0 - std::uint64_t(p.ddx[c])), f, w);
  s.offset = load_register(leaf->offset[c], f, w);
  s.length = xr - xl + 1;
  return s;
}

// The classic code interpolator steps the shaded sub-triangle's span; in the same clock the copy's adder
// turns each value into the copy's (offset + I, or offset - I for a reflected copy, whose pixels run the
// other way).
SpanTrace run(const Adder& add, const SpanLoad& s, const UnitConfig& unit) {
  const SpanTrace shaded = unit_row(UnitKind::classic).model->run(add, s, unit);
  SpanTrace t;
  t.clocks = shaded.clocks;
  t.values.assign(std::size_t(s.length), 0);
  t.clock.assign(std::size_t(s.length), 0);
  const std::int32_t offset = s.offset;
  for (int x = 0; x < s.length; ++x) {
    const std::int32_t v = shaded.values[std::size_t(x)];
    const std::size_t i = std::size_t(s.sign > 0 ? x : s.length - 1 - x);
    t.values[i] = s.sign > 0 ? add(offset, v) : add(offset, add(~v, 1));
    t.clock[i] = shaded.clock[std::size_t(x)];
  }
  return t;
}

}  // namespace

const char* sierpinski_grid_name(SierpinskiGrid g) {
  switch (g) {
    case SierpinskiGrid::even: return "even";
    case SierpinskiGrid::odd: return "odd";
    case SierpinskiGrid::touch: return "touch";
    case SierpinskiGrid::overlap: return "overlap";
  }
  return "?";
}

extern const UnitModel kSierpinskiModel = {parse, name, classic_span_clocks, run, load, nullptr, nullptr, nullptr};

}  // namespace parashade
