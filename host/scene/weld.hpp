#pragma once
// Merging coincident vertices, for meshes assembled from pieces that meet at shared edges.
#include <cstddef>

#include "parashade/mesh.hpp"

namespace parashade::detail {

// Merges vertices closer than `tolerance` (per coordinate) into the first of them; a merged vertex
// gets the normalized sum of its members' normals, so normals agree across a seam. Triangles left
// with a repeated vertex (zero area) are removed; returns how many.
std::size_t weld_vertices(Mesh& mesh, float tolerance);

}  // namespace parashade::detail
