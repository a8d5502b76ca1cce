/* Phong through a modeled shading unit in fixed point: the unit's registers interpolate the normal's
 * components (scaled by NORMAL_REGISTER_LEVELS, fixed_point.h) along the span exactly as Gouraud's
 * units interpolate intensities (unit_registers.h); each pixel's normal is then normalized and shaded
 * in float as in method_phong.h. Needs method_phong.h and unit_registers.h included before. */
#ifndef PARASHADE_METHOD_PHONG_UNITS_H
#define PARASHADE_METHOD_PHONG_UNITS_H

INLINE void shade_unit_normals(const SpanRegisters* regs, intV i, int length, __global const float* a, int dy,
                               floatV rel, floatV* r, floatV* g, floatV* b, __constant float4* lights,
                               __constant float4* materials, float4 viewer) {
  const float scale = 1.0f / ((float)NORMAL_REGISTER_LEVELS * (float)(1 << FRAC_BITS));
  floatV nx = convert_floatV(unit_register(regs, 0, i, length)) * scale;
  floatV ny = convert_floatV(unit_register(regs, 1, i, length)) * scale;
  floatV nz = convert_floatV(unit_register(regs, 2, i, length)) * scale;
  normalize_lanes(&nx, &ny, &nz);
  shade_unit_normal(a, (floatV)(float)dy, rel, -1, nx, ny, nz, r, g, b, lights, materials, viewer);
}

#endif
