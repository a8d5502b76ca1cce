#pragma once
// The pictures of an image's error that render (--reference-image, --error-map, --error-legend, --flip-map)
// and compare (--error-map, --error-legend, --flip-map) write: the per-pixel error as a colour map of the
// image's size or, to EXR, as its values in levels; the map's scale as a picture of its own; the FLIP map
// (error_map.hpp, flip.hpp). Staged (output_file.hpp), so the caller commits them with its other outputs.
#include <filesystem>
#include <string>
#include <vector>

#include "parashade/error_map.hpp"
#include "parashade/image.hpp"
#include "parashade/output_file.hpp"

namespace parashade {

struct ErrorPictureFiles {
  std::filesystem::path map, legend;  // empty: none
  ErrorScale scale;
};

// The error map and its legend for `errors` (pixel_errors: levels per pixel, NaN not compared; width x
// height) staged at files.map (EXR: one float channel of the errors in levels, NaN kept; else the colour
// map on files.scale) and files.legend; `lines` receives one line per file saying what it holds.
std::vector<StagedFile> stage_error_pictures(const ErrorPictureFiles& files, const std::vector<double>& errors,
                                             int width, int height, std::vector<std::string>& lines);

// A FLIP map (ldr_flip's values) staged at `path`: EXR the values, else flip_map_image's magma picture.
StagedFile stage_flip_map(const std::filesystem::path& path, const std::vector<float>& map, int width, int height,
                          std::vector<std::string>& lines);

// Usage checks of the picture options, by their names: --error-legend needs an error map that is a
// picture (not EXR, whose values need no legend). Throws UsageError.
void check_error_picture_options(const ErrorPictureFiles& files, const std::string& map_option);

}  // namespace parashade
