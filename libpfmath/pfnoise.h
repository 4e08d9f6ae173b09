/* pfnoise.h — band-limited gradient noise (Perlin's improved noise and
 * relatives), in float and in fixed point, 1D to 4D, with analytic gradients
 * and filtered fractal sums.
 *
 * All noise functions are gradient noise in the manner of Perlin's 2002
 * "improved noise": a hash of the integer lattice point picks a gradient g from
 * a small table, each lattice corner contributes g·(p − corner), and the
 * corner contributions are blended with the quintic fade
 * f(t) = 6t⁵ − 15t⁴ + 10t³ (C2, so the noise is C1 with continuous second
 * derivative across cells).  Every function is 0 at every lattice point and
 * is periodic with period 256 in every coordinate (exactly, for float inputs
 * with |x| < 2^22 and for every fixed-point input).
 *
 * Ranges (sup over all points and all permutations; see docs/noise.md and the
 * comments in pfnoise_table.c for the argument; tests/test_noise.c recomputes
 * each bound from the library's gradient tables):
 *   1D  |n| <= PF_NOISE1_MAX = 1        (attained)
 *   2D  |n| <= PF_NOISE2_MAX = 1        (attained)
 *   3D  |n| <= PF_NOISE3_MAX = 1.0364   (sup 1.036354, Perlin's gradients,
 *                                        not rescaled so that his published
 *                                        reference values are reproduced)
 *   4D  |n| <= PF_NOISE4_MAX = 1.0244   (sup 1.024389)
 * The fractal sums are normalised by the sum of the octave amplitudes, so
 * |fbm| <= PF_NOISEn_MAX and 0 <= turbulence <= PF_NOISEn_MAX.
 *
 * Permutation: every function has a form using the default table (Perlin's
 * published permutation, pf_noise_perlin_perm) and a _t form taking a table
 * built by pf_noise_table_init() (any 256-entry permutation) or
 * pf_noise_table_seed() (a permutation shuffled from a 64-bit seed).
 *
 * Float results are bit-identical between the scalar and the array forms and
 * between the CPU-specific clones of the array forms (no contraction into
 * FMA is used).  Fixed-point results use integer arithmetic only and are
 * bit-identical on every compiler, flag set and CPU.
 */
#ifndef PFNOISE_H
#define PFNOISE_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define PF_NOISE1_MAX 1.0f
#define PF_NOISE2_MAX 1.0f
#define PF_NOISE3_MAX 1.0364f
#define PF_NOISE4_MAX 1.0244f

/* Mean of |n| over a period for the default permutation (measured with 2^24
 * random points; tests/test_noise_fbm.c re-measures it; other permutations
 * differ a little, most in 1D, which has only 256 cells).
 * Turbulence fades a filtered-out octave to this value, which is what a box
 * filter wider than the octave's period converges to. */
#define PF_NOISE1_ABSMEAN 0.2406f
#define PF_NOISE2_ABSMEAN 0.2165f
#define PF_NOISE3_ABSMEAN 0.2203f
#define PF_NOISE4_ABSMEAN 0.1572f

/* Lookup tables derived from one permutation p of 0..255.  Entry i of each
 * table describes lattice hashes p[i mod 256] (low 16 bits) and
 * p[(i+1) mod 256] (high 16 bits), so one load serves a pair of lattice
 * corners that differ by one in the last coordinate. */
typedef struct pf_noise_table {
    uint32_t hash[512]; /* p[i] | p[i+1] << 16                           */
    uint32_t g1[512];   /* 1D gradient codes, see pfnoise_table.c        */
    uint32_t g2[512];   /* 2D gradient codes                             */
    uint32_t g3[512];   /* 3D gradient codes (Perlin's 12 edge vectors)  */
    uint32_t g4[512];   /* 4D gradient codes (32 vectors (0,±1,±1,±1)…)  */
    uint8_t perm[256];
} pf_noise_table;

/* Perlin's permutation from the 2002 reference implementation. */
extern const uint8_t pf_noise_perlin_perm[256];

/* Builds t from perm; returns 0, or -1 (t untouched) if perm is not a
 * permutation of 0..255. */
int pf_noise_table_init(pf_noise_table *t, const uint8_t perm[256]);
/* Fisher–Yates shuffle of 0..255 driven by splitmix64(seed). */
void pf_noise_table_seed(pf_noise_table *t, uint64_t seed);
/* The default table (Perlin's permutation). */
const pf_noise_table *pf_noise_default_table(void);

/* ---- float ------------------------------------------------------------ */
float pf_noise1f(float x);
float pf_noise2f(float x, float y);
float pf_noise3f(float x, float y, float z);
float pf_noise4f(float x, float y, float z, float w);
float pf_noise1f_t(const pf_noise_table *t, float x);
float pf_noise2f_t(const pf_noise_table *t, float x, float y);
float pf_noise3f_t(const pf_noise_table *t, float x, float y, float z);
float pf_noise4f_t(const pf_noise_table *t, float x, float y, float z, float w);

/* Value and analytic gradient in one call. */
float pf_noise1f_d(float x, float *dx);
float pf_noise2f_d(float x, float y, float grad[2]);
float pf_noise3f_d(float x, float y, float z, float grad[3]);
float pf_noise4f_d(float x, float y, float z, float w, float grad[4]);
float pf_noise1f_d_t(const pf_noise_table *t, float x, float *dx);
float pf_noise2f_d_t(const pf_noise_table *t, float x, float y, float grad[2]);
float pf_noise3f_d_t(const pf_noise_table *t, float x, float y, float z, float grad[3]);
float pf_noise4f_d_t(const pf_noise_table *t, float x, float y, float z, float w,
                     float grad[4]);

/* Array forms: out[i] = noise(x[i], y[i], …) for i < n; t == NULL means the
 * default table.  out may alias an input array exactly (not partially). */
void pf_noise1f_array(const pf_noise_table *t, float *out, const float *x, size_t n);
void pf_noise2f_array(const pf_noise_table *t, float *out, const float *x,
                      const float *y, size_t n);
void pf_noise3f_array(const pf_noise_table *t, float *out, const float *x,
                      const float *y, const float *z, size_t n);
void pf_noise4f_array(const pf_noise_table *t, float *out, const float *x,
                      const float *y, const float *z, const float *w, size_t n);

/* ---- fixed point ------------------------------------------------------
 * Inputs are fixed<31,16> (Q16.16 in int32_t: value = x / 65536).
 *
 * The core, pf_noiseN_q(…, frac), returns round(n · 2^frac) for
 * 0 <= frac <= 28 in an int32_t, computed from an internal Q28 result with
 * error < 2^-24 (before the final rounding).  It never saturates:
 * |result| <= ceil(PF_NOISEn_MAX · 2^frac).  Any fixed output type is a
 * rounding shift plus a saturation of this; pf_noiseN_q15 is the
 * fixed<15,15> (int16_t, Q0.15) one: round(n · 2^15) saturated to
 * [-32768, 32767].  As n can reach ±1 (and ±1.0364 in 3D, ±1.0244 in 4D),
 * the Q0.15 forms saturate there; they agree with the float functions to
 * within 1 LSB wherever the rounded float value is representable. */
int32_t pf_noise1_q(const pf_noise_table *t, int32_t x, int frac);
int32_t pf_noise2_q(const pf_noise_table *t, int32_t x, int32_t y, int frac);
int32_t pf_noise3_q(const pf_noise_table *t, int32_t x, int32_t y, int32_t z, int frac);
int32_t pf_noise4_q(const pf_noise_table *t, int32_t x, int32_t y, int32_t z,
                    int32_t w, int frac);
int16_t pf_noise1_q15(int32_t x);
int16_t pf_noise2_q15(int32_t x, int32_t y);
int16_t pf_noise3_q15(int32_t x, int32_t y, int32_t z);
int16_t pf_noise4_q15(int32_t x, int32_t y, int32_t z, int32_t w);
/* Array forms (t == NULL: default table). */
void pf_noise2_q15_array(const pf_noise_table *t, int16_t *out, const int32_t *x,
                         const int32_t *y, size_t n);
void pf_noise3_q15_array(const pf_noise_table *t, int16_t *out, const int32_t *x,
                         const int32_t *y, const int32_t *z, size_t n);
void pf_noise2_q_array(const pf_noise_table *t, int32_t *out, const int32_t *x,
                       const int32_t *y, size_t n, int frac);
void pf_noise3_q_array(const pf_noise_table *t, int32_t *out, const int32_t *x,
                       const int32_t *y, const int32_t *z, size_t n, int frac);

/* Fast fixed<15,15> forms (pfnoise_fixed_fast.c): the same noise with Q16
 * values and Q18 fade weights, so that every product fits 32 bits.
 * Integer-only and bit-identical on every compiler, flag set and CPU, like
 * the exact forms, but not equal to them: the result r is within
 * PF_NOISEn_FAST_ERR LSB of 2^15·n (n the exact noise at the input point,
 * saturated to [-32768, 32767]) -- proven in pfnoise_fixed_fast.c -- so
 * within 2 (2D) and 3 (3D) LSB of the correctly rounded value; measured
 * maxima are lower (docs/noise.md).  Same range and saturation as
 * pf_noiseN_q15; 0 at lattice points, period 256. */
#define PF_NOISE2_FAST_ERR 1.74
#define PF_NOISE3_FAST_ERR 3.21
int16_t pf_noise2_q15_fast(int32_t x, int32_t y);
int16_t pf_noise3_q15_fast(int32_t x, int32_t y, int32_t z);
void pf_noise2_q15_fast_array(const pf_noise_table *t, int16_t *out, const int32_t *x,
                              const int32_t *y, size_t n);
void pf_noise3_q15_fast_array(const pf_noise_table *t, int16_t *out, const int32_t *x,
                              const int32_t *y, const int32_t *z, size_t n);

/* ---- fractal sums -----------------------------------------------------
 * fbm = Σ_k a_k·w_k·n(f_k·p + o_k) / Σ_k |a_k|, a_k = gain^k,
 * f_k = lacunarity^k, o_k = k·(0.7548777, 0.5698403, …) (decorrelates the
 * octaves at the origin), k < octaves.
 * turbulence replaces n by |n| and fades a filtered octave to
 * PF_NOISEn_ABSMEAN instead of to 0.
 *
 * Band limit: filter_width is the sampling footprint (pixel size) in input
 * units, 0 for none.  The noise keeps > 96 % of its energy below 1 cycle
 * per lattice unit and > 99.9 % below 2.  An octave is kept whole while
 * f_k·filter_width <= 1/4 (its 2-cycle band edge at or under the Nyquist
 * frequency 1/(2·filter_width)) and faded out (smoothstep) to nothing at
 * f_k·filter_width >= 1/2 (where its 1-cycle main band would reach
 * Nyquist).  Turbulence fades two octaves earlier (f_k·filter_width from
 * 1/16 to 1/8): |n| is creased where n = 0, so its spectrum reaches
 * further.  Measured share of energy above Nyquist (tests/
 * test_noise_spectrum.c): < 0.03 % for fbm, < 0.07 % for turbulence.
 * Ranges: |fbm| <= PF_NOISEn_MAX, 0 <= turbulence <= PF_NOISEn_MAX.
 *
 * Hostile parameters (issue 11): at most PF_NOISE_MAX_OCTAVES octaves are
 * summed (more are clamped; octaves <= 0 give 0).  An octave whose scaled
 * point f_k·p + o_k overflows (is not finite: huge coordinates, a frequency
 * that overflowed, ±inf coordinates) counts as filtered out -- fbm 0,
 * turbulence PF_NOISEn_ABSMEAN -- the limit of its band weight as f_k
 * grows.  So for every non-NaN coordinate and lacunarity, finite gain and
 * any octaves and filter_width, the result is finite and within the ranges
 * above; a NaN coordinate or lacunarity or a non-finite gain gives NaN. */
#define PF_NOISE_MAX_OCTAVES 64
float pf_fbm1f(float x, int octaves, float lacunarity, float gain, float filter_width);
float pf_fbm2f(float x, float y, int octaves, float lacunarity, float gain,
               float filter_width);
float pf_fbm3f(float x, float y, float z, int octaves, float lacunarity, float gain,
               float filter_width);
float pf_fbm4f(float x, float y, float z, float w, int octaves, float lacunarity,
               float gain, float filter_width);
float pf_turbulence1f(float x, int octaves, float lacunarity, float gain,
                      float filter_width);
float pf_turbulence2f(float x, float y, int octaves, float lacunarity, float gain,
                      float filter_width);
float pf_turbulence3f(float x, float y, float z, int octaves, float lacunarity,
                      float gain, float filter_width);
float pf_turbulence4f(float x, float y, float z, float w, int octaves,
                      float lacunarity, float gain, float filter_width);
/* Weight of an octave of frequency f for a footprint filter_width
 * (1, smoothstep, 0 as above); exposed for callers that build their own sums. */
float pf_noise_band_weight(float f, float filter_width);

#ifdef __cplusplus
}
#endif
#endif
