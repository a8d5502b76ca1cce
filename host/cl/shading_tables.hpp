#pragma once
// The scene's lights and materials as the kernels read them (kernels/blinn_phong.h): two float4 per light,
// three per material, in constant memory.
#include <vector>

#include <CL/opencl.hpp>

#include "parashade/combined.hpp"
#include "parashade/scene.hpp"
#include "parashade/specular_models.hpp"

namespace parashade {

// Per light: (position, 1) for a point light or (direction towards the light, 0); then 255 * colour.
std::vector<cl_float4> light_table(const Scene& s);
// Per material: 255 * ambient * ambient light with the shininess in .w; the diffuse colour with the scale
// a of a cos^k(a alpha) specular model in .w; the specular colour, its .w spare (set_combined_limits).
std::vector<cl_float4> material_table(const Scene& s, const SpecularModel& spec);
// The viewer as the kernels read it: the camera's position for a local viewer, else the unit direction
// towards the camera.
cl_float4 viewer_value(const Scene& s, bool local_viewer);
// combined:auto without a triangle choice: the limit on the relative normal change per segment of each
// material, from the error budget, into the spare .w of its specular entry. With a choice the limit is
// per triangle (PHONG_PSI_SLOT).
void set_combined_limits(const Scene& s, const CombinedConfig& c, std::vector<cl_float4>& materials);

}  // namespace parashade
