/* The order-free depth key of the planned frame (docs/planner.md): the depth's bits mapped so that
 * unsigned order is float order (-0 taken as +0: the strict test sees them equal), above the primitive
 * index. The least key at a pixel is the nearest triangle and, among equally near ones, the first in
 * primitive order: what the plain frame's in-order `isless` test keeps. */
#ifndef PARASHADE_PLAN_KEY_H
#define PARASHADE_PLAN_KEY_H

#define PLAN_NO_KEY 0xFFFFFFFFFFFFFFFFul

INLINE ulong plan_key(float z, uint ti) {
  const uint bits = as_uint(z == 0.0f ? 0.0f : z);
  const uint ordered = (bits & 0x80000000u) ? ~bits : (bits | 0x80000000u);
  return ((ulong)ordered << 32) | ti;
}

/* Offers the key of every lane in `mask` to the pixels at row[0 .. VEC). */
INLINE void plan_offer_keys(floatV z, intV mask, uint ti, __global ulong* row) {
  if (!any_lanes(mask)) return;
  float zs[VEC];
  int ms[VEC];
  vstoreV(z, 0, zs);
  vstoreV(mask, 0, ms);
  for (int l = 0; l < VEC; ++l)
    if (ms[l]) atom_min(row + l, plan_key(zs[l], ti));
}

/* The lanes (of those in `mask`) whose pixel's least key is triangle ti's. */
INLINE intV plan_won(uint ti, __global const ulong* row, intV mask) {
  if (!any_lanes(mask)) return (intV)0;
  int ms[VEC], won[VEC];
  vstoreV(mask, 0, ms);
  for (int l = 0; l < VEC; ++l) won[l] = ms[l] && row[l] != PLAN_NO_KEY && (uint)row[l] == ti ? -1 : 0;
  return vload16(0, won);
}

#endif
