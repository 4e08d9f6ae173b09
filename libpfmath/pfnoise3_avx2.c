/* 3D noise, one point at a time, for x86-64-v3 (AVX2): the body that
 * pf_noise3f and pf_noise3f_t run on such CPUs (compiled twice, for v3 and
 * v4), picked once at load time (ifunc) between it and the SSE2 body of
 * pfnoise3.c.
 *
 * Why a second body.  A call is ~80 cycles of dependent latency (lattice
 * index, 3 dependent table loads, the gradient dot products, 3 levels of
 * lerp), so a loop of calls runs as fast as consecutive calls overlap; in
 * the noise bench (2^16 calls, AMD Zen 4) the time per call followed the
 * number of vector operations per call far more than its latency: 40 NOPs
 * more changed nothing, 7 fewer multiplies saved 8 %.  So this body does
 * the same work in fewer vector operations: the 8 corners fill the 8 lanes
 * of one ymm vector (the SSE2 body needs two xmm vectors), the cell comes
 * from SSE4.1 floor (1 instruction instead of 5, and no range test or
 * second path), the codes are broadcast straight from the table and
 * blended, and the lerps pair lanes inside 128-bit halves until the last.
 *
 * Lanes: corner (i, j, k) (x, y, z offsets) in lane i + 2j + 4k, so the
 * x-lerp pairs lanes (0,1) (2,3) (4,5) (6,7), the y-lerp (0,2) (4,6) and
 * the z-lerp (0,4).  Lanes 4..7 read the high (z + 1) halves of the pair
 * codes with pfnoise3.c's masks and pre-scaled offsets.
 *
 * Bit-identical to the array body (core3): lane by lane the same operands
 * in the same order, with one change of form: k·d + acc as fma(k, d, acc).
 * k·d is exact (k ∈ {0,1,2}·2^f and d pre-scaled by 2^-f, both exact or,
 * for a subnormal d·2^-f, scaled back up exactly), so the fused form rounds
 * the same exact sum once, as the array body's add does; signed zeros too
 * (the product's sign is the same).  The lerps and the fade keep separate
 * multiply and add (no contraction: the pragma below).  Checked against the
 * array form by tests/test_noise_scalar.c. */
#include "pfnoise.h"

#include <stddef.h>
#include <stdint.h>

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC optimize("no-trapping-math", "fp-contract=off")
#endif
#include "pfnoise_impl.h"

#if PF_NOISE3_DISPATCH
#include <immintrin.h>

#define V3 __attribute__((target("arch=x86-64-v3")))

/* Constants as tables, so that they are memory operands (GCC otherwise
 * builds some splats from a general register: 3 instructions each). */
#define A16 __attribute__((aligned(16)))
#define A32 __attribute__((aligned(32)))
static const float k_big[4] A16 = {12582912.0f, 12582912.0f, 12582912.0f, 12582912.0f};
static const float k_6[4] A16 = {6.0f, 6.0f, 6.0f, 6.0f}, k_15[4] A16 = {15.0f, 15.0f, 15.0f, 15.0f},
                   k_10[4] A16 = {10.0f, 10.0f, 10.0f, 10.0f};
/* per lane: pre-scale of the offset, field mask, corner's count of 1 offsets */
static const float k_sx[8] A32 = {1.0f, 1.0f, 1.0f, 1.0f, 0x1p-16f, 0x1p-16f, 0x1p-16f, 0x1p-16f};
static const float k_sy[8] A32 = {0x1p-2f, 0x1p-2f, 0x1p-2f, 0x1p-2f,
                                  0x1p-18f, 0x1p-18f, 0x1p-18f, 0x1p-18f};
static const float k_sz[8] A32 = {0x1p-4f, 0x1p-4f, 0x1p-4f, 0x1p-4f,
                                  0x1p-20f, 0x1p-20f, 0x1p-20f, 0x1p-20f};
static const uint32_t k_mx[8] A32 = {3u, 3u, 3u, 3u, 3u << 16, 3u << 16, 3u << 16, 3u << 16};
static const uint32_t k_my[8] A32 = {12u, 12u, 12u, 12u, 3u << 18, 3u << 18, 3u << 18, 3u << 18};
static const uint32_t k_mz[8] A32 = {48u, 48u, 48u, 48u, 3u << 20, 3u << 20, 3u << 20, 3u << 20};
static const float k_01[8] A32 = {0.0f, 0.0f, 0.0f, 0.0f, 1.0f, 1.0f, 1.0f, 1.0f};
static const int32_t k_px[8] A32 = {0, 4, 0, 4, 0, 4, 0, 4}, k_py[8] A32 = {1, 1, 5, 5, 1, 1, 5, 5},
                     k_pz[8] A32 = {2, 2, 2, 2, 6, 6, 6, 6};
/* v = f[1] for the y-lerp, read in lanes 0 and 4 only (the last index
 * differs so that GCC keeps the table instead of building a splat) */
static const int32_t k_1[8] A32 = {1, 1, 1, 1, 1, 1, 1, 0};
static const float k_o[8] A32 = {0.0f, 1.0f, 1.0f, 2.0f, 1.0f, 2.0f, 2.0f, 3.0f};

#define LD4(a) _mm_load_ps((const float *)(a))
#define LD8(a) _mm256_load_ps((const float *)(a))
#define LD8I(a) _mm256_load_si256((const __m256i *)(a))

V3 static inline __attribute__((always_inline)) float
point3_avx2(const pf_noise_table *t, float x, float y, float z)
{
    const uint32_t *restrict hash = t->hash, *restrict g = t->g3;
    /* {x, y, z, z}: lane 3 repeats z (computed, never read) */
    __m128 p = _mm_setr_ps(x, y, z, z);
    /* The array body's own cell and offset, one instruction each (SSE4.1
     * floor): d0 = p − floor(p), index floor(p) mod 256 from the low bits
     * of floor(p) + 1.5·2^23.  These are core3's operations for every
     * input, huge, infinite and NaN included, so unlike the SSE2 body this
     * one needs no range test and no other path. */
    __m128 fl = _mm_floor_ps(p);
    __m128 d0 = _mm_sub_ps(p, fl);
    __m128i L = _mm_castps_si128(_mm_add_ps(fl, LD4(k_big)));
    /* pf_fade4: t·t·t·(t·(t·6 − 15) + 10) */
    __m128 f = _mm_mul_ps(_mm_mul_ps(_mm_mul_ps(d0, d0), d0),
                          _mm_add_ps(_mm_mul_ps(d0, _mm_sub_ps(_mm_mul_ps(d0, LD4(k_6)), LD4(k_15))),
                                     LD4(k_10)));

    uint64_t xy = (uint64_t)_mm_cvtsi128_si64(L); /* one move for two indices */
    size_t X = xy & 255u, Y = (xy >> 32) & 255u, Z = (uint32_t)_mm_extract_epi32(L, 2) & 255u;
    uint32_t P = hash[X];
    const uint32_t *hY = hash + Y, *gZ = g + Z;
    uint32_t PA = hY[P & 0xffffu], PB = hY[P >> 16];
    /* codes c_ij of corners (i, j, *), in lanes i + 2j of both halves */
    __m256i b00 = _mm256_set1_epi32((int32_t)gZ[PA & 0xffffu]),
            b01 = _mm256_set1_epi32((int32_t)gZ[PA >> 16]),
            b10 = _mm256_set1_epi32((int32_t)gZ[PB & 0xffffu]),
            b11 = _mm256_set1_epi32((int32_t)gZ[PB >> 16]);
    __m256i C = _mm256_blend_epi32(_mm256_blend_epi32(b00, b10, 0x22),
                                   _mm256_blend_epi32(b01, b11, 0x88), 0xcc);

    /* offsets per lane, pre-scaled like core3's x0h, y0l, z1h...: from
     * D = (d0 | d1) = x0 y0 z0 z0 x1 y1 z1 z1, one permute each */
    __m256 D = _mm256_sub_ps(_mm256_set_m128(d0, d0), LD8(k_01));
    __m256 xx = _mm256_mul_ps(_mm256_permutevar8x32_ps(D, LD8I(k_px)), LD8(k_sx));
    __m256 yy = _mm256_mul_ps(_mm256_permutevar8x32_ps(D, LD8I(k_py)), LD8(k_sy));
    __m256 zz = _mm256_mul_ps(_mm256_permutevar8x32_ps(D, LD8I(k_pz)), LD8(k_sz));
    /* S = (x0 + y0) + z0, then S − (number of 1 offsets of the corner) */
    __m128 S = _mm_add_ps(_mm_add_ps(d0, _mm_movehdup_ps(d0)), _mm_movehl_ps(d0, d0));
    __m256 ss = _mm256_sub_ps(_mm256_broadcastss_ps(S), LD8(k_o));

    __m256 kx = _mm256_cvtepi32_ps(_mm256_and_si256(C, LD8I(k_mx))),
           ky = _mm256_cvtepi32_ps(_mm256_and_si256(C, LD8I(k_my))),
           kz = _mm256_cvtepi32_ps(_mm256_and_si256(C, LD8I(k_mz)));
    __m256 n = _mm256_sub_ps(_mm256_fmadd_ps(kz, zz, _mm256_fmadd_ps(ky, yy, _mm256_mul_ps(kx, xx))),
                             ss);

    __m256 u = _mm256_broadcastss_ps(f),
           v = _mm256_permutevar8x32_ps(_mm256_castps128_ps256(f), LD8I(k_1));
    __m256 a = _mm256_add_ps(n, _mm256_mul_ps(u, _mm256_sub_ps(_mm256_movehdup_ps(n), n)));
    __m256 b = _mm256_add_ps(a, _mm256_mul_ps(v, _mm256_sub_ps(_mm256_permute_ps(a, 0xee), a)));
    __m128 b0 = _mm256_castps256_ps128(b), b1 = _mm256_extractf128_ps(b, 1);
    return _mm_cvtss_f32(_mm_add_ss(b0, _mm_mul_ss(_mm_movehl_ps(f, f), _mm_sub_ss(b1, b0))));
}

V3 float pf_noise3f_t_avx2_(const pf_noise_table *t, float x, float y, float z)
{
    return point3_avx2(t ? t : &pf_noise_default_, x, y, z);
}

V3 static float noise3_avx2(float x, float y, float z)
{
    return point3_avx2(&pf_noise_default_, x, y, z);
}

/* The same body compiled for x86-64-v4: the same operations, but EVEX
 * encoding folds the constant splats into their operations as embedded
 * broadcasts (4 loads fewer); 5-7 % faster on Zen 4 in the harness. */
#define V4 __attribute__((target("arch=x86-64-v4")))
V4 float pf_noise3f_t_avx512_(const pf_noise_table *t, float x, float y, float z)
{
    return point3_avx2(t ? t : &pf_noise_default_, x, y, z);
}

V4 static float noise3_avx512(float x, float y, float z)
{
    return point3_avx2(&pf_noise_default_, x, y, z);
}

/* Load-time choice (ifunc resolvers run before constructors and before the
 * sanitizers' runtime is set up: nothing here may be instrumented). */
typedef float noise3_fn(float, float, float);
typedef float noise3t_fn(const pf_noise_table *, float, float, float);
#define PF_RESOLVER __attribute__((no_sanitize_address, no_sanitize_undefined, used))

PF_RESOLVER static noise3_fn *pick_noise3(void)
{
    __builtin_cpu_init();
    if (__builtin_cpu_supports("x86-64-v4"))
        return noise3_avx512;
    return __builtin_cpu_supports("x86-64-v3") ? noise3_avx2 : pf_noise3f_sse2_;
}

PF_RESOLVER static noise3t_fn *pick_noise3t(void)
{
    __builtin_cpu_init();
    if (__builtin_cpu_supports("x86-64-v4"))
        return pf_noise3f_t_avx512_;
    return __builtin_cpu_supports("x86-64-v3") ? pf_noise3f_t_avx2_ : pf_noise3f_t_sse2_;
}

float pf_noise3f(float x, float y, float z) __attribute__((ifunc("pick_noise3")));
float pf_noise3f_t(const pf_noise_table *t, float x, float y, float z)
    __attribute__((ifunc("pick_noise3t")));

#else /* no dispatch: the SSE2 (or generic) body */

float pf_noise3f(float x, float y, float z) { return pf_noise3f_sse2_(x, y, z); }

float pf_noise3f_t(const pf_noise_table *t, float x, float y, float z)
{
    return pf_noise3f_t_sse2_(t, x, y, z);
}

#endif
