/* Every constant the host (C++) and the kernels (OpenCL C) share, each defined once, with why it has its
 * value. Plain macros only, so the file is the same text in both languages; it includes nothing. */
#ifndef PARASHADE_CONSTANTS_H
#define PARASHADE_CONSTANTS_H

/* Screen format (docs/pipeline.md): positions in 1/2^SUBPIXEL_BITS pixel, as llvmpipe's 8. 8 is the most
 * that keeps an edge function's per-pixel step (a vertex difference across the guard band, up to
 * 3 * MAX_RESOLUTION pixels, in sub-pixels, times 2^SUBPIXEL_BITS) below 2^31 (triangle_record.h). */
#define SUBPIXEL_BITS 8

/* Pixel addresses are 12 bits, as in the sources' hardware ([Malovanyi 2019, parallel Gouraud] ch. 3): resolutions up to
 * MAX_RESOLUTION x MAX_RESOLUTION, and so spans of at most MAX_RESOLUTION pixels. */
#define SCREEN_ADDRESS_BITS 12
#define MAX_RESOLUTION (1 << SCREEN_ADDRESS_BITS)

/* Lanes of the kernels' vectors (common.h's floatV is float16): a work-item shades a row segment of VEC
 * pixels at once, and finds the spans of VEC rows at once. 16 floats fill an AVX-512 register. PoCL
 * vectorizes across work-items by wrapping the work-item loop around the whole body, which leaves a
 * per-triangle loop scalar; explicit float16/int16 rows compile to full AVX-512 instead. */
#define VEC 16

/* Screen tile edge in pixels: 16, 32 or 64 (--tile), the powers of two from TILE_MIN to TILE_MAX. A tile
 * row is whole VEC-pixel segments (TILE_MIN = VEC); a work-item keeps the tile's depth and colour
 * (4 * TILE^2 floats) in private memory. The kernels get the size as -D TILE. Default 32: against 16 a
 * triangle is binned to fewer tiles, so fewer tiles repeat its per-triangle work (Gouraud frames 1.03-1.32x
 * faster on every test scene, Phong 0.95-1.14x; bench/README.md run J); 64-px tiles lose with many
 * triangles, since every row of a tile tests every triangle binned to it. */
#define TILE_MIN VEC
#define TILE_MAX 64
#define TILE_DEFAULT 32

/* The lanes shape's work-group (render_lanes.cl, --work-group-size 0): work-items per tile, each owning
 * TILE * TILE / LANES_WORK_GROUP_DEFAULT of its pixels (at most the tile's pixels). */
#define LANES_WORK_GROUP_DEFAULT 256
/* The largest --work-group-size taken (a device may allow fewer: the renderer checks its own). */
#define MAX_WORK_GROUP_SIZE 4096

/* Small triangles (TRIANGLE_SMALL, triangle_record.h): vertex extent at most SMALL_EXTENT pixels both
 * ways. Their edge functions stay below 2^30 over their box and the 16 pixels beyond it, so the kernels
 * may evaluate them per pixel in 32 bits (kernels/span.h). */
#define SMALL_EXTENT 64

/* Limits of the modeled shading units (--units, docs/units.md; --cu, docs/planner.md):
 * interleave:M, 1 <= M <= MAX_INTERLEAVE_LANES. The code relies on it twice: the kernels split a pixel
 *   offset by M for interleave:M:own with a float quotient, exact while (i + 1/2) / M stays >= 1/32 away
 *   from an integer (unit_registers.h), and setup's plane limit leaves room for 16 * dI (setup.hpp);
 * segment:P, P a power of two in 2..MAX_SEGMENT_LANES: the sources' adder table ends at P = 64 ([Malovanyi 2019, parallel Gouraud] ch. 3);
 * sierpinski:D, 1 <= D <= MAX_SIERPINSKI_DEPTH: a bound we set, not a figure of the sources; setup writes
 *   4^D sub-triangle records per triangle (64 at D = 3), and the golden tests cover D = 1..3;
 * --cu U, 1 <= U <= MAX_MODELED_UNITS: a bound the planner sets on its per-unit tables (one work list and
 *   one load entry per unit), not a figure of the sources. */
#define MAX_INTERLEAVE_LANES 16
#define MAX_SEGMENT_LANES 64
#define MAX_SIERPINSKI_DEPTH 3
#define MAX_MODELED_UNITS 4096

/* Span registers (--arith fixed:I.F, kernels/fixed_point.h): I integer bits including the sign, at least
 * REGISTER_MIN_INT_BITS to hold level 255 and a sign; width I + F at most REGISTER_MAX_BITS, the 32-bit
 * ps_int the registers are modeled in. */
#define REGISTER_MIN_INT_BITS 9
#define REGISTER_MAX_BITS 32

/* Dichotomy normalization (--normalize dichotomy:S:K, kernels/normalize_dichotomy.h): segments of 2^K
 * pixels, 1 <= K <= MAX_DICHOTOMY_SEGMENT_LOG2. A bound we set, not the source's: each pixel descends up
 * to K + 3 bisection levels, and the tests and docs/phong-methods.md measure K up to 6. */
#define MAX_DICHOTOMY_SEGMENT_LOG2 6

#endif
