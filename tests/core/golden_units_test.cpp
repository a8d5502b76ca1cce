// The golden unit models on spans worked out by hand, their clock counts against the cost model,
// and the register model's rounding, saturation and wrap-around.
#include <gtest/gtest.h>

#include "parashade/errors.hpp"
#include "parashade/golden_units.hpp"
#include "parashade/unit_table.hpp"

namespace parashade {
namespace {

const Arithmetic kFixed{true, 12, 4};  // W = 16 bits, 4 fraction bits: one level = 16

SpanLoad span(std::int32_t start, std::int32_t end, std::int32_t step, std::int32_t own_step, int length) {
  SpanLoad s;
  s.start = start;
  s.end = end;
  s.step = step;
  s.own_step = own_step;
  s.length = length;
  return s;
}

TEST(GoldenUnits, ClassicAccumulatesTheStep) {
  const SpanTrace t = run_unit({UnitKind::classic, 1, false}, kFixed, span(100, 0, 7, 0, 5));
  EXPECT_EQ(t.values, (std::vector<std::int32_t>{100, 107, 114, 121, 128}));
  EXPECT_EQ(t.clocks, 5u);
}

TEST(GoldenUnits, CounterRunsFromBothEndsAndTheLeftTakesTheOddMiddle) {
  // E = 131 is not S + 4*7 = 128: the right interpolator starts from its own rounded end value.
  const SpanTrace odd = run_unit({UnitKind::counter, 2, false}, kFixed, span(100, 131, 7, 0, 5));
  EXPECT_EQ(odd.values, (std::vector<std::int32_t>{100, 107, 114, 124, 131}));
  EXPECT_EQ(odd.clocks, 3u);
  const SpanTrace even = run_unit({UnitKind::counter, 2, false}, kFixed, span(100, 131, 7, 0, 4));
  EXPECT_EQ(even.values, (std::vector<std::int32_t>{100, 107, 124, 131}));
  EXPECT_EQ(even.clocks, 2u);
  const SpanTrace one = run_unit({UnitKind::counter, 2, false}, kFixed, span(100, 100, 7, 0, 1));
  EXPECT_EQ(one.values, (std::vector<std::int32_t>{100}));
  EXPECT_EQ(one.clocks, 1u);
}

TEST(GoldenUnits, InterleaveWithShiftedStepEqualsClassic) {
  const SpanTrace t = run_unit({UnitKind::interleave, 3, false}, kFixed, span(10, 0, 5, 999, 7));
  EXPECT_EQ(t.values, (std::vector<std::int32_t>{10, 15, 20, 25, 30, 35, 40}));
  EXPECT_EQ(t.clocks, 3u);  // ceil(7 / 3)
}

TEST(GoldenUnits, InterleaveWithOwnStepUsesItBetweenRounds) {
  // Interpolators start at S, S + dI, S + 2 dI and step by the own-rounded 3 dI = 16 (not 15).
  const SpanTrace t = run_unit({UnitKind::interleave, 3, true}, kFixed, span(10, 0, 5, 16, 7));
  EXPECT_EQ(t.values, (std::vector<std::int32_t>{10, 15, 20, 26, 31, 36, 42}));
  EXPECT_EQ(t.clocks, 3u);
}

TEST(GoldenUnits, SegmentProducesPPerClockFromMultiples) {
  const SpanTrace t = run_unit({UnitKind::segment, 4, false}, kFixed, span(1, 0, 3, 0, 10));
  EXPECT_EQ(t.values, (std::vector<std::int32_t>{1, 4, 7, 10, 13, 16, 19, 22, 25, 28}));
  EXPECT_EQ(t.clocks, 3u);
  const SpanTrace wide = run_unit({UnitKind::segment, 64, false}, kFixed, span(1, 0, 3, 0, 3));
  EXPECT_EQ(wide.values, (std::vector<std::int32_t>{1, 4, 7}));
  EXPECT_EQ(wide.clocks, 1u);
}

// The sources print w(P) = 2, 4, 8, 14, 22, 32 for P = 2..64 ([Malovanyi 2019, parallel Gouraud] ch. 3). Our construction needs P/2 - 1
// adders for the multiples (odd multiples only), P - 1 output adders and one accumulator.
TEST(GoldenUnits, SegmentAdderCountsOfOurConstruction) {
  const int p[] = {2, 4, 8, 16, 32, 64};
  const int multiples[] = {0, 1, 3, 7, 15, 31};
  const int total[] = {2, 5, 11, 23, 47, 95};
  for (int k = 0; k < 6; ++k) {
    const SegmentAdders a = segment_adders(p[k]);
    EXPECT_EQ(a.multiples, multiples[k]) << "P = " << p[k];
    EXPECT_EQ(a.outputs, p[k] - 1);
    EXPECT_EQ(a.total(), total[k]) << "P = " << p[k];
  }
}

TEST(GoldenUnits, AddersWrapAroundTheRegisterWidth) {
  const Arithmetic narrow{true, 9, 1};  // W = 10: -512 .. 511
  const SpanTrace t = run_unit({UnitKind::classic, 1, false}, narrow, span(509, 0, 1, 0, 4));
  EXPECT_EQ(t.values, (std::vector<std::int32_t>{509, 510, 511, -512}));
  const SpanTrace back = run_unit({UnitKind::counter, 2, false}, narrow, span(0, -511, 3, 0, 2));
  EXPECT_EQ(back.values, (std::vector<std::int32_t>{0, -511}));
}

// Every unit of the table, in every configuration its golden tests run.
TEST(GoldenUnits, ClocksMatchTheCostModelForEveryLength) {
  for (const UnitRow& row : unit_table()) {
    for (const std::string& spec : row.golden_tests) {
      const UnitConfig u = parse_units(spec);
      for (int length = 1; length <= 300; ++length) {
        const SpanTrace t = run_unit(u, kFixed, span(0, 0, 1, u.lanes, length));
        ASSERT_EQ(t.values.size(), std::size_t(length));
        EXPECT_EQ(t.clocks, std::uint64_t(span_clocks(u, length))) << spec << " L=" << length;
      }
    }
  }
}

TEST(GoldenUnits, RejectFloatAndEmptySpans) {
  EXPECT_THROW(run_unit({}, Arithmetic{}, span(0, 0, 1, 0, 3)), std::invalid_argument);
  EXPECT_THROW(run_unit({}, kFixed, span(0, 0, 1, 0, 0)), std::invalid_argument);
}

TEST(RegisterModel, LoadRoundsToNearestTiesUpAndSaturates) {
  const std::int64_t one = std::int64_t(1) << PLANE_FRAC;  // 1.0 level in setup's format
  EXPECT_EQ(load_register(one + one / 32, 4, 16), 17);      // 1.03125 -> 16.5 sixteenths -> 17 (tie up)
  EXPECT_EQ(load_register(one + one / 32 - 1, 4, 16), 16);  // just below the tie
  EXPECT_EQ(load_register(-one - one / 32, 4, 16), -16);    // -16.5 -> -16 (ties up, toward +inf)
  EXPECT_EQ(load_register(4096 * one, 4, 16), 32767);       // beyond the register: saturated
  EXPECT_EQ(load_register(-4096 * one, 4, 16), -32768);
}

TEST(RegisterModel, OutputLevelRoundsAndSaturates) {
  EXPECT_EQ(register_level(16 * 100 + 7, 4), 100);
  EXPECT_EQ(register_level(16 * 100 + 8, 4), 101);  // tie up
  EXPECT_EQ(register_level(-3, 4), 0);
  EXPECT_EQ(register_level(16 * 300, 4), 255);
}

TEST(RegisterModel, LoadSpanTakesEndsStepAndOwnStepFromThePlane) {
  FixedPlanes p{};
  const std::int64_t one = std::int64_t(1) << PLANE_FRAC;
  p.ref[1] = 10 * one;
  p.ddx[1] = one / 3;  // 0.333.. levels per pixel
  p.ddy[1] = 2 * one;
  const SpanLoad s = load_span(p, 1, 3, 9, 2, {UnitKind::interleave, 4, true}, kFixed);
  EXPECT_EQ(s.start, 16 * 15);                // 10 + 3/3 + 2*2 = 15 levels
  EXPECT_EQ(s.end, 16 * 17);                  // 10 + 9/3 + 4 = 17
  EXPECT_EQ(s.step, 5);                       // 16/3 = 5.33 -> 5
  EXPECT_EQ(s.own_step, 21);                  // 4 * 16/3 = 21.33 -> 21 (4 * 5 = 20 when shifted)
  EXPECT_EQ(s.length, 7);
}

// Every row of the unit table: its specs parse to it and its names parse back to the same unit, its spec
// form is in the error message that lists the valid units, it has a golden model and a cost model, and a
// unit without parameters has its lanes.
TEST(UnitTable, EveryRowParsesItsOwnSpecsAndNamesThem) {
  std::string valid;
  try {
    parse_units("no-such-unit");
  } catch (const UsageError& e) {
    valid = e.what();
  }
  for (const UnitRow& row : unit_table()) {
    SCOPED_TRACE(row.spec);
    const UnitModel& model = *row.model;
    EXPECT_EQ(&unit_row(row.kind), &row);
    EXPECT_NE(valid.find(row.spec), std::string::npos) << valid;
    EXPECT_TRUE(model.run && model.span_clocks);
    EXPECT_EQ(!model.parse, !model.name) << "a unit with parameters both parses and names them";
    EXPECT_EQ(!model.parse, row.lanes > 0) << "lanes: the row's for a unit without parameters, else its parser's";
    EXPECT_FALSE(row.golden_tests.empty()) << "no configuration for the golden-model tests";
    for (const auto* list : {&row.golden_tests, &row.scaling_sweep, &row.error_study}) {
      for (const std::string& spec : *list) {
        const UnitConfig u = parse_units(spec);
        EXPECT_EQ(u.kind, row.kind) << spec;
        const UnitConfig again = parse_units(unit_name(u));
        EXPECT_EQ(unit_name(again), unit_name(u)) << spec;
        EXPECT_EQ(again.lanes, u.lanes) << spec;
      }
    }
    for (const std::string& spec : row.error_study) EXPECT_TRUE(model.error_bound) << spec;
  }
}

TEST(UnitSpecs, ParseValidAndNameInvalid) {
  EXPECT_EQ(unit_name(parse_units("interleave:4:own")), "interleave:4:own");
  EXPECT_EQ(parse_units("segment:64").lanes, 64);
  EXPECT_EQ(parse_units("counter").lanes, 2);
  for (const char* bad : {"interleave:0", "interleave:17", "segment:3", "segment:128", "segment:1", "sierpinski:x", ""})
    EXPECT_THROW(parse_units(bad), UsageError) << bad;
  EXPECT_EQ(unit_name(parse_units("sierpinski:2:odd:seal")), "sierpinski:2:odd:seal");
  EXPECT_EQ(parse_units("sierpinski").depth, 1);
  EXPECT_EQ(parse_units("sierpinski:3").lanes, 64);
  for (const char* bad : {"sierpinski:0", "sierpinski:4", "sierpinski:1:seal:odd", "sierpinski:1:both"})
    EXPECT_THROW(parse_units(bad), UsageError) << bad;
  EXPECT_EQ(division_name(parse_division("shiftadd:8:trunc")), "shiftadd:8:trunc");
  EXPECT_EQ(parse_division("shiftadd:12").bits, 12);
  EXPECT_EQ(parse_division("exact").mode, DIV_EXACT);
  for (const char* bad : {"shiftadd:0", "shiftadd:31", "shiftadd", "shiftadd:8:round", "divide"})
    EXPECT_THROW(parse_division(bad), UsageError) << bad;
  EXPECT_EQ(arith_name(parse_arith("fixed:16.8")), "fixed:16.8");
  EXPECT_EQ(parse_arith("fixed").width(), 24);
  for (const char* bad : {"fixed:8.8", "fixed:20.13", "fixed:12.0", "fixed:12", "double"})
    EXPECT_THROW(parse_arith(bad), UsageError) << bad;
}

}  // namespace
}  // namespace parashade
