#pragma once
// Procedural shapes. All are closed where the shape is closed, with outward unit normals (analytic
// where the surface is smooth, per face where it has creases), counter-clockwise front faces.
#include "parashade/mesh.hpp"

namespace parashade {

// UV sphere of radius 1 at the origin: 2*slices*(stacks-1) triangles (slices >= 3, stacks >= 2);
// slices = 64, stacks = 65 gives 8192 triangles.
Mesh make_sphere(int slices, int stacks);
// Torus in the xz-plane around the y axis.
Mesh make_torus(float major_radius, float minor_radius, int major_segments, int minor_segments);
// Axis-aligned box centred at the origin with the given full extents; flat faces (24 vertices).
Mesh make_box(glm::vec3 size);
// Cylinder along y centred at the origin, smooth side, flat caps.
Mesh make_cylinder(float radius, float height, int segments, bool caps);
// Newell's Utah teapot from its 32 bicubic Bezier patches; each patch is tessellated into
// level x level quads (2*level^2 triangles). Normals from the patch derivatives.
Mesh make_teapot(int level);

}  // namespace parashade
