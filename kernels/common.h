/* Settings and vector types every kernel shares. */
#ifndef PARASHADE_COMMON_H
#define PARASHADE_COMMON_H

/* No silent fused multiply-adds: results must not depend on what the compiler contracts. */
#pragma OPENCL FP_CONTRACT OFF

/* A work-item owns one row segment of VEC pixels; its pixels are the lanes of these vectors. */
#define VEC 16
typedef float16 floatV;
typedef int16 intV;
typedef uint16 uintV;
#define convert_floatV convert_float16
#define convert_intV convert_int16
#define convert_uintV convert_uint16
#define convert_ucharV_sat_rte convert_uchar16_sat_rte
#define vstoreV vstore16
#define LANE_INDEX ((intV)(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15))

/* 1/sqrt(x), and 0 where x is 0: a zero vector stays zero instead of becoming NaN. */
inline floatV safe_rsqrt(floatV x) { return select((floatV)0.0f, rsqrt(x), isgreater(x, (floatV)0.0f)); }

/* An 8-bit level: round to nearest (ties to even) and saturate. rint + clamp + truncation compiles
 * to three vector instructions where convert_uchar16_sat_rte is emulated with a dozen. */
inline uintV to_level(floatV x) { return convert_uintV(clamp(rint(x), 0.0f, 255.0f)); }

#ifndef TILE
#define TILE 16
#endif
#define SEGMENTS (TILE / VEC)

#endif
