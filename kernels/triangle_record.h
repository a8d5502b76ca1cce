/* Per-triangle setup records, shared by the host (C++) and the kernels (OpenCL C): one layout, one
 * definition. Written by host/pipeline/setup.cpp, read by the unit kernels.
 *
 * Coverage: for edge e, E_e(x, y) = edge_c[e] + edge_a[e]*(x - x0) + edge_b[e]*(y - y0) is the edge
 * function of screen_geometry.hpp at the centre of pixel (x, y), minus the edge's top-left bias; the
 * pixel is covered when all three are >= 0. edge_a, edge_b are exact (|.| < 2^31 in the guard band),
 * edge_c needs 64 bits.
 * Small triangles (vertex extent <= SMALL_EXTENT pixels both ways) have |E| < 2^30 over their box and
 * the 16 pixels beyond it, so the kernels may evaluate their edge functions per pixel in 32 bits.
 * Planes: value(x, y) = ref + ddx*(x - x0) + ddy*(y - y0), with (x0, y0) the bounding box corner. */
#ifndef PARASHADE_TRIANGLE_RECORD_H
#define PARASHADE_TRIANGLE_RECORD_H

#include "constants.h" /* SMALL_EXTENT */

#ifdef __OPENCL_VERSION__
typedef long ps_long;
typedef int ps_int;
typedef short ps_short;
typedef float ps_float;
#else
#include <cstdint>
typedef std::int64_t ps_long;
typedef std::int32_t ps_int;
typedef std::int16_t ps_short;
typedef float ps_float;
#endif

typedef struct {
  ps_long edge_c[3];
  ps_int edge_a[3];
  ps_int edge_b[3];
  ps_short x0, y0, x1, y1;  /* pixels whose centres may be covered, clamped to the screen; empty if x0 > x1 */
  ps_float z_ref, z_ddx, z_ddy;  /* window depth plane */
  ps_int flags;                  /* TRIANGLE_SMALL */
} TriangleGeometry;

#define TRIANGLE_SMALL 1 /* vertex extent <= SMALL_EXTENT (constants.h) */

/* Per-method attribute records: ATTR_* floats per triangle, indexed like TriangleGeometry. */
#define FLAT_ATTR_FLOATS 4      /* r, g, b (levels), unused */
#define GOURAUD_ATTR_FLOATS 9  /* ref r,g,b; ddx r,g,b (the constant span increment dI_G); ddy r,g,b */
/* Phong: normal ref xyz, ddx xyz, ddy xyz; position ref xyz, ddx xyz, ddy xyz; material; 3 spare slots
 * that the combined method's per-triangle choice uses (triangle_choice.hpp). A triangle it gives to
 * Gouraud holds its colour planes (Gouraud's layout) in slots 0..8 instead of the normal planes, and zeros in
 * the position slots 9..17 (it is shaded from its colours alone, never by a deferred tile's winners). */
#define PHONG_ATTR_FLOATS 22
#define PHONG_MATERIAL_SLOT 18
#define PHONG_HIGHLIGHT_SLOT 19 /* combined --highlight-test: lights whose specular term is evaluated (mask) */
#define PHONG_METHOD_SLOT 20    /* combined with a triangle choice: 0 Phong per pixel, 1 Gouraud, 2 segments */
#define PHONG_PSI_SLOT 21       /* combined:auto with a triangle choice: the triangle's limit on the normal change */

#endif
