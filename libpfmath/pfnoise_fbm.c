/* Fractal sums of the float noise with band limiting by the sampling
 * footprint (see pfnoise.h for the formula and the fade-out rule).
 *
 * Range: fbm = Σ a_k w_k n_k / Σ|a_k| with 0 <= w_k <= 1 and
 * |n_k| <= PF_NOISEn_MAX, so |fbm| <= PF_NOISEn_MAX; float rounding cannot
 * push it over, as each rounded |a_k w_k n_k| <= |a_k| and rounded sums are
 * monotone in their terms.  Turbulence = Σ|a_k| (w_k |n_k| + (1 − w_k) μ)
 * / Σ|a_k| with 0 <= μ <= PF_NOISEn_MAX lies in [0, PF_NOISEn_MAX] the
 * same way.
 *
 * A filtered-out octave of fbm fades to 0, its mean; one of turbulence fades
 * to μ = E|n| (PF_NOISEn_ABSMEAN): a box filter much wider than the
 * octave's period returns its mean, not 0, so fading |n| to 0 would darken
 * distant turbulence. */
#include "pfnoise.h"

#include <math.h>

/* Octave offsets: irrational steps (powers of the inverse plastic number)
 * so that octaves do not all vanish together at the origin's lattice. */
static const float OFFSET[4] = {0.7548777f, 0.5698403f, 0.4301597f, 0.3247179f};
static const float ABSMEAN[5] = {0.0f, PF_NOISE1_ABSMEAN, PF_NOISE2_ABSMEAN,
                                 PF_NOISE3_ABSMEAN, PF_NOISE4_ABSMEAN};

/* 1 while f·w <= 1/4, smoothstep down to 0 at f·w = 1/2; w <= 0 or NaN
 * means no filtering. */
static inline __attribute__((always_inline)) float band_weight(float f, float filter_width)
{
    float r = f * filter_width;
    if (!(r > 0.25f))
        return 1.0f;
    if (r >= 0.5f)
        return 0.0f;
    float s = (0.5f - r) * 4.0f;
    return s * s * (3.0f - 2.0f * s);
}

/* Octave k at frequency f, or NAN when its scaled point f·p + o_k is not
 * finite (overflow, or an infinite coordinate): the caller then counts the
 * octave as filtered out.  Floats that large are integers, so such an
 * octave could only be sampled at lattice points; its band weight tends to
 * 0 as f grows, and 0 (fbm) or E|n| (turbulence) is that limit. */
float pf_noise_band_weight(float f, float filter_width)
{
    return band_weight(f, filter_width);
}

static inline __attribute__((always_inline)) float octave(int n, const float *p, float f,
                                                          int k)
{
    float q[4];
    for (int i = 0; i < n; i++) {
        q[i] = p[i] * f + (float)k * OFFSET[i];
        if (!isfinite(q[i]))
            return NAN;
    }
    switch (n) {
    case 1: return pf_noise1f(q[0]);
    case 2: return pf_noise2f(q[0], q[1]);
    case 3: return pf_noise3f(q[0], q[1], q[2]);
    default: return pf_noise4f(q[0], q[1], q[2], q[3]);
    }
}

/* The sum, with hostile parameters defined (pfnoise.h): NaN in, NaN out;
 * octaves clamped to [0, PF_NOISE_MAX_OCTAVES] (bounded time); octaves
 * that overflow are filtered out (octave() above); and for |gain| > 1 the
 * amplitude, the sum and the normaliser are rescaled together by a power
 * of two whenever |amp| reaches 1, so that amp·gain·n cannot overflow.  Such
 * a rescaling is exact and commutes with every later rounding (short of
 * underflow in terms already negligible), so finite sums are unchanged. */
/* Inlined into each entry point, so that n and turbulence are constants
 * there and the per-octave switch and loops fold away. */
static inline __attribute__((always_inline)) float sum(int n, const float *p, int octaves,
                                                       float lacunarity, float gain,
                                                       float filter_width, int turbulence)
{
    for (int i = 0; i < n; i++)
        if (isnan(p[i]))
            return NAN;
    if (isnan(lacunarity) || !isfinite(gain))
        return NAN;
    if (octaves > PF_NOISE_MAX_OCTAVES)
        octaves = PF_NOISE_MAX_OCTAVES;
    float total = 0.0f, norm = 0.0f, amp = 1.0f, f = 1.0f;
    for (int k = 0; k < octaves; k++) {
        /* |n| is creased along the zero set of n, so its spectrum decays only
         * like f^-4: turbulence fades each octave two octaves (a factor 4 in
         * frequency) earlier than fbm. */
        float a = fabsf(amp), w = band_weight(turbulence ? 4.0f * f : f, filter_width);
        float v = w > 0.0f ? octave(n, p, f, k) : 0.0f;
        if (isnan(v)) /* overflowed: filtered out */
            w = 0.0f, v = 0.0f;
        norm += a;
        if (turbulence)
            total += a * (w * fabsf(v) + (1.0f - w) * ABSMEAN[n]);
        else if (w > 0.0f)
            total += amp * w * v;
        if (a >= 1.0f && fabsf(gain) > 1.0f) {
            /* |amp| = m·2^e, m in [1/2, 1): bring it to [2^-9, 2^-8), so
             * that the next |amp·gain|·PF_NOISEn_MAX stays below FLT_MAX */
            int e;
            frexpf(amp, &e);
            amp = ldexpf(amp, -e - 8);
            total = ldexpf(total, -e - 8);
            norm = ldexpf(norm, -e - 8);
        }
        amp *= gain;
        f *= lacunarity;
    }
    return norm > 0.0f ? total / norm : 0.0f;
}

float pf_fbm1f(float x, int octaves, float lacunarity, float gain, float filter_width)
{
    return sum(1, &x, octaves, lacunarity, gain, filter_width, 0);
}

float pf_fbm2f(float x, float y, int octaves, float lacunarity, float gain,
               float filter_width)
{
    float p[2] = {x, y};
    return sum(2, p, octaves, lacunarity, gain, filter_width, 0);
}

float pf_fbm3f(float x, float y, float z, int octaves, float lacunarity, float gain,
               float filter_width)
{
    float p[3] = {x, y, z};
    return sum(3, p, octaves, lacunarity, gain, filter_width, 0);
}

float pf_fbm4f(float x, float y, float z, float w, int octaves, float lacunarity,
               float gain, float filter_width)
{
    float p[4] = {x, y, z, w};
    return sum(4, p, octaves, lacunarity, gain, filter_width, 0);
}

float pf_turbulence1f(float x, int octaves, float lacunarity, float gain,
                      float filter_width)
{
    return sum(1, &x, octaves, lacunarity, gain, filter_width, 1);
}

float pf_turbulence2f(float x, float y, int octaves, float lacunarity, float gain,
                      float filter_width)
{
    float p[2] = {x, y};
    return sum(2, p, octaves, lacunarity, gain, filter_width, 1);
}

float pf_turbulence3f(float x, float y, float z, int octaves, float lacunarity,
                      float gain, float filter_width)
{
    float p[3] = {x, y, z};
    return sum(3, p, octaves, lacunarity, gain, filter_width, 1);
}

float pf_turbulence4f(float x, float y, float z, float w, int octaves,
                      float lacunarity, float gain, float filter_width)
{
    float p[4] = {x, y, z, w};
    return sum(4, p, octaves, lacunarity, gain, filter_width, 1);
}
