/* The lanes shape's triangle records in local memory: a work-group reads a batch of its tile's records together
 * (each work-item some of their words), so every work-item then walks them from local memory instead of each
 * reading the same record from global memory. */
#ifndef PARASHADE_LANES_BATCH_H
#define PARASHADE_LANES_BATCH_H

/* Records tile_tris[first .. first + n) into batch (and their indices into ids), a record a work-item. The caller's
 * barrier makes them visible. (Copying the batch word by word over all the work-items, each word's record found by a
 * division, compiled on Intel's runtime to a lane-by-lane division in every iteration.) */
INLINE void load_batch(const FrameArgs* f, uint first, int n, int lid, __local TriangleGeometry* batch,
                       __local int* ids) {
  for (int j = lid; j < n; j += WORK_GROUP_SIZE) {
    const uint ti = f->tile_tris[first + j];
    ids[j] = (int)ti;
    batch[j] = f->tris[ti];
  }
}

#endif
