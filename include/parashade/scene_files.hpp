#pragma once
// The files a scene is made of, for callers that must not write over them (parashade render refuses an
// output that is one of its inputs).
#include <filesystem>
#include <vector>

#include "parashade/scene.hpp"

namespace parashade {

// load_scene (scene.hpp) that also appends every file it read to `files`: the scene file, then the mesh
// files it names (a bare mesh: the mesh file).
Scene load_scene(const std::filesystem::path& path, std::vector<std::filesystem::path>& files);

}  // namespace parashade
