#pragma once
// The files a render writes (render_step.hpp's result): the image, the report, and the pictures of the
// error (docs/pictures.md). Every output goes to a temporary file first and replaces its destination only
// when all were written: a failed report leaves the previous image and pictures in place.
#include <filesystem>
#include <string>
#include <vector>

#include "parashade/error_map.hpp"
#include "parashade/render_step.hpp"

namespace parashade {

struct RenderOutputs {
  std::filesystem::path image, report;  // report: empty for none
  // The exact reference as an image, the per-pixel error as a colour map, the reference's visible triangle
  // per pixel; each empty for none. They need the result's reference (RenderRequest::keep_reference:
  // needs_reference()).
  std::filesystem::path reference_image, error_map, triangle_map;
  bool against_exact = false;  // reference_image, error_map and FLIP against exact Phong, not the method's ideal
  // The error map's colour scale and its legend as a picture of its own (empty: none); the FLIP map (empty:
  // none), which needs the result's ErrorFigures::flip_map (RenderRequest::flip.keep_map) and not the
  // reference: a frame's worth of doubles and more that --flip-map alone does not keep.
  ErrorScale error_scale;
  std::filesystem::path error_legend, flip_map;

  // Whether any picture is asked for (each needs the error figures).
  bool pictures() const { return needs_reference() || !flip_map.empty(); }
  // Whether a picture drawn from the reference is (--reference-image, --error-map, --triangle-map).
  bool needs_reference() const { return !reference_image.empty() || !error_map.empty() || !triangle_map.empty(); }
  // The picture options given ("--reference-image", "--error-map", "--triangle-map", "--flip-map"), in that order.
  std::vector<std::string> picture_options() const;
  // Declares them to `files` by render's option names (-o, --report, --reference-image, --error-map,
  // --error-legend, --triangle-map, --flip-map).
  void declare(CommandFiles& files) const;
  // Writes them all; returns one line per picture saying what it holds (for the summary).
  std::vector<std::string> write(const RenderResult& r) const;
};

}  // namespace parashade
