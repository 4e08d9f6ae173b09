/* 1D gradient noise, float: gradients ±1…±8 (Gustavson), value scaled by
 * 1/4 so that |n| <= 1 (attained: slopes ±8 meeting at a cell centre). */
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

PF_INLINE float core1(const uint32_t *restrict g, float x)
{
    float xf = floorf(x);
    float x0 = x - xf, x1 = x0 - 1.0f;
    uint32_t X = lattice(xf);
    float u = fade(x0);
    uint32_t c = g[X];
    /* (k − 8)·d/4 with k = g + 8 in bits 0..4 (16..20 for the right corner). */
    float n0 = kf(c, 31u) * (x0 * 0.25f) - 2.0f * x0;
    float n1 = kf(c, 31u << 16) * (x1 * 0x1p-18f) - 2.0f * x1;
    return n0 + u * (n1 - n0);
}

float pf_noise1f_t(const pf_noise_table *t, float x)
{
    if (!t)
        t = &pf_noise_default_;
    return core1(t->g1, x);
}

float pf_noise1f(float x)
{
    return core1(pf_noise_default_.g1, x);
}

PF_CLONES
void pf_noise1f_array(const pf_noise_table *t, float *out, const float *x, size_t n)
{
    if (!t)
        t = &pf_noise_default_;
    const uint32_t *restrict g = t->g1;
    PF_IVDEP
    for (size_t i = 0; i < n; i++)
        out[i] = core1(g, x[i]);
}
