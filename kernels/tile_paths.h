/* Which paths a build of render_tiles.cl takes: the host's -D options (host/cl/kernel_variant.cpp,
 * build_options()) with their defaults, and every rule that follows from them, derived here once so that
 * no pass derives it again. Included after the method header, which may define COMBINED and SHADE_SPAN. */
#ifndef PARASHADE_TILE_PATHS_H
#define PARASHADE_TILE_PATHS_H

/* PLAN_PASS (docs/planner.md): 0 the plain frame; 1 the modeled units' depth pass, each unit walking its
 * own work lists and keeping per pixel the least key (depth, primitive index) by an atomic minimum;
 * 2 the resolve, which shades at each pixel only the triangle whose key won. The least key is what
 * the plain frame's in-order strict depth test keeps, whatever the order the units ran in. */
#ifndef PLAN_PASS
#define PLAN_PASS 0
#endif
#ifndef COMBINED
#define COMBINED 0
#endif
#ifndef STAMPS
#define STAMPS 0
#endif
#ifndef DEFER_STAMPS
#define DEFER_STAMPS 0
#endif
/* Flat and Gouraud shade a stamp's every lane: cheaper than asking whether any lane passed. */
#ifndef SHADE_EVERY_LANE
#define SHADE_EVERY_LANE 0
#endif
/* Triangles ahead whose record and attributes the tile loop prefetches. */
#ifndef PREFETCH_AHEAD
#define PREFETCH_AHEAD 4
#endif

/* The plain frame: no plan pass, modeled unit, per-span normalization or float image. Only it may shade
 * 4x4 stamps (the host's KernelVariant::stamps_apply() asks the same before it passes STAMPS), and only
 * its empty tiles need nothing but the background written (no keys, counters or float image). */
#define PLAIN_FRAME (PLAN_PASS == 0 && !UNIT_PATH && !SHADE_SPAN && !OUTPUT_FLOAT)
#if STAMPS && !PLAIN_FRAME
#error "STAMPS: the plain frame only"
#endif
/* A tile's first triangles are checked against the whole tile before its walk (tile_fill.h): the stamps' layout,
 * not the combined method's segment walk. */
#ifndef TILE_FILL /* -D TILE_FILL=0: the clear and the walk for every tile (bench_kernel_ab's B) */
#define TILE_FILL (STAMPS && !COMBINED)
#endif
#if TILE_FILL && (!STAMPS || COMBINED)
#error "TILE_FILL: the stamps of the plain frame, not the combined method"
#endif
/* A deferred tile is shaded a stamp at a time after its walk. */
#if DEFER_STAMPS && !STAMPS
#error "DEFER_STAMPS: the stamps only"
#endif

/* The units' depth pass offers depth keys; every other pass writes the frame. */
#define WRITES_FRAME (PLAN_PASS != 1)

/* Three counters a tile for the report (tile_counters): a unit's spans, or the per-span normalization's
 * setups. The combinations table refuses per-span normals through a unit, so a tile counts one or neither. */
#if UNIT_PATH && SHADE_SPAN
#error "UNIT_PATH and SHADE_SPAN: the units normalize per pixel"
#endif
#define COUNTS_TILE ((UNIT_PATH || SHADE_SPAN) && WRITES_FRAME)

/* Gouraud's fixed-point unit keeps its registers as the colour until the output rounds them, in int
 * vectors: their bits as floats would be denormals and NaNs, which a device may flush or quieten
 * (Oclgrind's select() sets the quiet bit of a signalling NaN; docs/pipeline.md). */
#define REGISTER_COLOUR (UNIT_PATH && FIXED && UNIT_REGISTER_COLOUR)

#endif
