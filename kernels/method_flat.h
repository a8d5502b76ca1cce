/* Flat: the triangle's one value (computed in the vertex stage) on every pixel. */
#define ATTR_FLOATS FLAT_ATTR_FLOATS
/* One value per triangle: cheaper to keep on every lane than to ask whether any lane passed (method_gouraud.h). */
#define SHADE_EVERY_LANE 1

INLINE void shade_pixels_at(__global const float* a, floatV fdy, floatV rel, floatV* r, floatV* g, floatV* b,
                            __constant float4* lights, __constant float4* materials, float4 viewer) {
  *r = (floatV)a[0];
  *g = (floatV)a[1];
  *b = (floatV)a[2];
}

INLINE void shade_pixels(__global const float* a, int dy, floatV rel, floatV* r, floatV* g, floatV* b,
                         __constant float4* lights, __constant float4* materials, float4 viewer) {
  shade_pixels_at(a, (floatV)(float)dy, rel, r, g, b, lights, materials, viewer);
}
