#pragma once
// The vertex stage (GLM transforms, per-vertex lighting where the method needs it) and primitive
// assembly (clip in clip space, cull back faces, snap to the sub-pixel grid, orient): Scene -> ScreenGeometry.
#include <glm/glm.hpp>

#include "parashade/method.hpp"
#include "parashade/scene.hpp"
#include "parashade/screen_geometry.hpp"

namespace parashade {

struct GeometryRequest {
  Method method = Method::gouraud;
  // false: only the attributes the method's kernel needs (the timed path); true: every attribute the
  // exact reference needs too (world positions, normals, inv_w).
  bool for_reference = false;
  // Also the vertex intensities (Gouraud's), for a method that gives some triangles to Gouraud
  // (combined with a per-triangle choice).
  bool vertex_colours = false;
};

// Projection x view of the scene's camera for its resolution (OpenGL clip-space conventions).
glm::mat4 view_projection(const Scene& scene);

// Fills `out` (its buffers are reused across frames). Deterministic: the same scene gives the same
// triangles in the same order whatever the thread count.
void build_screen_geometry(const Scene& scene, const GeometryRequest& request, ScreenGeometry& out);

}  // namespace parashade
