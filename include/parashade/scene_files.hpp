#pragma once
// The files a scene is made of, for callers that must not write over them (parashade render refuses an
// output that is one of its inputs).
#include <filesystem>
#include <optional>
#include <utility>
#include <vector>

#include "parashade/scene.hpp"

namespace parashade {

// load_scene (scene.hpp) that also appends every file it read to `files`: the scene file, then the mesh
// files it names (a bare mesh: the mesh file).
Scene load_scene(const std::filesystem::path& path, std::vector<std::filesystem::path>& files);
// The same at the resolution it will be rendered: `size` (WIDTH, HEIGHT; nullopt: the scene's own, checked by
// check_resolution beforehand) replaces the scene's before the host memory budget is judged.
Scene load_scene(const std::filesystem::path& path, std::vector<std::filesystem::path>& files,
                 const std::optional<std::pair<int, int>>& size);

}  // namespace parashade
