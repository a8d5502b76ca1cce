/* The stamps' layout of a tile (STAMPS, the plain frame): STAMP x STAMP pixels a stamp, lane l at row l / 4 and
 * column l % 4, so a small triangle's few pixels fill more of the lanes it shades than a 1 x VEC row segment's;
 * STAMPS_X stamps across a tile, TILE_VECTORS in all (as row segments). */
#ifndef PARASHADE_STAMP_LAYOUT_H
#define PARASHADE_STAMP_LAYOUT_H

#define STAMP 4
#define STAMPS_X (TILE / STAMP)
#define STAMP_ROW ((intV)(0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3))
#define STAMP_COLUMN ((intV)(0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3))

#endif
