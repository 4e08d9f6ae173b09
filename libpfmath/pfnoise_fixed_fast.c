/* Fast fixed-point gradient noise: fixed<15,15> results from Q16.16 inputs,
 * integers only.  Same lattice, hashing and gradients as pfnoise_fixed.c
 * (the exact version: Q28 values, 32x32 -> 64-bit products, within 1 LSB);
 * this one keeps values in Q16 and fade weights in Q18 so that every
 * product fits 32 bits (the array loops vectorise in 32-bit lanes, 16 per
 * AVX-512 vector, with vpmulld), and gives up part of an LSB or two for it.
 *
 * Why not 16-bit lanes (int16 values, pmulhrsw/pmaddwd, 32 per vector)?
 * Accuracy: a lerp multiplies the fade weight by a difference of two corner
 * values, which reaches ±4, so in int16 it is Q13 at best; every value
 * rounded to Q13/Q14 costs 1-2u, and the weight error is multiplied by the
 * differences (9δ in 3D, below).  A first version of this file with Q14
 * values and Q16 weights proved 4.2u (2D) and 7.2u (3D) (measured 3.1u and
 * 3.8u); Q15 weights (pmulhrsw) and Q13 values would put the bound near
 * 12u.  Speed: GCC 12 kept that version in 32-bit lanes all the same (the
 * gathered codes and the 17 x 17-bit lerp products are 32-bit, and it did
 * not form pmulhrsw from the usual idiom in this mixed-width loop), at
 * 2.90 ns per 3D point against 3.00 ns for this one; the loop is bound as
 * much by its 7 table lookups per 3D point, which GCC emulates with scalar
 * loads (no vpgatherdd, in the float array loops either).
 *
 * Formats (u = 2^-15, one LSB of the result):
 *  - s = t - 1/2 in Q16 (t = x mod 1 has 16 bits, so s is exact).
 *  - fade, centred: G = f(t) - 1/2 = s·(1 + r), r = 7/8 - z + z·q,
 *    q = (3/8)z - 1/4, z = 4s² (f(1/2 + s) - 1/2 = (15/8)s - 5s³ + 6s⁵):
 *    z in Q16 and Q17, q and r in Q17, G in Q18 clamped to [-2^17, 2^17];
 *    each product exact in 32 bits, each rounding to nearest (ties up).
 *    The lerp weight F̃ = 1/2 + G/2^18 is in [0, 1], exactly 0 at t = 0 (so
 *    the noise is 0 at lattice points), and exactly odd about t = 1/2.
 *    Its error δ = max |F̃ - F| over all 2^16 fractions, measured by
 *    tests/test_noise_fixed_fast.c, is 0.2441u < 0.245u.
 *    (Not from pf_bw_horner: its rules keep one spare integer bit per
 *    addition, and 16-bit Horner steps then leave G in Q12, δ ~ 2^-13.)
 *  - corner values n = g·(t - c) are exact in Q16 (|n| <= 2).
 *  - lerp a + F̃·(b - a) in Q16 rounded once (error <= 1/4 u): D = b - a
 *    (|D| <= 2^18) times W = 2^18·F̃ (19 bits) needs 37 bits, so W is split
 *    into 9-bit halves and the rounding shift is nested (exact, see
 *    lerp16).  The result is a rounded convex combination of a and b, so
 *    every value stays within ±2^17.  The last lerp rounds to Q15 (<= 1/2 u)
 *    and saturates to [-32768, 32767] (3D noise reaches ±1.0364).
 *
 * Error bound (against the exact noise n at the input point, result r, in
 * u; the saturation only moves r towards clamp(2^15·n)).  Write each
 * computed lerp as ã + F̃(b̃ - ã) + ρ = a + F(b - a) + [(1 - F̃)(ã - a) +
 * F̃(b̃ - b)] + (F̃ - F)(b - a) + ρ (a, b exact): errors of the inputs pass
 * through convexly, the fade adds |F̃ - F|·|b - a| <= δ|b - a|, the rounding
 * adds |ρ|.  Summed over the tree with the computed weights W̃, the fade
 * terms are δ·Σ W̃·|b - a| per axis; with |g·d| <= Σ|d_i| (components of g
 * are 0 or ±1) and Σ_j W̃_j |d_j| = (1 - F̃)t + F̃(1 - t) <= 1/2 + δ (the
 * range argument of pfnoise_table.c), those weighted differences are at most
 *   2D: 2 + 2δ (x), 2 (y)                 -> 4δ + 2δ²
 *   3D: 3 + 4δ (x), 3 + 2δ (y), 3 (z)     -> 9δ + 6δ²
 * Adding the roundings (corners exact, inner lerp levels 1/4 u each, the
 * last 1/2 u):
 *   2D: |r - 2^15·n| <= 0.75u + 4δ + 2δ² < 1.74u = PF_NOISE2_FAST_ERR
 *   3D: |r - 2^15·n| <= 1.0u  + 9δ + 6δ² < 3.21u = PF_NOISE3_FAST_ERR
 * so r is within 2 (2D) and 3 (3D) LSB of the correctly rounded value
 * (|r - round(2^15·n)| < 2.24 and 3.71).  The fade term is the larger
 * part.  A fade with r in Q20 (δ = 0.156u, bounds 1.38u and 2.41u) cost
 * this loop 5 % and made it no faster than the float array; one correctly
 * rounded to Q18 (δ = 2^-19: 1.0u and 1.57u) needs 64-bit products and
 * cost 20 %.
 * tests/test_noise_fixed_fast.c measures the error against an independent
 * double evaluation over 2^22 random points plus cell edges and lattice
 * points and requires it within these bounds.
 *
 * Everything is int32/uint32 arithmetic without overflow; right shifts of
 * negative values are arithmetic (checked below; GCC, Clang and MSVC define
 * them so), so the results are bit-identical under any flags or CPU. */
#include "pfnoise.h"

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC optimize("tree-vectorize")
#endif
#include "pfnoise_impl.h"

_Static_assert((-3 >> 1) == -2, "signed right shift must be arithmetic (floor)");

/* G = f(t) - 1/2 in Q18 for the fraction t (Q16) of x, as s·(1 + r) with
 * r = 7/8 - z + z·q, q = (3/8)z - 1/4, z = 4s²: a = |s|·2^16 <= 2^15,
 * a² = z in Q30 exactly, z rounded to Q16 and Q17, q and r in Q17, and
 * |s|·r = a·r/2^17 (< 2^32 unsigned) rounded to Q18. */
PF_INLINE int32_t fade_g18(int32_t x)
{
    int32_t s = (int32_t)((uint32_t)x & 0xffffu) - 32768; /* s·2^16 */
    uint32_t a = (uint32_t)(s < 0 ? -s : s);
    int32_t ss = (int32_t)(a * a);                        /* <= 2^30 */
    int32_t z16 = (ss + 8192) >> 14, z17 = (ss + 4096) >> 13;
    int32_t q = (3 * z16 - 131072 + 2) >> 2;              /* [-2^15, 2^14] */
    int32_t r = 114688 - z17 + ((z16 * q + 32768) >> 16); /* [0, 7/8·2^17] */
    int32_t m = (int32_t)((a * (uint32_t)r + 16384u) >> 15);
    int32_t g = s < 0 ? 4 * s - m : 4 * s + m;
    return g < -131072 ? -131072 : g > 131072 ? 131072 : g;
}

/* a + F̃·(b - a), F̃ = W/2^18, W = 2^17 + G in [0, 2^18], values in Q16
 * (|a|, |b| <= 2^17, |D| <= 2^18).  With W = 2^9·Wh + Wl,
 * floor((D·W + 2^17)/2^18) = floor((D·Wh + floor((D·Wl + 2^17)/2^9))/2^9)
 * exactly (nested floors of an integer numerator), both products < 2^27. */
typedef struct {
    int32_t h, l;
} weight;

PF_INLINE weight fade_w(int32_t x)
{
    int32_t w = 131072 + fade_g18(x);
    weight r = {w >> 9, w & 511};
    return r;
}

PF_INLINE int32_t lerp16(weight f, int32_t a, int32_t b)
{
    int32_t d = b - a;
    return a + ((d * f.h + ((d * f.l + 131072) >> 9)) >> 9);
}

/* The last lerp, rounded to Q15 and saturated. */
PF_INLINE int16_t lerp15(weight f, int32_t a, int32_t b)
{
    int32_t d = b - a;
    int32_t v = (a * 512 + d * f.h + ((d * f.l + 262144) >> 9)) >> 10;
    return (int16_t)(v > 32767 ? 32767 : v < -32768 ? -32768 : v);
}

PF_INLINE uint32_t cell(int32_t x)
{
    return ((uint32_t)x >> 16) & 255u;
}

/* Corner values, exact: with k = g + 1 in {0,1,2} read from the code's
 * 2-bit fields masked in place (bits 0, 2, 4, so k_i·2^(2i)) and the
 * offsets pre-scaled by 16, 4, 1, 16·n = Σ (c & mask_i)·d_i' - 16·Σ d_i
 * costs one and, one multiply and one add per component (|16·n| <= 2^21);
 * it is a multiple of 16, so the shift back to Q16 is exact. */
PF_INLINE int32_t q16(int32_t n16)
{
    return n16 >> 4;
}

PF_INLINE int16_t core2(const uint32_t *restrict hash, const uint32_t *restrict g, int32_t x,
                        int32_t y)
{
    int32_t x0 = (int32_t)((uint32_t)x & 0xffffu), x1 = x0 - 65536;
    int32_t y0 = (int32_t)((uint32_t)y & 0xffffu), y1 = y0 - 65536;
    uint32_t X = cell(x), Y = cell(y);
    uint32_t P = hash[X];
    uint32_t cA = g[(P & 0xffffu) + Y], cB = g[(P >> 16) + Y];
    int32_t x016 = 16 * x0, x116 = 16 * x1, y04 = 4 * y0, y14 = 4 * y1;
    int32_t S = 16 * (x0 + y0), U = 16 * 65536;
#define C2(c, xx, yy, ss) q16((int32_t)((c) & 3u) * (xx) + (int32_t)((c) & 12u) * (yy) - (ss))
    int32_t n00 = C2(cA, x016, y04, S), n01 = C2(cA >> 16, x016, y14, S - U);
    int32_t n10 = C2(cB, x116, y04, S - U), n11 = C2(cB >> 16, x116, y14, S - 2 * U);
#undef C2
    weight u = fade_w(x), v = fade_w(y);
    return lerp15(v, lerp16(u, n00, n10), lerp16(u, n01, n11));
}

PF_INLINE int16_t core3(const uint32_t *restrict hash, const uint32_t *restrict g, int32_t x,
                        int32_t y, int32_t z)
{
    int32_t x0 = (int32_t)((uint32_t)x & 0xffffu), x1 = x0 - 65536;
    int32_t y0 = (int32_t)((uint32_t)y & 0xffffu), y1 = y0 - 65536;
    int32_t z0 = (int32_t)((uint32_t)z & 0xffffu), z1 = z0 - 65536;
    uint32_t X = cell(x), Y = cell(y), Z = cell(z);
    uint32_t P = hash[X];
    uint32_t A = (P & 0xffffu) + Y, B = (P >> 16) + Y;
    uint32_t PA = hash[A], PB = hash[B];
    uint32_t c00 = g[(PA & 0xffffu) + Z], c01 = g[(PA >> 16) + Z];
    uint32_t c10 = g[(PB & 0xffffu) + Z], c11 = g[(PB >> 16) + Z];
    int32_t x016 = 16 * x0, x116 = 16 * x1, y04 = 4 * y0, y14 = 4 * y1;
    /* 16·Σ d_i for each corner: S - 16·65536·(number of far sides) */
    int32_t S = 16 * (x0 + y0 + z0), U = 16 * 65536;
#define C3(c, xx, yy, zz, ss) \
    q16((int32_t)((c) & 3u) * (xx) + (int32_t)((c) & 12u) * (yy) + \
        (int32_t)((c) & 48u) * (zz) - (ss))
    int32_t n000 = C3(c00, x016, y04, z0, S), n001 = C3(c00 >> 16, x016, y04, z1, S - U);
    int32_t n010 = C3(c01, x016, y14, z0, S - U), n011 = C3(c01 >> 16, x016, y14, z1, S - 2 * U);
    int32_t n100 = C3(c10, x116, y04, z0, S - U), n101 = C3(c10 >> 16, x116, y04, z1, S - 2 * U);
    int32_t n110 = C3(c11, x116, y14, z0, S - 2 * U),
            n111 = C3(c11 >> 16, x116, y14, z1, S - 3 * U);
#undef C3
    weight u = fade_w(x), v = fade_w(y), w = fade_w(z);
    int32_t a00 = lerp16(u, n000, n100), a01 = lerp16(u, n001, n101);
    int32_t a10 = lerp16(u, n010, n110), a11 = lerp16(u, n011, n111);
    return lerp15(w, lerp16(v, a00, a10), lerp16(v, a01, a11));
}

#define TAB(t) ((t) ? (t) : &pf_noise_default_)

/* Library-internal (hidden in the shared library): the fade, for
 * tests/test_noise_fixed_fast.c, which checks it against f over all 2^16
 * fractions. */
__attribute__((visibility("hidden"))) int32_t pf__noise_fast_fade_g18(int32_t x);
int32_t pf__noise_fast_fade_g18(int32_t x)
{
    return fade_g18(x);
}

int16_t pf_noise2_q15_fast(int32_t x, int32_t y)
{
    return core2(pf_noise_default_.hash, pf_noise_default_.g2, x, y);
}

int16_t pf_noise3_q15_fast(int32_t x, int32_t y, int32_t z)
{
    return core3(pf_noise_default_.hash, pf_noise_default_.g3, x, y, z);
}

PF_CLONES
void pf_noise2_q15_fast_array(const pf_noise_table *t, int16_t *out, const int32_t *x,
                              const int32_t *y, size_t n)
{
    const uint32_t *restrict hash = TAB(t)->hash, *restrict g = TAB(t)->g2;
    PF_IVDEP
    for (size_t i = 0; i < n; i++)
        out[i] = core2(hash, g, x[i], y[i]);
}

PF_CLONES
void pf_noise3_q15_fast_array(const pf_noise_table *t, int16_t *out, const int32_t *x,
                              const int32_t *y, const int32_t *z, size_t n)
{
    const uint32_t *restrict hash = TAB(t)->hash, *restrict g = TAB(t)->g3;
    PF_IVDEP
    for (size_t i = 0; i < n; i++)
        out[i] = core3(hash, g, x[i], y[i], z[i]);
}
