/* The extra-triangulation unit ([Malovanyi 2019, parallel Gouraud] ch. 3, "Sierpinski"): a triangle split by its midlines, recursively
 * to depth D, into 4^D congruent sub-triangles. The code interpolator shades one of them (the one at
 * the top vertex); every other one is that sub-triangle translated by a whole number of pixels (same
 * orientation) or point-reflected (the middle ones), and its intensities come from the shaded one
 * through one adder each: I(P) = I0(P - D) + offset, or I(P) = offset - I0(C - P).
 * Setup (host/units/sierpinski_setup.cpp) writes one record per sub-triangle; this is the unit's part of it,
 * shared by host and kernels. The record's edge functions are the shaded sub-triangle's, mapped, so a
 * copy covers exactly the mapped pixels of the shaded one; its FixedPlanes hold the shaded
 * sub-triangle's planes seen through the same map (value at P = I0(map(P))). */
#ifndef PARASHADE_SIERPINSKI_LEAF_H
#define PARASHADE_SIERPINSKI_LEAF_H

#include "triangle_record.h"

typedef struct {
  ps_long offset[3]; /* per channel, setup's plane format: translated I(P) - I(P - D); reflected I(P) + I(C - P) */
  ps_int sign;       /* +1: the shaded sub-triangle or a translated copy; -1: a point-reflected copy */
  ps_int shaded;     /* 1 for the sub-triangle the code interpolator shades: only its spans cost clocks */
} SierpinskiLeaf;

#endif
