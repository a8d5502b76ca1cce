#pragma once
// Test vectors for a shading unit's hardware (hw/, docs/hardware.md "Test vectors"): span inputs as the
// unit's registers are loaded (S, E, dI, M*dI already rounded to I.F by setup) and, per clock after the
// load, the pixels the golden model (unit_table.hpp) produces. `parashade vectors` writes them; the
// Verilator testbenches (tests/hw/) and a designer's own RTL check against them.
#include <cstdint>
#include <string>
#include <vector>

#include "parashade/golden_units.hpp"
#include "parashade/units.hpp"

namespace parashade {

// The units that have hardware in hw/ and so test vectors: every span accumulator (the sierpinski unit's
// copies need its sub-triangle setup, which has no RTL).
bool has_test_vectors(const UnitConfig& unit);

// The spans of a vectors file: hand-picked cases (the golden tests' spans, every short length, rounding
// ties, saturation on both sides of [0, 255], adders wrapping both ways, 4096-pixel spans), then
// `random_spans` spans of 1..4096 pixels loaded from random planes through load_span (seeded; the
// same arguments give the same spans).
std::vector<SpanLoad> test_vector_spans(const UnitConfig& unit, const Arithmetic& a, int random_spans,
                                        std::uint64_t seed);

// The vectors file's text (format: docs/hardware.md): a header, then per span its inputs and modeled
// clocks and one line per output clock. Throws UsageError for a unit without test vectors or float.
std::string test_vectors_text(const UnitConfig& unit, const Arithmetic& a, const std::vector<SpanLoad>& spans,
                              std::uint64_t seed);

}  // namespace parashade
