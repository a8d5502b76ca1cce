/* Gouraud: the vertex values interpolated linearly. Along a span each channel steps by the constant
 * span increment dI_G of its triangle (attribute ddx, computed once in setup, [Gouraud simplification]); the start of
 * the row comes from the y increment. Float arithmetic here; the fixed-point units come later. */
#define ATTR_FLOATS GOURAUD_ATTR_FLOATS
/* Shading a stamp costs less than asking whether any of its lanes passed the depth test (a reduction and a
 * branch that mispredicts): stamps shade every lane and keep those that pass. */
#define SHADE_EVERY_LANE 1

/* At the lanes' row offsets fdy (one value on a row segment, four rows on a stamp). */
INLINE void shade_pixels_at(__global const float* a, floatV fdy, floatV rel, floatV* r, floatV* g, floatV* b,
                            __constant float4* lights, __constant float4* materials, float4 viewer) {
  *r = (a[0] + a[6] * fdy) + a[3] * rel;
  *g = (a[1] + a[7] * fdy) + a[4] * rel;
  *b = (a[2] + a[8] * fdy) + a[5] * rel;
}

INLINE void shade_pixels(__global const float* a, int dy, floatV rel, floatV* r, floatV* g, floatV* b,
                         __constant float4* lights, __constant float4* materials, float4 viewer) {
  shade_pixels_at(a, (floatV)(float)dy, rel, r, g, b, lights, materials, viewer);
}
