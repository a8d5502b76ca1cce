#pragma once
// Per-triangle choice of the shading method inside the combined method ([Dembitsky 2025, software/hardware rendering] ch. 3 "adaptive
// Gouraud/Phong", issue 4(b, c); docs/triangle-choice.md): each triangle is shaded either by Gouraud
// (its vertex intensities interpolated linearly) or by Phong's normals — per pixel, or at the ends of
// 2^K-pixel segments (combined:K / combined:auto).
//
// Rules:
//  * bound (combined:auto's default): Gouraud where the triangle's expected worst-case error against
//    Phong, from the chord bounds of combined.hpp applied to its edges and spans, stays within the
//    shading budget; otherwise segments, with K per span from a limit on the relative normal change
//    that depends on which terms the triangle can show (a terminator crossing it, a highlight in it),
//    where the triangle allows K >= walk_min_k and is wide enough; otherwise Phong per pixel.
//  * sources: the thesis's listing (AdaptivGourauAndFong.selectMetod): Gouraud when every pair of
//    vertex normals is close (n_i.n_j > m), and N.h (h = L_0 + V, unnormalized, as printed) and N.L_0
//    differ by at most q and p between vertices; Phong otherwise. Thresholds m, q, p = 0.9, 0.004, 0.008.
//  * sources-literal: the listing as printed, whose first test is inverted (it returns Phong when
//    |n_i.n_j| > m, i.e. when the normals are close): Gouraud only for triangles whose normals differ.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "parashade/combined.hpp"
#include "parashade/scene.hpp"
#include "parashade/screen_geometry.hpp"

namespace parashade {

// Per triangle, what the kernel needs (written into the Phong record's spare slots by
// apply_triangle_choice).
// How a triangle is shaded (the kernel's PHONG_METHOD_SLOT): Phong per pixel, Gouraud (vertex
// intensities interpolated; colour planes in the normal slots), or segments (combined_walk.h).
enum class TriangleMethod { phong = 0, gouraud = 1, segments = 2 };

struct TriangleShading {
  TriangleMethod method = TriangleMethod::phong;
  std::uint32_t specular_mask = 0;  // lights whose specular term can show (highlight-presence test)
  float psi_limit = 0.0f;        // segments: largest relative normal change per segment (combined:auto)
};

struct TriangleChoiceStats {
  std::uint64_t triangles = 0;
  std::uint64_t gouraud = 0;             // shaded by Gouraud
  std::uint64_t segments = 0;            // walked by segments (the rest: Phong per pixel)
  std::uint64_t without_highlight = 0;   // no light's specular term can show
  std::uint64_t terminator = 0;          // wide enough to walk, and a light's terminator may cross it
  std::uint64_t light_terms_skipped = 0; // (triangle, light) specular terms the mask leaves out
  double largest_expected_levels = 0.0;  // largest expected Gouraud error among the Gouraud triangles
};

// Expected worst-case |Gouraud - Phong| of one term max(0, cos)^n over a triangle whose shaded normals
// (and the term's direction, L or H) span at most phi radians: the edge's chord error plus the span's
// (whose ends are unnormalized interpolations, length >= cos(phi/2)). `crosses_zero`: the clamped
// term's zero (the terminator for n = 1) may lie inside. A bound for a directional light and a distant
// viewer, where the choice uses it; where L or H moves the choice bounds the term by
// moving_direction_bound.hpp instead (docs/triangle-choice.md §2).
double gouraud_term_bound(double phi, double n, bool crosses_zero);

// Chooses for every screen triangle of g. `shading_budget` is the budget in levels for the shading
// error (combined_shading_budget: --max-error minus the 8-bit rounding).
// How the bound rule's per-triangle bounds are computed: in float on vector lanes (light_bounds_lanes.hpp,
// what the renderer uses) or by the scalar double reference (light_bounds.hpp; tests compare the two).
enum class ChoiceArithmetic { float_lanes, double_reference };

TriangleChoiceStats choose_triangle_methods(const Scene& s, const ScreenGeometry& g, const CombinedConfig& c,
                                            double shading_budget, std::vector<TriangleShading>& out,
                                            ChoiceArithmetic arithmetic = ChoiceArithmetic::float_lanes);

// The same choice range by range, for a caller that runs it inside its own parallel loop: the frame's setup
// chooses each range right before setting it up, so the two share one wake-up of the host threads.
// choose() may run on disjoint ranges from several threads at once; stats() once every triangle is chosen.
class TriangleChooser {
 public:
  TriangleChooser(const Scene& s, const ScreenGeometry& g, const CombinedConfig& c, double shading_budget,
                  std::vector<TriangleShading>& out, ChoiceArithmetic arithmetic = ChoiceArithmetic::float_lanes);
  ~TriangleChooser();
  void choose(std::size_t first, std::size_t last);  // out[first .. last)
  TriangleChoiceStats stats() const;

 private:
  struct Shared;
  std::unique_ptr<Shared> shared_;
};

// Writes the choice of triangles first .. last - 1 into their Phong records (kernels/triangle_record.h:
// PHONG_HIGHLIGHT_SLOT, PHONG_METHOD_SLOT, PHONG_PSI_SLOT). The colour planes of Gouraud triangles are setup's.
void apply_triangle_choice(const std::vector<TriangleShading>& choice, float* attributes, std::size_t stride,
                           std::size_t first, std::size_t last);

}  // namespace parashade
