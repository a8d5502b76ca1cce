#pragma once
// Lower-degree specular models replacing cos^n(alpha), cos(alpha) = N.H ([Dembitsky 2025, software/hardware rendering] ch. 3;
// docs/phong-methods.md). All return values in [0, 1] and 0 for cos(alpha) <= 0.
#include <string>

namespace parashade {

enum class SpecularKind {
  exact,       // cos^n
  cosk_taylor, // cos^k(a alpha), a = sqrt(n/k) (equal second derivative at alpha = 0); 0 past pi/(2a)
  cosk_lobe,   // cos^k(a alpha), a from equal lobe integrals int cos^n sin = int cos^k(a .) sin
  quadratic,   // (1 + (n/2)(cos - 1))^2, 0 below the threshold cos = 1 - 2/n
  sevenths,    // (1 + (7n/16)(cos - 1))^p, 0 below cos = 1 - 16/(7n): "7n/16", shifts only
};

// The exponent p of the 7n/16 variant: the p minimizing the worst absolute error over n = 1..1000
// (found by phong-study; 16/7 is the exponent of equal slope at alpha = 0, docs/phong-methods.md).
constexpr double kSeventhsExponent = 2.0;

struct SpecularModel {
  SpecularKind kind = SpecularKind::exact;
  int k = 2;                             // cosk_*: 2 or 4
  double p = kSeventhsExponent;          // sevenths
};

// "exact", "cosk:taylor:2|4", "cosk:lobe:2|4", "quadratic", "7n16[:P]". Throws UsageError naming the text.
SpecularModel parse_specular(const std::string& text);
std::string specular_name(const SpecularModel& m);

// a of cos^k(a alpha) for exponent n (n > 0).
double taylor_scale(double n, int k);
double lobe_scale(double n, int k);

// The model's value at cos(alpha) = c for exponent n; `scale` is a (cosk_*), ignored otherwise.
double specular_value(const SpecularModel& m, double n, double c, double scale);
// Convenience: computes the scale itself.
double specular_value(const SpecularModel& m, double n, double c);

}  // namespace parashade
