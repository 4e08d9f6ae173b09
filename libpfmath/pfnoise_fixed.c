/* Gradient noise in fixed point, integers only: inputs fixed<31,16>
 * (Q16.16), result Q28 internally, then rounded (RNE) to the caller's
 * fraction bits.  Same lattice, hashing and gradients as the float versions
 * (pfnoise1.c … pfnoise4.c), so the two agree up to rounding.
 *
 * Precision budget (3D; the others are alike):
 *  - t = x mod 1 is exact (16 bits), so every corner offset d and every
 *    gradient dot product g·d is exact; dots are kept in Q28 (|g·d| <= 3).
 *  - fade f(t) = 6t⁵ − 15t⁴ + 10t³ is evaluated by pf_fx_horner32 (pffixed.h)
 *    with the step formats that fit/bitwidth.c's pf_bw_horner assigns to
 *    the coefficients (6, −15, 10, 0, 0, 0 as fixed<4,0>), t as unsigned
 *    fixed<16,16> and the result as fixed<23,23>; every step fits 31 bits.
 *    tests/test_noise_fixed.c re-derives FADE_C/FADE_SHIFT from
 *    pf_bw_horner.  Error: one RNE per step at 2^-24, amplified by at most
 *    |∂/∂p| <= 1 on the way down, so |f − f̃| < 2^-21.
 *  - each lerp a + f·(b − a) is one pf_mulshift32 (RNE) to Q28: |b − a| <= 4
 *    (6 in 4D) gives |error| <= 4·2^-21 + 2^-29 per lerp, and lerps of
 *    lerps are convex, so the Q28 result is within 3·2^-19 < 2^-17 of the
 *    exact noise at the input point: under 1/4 LSB of Q0.15 before the
 *    final rounding, so the Q0.15 result is within 1 LSB of the exact value
 *    (and of the float noise, whose own error is ~1e-6, plus rounding).
 * All arithmetic is on int32/int64 with no overflow and no undefined or
 * implementation-defined behaviour, so results are bit-identical under any
 * compiler, flags or CPU (golden hashes in tests/test_noise_fixed.c). */
#include "pffixed.h"
#include "pfnoise.h"

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC optimize("tree-vectorize")
#endif
#include "pfnoise_impl.h"

/* Horner steps for f(t) = ((((6t − 15)t + 10)t + 0)t + 0)t + 0, formats
 * from pf_bw_horner (see above): c[k] is the coefficient at step k's lsb. */
#define FADE_BITS 23
static const int32_t FADE_C[6] = {0, 0, 0, 10 << 23, -15 * 65536, 6};
static const int8_t FADE_SHIFT[5] = {16, 16, 16, 9, 0};

/* pf_fx_horner32(t, FADE_C, FADE_SHIFT, 5) written out step by step, so
 * that the shifts are constants and the array loops vectorise (GCC does not
 * unroll the header's loop first).  The formats guarantee that no step
 * saturates, so this equals pf_fx_horner32 (the test checks all 2^16 t). */
PF_INLINE int32_t fade_q23(int32_t t)
{
    int32_t p = FADE_C[5];
    p = pf_mulshift32(p, t, FADE_SHIFT[4]) + FADE_C[4];
    p = pf_mulshift32(p, t, FADE_SHIFT[3]) + FADE_C[3];
    p = pf_mulshift32(p, t, FADE_SHIFT[2]) + FADE_C[2];
    p = pf_mulshift32(p, t, FADE_SHIFT[1]) + FADE_C[1];
    return pf_mulshift32(p, t, FADE_SHIFT[0]) + FADE_C[0];
}

/* a + f·(b − a), Q28, f in Q23. */
PF_INLINE int32_t lerp_q28(int32_t f, int32_t a, int32_t b)
{
    return a + pf_mulshift32(f, b - a, FADE_BITS);
}

/* Fraction t (Q16) and lattice index (mod 256) of a Q16.16 coordinate;
 * unsigned arithmetic, so no implementation-defined right shift. */
PF_INLINE int32_t frac16(int32_t x)
{
    return (int32_t)((uint32_t)x & 0xffffu);
}

PF_INLINE uint32_t cell(int32_t x)
{
    return ((uint32_t)x >> 16) & 255u;
}

/* (k − 1)·d for the 2-bit field of code c at bit s. */
PF_INLINE int32_t gd(uint32_t c, int s, int32_t d)
{
    return ((int32_t)((c >> s) & 3u) - 1) * d;
}

/* Q28 results. */
PF_INLINE int32_t core1(const uint32_t *restrict g, int32_t x)
{
    int32_t t = frac16(x);
    uint32_t c = g[cell(x)];
    /* (k − 8)·d/4 with d in Q26 is g·d/4 in Q28, exact. */
    int32_t d0 = t * 1024, d1 = (t - 65536) * 1024;
    int32_t n0 = ((int32_t)(c & 31u) - 8) * d0;
    int32_t n1 = ((int32_t)((c >> 16) & 31u) - 8) * d1;
    return lerp_q28(fade_q23(t), n0, n1);
}

PF_INLINE int32_t core2(const uint32_t *restrict hash, const uint32_t *restrict g, int32_t x,
                        int32_t y)
{
    int32_t tx = frac16(x), ty = frac16(y);
    uint32_t X = cell(x), Y = cell(y);
    int32_t x0 = tx * 4096, x1 = (tx - 65536) * 4096;
    int32_t y0 = ty * 4096, y1 = (ty - 65536) * 4096;
    uint32_t P = hash[X];
    uint32_t cA = g[(P & 0xffffu) + Y], cB = g[(P >> 16) + Y];
    int32_t n00 = gd(cA, 0, x0) + gd(cA, 2, y0), n01 = gd(cA, 16, x0) + gd(cA, 18, y1);
    int32_t n10 = gd(cB, 0, x1) + gd(cB, 2, y0), n11 = gd(cB, 16, x1) + gd(cB, 18, y1);
    int32_t u = fade_q23(tx), v = fade_q23(ty);
    return lerp_q28(v, lerp_q28(u, n00, n10), lerp_q28(u, n01, n11));
}

PF_INLINE int32_t core3(const uint32_t *restrict hash, const uint32_t *restrict g, int32_t x,
                        int32_t y, int32_t z)
{
    int32_t tx = frac16(x), ty = frac16(y), tz = frac16(z);
    uint32_t X = cell(x), Y = cell(y), Z = cell(z);
    int32_t x0 = tx * 4096, x1 = (tx - 65536) * 4096;
    int32_t y0 = ty * 4096, y1 = (ty - 65536) * 4096;
    int32_t z0 = tz * 4096, z1 = (tz - 65536) * 4096;
    uint32_t P = hash[X];
    uint32_t A = (P & 0xffffu) + Y, B = (P >> 16) + Y;
    uint32_t PA = hash[A], PB = hash[B];
    uint32_t c00 = g[(PA & 0xffffu) + Z], c01 = g[(PA >> 16) + Z];
    uint32_t c10 = g[(PB & 0xffffu) + Z], c11 = g[(PB >> 16) + Z];
#define LO(c, xx, yy) (gd(c, 0, xx) + gd(c, 2, yy) + gd(c, 4, z0))
#define HI(c, xx, yy) (gd(c, 16, xx) + gd(c, 18, yy) + gd(c, 20, z1))
    int32_t n000 = LO(c00, x0, y0), n001 = HI(c00, x0, y0);
    int32_t n010 = LO(c01, x0, y1), n011 = HI(c01, x0, y1);
    int32_t n100 = LO(c10, x1, y0), n101 = HI(c10, x1, y0);
    int32_t n110 = LO(c11, x1, y1), n111 = HI(c11, x1, y1);
#undef LO
#undef HI
    int32_t u = fade_q23(tx), v = fade_q23(ty), w = fade_q23(tz);
    int32_t a00 = lerp_q28(u, n000, n100), a01 = lerp_q28(u, n001, n101);
    int32_t a10 = lerp_q28(u, n010, n110), a11 = lerp_q28(u, n011, n111);
    return lerp_q28(w, lerp_q28(v, a00, a10), lerp_q28(v, a01, a11));
}

PF_INLINE int32_t core4(const uint32_t *restrict hash, const uint32_t *restrict g, int32_t x,
                        int32_t y, int32_t z, int32_t w)
{
    int32_t tx = frac16(x), ty = frac16(y), tz = frac16(z), tw = frac16(w);
    uint32_t X = cell(x), Y = cell(y), Z = cell(z), W = cell(w);
    int32_t dx[2] = {tx * 4096, (tx - 65536) * 4096}, dy[2] = {ty * 4096, (ty - 65536) * 4096};
    int32_t dz[2] = {tz * 4096, (tz - 65536) * 4096}, dw[2] = {tw * 4096, (tw - 65536) * 4096};
    uint32_t P = hash[X];
    uint32_t A = (P & 0xffffu) + Y, B = (P >> 16) + Y;
    uint32_t PA = hash[A], PB = hash[B];
    uint32_t PP[4] = {hash[(PA & 0xffffu) + Z], hash[(PA >> 16) + Z], hash[(PB & 0xffffu) + Z],
                      hash[(PB >> 16) + Z]};
    /* n[i][j][k][l]: corner (i,j,k,l). */
    int32_t n[2][2][2][2];
    for (int ij = 0; ij < 4; ij++) {
        int i = ij >> 1, j = ij & 1;
        for (int k = 0; k < 2; k++) {
            uint32_t c = g[(k ? PP[ij] >> 16 : PP[ij] & 0xffffu) + W];
            for (int l = 0; l < 2; l++)
                n[i][j][k][l] = gd(c, 16 * l, dx[i]) + gd(c, 16 * l + 2, dy[j]) +
                                gd(c, 16 * l + 4, dz[k]) + gd(c, 16 * l + 6, dw[l]);
        }
    }
    int32_t fx = fade_q23(tx), fy = fade_q23(ty), fz = fade_q23(tz), fw = fade_q23(tw);
    int32_t b[2][2][2], c2[2][2], d[2];
    for (int j = 0; j < 2; j++)
        for (int k = 0; k < 2; k++)
            for (int l = 0; l < 2; l++)
                b[j][k][l] = lerp_q28(fx, n[0][j][k][l], n[1][j][k][l]);
    for (int k = 0; k < 2; k++)
        for (int l = 0; l < 2; l++)
            c2[k][l] = lerp_q28(fy, b[0][k][l], b[1][k][l]);
    for (int l = 0; l < 2; l++)
        d[l] = lerp_q28(fz, c2[0][l], c2[1][l]);
    /* ×2/3 as in the float version: round(2^31·2/3) = 1431655765. */
    return pf_mulshift32(lerp_q28(fw, d[0], d[1]), 1431655765, 31);
}

/* Q28 -> Q(frac), RNE; frac outside [0, 28] is clamped. */
PF_INLINE int32_t to_frac(int32_t v, int frac)
{
    frac = frac < 0 ? 0 : frac > 28 ? 28 : frac;
    return frac == 28 ? v : pf_mulshift32(v, 1, 28 - frac);
}

PF_INLINE int16_t to_q15(int32_t v)
{
    int32_t r = pf_mulshift32(v, 1, 13);
    return (int16_t)(r > INT16_MAX ? INT16_MAX : r < INT16_MIN ? INT16_MIN : r);
}

#define TAB(t) ((t) ? (t) : &pf_noise_default_)

int32_t pf_noise1_q(const pf_noise_table *t, int32_t x, int frac)
{
    return to_frac(core1(TAB(t)->g1, x), frac);
}

int32_t pf_noise2_q(const pf_noise_table *t, int32_t x, int32_t y, int frac)
{
    return to_frac(core2(TAB(t)->hash, TAB(t)->g2, x, y), frac);
}

int32_t pf_noise3_q(const pf_noise_table *t, int32_t x, int32_t y, int32_t z, int frac)
{
    return to_frac(core3(TAB(t)->hash, TAB(t)->g3, x, y, z), frac);
}

int32_t pf_noise4_q(const pf_noise_table *t, int32_t x, int32_t y, int32_t z, int32_t w,
                    int frac)
{
    return to_frac(core4(TAB(t)->hash, TAB(t)->g4, x, y, z, w), frac);
}

int16_t pf_noise1_q15(int32_t x)
{
    return to_q15(core1(pf_noise_default_.g1, x));
}

int16_t pf_noise2_q15(int32_t x, int32_t y)
{
    return to_q15(core2(pf_noise_default_.hash, pf_noise_default_.g2, x, y));
}

int16_t pf_noise3_q15(int32_t x, int32_t y, int32_t z)
{
    return to_q15(core3(pf_noise_default_.hash, pf_noise_default_.g3, x, y, z));
}

int16_t pf_noise4_q15(int32_t x, int32_t y, int32_t z, int32_t w)
{
    return to_q15(core4(pf_noise_default_.hash, pf_noise_default_.g4, x, y, z, w));
}

PF_CLONES
void pf_noise2_q15_array(const pf_noise_table *t, int16_t *out, const int32_t *x,
                         const int32_t *y, size_t n)
{
    const uint32_t *restrict hash = TAB(t)->hash, *restrict g = TAB(t)->g2;
    PF_IVDEP
    for (size_t i = 0; i < n; i++)
        out[i] = to_q15(core2(hash, g, x[i], y[i]));
}

PF_CLONES
void pf_noise3_q15_array(const pf_noise_table *t, int16_t *out, const int32_t *x,
                         const int32_t *y, const int32_t *z, size_t n)
{
    const uint32_t *restrict hash = TAB(t)->hash, *restrict g = TAB(t)->g3;
    PF_IVDEP
    for (size_t i = 0; i < n; i++)
        out[i] = to_q15(core3(hash, g, x[i], y[i], z[i]));
}

PF_CLONES
void pf_noise2_q_array(const pf_noise_table *t, int32_t *out, const int32_t *x,
                       const int32_t *y, size_t n, int frac)
{
    const uint32_t *restrict hash = TAB(t)->hash, *restrict g = TAB(t)->g2;
    frac = frac < 0 ? 0 : frac > 28 ? 28 : frac;
    PF_IVDEP
    for (size_t i = 0; i < n; i++)
        out[i] = pf_mulshift32(core2(hash, g, x[i], y[i]), 1, 28 - frac);
}

PF_CLONES
void pf_noise3_q_array(const pf_noise_table *t, int32_t *out, const int32_t *x,
                       const int32_t *y, const int32_t *z, size_t n, int frac)
{
    const uint32_t *restrict hash = TAB(t)->hash, *restrict g = TAB(t)->g3;
    frac = frac < 0 ? 0 : frac > 28 ? 28 : frac;
    PF_IVDEP
    for (size_t i = 0; i < n; i++)
        out[i] = pf_mulshift32(core3(hash, g, x[i], y[i], z[i]), 1, 28 - frac);
}
