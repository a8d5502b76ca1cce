#pragma once
// A scene as bytes, for rank 0 to send each rank its share (`--read-scene rank-0`, docs/distributed.md)
// instead of every rank reading the file. Everything the renderer reads travels bit for bit (floats as
// their bytes, never as text), so a rank renders exactly what it would have built from the file.
#include <cstdint>
#include <vector>

#include "parashade/scene.hpp"

namespace parashade::distributed {

// The scene and, per face of its meshes in order, that face's index in the whole scene (sort-last's
// depth keys carry it); `global_face` may be empty (sort-first: the whole scene).
std::vector<char> scene_to_bytes(const Scene& scene, const std::vector<std::uint32_t>& global_face);

// The inverse; throws InputError when the bytes end early or carry more than they should.
Scene scene_from_bytes(const std::vector<char>& bytes, std::vector<std::uint32_t>& global_face);

}  // namespace parashade::distributed
