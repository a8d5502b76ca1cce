// The accumulated fixed-point error of the shading units (docs/unit-error.md): errors worked out by
// hand on spans whose values sit on rounding ties, the derived bound (written out again here, not
// taken from unit_error_bound) never exceeded and reached, the counter unit halving the classic
// error, the shifted even/odd unit equal to classic bit for bit, the own-step unit accumulating
// less, and the source's printed formulas checked where the derivation says they hold or fail.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "parashade/golden_units.hpp"
#include "parashade/unit_error.hpp"
#include "parashade/unit_table.hpp"

namespace parashade {
namespace {

const UnitConfig kClassic{UnitKind::classic, 1, false};
const UnitConfig kCounter{UnitKind::counter, 2, false};
UnitConfig interleave(int m, bool own) { return {UnitKind::interleave, m, own}; }
UnitConfig segment(int p) { return {UnitKind::segment, p, false}; }

std::vector<UnitConfig> all_units() {
  return {kClassic,         kCounter,         interleave(2, false), interleave(4, false), interleave(2, true),
          interleave(3, true), interleave(4, true), interleave(16, true), segment(2),        segment(8),
          segment(64)};
}

// |error(z)| <= this, levels. h = 2^-(F+1) is one register load's rounding, e = 2^-33 setup's plane
// rounding (32 fraction bits). Every unit starts from S (error h + e) and adds the rounded dI
// (error h + e per addition), except: the counter unit's right interpolator starts from its own
// rounded end value E (plane error up to L e) and walks back; interleave:M:own reaches pixel kM + j
// from S by j additions of dI and k additions of its own rounded M dI (plane error M e).
double expected_bound(const UnitConfig& u, int f, int length, int z) {
  const double h = std::ldexp(1.0, -(f + 1)), e = std::ldexp(1.0, -33);
  if (u.kind == UnitKind::counter && z >= (length + 1) / 2) return h + length * e + (length - 1 - z) * (h + e);
  if (u.kind == UnitKind::interleave && u.own_step) {
    const int k = z / u.lanes, j = z % u.lanes;
    return (1 + j) * (h + e) + k * (h + u.lanes * e);
  }
  return (1 + z) * (h + e);
}

std::vector<double> errors(const UnitConfig& u, const Arithmetic& a, double start, double step, int length) {
  const SpanError e = measure_span_error(u, a, ExactSpan{start, step, length});
  EXPECT_FALSE(e.wrapped);
  return e.error;
}

std::vector<double> in_32nds(std::initializer_list<int> v) {
  std::vector<double> out;
  for (int x : v) out.push_back(x / 32.0);
  return out;
}

// F = 4: one LSB is 1/16 level, a tie 1/32. S = 10 + 1/32 and dI = 1/32 both lie on ties and round
// up, each by exactly 1/32: the classic error at pixel z is (1 + z)/32, the bound with nothing to spare.
TEST(UnitError, ErrorsOnTiesWorkedOutByHand) {
  const Arithmetic a{true, 12, 4};
  const double s = 10 + 1 / 32.0, d = 1 / 32.0;
  EXPECT_EQ(errors(kClassic, a, s, d, 8), in_32nds({1, 2, 3, 4, 5, 6, 7, 8}));
  EXPECT_EQ(errors(segment(4), a, s, d, 8), in_32nds({1, 2, 3, 4, 5, 6, 7, 8}));
  EXPECT_EQ(errors(interleave(2, false), a, s, d, 8), in_32nds({1, 2, 3, 4, 5, 6, 7, 8}));
  // Counter: E = S + 7 dI = 10.25 is exact; the right interpolator subtracts the rounded-up dI, so
  // its error grows the other way from 0 at the right end. The largest error is the left's 4/32.
  EXPECT_EQ(errors(kCounter, a, s, d, 8), in_32nds({1, 2, 3, 4, -3, -2, -1, 0}));
  // interleave:2:own: 2 dI = 1/16 is exact on its own. The even pixels keep S's 1/32; the odd
  // interpolator starts at S + dI (two roundings, 2/32) and keeps that.
  EXPECT_EQ(errors(interleave(2, true), a, s, d, 8), in_32nds({1, 2, 1, 2, 1, 2, 1, 2}));
  // interleave:4:own: 4 dI = 1/8 exact; interpolator j starts at S + j dI: (1 + j)/32.
  EXPECT_EQ(errors(interleave(4, true), a, s, d, 8), in_32nds({1, 2, 3, 4, 1, 2, 3, 4}));
  // Just below the ties both round down: the errors change sign and lose the 2^-30 below.
  const std::vector<double> below = errors(kClassic, a, s - 0x1p-30, d - 0x1p-30, 4);
  for (int z = 0; z < 4; ++z) EXPECT_DOUBLE_EQ(below[std::size_t(z)], -(1 + z) / 32.0 + (1 + z) * 0x1p-30) << z;
}

// 9.4 holds 255.9375 at most: 255 plus an accumulated error above 15/16 wraps to negative values.
TEST(UnitError, RegisterWrapIsFlaggedAndTheErrorReduced) {
  const ExactSpan span{253 + 25 / 32.0, 1 / 32.0, 40};  // tie start, tie step; exact end value 255
  const SpanError narrow = measure_span_error(kClassic, Arithmetic{true, 9, 4}, span);
  EXPECT_TRUE(narrow.wrapped);
  EXPECT_EQ(narrow.error.back(), 40 / 32.0);
  const SpanError wide = measure_span_error(kClassic, Arithmetic{true, 12, 4}, span);
  EXPECT_FALSE(wide.wrapped);
  EXPECT_EQ(wide.error, narrow.error);
}

struct Case {
  Arithmetic arith;
  std::vector<int> lengths;
};

// Every pixel of every drawn span is within the bound, and over the spans of one long length the
// worst pixel comes close to it: a unit that accumulated more error, or a bound that were vacuous,
// fails here.
TEST(UnitError, MeasuredErrorNeverExceedsTheBoundAndReachesIt) {
  const std::vector<Case> cases = {{{true, 12, 8}, {1, 2, 3, 5, 8, 17, 64, 255, 1000}},
                                   {{true, 16, 4}, {1, 2, 7, 64, 255, 1000}},
                                   {{true, 10, 14}, {1, 3, 64, 1000}},
                                   {{true, 9, 4}, {1, 2, 3, 4, 8, 16}}};  // longer spans may wrap 9 integer bits
  for (const Case& c : cases) {
    for (int length : c.lengths) {
      const std::vector<ExactSpan> spans = draw_spans(length, 300, 7, c.arith);
      for (const UnitConfig& u : all_units()) {
        SCOPED_TRACE(unit_name(u) + " " + arith_name(c.arith) + " L = " + std::to_string(length));
        double worst = 0, worst_bound = 0;
        int above = 0;
        for (const ExactSpan& s : spans) {
          const SpanError e = measure_span_error(u, c.arith, s);
          ASSERT_FALSE(e.wrapped);
          for (int z = 0; z < length; ++z) {
            const double bound = expected_bound(u, c.arith.frac_bits, length, z);
            above += std::fabs(e.error[std::size_t(z)]) > bound;
            worst = std::max(worst, std::fabs(e.error[std::size_t(z)]));
            worst_bound = std::max(worst_bound, bound);
          }
        }
        EXPECT_EQ(above, 0);
        // interleave:16:own: for even M, dI and M dI cannot both lie on ties, so the bound's two kinds
        // of rounding are not at their worst together (measured 0.86 to 0.95); the others reach it.
        const bool wide_own = u.kind == UnitKind::interleave && u.own_step && u.lanes > 4;
        if (length >= 64) EXPECT_GT(worst / worst_bound, wide_own ? 0.8 : 0.95);
        if (length >= 255) EXPECT_GT(worst / worst_bound, wide_own ? 0.8 : 0.99);
      }
    }
  }
}

TEST(UnitError, StudyReportsTheSameBoundAndNoExcess) {
  const Arithmetic a{true, 12, 8};
  UnitErrorOptions o;
  o.lengths = {1, 5, 64, 300};
  o.trials = 200;
  for (const UnitConfig& u : all_units()) {
    const UnitErrorStudy s = study_unit_error(u, a, o);
    ASSERT_EQ(s.lengths.size(), o.lengths.size());
    for (const UnitErrorAtLength& r : s.lengths) {
      SCOPED_TRACE(unit_name(u) + " L = " + std::to_string(r.length));
      double bound = 0;
      for (int z = 0; z < r.length; ++z) bound = std::max(bound, expected_bound(u, 8, r.length, z));
      EXPECT_DOUBLE_EQ(r.bound, bound);
      EXPECT_EQ(r.bound_exceeded, 0u);
      EXPECT_EQ(r.spans, 200u);
      EXPECT_EQ(r.random_spans, 100u);
      EXPECT_EQ(r.pixels, 200u * std::uint64_t(r.length));
      EXPECT_EQ(r.max_by_z.size(), std::size_t(r.length));
      EXPECT_EQ(r.max_abs, *std::max_element(r.max_by_z.begin(), r.max_by_z.end()));
      EXPECT_LE(r.mean_abs, r.max_abs_random);
      EXPECT_LE(r.max_abs_random, r.max_abs);
    }
  }
}

// Every span unit of the table, in the configurations its row gives the study: its own bound (the row's,
// not the one written out above) holds and is no vacuous one, so a unit added to the table is checked
// here without being listed.
TEST(UnitError, EveryTableUnitHoldsAndReachesItsOwnBound) {
  UnitErrorOptions o;
  o.lengths = {1, 5, 64, 300};
  o.trials = 200;
  for (const UnitRow& row : unit_table()) {
    for (const std::string& spec : row.error_study) {
      const UnitErrorStudy s = study_unit_error(parse_units(spec), Arithmetic{true, 12, 8}, o);
      for (const UnitErrorAtLength& r : s.lengths) {
        EXPECT_EQ(r.bound_exceeded, 0u) << spec << " L = " << r.length;
        if (r.length >= 64) EXPECT_GT(r.max_abs / r.bound, 0.8) << spec << " L = " << r.length;
      }
    }
  }
}

// The counter unit's worst pixel is the middle one, ceil(L/2) - 1 steps from its start, against
// L - 1 steps for classic: about half the error.
TEST(UnitError, CounterHalvesTheClassicError) {
  const Arithmetic a{true, 12, 8};
  UnitErrorOptions o;
  o.lengths = {1024, 1025};
  o.trials = 300;
  const UnitErrorStudy classic = study_unit_error(kClassic, a, o), counter = study_unit_error(kCounter, a, o);
  for (std::size_t i = 0; i < o.lengths.size(); ++i) {
    const double ratio = counter.lengths[i].max_abs / classic.lengths[i].max_abs;
    EXPECT_GT(ratio, 0.45) << o.lengths[i];
    EXPECT_LT(ratio, 0.55) << o.lengths[i];
    const double mean_ratio = counter.lengths[i].mean_abs / classic.lengths[i].mean_abs;
    EXPECT_GT(mean_ratio, 0.4) << o.lengths[i];
    EXPECT_LT(mean_ratio, 0.6) << o.lengths[i];
    // The price of the split: where the two interpolators meet, the left's error (+ about L/2
    // roundings) sits next to the right's (- about L/2): a seam of about L roundings between
    // neighbouring pixels, where classic's error changes by at most one rounding per pixel.
    EXPECT_GT(counter.lengths[i].max_jump, 0.9 * o.lengths[i] * 0x1p-9) << o.lengths[i];
    EXPECT_LE(classic.lengths[i].max_jump, 0x1p-9 + 0x1p-32);
    // Split: the left end and the right end of the counter unit are each one rounding off.
    EXPECT_LE(counter.lengths[i].max_by_z.front(), 0x1p-9 + 0x1p-32);
    EXPECT_LE(counter.lengths[i].max_by_z.back(), 0x1p-9 + 0x1p-32 * 1025);
  }
}

// M times the rounded dI is exactly what classic adds M times; P-multiples of it likewise.
TEST(UnitError, ShiftedInterleaveAndSegmentEqualClassicBitForBit) {
  for (const Arithmetic& a : {Arithmetic{true, 12, 8}, Arithmetic{true, 9, 4}, Arithmetic{true, 10, 22}}) {
    for (int length : {1, 2, 7, 100, 333}) {
      for (const ExactSpan& s : draw_spans(length, 60, 3, a)) {
        const std::vector<std::int32_t> classic = run_unit(kClassic, a, load_exact_span(s, kClassic, a)).values;
        for (int m = 1; m <= 16; ++m)
          ASSERT_EQ(run_unit(interleave(m, false), a, load_exact_span(s, interleave(m, false), a)).values, classic)
              << "interleave:" << m << " " << arith_name(a) << " L = " << length;
        for (int p = 2; p <= 64; p *= 2)
          ASSERT_EQ(run_unit(segment(p), a, load_exact_span(s, segment(p), a)).values, classic)
              << "segment:" << p << " " << arith_name(a) << " L = " << length;
      }
    }
  }
}

// Pixel kM + j of interleave:M:own took j + k roundings instead of kM + j: for long spans about 1/M
// of the classic error, worst and mean.
TEST(UnitError, OwnStepAccumulatesLessThanClassicOnLongSpans) {
  const Arithmetic a{true, 12, 8};
  UnitErrorOptions o;
  o.lengths = {1024};
  o.trials = 300;
  const auto max_of = [&](const UnitConfig& u) { return study_unit_error(u, a, o).lengths[0]; };
  const UnitErrorAtLength classic = max_of(kClassic), own2 = max_of(interleave(2, true)),
                          own4 = max_of(interleave(4, true)), shifted2 = max_of(interleave(2, false));
  EXPECT_EQ(shifted2.max_abs, classic.max_abs);
  EXPECT_EQ(shifted2.mean_abs, classic.mean_abs);
  EXPECT_GT(own2.max_abs / classic.max_abs, 0.45);
  EXPECT_LT(own2.max_abs / classic.max_abs, 0.52);
  EXPECT_GT(own4.max_abs / classic.max_abs, 0.22);
  EXPECT_LT(own4.max_abs / classic.max_abs, 0.27);
  EXPECT_LT(own2.mean_abs / classic.mean_abs, 0.6);
  EXPECT_LT(own4.mean_abs / classic.mean_abs, 0.35);
}

TEST(UnitError, SourceFormulaValues) {
  // δ_K = δ0 + z 2^-(V+1), δ_KH = δ0 + floor(z/2) 2^-(V+2), δ0 = 2^-(V+1); V = 8.
  EXPECT_EQ(source_formula(kClassic, 8, 100, 10), 11 * 0x1p-9);
  EXPECT_EQ(source_formula(segment(8), 8, 100, 10), 11 * 0x1p-9);
  EXPECT_EQ(source_formula(interleave(2, false), 8, 100, 5), 0x1p-8);
  EXPECT_EQ(source_formula(interleave(2, true), 8, 100, 4), 0x1p-8);
  EXPECT_EQ(source_formula(kCounter, 8, 10, 7), 3 * 0x1p-9);  // min(7, 2) steps from the right end
  EXPECT_EQ(source_formula(kCounter, 8, 10, 2), 3 * 0x1p-9);
  EXPECT_TRUE(std::isnan(source_formula(interleave(4, true), 8, 100, 4)));
  EXPECT_EQ(source_delta_delta(8, 4), 3 * 0x1p-9);
  EXPECT_EQ(source_formula_name(interleave(2, true)), "δ_KH");
  EXPECT_EQ(source_formula_name(interleave(3, true)), "");
}

// δ_K and the split hold for our units. δ_KH fails with V = F: even with its own rounded step the
// pair's worst error at pixel z is about floor(z/2)·2^-(V+1), twice the printed floor(z/2)·2^-(V+2),
// and the shifted pair's is classic's, four times. With one more fraction bit (F = V + 1) every
// rounding halves and the own-step pair's worst error is within δ_KH.
TEST(UnitError, PrintedFormulasHoldOrFailAsDerived) {
  UnitErrorOptions o;
  o.lengths = {2, 3, 16, 1024};
  o.trials = 300;
  const Arithmetic a{true, 12, 8};
  for (const UnitConfig& u : {kClassic, kCounter, segment(8)}) {
    const UnitErrorStudy s = study_unit_error(u, a, o);
    for (const UnitErrorAtLength& r : s.lengths) {
      EXPECT_EQ(r.formula_exceeded, 0u) << unit_name(u) << " L = " << r.length;
      EXPECT_GT(r.worst_over_formula, 0.99) << unit_name(u) << " L = " << r.length;  // and tight
    }
  }
  const UnitErrorAtLength own = study_unit_error(interleave(2, true), a, o).lengths.back();
  EXPECT_GT(own.formula_exceeded, 0u);
  EXPECT_GT(own.worst_over_formula, 1.9);
  EXPECT_LT(own.worst_over_formula, 2.1);
  const UnitErrorAtLength shifted = study_unit_error(interleave(2, false), a, o).lengths.back();
  EXPECT_GT(shifted.worst_over_formula, 3.9);
  // At L = 2 the odd pixel is S + dI, two roundings, where δ_KH allows one.
  const UnitErrorAtLength two = study_unit_error(interleave(2, true), a, o).lengths.front();
  EXPECT_GT(two.formula_exceeded, 0u);

  o.formula_bits = 8;
  for (const UnitErrorAtLength& r : study_unit_error(interleave(2, true), Arithmetic{true, 12, 9}, o).lengths)
    EXPECT_EQ(r.formula_exceeded, 0u) << "interleave:2:own fixed:12.9 against V = 8, L = " << r.length;
  EXPECT_GT(study_unit_error(interleave(2, false), Arithmetic{true, 12, 9}, o).lengths.back().formula_exceeded, 0u);
}

TEST(UnitError, DrawnSpansStayInRangeAndAreReproducible) {
  const Arithmetic a{true, 12, 6};
  for (int length : {1, 2, 9, 4096}) {
    const std::vector<ExactSpan> spans = draw_spans(length, 400, 11, a);
    ASSERT_EQ(spans.size(), 400u);
    int on_tie = 0;
    for (const ExactSpan& s : spans) {
      EXPECT_EQ(s.length, length);
      const double end = s.start + s.step * (length - 1);
      EXPECT_GE(std::min(s.start, end), -0x1p-6);
      EXPECT_LE(std::max(s.start, end), 255 + 0x1p-6);
      on_tie += std::fabs(std::ldexp(s.start, 6) - std::floor(std::ldexp(s.start, 6)) - 0.5) < 1e-6;
    }
    EXPECT_GE(on_tie, 190) << length;  // the adversarial half starts on (or just below) a tie
    const std::vector<ExactSpan> again = draw_spans(length, 400, 11, a), other = draw_spans(length, 400, 12, a);
    EXPECT_EQ(again[17].start, spans[17].start);
    EXPECT_EQ(again[18].step, spans[18].step);
    EXPECT_NE(other[16].start, spans[16].start);
  }
}

TEST(UnitError, RejectsWhatItCannotStudy) {
  UnitErrorOptions o;
  o.lengths = {4};
  EXPECT_THROW(study_unit_error(kClassic, Arithmetic{}, o), std::invalid_argument);  // float
  o.lengths = {0};
  EXPECT_THROW(study_unit_error(kClassic, Arithmetic{true, 12, 8}, o), std::invalid_argument);
  o.lengths = {4};
  o.trials = 0;
  EXPECT_THROW(study_unit_error(kClassic, Arithmetic{true, 12, 8}, o), std::invalid_argument);
}

}  // namespace
}  // namespace parashade
