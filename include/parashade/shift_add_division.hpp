#pragma once
// Division by a span length k with shifts and adds ([Romanyuk & Obidnyk 2011, faster shading]): 1/k is replaced by n binary
// digits, 1/k ~ sum_{j=1..n} i_j * 2^-j with i_j in {0, 1}, and a quotient D/k becomes the sum of D
// shifted right by j for every j with i_j = 1 -- a shift register feeding an accumulating adder that
// adds only where i_j = 1. The digits are the n-bit expansion of 1/k, truncated or rounded to nearest
// at bit n (the source's Table 1 is the rounded one; docs/shift-add-division.md).
// Digits are held as an integer m = sum i_j * 2^(n-j), so the approximation is m / 2^n. For k = 1 the
// quotient needs the unshifted term 2^0, which m holds as the bit above the n fraction bits.
#include <cstdint>
#include <string>
#include <vector>

namespace parashade {

enum class ReciprocalRounding {
  truncate,  // m = floor(2^n / k): never above 1/k, |error| < 2^-n
  nearest,   // m = round(2^n / k), ties up: |error| <= 2^-(n+1), equal only at the tie k = 2^(n+1)
};

// At most 30 digits: m (2^n for k = 1) stays within a signed 32-bit register, and a span register
// difference (W <= 32 bits) shifted further contributes nothing but its sign.
constexpr int kMaxShiftAddBits = 30;

struct ShiftAddReciprocal {
  int k = 1;
  int n = 1;
  ReciprocalRounding rounding = ReciprocalRounding::truncate;
  std::uint64_t bits = 0;  // m; i_j is bit (n - j) of m, j = 0..n

  bool term(int j) const { return j >= 0 && j <= n && ((bits >> (n - j)) & 1u) != 0; }
  double value() const;        // m / 2^n, exactly
  int adds() const;            // adder activations: the number of j with i_j = 1
  int last_shift() const;      // the largest j with i_j = 1 (0 when m = 0): shifts the register needs
  std::string terms() const;   // "1/8 + 1/64"; "0" when m = 0
};

// The n-digit approximation of 1/k. Throws std::invalid_argument naming k when k < 1, or n when n is
// outside 1..kMaxShiftAddBits.
ShiftAddReciprocal shift_add_reciprocal(int k, int n, ReciprocalRounding rounding = ReciprocalRounding::truncate);

// D/k as the hardware forms it: the register holds D (an integer, e.g. a fixed-point intensity
// difference) and shifts it right one place per clock; where i_j = 1 the adder accumulates it. Each
// shifted term loses its low bits (arithmetic shift, rounding toward -inf), as a shift register does.
struct ShiftAddQuotient {
  std::int64_t value = 0;
  int adds = 0;    // adder activations (one per i_j = 1; the first only loads the cleared accumulator)
  int shifts = 0;  // register shifts up to the last digit used
};
ShiftAddQuotient shift_add_divide(std::int64_t numerator, const ShiftAddReciprocal& r);

// Error of the approximate quotient numerator / k against the exact one, in real arithmetic (as the
// source's Table 1: dI = 255 * approximation for a 0 -> 255 ramp across k pixels).
struct DivisionErrorRow {
  ShiftAddReciprocal reciprocal;
  double exact = 0.0;      // numerator / k
  double approx = 0.0;     // numerator * m / 2^n
  double abs_error = 0.0;  // approx - exact (signed, as the source prints it)
  double rel_error = 0.0;  // (approx - exact) / exact (signed fraction)
};
// Rows for k = k_first..k_last. Throws std::invalid_argument for k_first < 1, k_last < k_first or bad n.
std::vector<DivisionErrorRow> division_error_table(int k_first, int k_last, int n, ReciprocalRounding rounding,
                                                   double numerator = 255.0);

struct DivisionErrorSummary {
  double max_abs_error = 0.0;      // max |approx - exact|
  int k_at_max_abs = 0;
  double mean_abs_error = 0.0;
  double max_rel_error = 0.0;      // max |rel_error|
  int k_at_max_rel = 0;
  double mean_rel_error = 0.0;     // mean |rel_error| over every row (exact rows count as 0)
  double mean_rel_error_inexact = 0.0;  // mean |rel_error| over the rows that are not exact
  double mean_adds = 0.0;
  int max_adds = 0;
  int rows = 0;
};
DivisionErrorSummary summarize(const std::vector<DivisionErrorRow>& rows);

}  // namespace parashade
