/* Settings and vector types every kernel shares. */
#ifndef PARASHADE_COMMON_H
#define PARASHADE_COMMON_H

#include "constants.h"

/* Fault injection for tests: the host defines this for a device named by PARASHADE_FAIL_DEVICE
 * (device.hpp), so that device's builds fail through the real build-failure path. */
#ifdef PARASHADE_FAIL_BUILD
#error "build failure injected by PARASHADE_FAIL_DEVICE"
#endif

/* No silent fused multiply-adds: results must not depend on what the compiler contracts. */
#pragma OPENCL FP_CONTRACT OFF

/* Helpers are always inlined: PoCL 3.1 otherwise keeps some as calls inside the hot loops (row_spans
 * was 12% of a frame profile as a call), which also stops vectorization across them. */
#define INLINE inline __attribute__((always_inline))

/* The kernel's shape (docs/pipeline.md, RenderOptions::kernel_shape): KERNEL_SHAPE_VECTOR, a work-item walks
 * whole tiles and owns one row segment or stamp of VEC pixels (constants.h) at a time as the lanes of these
 * vectors; KERNEL_SHAPE_LANES (render_lanes.cl), a work-item per pixel lane and a work-group per tile, the
 * lanes made by the device (an implicit vectorizer, a GPU's wavefront): the same shading code on one pixel,
 * the types below one lane wide. */
#define KERNEL_SHAPE_VECTOR 0
#define KERNEL_SHAPE_LANES 1
#ifndef KERNEL_SHAPE
#define KERNEL_SHAPE KERNEL_SHAPE_VECTOR
#endif

#if KERNEL_SHAPE == KERNEL_SHAPE_LANES
typedef float floatV;
typedef int intV;
typedef uint uintV;
#define convert_floatV convert_float
#define convert_intV convert_int
#define convert_uintV convert_uint
#define as_intV as_int
#define as_uintV as_uint
#define as_floatV as_float
/* A comparison as a lane mask, -1 where true: a vector comparison gives -1 already, a scalar one 1. */
#define LANE_MASK(c) (-(c))
#else
#if VEC != 16
#error "the vector types below are 16 lanes wide: VEC must be 16"
#endif
typedef float16 floatV;
typedef int16 intV;
typedef uint16 uintV;
#define convert_floatV convert_float16
#define convert_intV convert_int16
#define convert_uintV convert_uint16
#define convert_ucharV_sat_rte convert_uchar16_sat_rte
#define vstoreV vstore16
#define vloadV vload16
#define as_intV as_int16
#define as_uintV as_uint16
#define as_floatV as_float16
#define LANE_INDEX ((intV)(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15))
#define LANE_MASK(c) (c)
#endif

/* 1/sqrt(x), and 0 where x is 0: a zero vector stays zero instead of becoming NaN. */
INLINE floatV safe_rsqrt(floatV x) { return select((floatV)0.0f, rsqrt(x), isgreater(x, (floatV)0.0f)); }

/* (x, y, z) scaled to unit length per lane (a zero vector stays zero): every per-pixel normalization. */
INLINE void normalize_lanes(floatV* x, floatV* y, floatV* z) {
  const floatV inv = safe_rsqrt(*x * *x + *y * *y + *z * *z);
  *x *= inv;
  *y *= inv;
  *z *= inv;
}

/* An 8-bit level: round to nearest (ties to even) and saturate. Adding 2^23 to a value in [0, 255]
 * rounds it to an integer in the float's low mantissa bits (the default rounding mode is to nearest
 * even), which are then read as an integer. rint() and convert_*_sat_rte are emulated lane by lane on
 * PoCL 3.1 and cost more than the rest of an empty frame. */
INLINE uintV to_level(floatV x) { return as_uintV(clamp(x, 0.0f, 255.0f) + 8388608.0f) - 0x4B000000u; }

#ifndef TILE
#define TILE TILE_DEFAULT
#endif
#define SEGMENTS (TILE / VEC)

#if KERNEL_SHAPE == KERNEL_SHAPE_VECTOR
#if VEC == 16 && defined(__AVX512DQ__) && defined(__has_builtin) && !defined(NO_SIGN_BITS)
#if __has_builtin(__builtin_ia32_cvtd2mask512)
#define SIGN_BITS_INSTRUCTION 1
#endif
#endif
#ifdef SIGN_BITS_INSTRUCTION
/* AVX-512: the lanes' sign bits in one instruction (vpmovd2m). PoCL 3.1 does not find it in the halving below,
 * whose chain of extracts every listed winner waited on; the same bits, so the same frames. -D NO_SIGN_BITS
 * builds the halving instead (bench_kernel_ab's A/B, docs/pipeline.md). */
INLINE int any_lanes(intV m) { return __builtin_ia32_cvtd2mask512(m) != 0; }
INLINE uint lane_bits(intV m) { return __builtin_ia32_cvtd2mask512(m); }
#else
/* any() of a VEC-lane mask (lanes -1 or 0; the sign bits tested, as any()). PoCL 3.1 turns any() on 16
 * lanes into a chain of per-lane extracts and branches; OR-ing the halves down to one lane is a few vector
 * ORs and one test. */
INLINE int any_lanes(intV m) {
  const int8 h8 = m.lo | m.hi;
  const int4 h4 = h8.lo | h8.hi;
  const int2 h2 = h4.lo | h4.hi;
  return (h2.x | h2.y) < 0;
}

/* A VEC-lane mask's sign bits as bits (lane l: bit l), by halving as any_lanes. */
INLINE uint lane_bits(intV m) {
  const uintV b = (as_uintV(m) >> 31) << as_uintV(LANE_INDEX);
  const uint8 h8 = b.lo | b.hi;
  const uint4 h4 = h8.lo | h8.hi;
  const uint2 h2 = h4.lo | h4.hi;
  return h2.x | h2.y;
}
#endif

/* The largest of a VEC-lane vector's lanes, by halving as any_lanes. */
INLINE int max_lane(intV v) {
  const int8 h8 = max(v.lo, v.hi);
  const int4 h4 = max(h8.lo, h8.hi);
  const int2 h2 = max(h4.lo, h4.hi);
  return max(h2.x, h2.y);
}
#endif

/* Read prefetch of the cache line at p (any address space): a hint, no effect on results. Only where the
 * kernel is compiled for the CPU itself (the host's CPU_DEVICE: PoCL's CPU devices, Intel's CPU runtime, whose
 * OpenCL prefetch() is an out-of-line call but whose compiler emits prefetcht0 for the intrinsic): a device that
 * interprets or compiles for another target need not know the intrinsic (Oclgrind refuses the kernel:
 * "Undefined external function llvm.prefetch"). */
#ifndef CPU_DEVICE
#define CPU_DEVICE 0
#endif
#if CPU_DEVICE && defined(__clang__)
#define PREFETCH_LINE(p) __builtin_prefetch((p), 0, 3)
#else
#define PREFETCH_LINE(p)
#endif

#if KERNEL_SHAPE == KERNEL_SHAPE_VECTOR
/* A row of VEC frame pixels at p: stored non-temporally (the frame is written once and the kernel never
 * reads it back, so its lines need not be read in or kept) when p is aligned to the vector, else
 * ordinarily. FRAME_STORES_DONE orders the non-temporal stores before the work-item ends. */
INLINE void store_frame_row(uintV v, __global uint* p) {
#if defined(__clang__) && (defined(__x86_64__) || defined(__i386__))
  if (((size_t)p & (sizeof(uintV) - 1)) == 0) {
    __builtin_nontemporal_store(v, (__global uintV*)p);
    return;
  }
#endif
  vstoreV(v, 0, p);
}
#endif
#if defined(__clang__) && (defined(__x86_64__) || defined(__i386__))
#define FRAME_STORES_DONE() __builtin_ia32_sfence()
#else
#define FRAME_STORES_DONE() mem_fence(CLK_GLOBAL_MEM_FENCE)
#endif

#endif
