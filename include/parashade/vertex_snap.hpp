#pragma once
// The vertex stage's per-vertex step: clip-space position, clip outcode, and the snapped sub-pixel screen
// position, window depth and 1/w. snap() and outcode_of() are the definitions; transform_vertices()
// computes them for many vertices at once (vectors of lanes) and gives the same bits (a test checks).
#include <cstddef>
#include <cstdint>

#include <glm/glm.hpp>

namespace parashade {

// Clip planes; bit i of an outcode = outside plane i.
enum : std::uint8_t { kNear = 1, kFar = 2, kLeft = 4, kRight = 8, kBottom = 16, kTop = 32 };
constexpr std::uint8_t kNonFinite = 64;  // not a plane: the vertex has NaN or Inf coordinates

std::uint8_t outcode_of(const glm::vec4& c);

struct Snapped {
  glm::ivec2 xy;
  float depth;
  float inv_w;
};

// Clip space -> sub-pixel screen position (y down), window depth and 1/w. Only meaningful for points
// inside the guard band (the callers guarantee it); values are clamped so nothing overflows otherwise.
Snapped snap(const glm::vec4& c, int width, int height);

// Vertices [0, count) of `position` through `m` (model-view-projection, glm's float matrix product):
// clip[i] = m * (position[i], 1), outcode[i] = outcode_of(clip[i]), and snap(clip[i]) into xy, depth, inv_w;
// eight at a time in vector lanes where they pay (vertex_lanes.hpp), the same bits.
struct SnappedVertices {
  glm::vec4* clip;  // may be null: not kept (the vertex stage recomputes the few that clipping needs)
  std::uint8_t* outcode;
  glm::ivec2* xy;
  float* depth;
  float* inv_w;
};
void transform_vertices(const glm::mat4& m, const glm::vec3* position, std::size_t count, int width, int height,
                        const SnappedVertices& out);

}  // namespace parashade
