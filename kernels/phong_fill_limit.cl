/* The Phong floor (bench_llvmpipe's phong_plane_fill_limit): every pixel's normal and world position from one
 * triangle's planes, the normal normalized and lit by the scene's lights (method_phong.h's shade_pixels_at: the
 * frame kernel's own code, built with its -D options), its depth from a plane, packed and written as the frame
 * kernel does: the least per-pixel work of a Phong frame whose one triangle covers the screen, with no coverage
 * test, triangle loop, tile or depth buffer. `a` is the record of that triangle (PHONG_ATTR_FLOATS, planes about
 * the frame's top-left pixel); rows as plane_fill_limit's (fill_limit.cl); `width` a multiple of VEC. */

__kernel void phong_plane_fill_limit(__global uint* restrict out, __global const float* restrict a, float4 depth,
                                     int width, int height, __constant float4* lights, __constant float4* materials,
                                     float4 viewer) {
  for (int y = get_global_id(0); y < height; y += get_global_size(0)) {
    const floatV fdy = (floatV)(float)y;
    for (int x = 0; x < width; x += VEC) {
      const floatV rel = convert_floatV(LANE_INDEX + x);
      const floatV z = (floatV)(depth.x + depth.z * (float)y) + depth.y * rel;
      const uintV covered = convert_uintV(isless(z, (floatV)INFINITY)) & 0xFF000000u;
      floatV r, g, b;
      shade_pixels_at(a, fdy, rel, &r, &g, &b, lights, materials, viewer);
      store_frame_row(to_level(r) | (to_level(g) << 8) | (to_level(b) << 16) | covered, out + (size_t)y * width + x);
    }
  }
  FRAME_STORES_DONE();
}
