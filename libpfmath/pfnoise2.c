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

float pf_noise2f_t(const pf_noise_table *t, float x, float y)
{
    return core2(t->hash, t->g2, x, y);
}

float pf_noise2f(float x, float y)
{
    return core2(pf_noise_default_.hash, pf_noise_default_.g2, x, y);
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
