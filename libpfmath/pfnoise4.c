/* 4D gradient noise, float: the 32 gradients with one zero and three ±1
 * components, value scaled by 2/3 (|n| <= 1.0244).  Same scheme as
 * pfnoise3.c: 1 + 2 + 4 + 8 table loads give the 16 corner gradients. */
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

PF_INLINE float core4(const uint32_t *restrict hash, const uint32_t *restrict g, float x,
                      float y, float z, float w)
{
    float xf = floorf(x), yf = floorf(y), zf = floorf(z), wf = floorf(w);
    float x0 = x - xf, y0 = y - yf, z0 = z - zf, w0 = w - wf;
    float x1 = x0 - 1.0f, y1 = y0 - 1.0f, z1 = z0 - 1.0f, w1 = w0 - 1.0f;
    uint32_t X = lattice(xf), Y = lattice(yf), Z = lattice(zf), W = lattice(wf);
    float fx = fade(x0), fy = fade(y0), fz = fade(z0), fw = fade(w0);

    uint32_t P = hash[X];
    uint32_t A = (P & 0xffffu) + Y, B = (P >> 16) + Y;
    uint32_t PA = hash[A], PB = hash[B];
    uint32_t PAA = hash[(PA & 0xffffu) + Z], PAB = hash[(PA >> 16) + Z];
    uint32_t PBA = hash[(PB & 0xffffu) + Z], PBB = hash[(PB >> 16) + Z];
    uint32_t c000 = g[(PAA & 0xffffu) + W], c001 = g[(PAA >> 16) + W];
    uint32_t c010 = g[(PAB & 0xffffu) + W], c011 = g[(PAB >> 16) + W];
    uint32_t c100 = g[(PBA & 0xffffu) + W], c101 = g[(PBA >> 16) + W];
    uint32_t c110 = g[(PBB & 0xffffu) + W], c111 = g[(PBB >> 16) + W];

    /* cXYZ holds corners (X,Y,Z,w=0) in the low half and (X,Y,Z,w=1) high. */
    float xl[2] = {x0, x1}, xh[2] = {x0 * 0x1p-16f, x1 * 0x1p-16f};
    float yl[2] = {y0 * 0x1p-2f, y1 * 0x1p-2f}, yh[2] = {y0 * 0x1p-18f, y1 * 0x1p-18f};
    float zl[2] = {z0 * 0x1p-4f, z1 * 0x1p-4f}, zh[2] = {z0 * 0x1p-20f, z1 * 0x1p-20f};
    float wl = w0 * 0x1p-6f, wh = w1 * 0x1p-22f;
    float S = x0 + y0 + z0 + w0;
#define PAIR(c, i, j, k, lo, hi)                                                           \
    float lo = kf(c, 3u) * xl[i] + kf(c, 12u) * yl[j] + kf(c, 48u) * zl[k] +              \
               kf(c, 192u) * wl - (S - (float)(i + j + k));                               \
    float hi = kf(c, 3u << 16) * xh[i] + kf(c, 3u << 18) * yh[j] +                        \
               kf(c, 3u << 20) * zh[k] + kf(c, 3u << 22) * wh - (S - (float)(i + j + k + 1));
    PAIR(c000, 0, 0, 0, n0000, n0001)
    PAIR(c001, 0, 0, 1, n0010, n0011)
    PAIR(c010, 0, 1, 0, n0100, n0101)
    PAIR(c011, 0, 1, 1, n0110, n0111)
    PAIR(c100, 1, 0, 0, n1000, n1001)
    PAIR(c101, 1, 0, 1, n1010, n1011)
    PAIR(c110, 1, 1, 0, n1100, n1101)
    PAIR(c111, 1, 1, 1, n1110, n1111)
#undef PAIR
#define LERP(a, b, f) ((a) + (f) * ((b) - (a)))
    float a000 = LERP(n0000, n1000, fx), a001 = LERP(n0001, n1001, fx);
    float a010 = LERP(n0010, n1010, fx), a011 = LERP(n0011, n1011, fx);
    float a100 = LERP(n0100, n1100, fx), a101 = LERP(n0101, n1101, fx);
    float a110 = LERP(n0110, n1110, fx), a111 = LERP(n0111, n1111, fx);
    float b00 = LERP(a000, a100, fy), b01 = LERP(a001, a101, fy);
    float b10 = LERP(a010, a110, fy), b11 = LERP(a011, a111, fy);
    float c0 = LERP(b00, b10, fz), c1 = LERP(b01, b11, fz);
    return LERP(c0, c1, fw) * (2.0f / 3.0f);
#undef LERP
}

float pf_noise4f_t(const pf_noise_table *t, float x, float y, float z, float w)
{
    if (!t)
        t = &pf_noise_default_;
    return core4(t->hash, t->g4, x, y, z, w);
}

float pf_noise4f(float x, float y, float z, float w)
{
    return core4(pf_noise_default_.hash, pf_noise_default_.g4, x, y, z, w);
}

PF_CLONES
void pf_noise4f_array(const pf_noise_table *t, float *out, const float *x, const float *y,
                      const float *z, const float *w, size_t n)
{
    if (!t)
        t = &pf_noise_default_;
    const uint32_t *restrict hash = t->hash, *restrict g = t->g4;
    PF_IVDEP
    for (size_t i = 0; i < n; i++)
        out[i] = core4(hash, g, x[i], y[i], z[i], w[i]);
}
