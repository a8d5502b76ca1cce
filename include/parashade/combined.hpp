#pragma once
// Combined Gouraud/Phong shading on digital segments ([Romanyuk & Romanyuk, combined shading], docs/combined.md): exact Blinn–Phong
// at the ends of segments of 2^k pixels along each span, linear interpolation inside. Here: the
// method's parameters and the worst-case error bounds that `combined:auto` chooses k from.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "parashade/scene.hpp"

namespace parashade {

// Per-triangle choice between Gouraud and the segments (triangle_choice.hpp).
enum class TriangleRule { none, bound, sources, sources_literal, list };

struct CombinedConfig {
  int k = 2;               // segment length 2^k pixels (fixed k)
  bool automatic = false;  // k per span from the error bound (combined:auto)
  double max_error = 1.0;  // auto: budget in 8-bit levels for the 8-bit image against Phong
  // Highlight-presence test (highlight.hpp): per triangle, skip the specular term of the lights that
  // cannot add more than negligible_specular levels anywhere in it.
  bool highlight_test = false;
  // Triangles with a narrower bounding box go by Phong per pixel (-1: 2^(k+1), 8 for auto; 0: none).
  int min_width = -1;
  double negligible_specular = 0.05;
  // Per-triangle Gouraud choice: none for combined:K unless asked, bound for combined:auto.
  TriangleRule rule = TriangleRule::none;
  double source_m = 0.9, source_q = 0.004, source_p = 0.008;  // the sources' thresholds
  // list: a choice made elsewhere (scripts/mix_oracle.py's): the screen triangles that go by Phong (ascending,
  // once each), the rest by Gouraud; read from list_file, indices as render --triangle-map numbers them minus one.
  // Indices, not flags: the file's size bounds the memory, whatever index it names.
  std::shared_ptr<const std::vector<std::uint32_t>> phong_list;
  std::string list_file;
  // combined:auto with a choice: triangles whose segments could not reach 2^walk_min_k pixels go by Phong
  // per pixel (the walk's fixed costs exceed what shorter segments save); above kCombinedMaxK: none walk.
  int walk_min_k = 2;
};

// "none", "bound", "sources[:M,Q,P]", "sources-literal[:M,Q,P]", "list:FILE" (FILE: whitespace-separated screen
// triangle indices to shade by Phong); throws UsageError naming the text, InputError for an unreadable or
// malformed FILE.
void parse_triangle_rule(const std::string& text, CombinedConfig& c);
std::string triangle_rule_name(const CombinedConfig& c);

constexpr int kCombinedMaxK = 6;  // longest segment 64 pixels
constexpr int kNeverWalk = 1 << 20;  // a minimum width no triangle reaches (combined:0 goes by Phong per pixel)

// "combined:K" (K = 0..kCombinedMaxK) or "combined:auto"; throws UsageError otherwise.
CombinedConfig parse_combined(const std::string& method_text);
std::string combined_name(const CombinedConfig& c);
// The kernel skips the specular terms a per-triangle mask leaves out (--highlight-test, or the bound rule
// of the per-triangle choice, which computes the mask anyway).
bool uses_highlight_mask(const CombinedConfig& c);
// Triangles narrower than this (bounding box, pixels) are shaded by Phong per pixel (combined:K, and
// combined:auto without a per-triangle choice); combined:0 walks none.
int combined_min_width(const CombinedConfig& c);
// The shading error allowed to the segments: the budget minus the 8-bit image's rounding (0.5 level).
double combined_shading_budget(const CombinedConfig& c);
// What one specular term the highlight mask drops may add, in levels, with `lights` lights. The dropped
// terms are charged to the shading budget (combined_shading_budget's, or a caller's), so where a budget
// applies (combined:auto, --triangle-choice bound) their sum must fit it: negligible_specular, lowered to
// shading_budget / lights when the lights together would pass it (24 faint lights at 0.05 each made 1.2
// levels against a budget of 0.5). Without a budget (combined:K --highlight-test): negligible_specular.
double dropped_specular_levels(const CombinedConfig& c, double shading_budget, std::size_t lights);
// Float Phong's own error against its ideal in levels, at most 64u 255 sum_l max_c I_l,c (k_d,c + k_s,c (n + 1))
// for the scene's worst material (docs/error-bounds.md, u = 2^-24). The budget holds against Phong's float
// image, so 0.5 (the 8-bit rounding) plus this is the floor under --max-error against ideal Phong.
double phong_float_error_bound(const Scene& s);

// Worst-case |exact - chord| of one segment for a term max(0, A cos(theta - theta0))^n (A <= 1) whose
// end normals are phi apart on a great circle, the chord linear in the angle (docs/combined.md §2).
// n = 1 is the diffuse term. crosses_zero = false: the term's clamp (the terminator for n = 1) is known
// not to lie inside the segment, so only the smooth peak case remains.
double chord_error_bound(double phi, double n, bool crosses_zero = true);
// Largest |d/dtheta max(0, cos theta)^n| (n >= 1): how fast a misplaced angle changes the term.
double term_slope_bound(double n);
// Largest |atan(u tan(phi/2)) - u phi/2| over u in [-1, 1]: how far the normalized chord point is from
// the point uniform in angle.
double nonuniform_angle(double phi);
// The same bound for a segment whose unnormalized end normals N_a, N_b = N_a + w satisfy
// |w| <= psi * min|N| over the segment: phi <= asin(psi), and the chord's parameter is off the
// angle's by at most delta = (sqrt(rho) - 1) / (sqrt(rho) + 1), rho = 1 + psi (docs/combined.md §3).
// Returns 1 (the whole range of a term) for psi >= 1.
double segment_term_bound(double psi, double n, bool crosses_zero = true);
// The error of a term (in [0, 1]) whose argument angle is off by at most `shift`: slope times shift.
double angle_shift_error(double shift, double n);
// The terms a segment can show: `terminator` false means no diffuse term crosses its zero (no
// first-order kink), `specular` false means no specular term (the highlight mask skips it).
struct SegmentTerms {
  bool terminator = true;
  bool specular = true;
};
// Worst-case error in 8-bit levels (largest channel) of one pixel of material m under the scene's
// lights when every segment has relative normal change <= psi; L and H are taken as constant along a
// segment (exact for directional lights and a distant viewer).
double segment_error_levels(const Scene& s, const Material& m, double psi, SegmentTerms terms = {});
// The largest psi whose segment_error_levels stays <= budget levels (0 when none does).
double psi_limit(const Scene& s, const Material& m, double budget_levels, SegmentTerms terms = {});

}  // namespace parashade
