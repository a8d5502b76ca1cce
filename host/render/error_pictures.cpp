#include "error_pictures.hpp"

#include <cmath>
#include <cstdio>

#include "parashade/errors.hpp"
#include "parashade/flip.hpp"

namespace parashade {

std::vector<StagedFile> stage_error_pictures(const ErrorPictureFiles& files, const std::vector<double>& errors,
                                             int width, int height, std::vector<std::string>& lines) {
  std::vector<StagedFile> staged;
  const double top = error_scale_top(errors);
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.2f", top);
  if (!files.map.empty() && is_exr(files.map)) {
    staged.push_back(stage_values(files.map, std::vector<float>(errors.begin(), errors.end()), width, height));
    lines.push_back("error map " + files.map.string() + ": per-pixel error in levels (one float channel Y; NaN: "
                    "not compared)");
  } else if (!files.map.empty()) {
    staged.push_back(stage_image(files.map, error_map_image(errors, width, height, files.scale)));
    lines.push_back("error map " + files.map.string() + ": " + error_scale_name(files.scale) + " scale 0.." + buf +
                    " levels (its top is the largest error, at least 1)");
  }
  if (!files.legend.empty()) {
    bool top_is_max = false;
    for (double e : errors) top_is_max = top_is_max || e == top;
    staged.push_back(stage_image(files.legend, error_legend_image(top, top_is_max, files.scale, height)));
    lines.push_back("error legend " + files.legend.string() + ": the map's colours, " + error_scale_name(files.scale) +
                    " 0.." + buf + " levels");
  }
  return staged;
}

StagedFile stage_flip_map(const std::filesystem::path& path, const std::vector<float>& map, int width, int height,
                          std::vector<std::string>& lines) {
  if (is_exr(path)) {
    lines.push_back("FLIP map " + path.string() + ": per-pixel LDR-FLIP in [0, 1] (one float channel Y)");
    return stage_values(path, map, width, height);
  }
  lines.push_back("FLIP map " + path.string() + ": per-pixel LDR-FLIP, magma from 0 (black) to 1");
  return stage_image(path, flip_map_image(map, width, height));
}

void check_error_picture_options(const ErrorPictureFiles& files, const std::string& map_option) {
  if (files.legend.empty()) return;
  if (files.map.empty())
    throw UsageError("--error-legend draws the colours of " + map_option + "; give " + map_option + " too");
  if (is_exr(files.map))
    throw UsageError("--error-legend draws the colours of a picture; " + map_option + " " + files.map.string() +
                     " holds the error values themselves (EXR)");
}

}  // namespace parashade
