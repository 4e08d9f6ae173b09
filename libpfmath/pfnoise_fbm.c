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
float pf_noise_band_weight(float f, float filter_width)
{
    float r = f * filter_width;
    if (!(r > 0.25f))
        return 1.0f;
    if (r >= 0.5f)
        return 0.0f;
    float s = (0.5f - r) * 4.0f;
    return s * s * (3.0f - 2.0f * s);
}

static float octave(int n, const float *p, float f, int k)
{
    float q[4];
    for (int i = 0; i < n; i++)
        q[i] = p[i] * f + (float)k * OFFSET[i];
    switch (n) {
    case 1: return pf_noise1f(q[0]);
    case 2: return pf_noise2f(q[0], q[1]);
    case 3: return pf_noise3f(q[0], q[1], q[2]);
    default: return pf_noise4f(q[0], q[1], q[2], q[3]);
    }
}

static float sum(int n, const float *p, int octaves, float lacunarity, float gain,
                 float filter_width, int turbulence)
{
    float total = 0.0f, norm = 0.0f, amp = 1.0f, f = 1.0f;
    for (int k = 0; k < octaves; k++) {
        /* |n| is creased along the zero set of n, so its spectrum decays only
         * like f^-4: turbulence fades each octave two octaves (a factor 4 in
         * frequency) earlier than fbm. */
        float a = fabsf(amp), w = pf_noise_band_weight(turbulence ? 4.0f * f : f, filter_width);
        norm += a;
        if (turbulence) {
            float v = w > 0.0f ? fabsf(octave(n, p, f, k)) : 0.0f;
            total += a * (w * v + (1.0f - w) * ABSMEAN[n]);
        } else if (w > 0.0f) {
            total += amp * w * octave(n, p, f, k);
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
