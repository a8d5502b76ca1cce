#pragma once
// Procedural shapes. All are closed where the shape is closed, with outward unit normals (analytic
// where the surface is smooth, per face where it has creases), counter-clockwise front faces.
#include "parashade/mesh.hpp"

namespace parashade {

// UV sphere of radius 1 at the origin, poles on the y axis: 2*slices*(stacks-1) triangles (slices >= 3,
// stacks >= 2; one triangle per slice at each pole, so none has zero area); slices = 64, stacks = 65
// gives 8192 triangles. Vertices are shared around the seam.
Mesh make_sphere(int slices, int stacks);
// Torus in the xz-plane around the y axis (0 < minor_radius < major_radius, segments >= 3):
// 2*major_segments*minor_segments triangles on shared vertices.
Mesh make_torus(float major_radius, float minor_radius, int major_segments, int minor_segments);
// Axis-aligned box centred at the origin with the given full extents; flat faces (24 vertices, 12 triangles).
Mesh make_box(glm::vec3 size);
// Cylinder along y centred at the origin (segments >= 3), smooth side (2*segments triangles), flat caps
// on their own vertices (segments triangles each). Without caps it is an open tube.
Mesh make_cylinder(float radius, float height, int segments, bool caps);
// Newell's Utah teapot from its 32 bicubic Bezier patches, y up, base on y = 0, spout toward +x
// (x in [-3, 3.43], y in [0, 3.15], z in [-2, 2]). Each patch is tessellated into level x level quads
// (level >= 2: at 1 the handle's and spout's halves fall onto their mid-plane); normals from the patch
// derivatives. Patch seams are welded (normals averaged along them) and the zero-area triangles at the
// lid tip and the bottom centre dropped: 64*level^2 - 8*level triangles. As in Newell's data the surface
// is not closed: the lid does not touch the rim, the spout is open, the handle and spout pierce the body.
Mesh make_teapot(int level);

// Every function throws InputError for parameters outside the ranges above.

}  // namespace parashade
