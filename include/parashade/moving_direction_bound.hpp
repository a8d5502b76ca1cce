#pragma once
// The chord error of one lighting term along a segment when the light direction L, the view direction V
// and the normal N all move (a point light, a local viewer; docs/combined.md §2b). The bounds of
// combined.hpp take L and H constant along a segment, which holds only for directional lights and a
// distant viewer. This one is second order: for g(s) = max(0, N(s).D(s))^n on s in [0, 1] (D = L for the
// diffuse term, n = 1; D = H for the specular term) the chord's error is at most max|g''| / 8, and g'' is
// bounded from how fast N and D turn:
//   c = N.D, |c'| <= W sqrt(1 - c^2), |c''| <= W^2 + A sqrt(1 - c^2)   (W = w_N + w_D, A = a_N + a_D),
//   g'' = n c^(n-2) ((n - 1) c'^2 + c c''),
// with w the turning rates and a the tangential accelerations of the unit vectors (per unit of s).
#include <cmath>

namespace parashade {

// Rates along one segment, per unit of its parameter s in [0, 1].
struct SegmentRates {
  double normal = 0.0;     // |dN/ds| of the normalized interpolated normal (<= psi, combined.md §2)
  double light = 0.0;      // |dL/ds| (point light: |dp/ds| / distance; 0 for a directional light)
  double view = 0.0;       // |dV/ds| (local viewer: |dp/ds| / distance; 0 for a distant viewer)
  double half_min = 2.0;   // |L + V| >= this along the segment (H = (L + V) / |L + V|)
};

// max over c in [0, 1] of n c^(n-2) ((n - 1)(1 - c^2) + c), n >= 2 (closed form of each part's maximum).
double curvature_factor(double n);

// Bound on |chord - exact| (in units of the term, capped at 1) of the diffuse term max(0, N.L)
// (specular = false) or the specular term max(0, N.H)^n along the segment. `crosses_zero`: the diffuse
// term's clamp may lie inside (adds the kink's first-order W / 4). A specular term with n < 2 has no
// bounded g'' at its clamp: 1 (no bound; the caller shades such triangles by Phong per pixel).
double moving_term_bound(const SegmentRates& r, double n, bool specular, bool crosses_zero);
// The same without the cap at 1, with the specular exponent given by curvature_factor(n) and
// term_slope_bound(n) (computed once per material by callers that evaluate it per triangle). Affine rates
// make it a quadratic in their parameter: the per-triangle choice solves for the segment limit directly.
double moving_term_bound_uncapped(const SegmentRates& r, double curvature, double slope, bool specular, bool crosses_zero);

}  // namespace parashade
