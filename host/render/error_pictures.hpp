#pragma once
// The pictures of an image's error that render (--reference-image, --error-map) and compare (--diff)
// write: the reference's values as an image and the per-pixel error as a colour map with its scale
// (error_map.hpp). Staged (output_file.hpp), so the caller commits them together with its other outputs.
#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "parashade/image.hpp"
#include "parashade/output_file.hpp"

namespace parashade {

// The error map of `image` against `reference` (values in levels; `covered` and `flipped` as
// compare_to_reference takes them) staged at `path`; `lines` receives what was written and the scale's top.
StagedFile stage_error_map(const std::filesystem::path& path, const RenderedImage& image,
                           const std::vector<std::uint8_t>& covered, const std::vector<glm::dvec3>& reference,
                           const std::vector<std::uint8_t>& flipped, std::vector<std::string>& lines);

}  // namespace parashade
