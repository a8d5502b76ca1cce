// The error of a frame against the exact reference (render_step.hpp).
#include "parashade/combined.hpp"
#include "parashade/flip.hpp"
#include "parashade/geometry_stage.hpp"
#include "parashade/render_step.hpp"
#include "parashade/triangle_choice.hpp"

namespace parashade {
namespace {

// The geometry the exact reference renders: the frame's triangles in the same order, with every attribute
// the reference needs, and the vertex intensities too where a per-triangle choice is made on it.
ScreenGeometry reference_geometry(const Scene& scene, Method method, bool chooses_per_triangle) {
  ScreenGeometry g;
  build_screen_geometry(scene, {method, true, chooses_per_triangle}, g);
  return g;
}

// The per-triangle choice's visible pixels per method: the choice made again on the reference's geometry `g`,
// counted on the reference's visibility.
ChoicePixels choice_pixels_of(const Scene& scene, const RenderOptions& options, const ScreenGeometry& g,
                              const ReferenceImage& ref) {
  std::vector<TriangleShading> choice;
  choose_triangle_methods(scene, g, options.combined, combined_shading_budget(options.combined), choice);
  return visible_pixels_by_method(ref.triangle, choice);
}

}  // namespace

std::string ideal_name(Method method) {
  return method == Method::combined ? "ideal phong" : std::string("ideal ") + method_name(method);
}

ReferenceImage exact_reference(const Scene& scene, Method method) {
  return render_reference(scene, reference_geometry(scene, method, false), method);
}

ErrorFigures error_against(const ReferenceImage& ref, Method method, const RenderedImage& image) {
  ErrorFigures e;
  // Where float depth kept another front surface than the reference: not shading error, counted apart.
  const std::vector<std::uint8_t> flipped = front_surface_flips(image, ref);
  e.implementation = compare_to_reference(image, ref.covered, ref.ideal, ideal_name(method), flipped);
  e.method = compare_to_reference(image, ref.covered, ref.exact, "exact phong", flipped);
  return e;
}

ErrorFigures error_figures(const Scene& scene, const RenderOptions& options, const RenderedImage& image,
                           bool keep_reference, const FlipRequest& flip) {
  const ScreenGeometry g = reference_geometry(scene, options.method, options.chooses_per_triangle());
  ReferenceImage ref = render_reference(scene, g, options.method);
  ErrorFigures e = error_against(ref, options.method, image);
  if (flip.enabled) {
    // The whole frame, background included, as FLIP's own tools compare two image files.
    std::vector<float> map = ldr_flip(flip_input(flip.against_exact ? ref.exact : ref.ideal), flip_input(image),
                                      image.width, image.height);
    (flip.against_exact ? e.method : e.implementation).flip = flip_figures(map);
    if (flip.keep_map) e.flip_map = std::move(map);
  }
  if (options.chooses_per_triangle()) e.choice_pixels = choice_pixels_of(scene, options, g, ref);
  if (keep_reference) e.reference = std::move(ref);
  return e;
}

}  // namespace parashade
