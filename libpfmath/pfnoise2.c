/* 2D gradient noise, float: Perlin-style improved noise on the 8 gradients
 * (±1,±1), (±1,0), (0,±1); |n| <= 1.  Branch-free like pfnoise3.c: 1 + 2
 * table loads per point, gradients applied as k·d − d from masked fields. */
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

PF_INLINE float core2(const uint32_t *restrict hash, const uint32_t *restrict g, float x,
                      float y)
{
    float xf = floorf(x), yf = floorf(y);
    float x0 = x - xf, y0 = y - yf;
    float x1 = x0 - 1.0f, y1 = y0 - 1.0f;
    uint32_t X = lattice(xf), Y = lattice(yf);
    float u = fade(x0), v = fade(y0);

    uint32_t P = hash[X];
    uint32_t cA = g[(P & 0xffffu) + Y], cB = g[(P >> 16) + Y];

    const float s2 = 0x1p-2f, s16 = 0x1p-16f, s18 = 0x1p-18f;
    float x0h = x0 * s16, x1h = x1 * s16, y0l = y0 * s2, y1h = y1 * s18;
    float S = x0 + y0;
    float n00 = kf(cA, 3u) * x0 + kf(cA, 12u) * y0l - S;
    float n01 = kf(cA, 3u << 16) * x0h + kf(cA, 3u << 18) * y1h - (S - 1.0f);
    float n10 = kf(cB, 3u) * x1 + kf(cB, 12u) * y0l - (S - 1.0f);
    float n11 = kf(cB, 3u << 16) * x1h + kf(cB, 3u << 18) * y1h - (S - 2.0f);

    float a0 = n00 + u * (n10 - n00), a1 = n01 + u * (n11 - n01);
    return a0 + v * (a1 - a0);
}

/* One point: the 4 corners 00 01 10 11 (x, y offsets) in the lanes of one
 * vector; lanes 1 and 3 are the high (y + 1) halves of the pair codes.
 * Lane by lane this is core2's arithmetic with the same operands in the
 * same order, so the result is bit-identical to it. */
PF_INLINE float point2(const uint32_t *restrict hash, const uint32_t *restrict g, float x,
                       float y)
{
    pf_v4f p = {x, y, 0.0f, 0.0f};
    if (__builtin_expect(!pf_small4(p), 0))
        return core2(hash, g, x, y);
    pf_v4u L;
    pf_v4f d0 = pf_cell4(p, &L), d1 = pf_minus1(d0);
    pf_v4f f = pf_fade4(d0);
    size_t X = L[0], Y = L[1];

    uint32_t P = hash[X];
    uint32_t cA = g[(P & 0xffffu) + Y], cB = g[(P >> 16) + Y];

    static const pf_v4f sx = {1.0f, 0x1p-16f, 1.0f, 0x1p-16f},
                        sy = {0x1p-2f, 0x1p-18f, 0x1p-2f, 0x1p-18f}, o = {0.0f, 1.0f, 1.0f, 2.0f};
    static const pf_v4u mx = {3u, 3u << 16, 3u, 3u << 16}, my = {12u, 3u << 18, 12u, 3u << 18};
    pf_v4f xx = __builtin_shuffle(d0, d1, (pf_v4i){0, 0, 4, 4}) * sx; /* x0 x0h x1 x1h */
    pf_v4f yy = __builtin_shuffle(d0, d1, (pf_v4i){1, 5, 1, 5}) * sy; /* y0l y1h y0l y1h */
    pf_v4f S = __builtin_shuffle(d0, (pf_v4i){0, 0, 0, 0}) + __builtin_shuffle(d0, (pf_v4i){1, 1, 1, 1});
    pf_v4u C = {cA, cA, cB, cB};
    pf_v4f n = pf_kf4(C, mx) * xx + pf_kf4(C, my) * yy - (S - o); /* n00 n01 n10 n11 */

    pf_v4f nh = __builtin_shuffle(n, (pf_v4i){2, 3, 2, 3});                /* n10 n11 */
    pf_v4f a = n + __builtin_shuffle(f, (pf_v4i){0, 0, 0, 0}) * (nh - n); /* a0 a1 */
    return a[0] + f[1] * (a[1] - a[0]);
}

float pf_noise2f_t(const pf_noise_table *t, float x, float y)
{
    if (!t)
        t = &pf_noise_default_;
    return point2(t->hash, t->g2, x, y);
}

float pf_noise2f(float x, float y)
{
    return point2(pf_noise_default_.hash, pf_noise_default_.g2, x, y);
}

PF_CLONES
void pf_noise2f_array(const pf_noise_table *t, float *out, const float *x, const float *y,
                      size_t n)
{
    if (!t)
        t = &pf_noise_default_;
    const uint32_t *restrict hash = t->hash, *restrict g = t->g2;
    PF_IVDEP
    for (size_t i = 0; i < n; i++)
        out[i] = core2(hash, g, x[i], y[i]);
}
