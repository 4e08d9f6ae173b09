/* Internal to libpfmath's noise files (not installed): the default table
 * and the vectorisation attributes every array form uses.  Each file keeps
 * its own `#pragma GCC optimize` (the float ones also turn off FMA
 * contraction), placed before this header. */
#ifndef PF_NOISE_IMPL_H
#define PF_NOISE_IMPL_H

#include "pfnoise.h"

#if defined(__GNUC__) && !defined(__clang__)
#define PF_IVDEP _Pragma("GCC ivdep")
#else
#define PF_IVDEP
#endif
/* runtime dispatch: the widest vectors the CPU has, any x86-64 */
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define PF_CLONES __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#else
#define PF_CLONES
#endif
#define PF_INLINE static inline __attribute__((always_inline))

/* ---- the scalar forms: one point at a time in 4-float vectors ----------
 * The array forms vectorise across points; a scalar call has one point, so
 * it puts the lattice corners in the lanes instead (GCC vector extensions:
 * SSE2 on any x86-64, whatever the target elsewhere).  Each lane performs
 * exactly the operations, in the same order, that the array body performs
 * for that corner, and no contraction is allowed (the files' pragma), so
 * results are bit-identical to the array forms (tests/test_noise_scalar.c).
 */
#if defined(__SSE__)
#include <xmmintrin.h>
#endif
typedef float pf_v4f __attribute__((vector_size(16)));
typedef int32_t pf_v4i __attribute__((vector_size(16)));
typedef uint32_t pf_v4u __attribute__((vector_size(16)));

/* GCC 12 loads a constant whose 4 lanes are equal as one float and a
 * shuffle; the scalar path's constants therefore carry a different value
 * in lane 3, which no caller reads (it holds 0 in every point vector). */

/* The scalar forms' fast path covers points whose coordinates are all
 * below 2^22 in magnitude (the range where the lattice index is exact);
 * anything else (huge, ±inf, NaN) takes the array body itself, which is
 * then bit-identical by construction.  The test is one compare and one
 * predictable branch.  Lanes 2 (2D) and 3 hold 0 and always pass. */
PF_INLINE int pf_small4(pf_v4f p)
{
    static const pf_v4u abs = {0x7fffffffu, 0x7fffffffu, 0x7fffffffu, 0x7fffffffu};
    static const pf_v4f lim = {0x1p22f, 0x1p22f, 0x1p22f, 1.0f};
    pf_v4i in = (pf_v4f)((pf_v4u)p & abs) < lim;
#if defined(__SSE__)
    return _mm_movemask_ps((__m128)in) == 15;
#else
    return (in[0] & in[1] & in[2] & in[3]) == -1;
#endif
}

/* Lattice cell and offset of every lane, for |p| < 2^22: m = p + 1.5·2^23
 * holds r = round(p) in its low mantissa bits and r = m − 1.5·2^23 exactly;
 * r − 1 where r > p gives floor(p).  The offset p − floor(p) is formed as
 * (p − r) + (0 or 1): p − r is exact (Sterbenz), so the one rounding is of
 * the same real number the array body rounds, p − floorf(p), and +0 comes
 * out for integral p as there (also for p = −0).  *cell = floor(p) mod 256,
 * the array body's lattice(floorf(p)). */
PF_INLINE pf_v4f pf_cell4(pf_v4f p, pf_v4u *cell)
{
    static const pf_v4f c = {12582912.0f, 12582912.0f, 12582912.0f, 0.0f};
    static const pf_v4u one = {0x3f800000u, 0x3f800000u, 0x3f800000u, 0x3f800000u},
                        low8 = {255u, 255u, 255u, 255u};
    pf_v4f m = p + c, r = m - c;
    pf_v4i up = r > p;
    *cell = ((pf_v4u)m + (pf_v4u)up) & low8;
    return (p - r) + (pf_v4f)((pf_v4u)up & one);
}

/* The fade 6t^5 - 15t^4 + 10t^3 per lane, in the evaluators' order
 * t·t·t·(t·(t·6 − 15) + 10). */
PF_INLINE pf_v4f pf_fade4(pf_v4f t)
{
    static const pf_v4f k6 = {6.0f, 6.0f, 6.0f, 0.0f}, k15 = {15.0f, 15.0f, 15.0f, 0.0f},
                        k10 = {10.0f, 10.0f, 10.0f, 0.0f};
    return t * t * t * (t * (t * k6 - k15) + k10);
}

/* Offsets d0 − 1 (lane 3 unused). */
PF_INLINE pf_v4f pf_minus1(pf_v4f d)
{
    static const pf_v4f one = {1.0f, 1.0f, 1.0f, 0.0f};
    return d - one;
}

/* k = field of c under the lane's mask, as a float (exact: < 2^23). */
PF_INLINE pf_v4f pf_kf4(pf_v4u c, pf_v4u mask)
{
    return __builtin_convertvector((pf_v4i)(c & mask), pf_v4f);
}

/* The scalar 3D noise has two bodies, both bit-identical to the array form:
 * SSE2 (pfnoise3.c, any target) and, on x86-64 with GCC, AVX2
 * (pfnoise3_avx2.c, compiled for v3 and for v4); pf_noise3f and
 * pf_noise3f_t run the widest one the CPU has (ifunc).  Internal; tests/test_noise_scalar.c checks each body. */
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define PF_NOISE3_DISPATCH 1
#else
#define PF_NOISE3_DISPATCH 0
#endif
#define PF_HIDDEN __attribute__((visibility("hidden")))
PF_HIDDEN float pf_noise3f_sse2_(float x, float y, float z);
PF_HIDDEN float pf_noise3f_t_sse2_(const pf_noise_table *t, float x, float y, float z);
#if PF_NOISE3_DISPATCH
__attribute__((target("arch=x86-64-v3"))) PF_HIDDEN float
pf_noise3f_t_avx2_(const pf_noise_table *t, float x, float y, float z);
__attribute__((target("arch=x86-64-v4"))) PF_HIDDEN float
pf_noise3f_t_avx512_(const pf_noise_table *t, float x, float y, float z);
#endif

/* Perlin's permutation's tables, const data generated at build time
 * (pfnoise_table.c): valid before any constructor runs. */
extern const pf_noise_table pf_noise_default_ __attribute__((visibility("hidden")));

#endif
