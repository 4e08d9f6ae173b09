/* 3D gradient noise, float: Perlin's improved noise (2002), evaluated
 * without branches in the arithmetic so that the array form vectorises.
 *
 * Hashing: one load of t->hash gives p[i] and p[i+1], so the 8 corner hashes
 * need 1 + 2 + 4 loads instead of 14, and the last level loads the
 * gradient codes directly (t->g3).  The gradient is applied
 * as Σ k_i·d_i − Σ d_i with k = g + 1 ∈ {0,1,2} read from a 2-bit field: the
 * field is masked in place (not shifted) and converted to float, and the
 * field's power of two is folded into a pre-scaled d_i, so each component
 * costs an and, a convert and a multiply-add, all exact except the adds. */
#include "pfnoise.h"

#include <math.h>
#include <string.h>

#if defined(__GNUC__) && !defined(__clang__)
/* -O2 uses GCC's "very cheap" vectoriser, which gives up on these loops;
 * floorf only vectorises (roundps) when FP traps are not modelled; no FMA
 * contraction, so that every clone (and the scalar form) rounds alike. */
#pragma GCC optimize("tree-vectorize", "no-trapping-math", "fp-contract=off")
#endif
#include "pfnoise_impl.h"

PF_INLINE float fade(float t)
{
    return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f);
}

/* floor(x) mod 256 for an integral float |xf| < 2^22: adding 1.5·2^23 puts
 * the integer in the low mantissa bits (2^22 ≡ 0 mod 256).  Larger values
 * give some lattice index without undefined behaviour. */
PF_INLINE uint32_t lattice(float xf)
{
    float m = xf + 12582912.0f;
    uint32_t u;
    memcpy(&u, &m, sizeof u);
    return u & 255u;
}

PF_INLINE float kf(uint32_t c, uint32_t mask)
{
    return (float)(int32_t)(c & mask);
}

/* The cell's 4 pair codes: corners (x, y) = 00 01 10 11, z = 0 in the low
 * half of each and z = 1 in the high half. */
PF_INLINE void codes3(const uint32_t *restrict hash, const uint32_t *restrict g, uint32_t X,
                      uint32_t Y, uint32_t Z, uint32_t c[4])
{
    uint32_t P = hash[X];
    uint32_t A = (P & 0xffffu) + Y, B = (P >> 16) + Y;
    uint32_t PA = hash[A], PB = hash[B];
    c[0] = g[(PA & 0xffffu) + Z], c[1] = g[(PA >> 16) + Z];
    c[2] = g[(PB & 0xffffu) + Z], c[3] = g[(PB >> 16) + Z];
}

/* acc + k·d where k·d is exact (k ∈ {0,1,2}·2^f, d a pre-scaled offset:
 * the product only shifts d's bits), so the fused multiply-add rounds the
 * same exact sum once, as the add does, signed zeros included: `fused`
 * (a constant after inlining) picks FMA where the target has it, with
 * results bit-identical to the plain form (tests/test_noise_scalar.c
 * checks the non-fused SSE2 scalar body against the array forms). */
PF_INLINE float madd_exact(float acc, float k, float d, int fused)
{
    return fused ? __builtin_fmaf(k, d, acc) : acc + k * d;
}

/* The noise at (x, y, z) from its cell's codes (the array body). */
PF_INLINE float blend3(float x, float y, float z, uint32_t c00, uint32_t c01, uint32_t c10,
                       uint32_t c11, int fused)
{
    float xf = floorf(x), yf = floorf(y), zf = floorf(z);
    float x0 = x - xf, y0 = y - yf, z0 = z - zf;
    float x1 = x0 - 1.0f, y1 = y0 - 1.0f, z1 = z0 - 1.0f;
    float u = fade(x0), v = fade(y0), w = fade(z0);

    /* Pre-scaled offsets: low corner fields at bits 0, 2, 4; the z+1 corner
     * of each pair uses fields at bits 16, 18, 20. */
    const float s2 = 0x1p-2f, s4 = 0x1p-4f, s16 = 0x1p-16f, s18 = 0x1p-18f, s20 = 0x1p-20f;
    float x0h = x0 * s16, x1h = x1 * s16;
    float y0l = y0 * s2, y1l = y1 * s2, y0h = y0 * s18, y1h = y1 * s18;
    float z0l = z0 * s4, z1h = z1 * s20;
    float S = x0 + y0 + z0;

#define DOT(c, m, xx, yy, zz)                                                                  \
    madd_exact(madd_exact(kf(c, m) * xx, kf(c, (m) << 2), yy, fused), kf(c, (m) << 4), zz, fused)
#define LO(c, xx, yy, ss) (DOT(c, 3u, xx, yy, z0l) - (ss))
#define HI(c, xx, yy, ss) (DOT(c, 3u << 16, xx, yy, z1h) - (ss))
    float n000 = LO(c00, x0, y0l, S), n001 = HI(c00, x0h, y0h, S - 1.0f);
    float n010 = LO(c01, x0, y1l, S - 1.0f), n011 = HI(c01, x0h, y1h, S - 2.0f);
    float n100 = LO(c10, x1, y0l, S - 1.0f), n101 = HI(c10, x1h, y0h, S - 2.0f);
    float n110 = LO(c11, x1, y1l, S - 2.0f), n111 = HI(c11, x1h, y1h, S - 3.0f);
#undef LO
#undef HI
#undef DOT

    float a00 = n000 + u * (n100 - n000), a01 = n001 + u * (n101 - n001);
    float a10 = n010 + u * (n110 - n010), a11 = n011 + u * (n111 - n011);
    float b0 = a00 + v * (a10 - a00), b1 = a01 + v * (a11 - a01);
    return b0 + w * (b1 - b0);
}

/* Packed cell key X | Y << 8 | Z << 16 of a point. */
PF_INLINE uint32_t cell3(float x, float y, float z)
{
    return lattice(floorf(x)) | lattice(floorf(y)) << 8 | lattice(floorf(z)) << 16;
}

PF_INLINE float core3(const uint32_t *restrict hash, const uint32_t *restrict g, float x,
                      float y, float z)
{
    uint32_t k = cell3(x, y, z), c[4];
    codes3(hash, g, k & 255u, (k >> 8) & 255u, k >> 16, c);
    return blend3(x, y, z, c[0], c[1], c[2], c[3], 0);
}

/* One point: the 8 corners in two vectors, x = 0 corners (000 001 010 011)
 * and x = 1 corners (100 101 110 111); lanes 1 and 3 are the high (z + 1)
 * halves of the pair codes.  Lane by lane this is core3's LO/HI with the
 * same operands in the same order, so the result is bit-identical to it. */
PF_INLINE float point3(const uint32_t *restrict hash, const uint32_t *restrict g, float x,
                       float y, float z)
{
    pf_v4f p = {x, y, z, 0.0f};
    if (__builtin_expect(!pf_small4(p), 0))
        return core3(hash, g, x, y, z);
    pf_v4u L;
    pf_v4f d0 = pf_cell4(p, &L), d1 = pf_minus1(d0);
    pf_v4f f = pf_fade4(d0);
    size_t X = L[0], Y = L[1], Z = L[2];

    uint32_t P = hash[X];
    size_t A = (P & 0xffffu) + Y, B = (P >> 16) + Y;
    uint32_t PA = hash[A], PB = hash[B];
    uint32_t c00 = g[(PA & 0xffffu) + Z], c01 = g[(PA >> 16) + Z];
    uint32_t c10 = g[(PB & 0xffffu) + Z], c11 = g[(PB >> 16) + Z];

    static const pf_v4f sx = {1.0f, 0x1p-16f, 1.0f, 0x1p-16f},
                        sy = {0x1p-2f, 0x1p-18f, 0x1p-2f, 0x1p-18f},
                        sz = {0x1p-4f, 0x1p-20f, 0x1p-4f, 0x1p-20f},
                        o0 = {0.0f, 1.0f, 1.0f, 2.0f}, o1 = {1.0f, 2.0f, 2.0f, 3.0f};
    static const pf_v4u mx = {3u, 3u << 16, 3u, 3u << 16}, my = {12u, 3u << 18, 12u, 3u << 18},
                        mz = {48u, 3u << 20, 48u, 3u << 20};
    pf_v4f X0 = __builtin_shuffle(d0, (pf_v4i){0, 0, 0, 0}),
           X1 = __builtin_shuffle(d1, (pf_v4i){0, 0, 0, 0}),
           Y0 = __builtin_shuffle(d0, (pf_v4i){1, 1, 1, 1}),
           Z0 = __builtin_shuffle(d0, (pf_v4i){2, 2, 2, 2});
    pf_v4f xx0 = X0 * sx, xx1 = X1 * sx;
    pf_v4f yy = __builtin_shuffle(d0, d1, (pf_v4i){1, 1, 5, 5}) * sy;
    pf_v4f zz = __builtin_shuffle(d0, d1, (pf_v4i){2, 6, 2, 6}) * sz;
    pf_v4f S = X0 + Y0 + Z0, ss0 = S - o0, ss1 = S - o1;
    pf_v4u C0 = {c00, c00, c01, c01}, C1 = {c10, c10, c11, c11};
    pf_v4f n0 = pf_kf4(C0, mx) * xx0 + pf_kf4(C0, my) * yy + pf_kf4(C0, mz) * zz - ss0;
    pf_v4f n1 = pf_kf4(C1, mx) * xx1 + pf_kf4(C1, my) * yy + pf_kf4(C1, mz) * zz - ss1;

    pf_v4f a = n0 + __builtin_shuffle(f, (pf_v4i){0, 0, 0, 0}) * (n1 - n0); /* a00 a01 a10 a11 */
    pf_v4f ah = __builtin_shuffle(a, (pf_v4i){2, 3, 2, 3});                 /* a10 a11 */
    pf_v4f b = a + __builtin_shuffle(f, (pf_v4i){1, 1, 1, 1}) * (ah - a);   /* b0 b1 */
    return b[0] + f[2] * (b[1] - b[0]);
}

/* The SSE2 bodies of pf_noise3f_t and pf_noise3f (pfnoise3_avx2.c picks
 * between them and the AVX2 body at load time). */
float pf_noise3f_t_sse2_(const pf_noise_table *t, float x, float y, float z)
{
    if (!t)
        t = &pf_noise_default_;
    return point3(t->hash, t->g3, x, y, z);
}

float pf_noise3f_sse2_(float x, float y, float z)
{
    return point3(pf_noise_default_.hash, pf_noise_default_.g3, x, y, z);
}

/* The array form in chunks of three passes: the cell keys (vectorised),
 * the cells' codes by scalar loads, looked up only when the cell differs
 * from the previous point's (coherent points share cells) and stored as
 * one 16-byte row per point (one store; four separate arrays cost 16 %
 * more on a coherent grid), and the blend (vectorised, reading the codes
 * contiguously).  Gathering the codes inside the vectorised loop cost more
 * (4.1 ns a point instead of 2.6 on a grid, docs/noise.md): GCC emulates
 * each of the 7 gathers per point with a scalar load and two lane moves.
 * The blend is the same arithmetic in the same order as core3, so results
 * stay bit-identical to it and to the scalar forms; `out` may still alias
 * an input exactly (each chunk's keys are read before its blend writes). */
PF_INLINE void array3(const pf_noise_table *t, float *out, const float *x, const float *y,
                      const float *z, size_t n, int fused)
{
    if (!t)
        t = &pf_noise_default_;
    const uint32_t *restrict hash = t->hash, *restrict g = t->g3;
    enum { CHUNK = 256 };
    uint32_t key[CHUNK], cs[CHUNK][4];
    uint32_t last = UINT32_MAX, c[4] = {0, 0, 0, 0};
    for (size_t base = 0; base < n; base += CHUNK) {
        size_t m = n - base < CHUNK ? n - base : CHUNK;
        const float *xs = x + base, *ys = y + base, *zs = z + base;
        PF_IVDEP
        for (size_t i = 0; i < m; i++)
            key[i] = cell3(xs[i], ys[i], zs[i]);
        for (size_t i = 0; i < m; i++) {
            uint32_t k = key[i];
            if (k != last) {
                codes3(hash, g, k & 255u, (k >> 8) & 255u, k >> 16, c);
                last = k;
            }
            memcpy(cs[i], c, sizeof c);
        }
        float *os = out + base;
        PF_IVDEP
        for (size_t i = 0; i < m; i++)
            os[i] = blend3(xs[i], ys[i], zs[i], cs[i][0], cs[i][1], cs[i][2], cs[i][3], fused);
    }
}

/* One array body per ISA, chosen at load time like target_clones would,
 * but with FMA for the gradient products where the ISA has it (the clones
 * of one source would all have to be plain, or all fused). */
#if PF_NOISE3_DISPATCH
typedef void array3_fn(const pf_noise_table *, float *, const float *, const float *,
                       const float *, size_t);
__attribute__((target("arch=x86-64-v4"))) static void
array3_v4(const pf_noise_table *t, float *out, const float *x, const float *y, const float *z,
          size_t n)
{
    array3(t, out, x, y, z, n, 1);
}

__attribute__((target("arch=x86-64-v3"))) static void
array3_v3(const pf_noise_table *t, float *out, const float *x, const float *y, const float *z,
          size_t n)
{
    array3(t, out, x, y, z, n, 1);
}

static void array3_base(const pf_noise_table *t, float *out, const float *x, const float *y,
                        const float *z, size_t n)
{
    array3(t, out, x, y, z, n, 0);
}

/* ifunc resolver: runs before constructors and sanitizers, uninstrumented */
__attribute__((no_sanitize_address, no_sanitize_undefined, used)) static array3_fn *
pick_array3(void)
{
    __builtin_cpu_init();
    if (__builtin_cpu_supports("x86-64-v4"))
        return array3_v4;
    return __builtin_cpu_supports("x86-64-v3") ? array3_v3 : array3_base;
}

void pf_noise3f_array(const pf_noise_table *t, float *out, const float *x, const float *y,
                      const float *z, size_t n) __attribute__((ifunc("pick_array3")));
#else
void pf_noise3f_array(const pf_noise_table *t, float *out, const float *x, const float *y,
                      const float *z, size_t n)
{
    array3(t, out, x, y, z, n, 0);
}
#endif
