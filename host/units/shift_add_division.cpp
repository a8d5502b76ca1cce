// Division by shifts and adds (shift_add_division.hpp). The digits come from integer division, so
// they are exact for every k and n; the error figures are computed in double, which holds m / 2^n
// exactly (m < 2^31).
#include "parashade/shift_add_division.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace parashade {
namespace {

void check_n(int n) {
  if (n < 1 || n > kMaxShiftAddBits)
    throw std::invalid_argument("shift-add division: number of shifts n = " + std::to_string(n) +
                                " is outside 1.." + std::to_string(kMaxShiftAddBits));
}

void check_k(int k) {
  if (k < 1)
    throw std::invalid_argument("shift-add division: span length k = " + std::to_string(k) + " must be >= 1");
}

// floor(d / 2^j) without relying on how >> treats negative values (implementation-defined before C++20).
std::int64_t floor_shift(std::int64_t d, int j) { return d >= 0 ? d >> j : ~((~d) >> j); }

}  // namespace

double ShiftAddReciprocal::value() const { return std::ldexp(double(bits), -n); }

int ShiftAddReciprocal::adds() const {
  int c = 0;
  for (std::uint64_t m = bits; m != 0; m &= m - 1) ++c;
  return c;
}

int ShiftAddReciprocal::last_shift() const {
  if (bits == 0) return 0;
  int low = 0;
  while (((bits >> low) & 1u) == 0) ++low;
  return n - low;
}

std::string ShiftAddReciprocal::terms() const {
  std::string s;
  for (int j = 0; j <= n; ++j) {
    if (!term(j)) continue;
    if (!s.empty()) s += " + ";
    s += j == 0 ? std::string("1") : "1/" + std::to_string(std::uint64_t(1) << j);
  }
  return s.empty() ? "0" : s;
}

ShiftAddReciprocal shift_add_reciprocal(int k, int n, ReciprocalRounding rounding) {
  check_k(k);
  check_n(n);
  ShiftAddReciprocal r;
  r.k = k;
  r.n = n;
  r.rounding = rounding;
  const std::uint64_t one = std::uint64_t(1) << n;  // 1.0 in n fraction bits
  const std::uint64_t kk = std::uint64_t(k);
  r.bits = rounding == ReciprocalRounding::truncate ? one / kk : (2 * one + kk) / (2 * kk);
  return r;
}

ShiftAddQuotient shift_add_divide(std::int64_t numerator, const ShiftAddReciprocal& r) {
  ShiftAddQuotient q;
  for (int j = 0; j <= r.n; ++j) {
    if (!r.term(j)) continue;  // i_j = 0: the register only shifts
    q.value += floor_shift(numerator, j);
    ++q.adds;
    q.shifts = j;
  }
  return q;
}

std::vector<DivisionErrorRow> division_error_table(int k_first, int k_last, int n, ReciprocalRounding rounding,
                                                   double numerator) {
  check_k(k_first);
  check_n(n);
  if (k_last < k_first)
    throw std::invalid_argument("shift-add division: table end k = " + std::to_string(k_last) +
                                " is below its start " + std::to_string(k_first));
  std::vector<DivisionErrorRow> rows;
  rows.reserve(std::size_t(k_last - k_first) + 1);
  for (int k = k_first;; ++k) {
    DivisionErrorRow row;
    row.reciprocal = shift_add_reciprocal(k, n, rounding);
    row.exact = numerator / k;
    row.approx = numerator * row.reciprocal.value();
    row.abs_error = row.approx - row.exact;
    row.rel_error = row.exact != 0.0 ? row.abs_error / row.exact : 0.0;
    rows.push_back(row);
    if (k == k_last) break;  // no k + 1 overflow at INT_MAX
  }
  return rows;
}

DivisionErrorSummary summarize(const std::vector<DivisionErrorRow>& rows) {
  DivisionErrorSummary s;
  s.rows = int(rows.size());
  if (rows.empty()) return s;
  double sum_abs = 0.0, sum_rel = 0.0, sum_rel_inexact = 0.0, sum_adds = 0.0;
  int inexact = 0;
  s.k_at_max_abs = s.k_at_max_rel = rows.front().reciprocal.k;
  for (const DivisionErrorRow& r : rows) {
    const double a = std::abs(r.abs_error), e = std::abs(r.rel_error);
    if (a > s.max_abs_error) {  // the first k wins a tie
      s.max_abs_error = a;
      s.k_at_max_abs = r.reciprocal.k;
    }
    if (e > s.max_rel_error) {
      s.max_rel_error = e;
      s.k_at_max_rel = r.reciprocal.k;
    }
    sum_abs += a;
    sum_rel += e;
    if (r.abs_error != 0.0) {
      sum_rel_inexact += e;
      ++inexact;
    }
    sum_adds += r.reciprocal.adds();
    s.max_adds = std::max(s.max_adds, r.reciprocal.adds());
  }
  s.mean_abs_error = sum_abs / s.rows;
  s.mean_rel_error = sum_rel / s.rows;
  s.mean_rel_error_inexact = inexact ? sum_rel_inexact / inexact : 0.0;
  s.mean_adds = sum_adds / s.rows;
  return s;
}

}  // namespace parashade
