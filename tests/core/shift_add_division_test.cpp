// Division by shifts and adds ([Romanyuk & Obidnyk 2011, faster shading]): the source's worked example and Table 1 with values typed in
// from the source and worked out by hand, exactness for powers of two, the error bounds checked in
// exact integer arithmetic, the hardware model of the quotient, and bad input.
#include "parashade/shift_add_division.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace parashade {
namespace {

using R = ReciprocalRounding;

std::vector<int> terms_of(const ShiftAddReciprocal& r) {
  std::vector<int> js;
  for (int j = 0; j <= r.n; ++j)
    if (r.term(j)) js.push_back(j);
  return js;
}

// [Romanyuk & Obidnyk 2011, faster shading]: k = 7, n = 6: 1/7 ~ 1/8 + 1/64; dI for 0 -> 255 is 35.8594 instead of 36.4286, absolute
// error 0.5692, relative 1.56 %. 64/7 = 9.14, so truncation and rounding agree here.
TEST(ShiftAddDivision, SourceExampleSevenSixShifts) {
  for (R mode : {R::truncate, R::nearest}) {
    const ShiftAddReciprocal r = shift_add_reciprocal(7, 6, mode);
    EXPECT_EQ(r.bits, 9u);  // 001001
    EXPECT_EQ(terms_of(r), (std::vector<int>{3, 6}));
    EXPECT_EQ(r.terms(), "1/8 + 1/64");
    EXPECT_EQ(r.value(), 0.125 + 0.015625);
    EXPECT_EQ(r.adds(), 2);
    EXPECT_EQ(r.last_shift(), 6);
    const double approx = 255.0 * r.value();
    EXPECT_EQ(approx, 35.859375);
    EXPECT_NEAR(255.0 / 7.0 - approx, 0.5692, 5e-5);
    EXPECT_NEAR((255.0 / 7.0 - approx) / (255.0 / 7.0) * 100.0, 1.5625, 1e-9);  // exactly 4/256
  }
}

// Table 1 of [Romanyuk & Obidnyk 2011, faster shading] (k = 2..16, n = 8): the printed approximations and dI errors for 0 -> 255.
// Every row is the expansion rounded to nearest at bit 8; truncation differs at k = 6, 7, 10, 13.
struct SourceRow {
  int k;
  std::vector<int> terms;  // j with i_j = 1, as printed
  double error;            // dI_approx - dI_exact as printed (4 decimals)
};
const std::vector<SourceRow> kTable1 = {
    {2, {1}, 0.0},           {3, {2, 4, 6, 8}, -0.3320}, {4, {2}, 0.0},          {5, {3, 4, 7, 8}, -0.1992},
    {6, {3, 5, 7, 8}, 0.3320}, {7, {3, 6, 8}, 0.4269},     {8, {3}, 0.0},          {9, {4, 5, 6}, -0.4427},
    {10, {4, 5, 7}, 0.3984}, {11, {4, 6, 7, 8}, -0.2716}, {12, {4, 6, 8}, -0.3320}, {13, {4, 6}, 0.3065},
    {14, {4, 7}, -0.2846},   {15, {4, 8}, -0.0664},     {16, {4}, 0.0},
};

TEST(ShiftAddDivision, SourceTable1IsTheRoundedExpansion) {
  const std::vector<DivisionErrorRow> rows = division_error_table(2, 16, 8, R::nearest);
  ASSERT_EQ(rows.size(), kTable1.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    SCOPED_TRACE("k = " + std::to_string(kTable1[i].k));
    EXPECT_EQ(rows[i].reciprocal.k, kTable1[i].k);
    EXPECT_EQ(terms_of(rows[i].reciprocal), kTable1[i].terms);
    EXPECT_EQ(rows[i].reciprocal.adds(), int(kTable1[i].terms.size()));
    // The source cuts (not rounds) some figures, e.g. k = 11: -0.27166 printed as -0.2716.
    EXPECT_NEAR(rows[i].abs_error, kTable1[i].error, 1e-4);
    EXPECT_NEAR(rows[i].exact, 255.0 / kTable1[i].k, 1e-12);
  }
}

TEST(ShiftAddDivision, TruncationDiffersFromTable1WhereTheNinthBitIsOne) {
  // floor(256 / k) worked out by hand: 6 -> 42 = 00101010, 7 -> 36 = 00100100, 10 -> 25 = 00011001,
  // 13 -> 19 = 00010011; the source's rows have 43, 37, 26, 20.
  EXPECT_EQ(shift_add_reciprocal(6, 8).bits, 42u);
  EXPECT_EQ(shift_add_reciprocal(7, 8).bits, 36u);
  EXPECT_EQ(shift_add_reciprocal(10, 8).bits, 25u);
  EXPECT_EQ(shift_add_reciprocal(13, 8).bits, 19u);
  EXPECT_EQ(terms_of(shift_add_reciprocal(13, 8)), (std::vector<int>{4, 7, 8}));
  EXPECT_EQ(shift_add_reciprocal(6, 8, R::nearest).bits, 43u);
  EXPECT_EQ(shift_add_reciprocal(13, 8, R::nearest).bits, 20u);
  // Rows where the ninth bit is 0 agree.
  for (int k : {3, 5, 9, 11, 12, 14, 15})
    EXPECT_EQ(shift_add_reciprocal(k, 8).bits, shift_add_reciprocal(k, 8, R::nearest).bits) << "k = " << k;
}

// The source's summary: max |error of dI| 0.4427, mean relative error 0.81 %. Rounded: max at k = 9,
// 255/9 - 255*28/256 = 0.44270833; relative errors are |256 - k*m| / 256 with |256 - k*m| summing to
// 31 over k = 2..16, so the mean over the 15 rows is 31 / (15 * 256) = 0.80729 %.
TEST(ShiftAddDivision, SourceSummaryFigures) {
  const DivisionErrorSummary s = summarize(division_error_table(2, 16, 8, R::nearest));
  EXPECT_NEAR(s.max_abs_error, 0.4427083333, 1e-9);
  EXPECT_EQ(s.k_at_max_abs, 9);
  EXPECT_NEAR(s.mean_rel_error, 31.0 / (15.0 * 256.0), 1e-12);
  EXPECT_NEAR(s.mean_rel_error_inexact, 31.0 / (11.0 * 256.0), 1e-12);
  EXPECT_NEAR(s.max_rel_error, 4.0 / 256.0, 1e-12);
  EXPECT_EQ(s.max_adds, 4);
  // Truncated: worst k = 13, 255/13 - 255*19/256 = 0.68960; |256 - k*m| sums to 41.
  const DivisionErrorSummary t = summarize(division_error_table(2, 16, 8, R::truncate));
  EXPECT_NEAR(t.max_abs_error, 0.6896033654, 1e-9);
  EXPECT_EQ(t.k_at_max_abs, 13);
  EXPECT_NEAR(t.mean_rel_error, 41.0 / (15.0 * 256.0), 1e-12);
}

TEST(ShiftAddDivision, PowersOfTwoAreExact) {
  for (int n = 1; n <= kMaxShiftAddBits; ++n)
    for (int p = 0; p <= n; ++p) {
      const int k = 1 << p;
      for (R mode : {R::truncate, R::nearest}) {
        const ShiftAddReciprocal r = shift_add_reciprocal(k, n, mode);
        EXPECT_EQ(r.bits, std::uint64_t(1) << (n - p)) << "k = " << k << ", n = " << n;
        EXPECT_EQ(r.value(), 1.0 / k);
        EXPECT_EQ(r.adds(), 1);
        EXPECT_EQ(r.last_shift(), p);
      }
    }
  // k = 1 uses the unshifted term.
  EXPECT_EQ(shift_add_reciprocal(1, 8).terms(), "1");
  EXPECT_EQ(shift_add_divide(-37, shift_add_reciprocal(1, 8)).value, -37);
}

// |1/k - m/2^n| < 2^-n for truncation and <= 2^-(n+1) for rounding, checked exactly in integers:
// 0 <= 2^n - k*m < k, and |2^(n+1) - 2*k*m| <= k with equality only at the tie k = 2^(n+1).
TEST(ShiftAddDivision, ErrorBoundsForAllSpanLengths) {
  for (int n = 1; n <= 24; ++n) {
    const std::int64_t one = std::int64_t(1) << n;
    for (int k = 1; k <= 4096; ++k) {
      const std::int64_t t = std::int64_t(shift_add_reciprocal(k, n, R::truncate).bits);
      const std::int64_t r = std::int64_t(shift_add_reciprocal(k, n, R::nearest).bits);
      const std::int64_t dt = one - k * t, dr = 2 * one - 2 * k * r;
      ASSERT_TRUE(dt >= 0 && dt < k) << "truncated, k = " << k << ", n = " << n << ", m = " << t;
      const std::int64_t adr = dr < 0 ? -dr : dr;
      if (k == 2 * one)
        ASSERT_EQ(adr, k) << "tie, n = " << n;
      else
        ASSERT_LT(adr, k) << "rounded, k = " << k << ", n = " << n << ", m = " << r;
      // The same bounds on the doubles the error table reports.
      const double et = 1.0 / k - shift_add_reciprocal(k, n, R::truncate).value();
      const double er = 1.0 / k - shift_add_reciprocal(k, n, R::nearest).value();
      ASSERT_GE(et, 0.0);
      ASSERT_LT(et, 1.0 / double(one));
      ASSERT_LE(er < 0 ? -er : er, 0.5 / double(one));
    }
  }
}

// The hardware quotient: the register's D shifted right by j (floor), summed where i_j = 1.
TEST(ShiftAddDivision, HardwareQuotient) {
  // k = 7, n = 6 on 255 in 16.16 fixed point: 255*65536/8 + 255*65536/64 = 2088960 + 261120.
  const ShiftAddQuotient q = shift_add_divide(255 << 16, shift_add_reciprocal(7, 6));
  EXPECT_EQ(q.value, 2350080);
  EXPECT_EQ(q.value / 65536.0, 35.859375);
  EXPECT_EQ(q.adds, 2);
  EXPECT_EQ(q.shifts, 6);
  EXPECT_EQ(shift_add_divide(-(255 << 16), shift_add_reciprocal(7, 6)).value, -2350080);
  // k = 3, n = 8 rounded: terms 1/4, 1/16, 1/64, 1/256. 100 -> 25 + 6 + 1 + 0 = 32 (each term loses its
  // fraction); -100 -> -25 - 7 - 2 - 1 = -35 (floor); all four terms pass the adder.
  const ShiftAddReciprocal third = shift_add_reciprocal(3, 8, R::nearest);
  EXPECT_EQ(shift_add_divide(100, third).value, 32);
  EXPECT_EQ(shift_add_divide(100, third).adds, 4);
  EXPECT_EQ(shift_add_divide(-100, third).value, -35);
  // A k beyond 2^n truncates to no digit at all: the quotient is 0 and the adder never fires.
  const ShiftAddQuotient none = shift_add_divide(1000, shift_add_reciprocal(300, 8));
  EXPECT_EQ(none.value, 0);
  EXPECT_EQ(none.adds, 0);
  EXPECT_EQ(shift_add_reciprocal(300, 8).terms(), "0");
}

TEST(ShiftAddDivision, BadInputNamesTheValue) {
  auto message = [](auto f) -> std::string {
    try {
      f();
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "(no exception)";
  };
  EXPECT_NE(message([] { shift_add_reciprocal(0, 8); }).find("k = 0"), std::string::npos);
  EXPECT_NE(message([] { shift_add_reciprocal(-3, 8); }).find("k = -3"), std::string::npos);
  EXPECT_NE(message([] { shift_add_reciprocal(7, 0); }).find("n = 0"), std::string::npos);
  EXPECT_NE(message([] { shift_add_reciprocal(7, 31); }).find("n = 31"), std::string::npos);
  EXPECT_NE(message([] { shift_add_reciprocal(7, -1, R::nearest); }).find("n = -1"), std::string::npos);
  EXPECT_NE(message([] { division_error_table(0, 16, 8, R::nearest); }).find("k = 0"), std::string::npos);
  EXPECT_NE(message([] { division_error_table(5, 4, 8, R::nearest); }).find("k = 4"), std::string::npos);
  EXPECT_NE(message([] { division_error_table(2, 16, 31, R::nearest); }).find("n = 31"), std::string::npos);
  // The largest valid inputs work.
  EXPECT_EQ(shift_add_reciprocal(1, kMaxShiftAddBits).bits, std::uint64_t(1) << 30);
  EXPECT_EQ(shift_add_reciprocal(2147483647, kMaxShiftAddBits).bits, 0u);
  EXPECT_EQ(shift_add_reciprocal(2147483647, kMaxShiftAddBits, R::nearest).bits, 1u);  // 2^30/(2^31-1) ~ 0.5
}

}  // namespace
}  // namespace parashade
