/* The lanes shape's triangle records in local memory: a work-group reads a batch of its tile's records together
 * (each work-item some of their words), so every work-item then walks them from local memory instead of each
 * reading the same record from global memory. */
#ifndef PARASHADE_LANES_BATCH_H
#define PARASHADE_LANES_BATCH_H

#define RECORD_WORDS (sizeof(TriangleGeometry) / sizeof(uint))

/* Records tile_tris[first .. first + n) into batch (and their indices into ids), by the work-items together. The
 * caller's barrier makes them visible. */
INLINE void load_batch(const FrameArgs* f, uint first, int n, int lid, __local TriangleGeometry* batch,
                       __local int* ids) {
  __local uint* to = (__local uint*)batch;
  for (int k = lid; k < n * (int)RECORD_WORDS; k += WORK_GROUP_SIZE) {
    const int j = k / (int)RECORD_WORDS;
    to[k] = ((__global const uint*)&f->tris[f->tile_tris[first + j]])[k - j * (int)RECORD_WORDS];
  }
  for (int j = lid; j < n; j += WORK_GROUP_SIZE) ids[j] = (int)f->tile_tris[first + j];
}

#endif
