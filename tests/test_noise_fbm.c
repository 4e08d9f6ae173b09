/* pfnoise fractal sums: documented ranges, the documented formula, the
 * band-weight rule, what a filtered-out octave fades to, and the
 * PF_NOISEn_ABSMEAN constants, and defined results for hostile parameters
 * (huge coordinates and octave counts, extreme gains).  (The spectral band limit itself is in
 * test_noise_spectrum.c.) */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "pfnoise.h"

static int quick;

static uint64_t rng_state = 0xa4093822299f31d0u;
static uint64_t rnd(void)
{
    uint64_t z = (rng_state += 0x9e3779b97f4a7c15u);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
    return z ^ (z >> 31);
}
static double urand(double lo, double hi) { return lo + (hi - lo) * (double)(rnd() >> 11) * 0x1p-53; }

static const float maxes[5] = {0, PF_NOISE1_MAX, PF_NOISE2_MAX, PF_NOISE3_MAX, PF_NOISE4_MAX};
static const float absmean[5] = {0, PF_NOISE1_ABSMEAN, PF_NOISE2_ABSMEAN, PF_NOISE3_ABSMEAN,
                                 PF_NOISE4_ABSMEAN};

static float fbm(int n, int turb, const float *p, int oct, float lac, float gain, float fw)
{
    switch (n) {
    case 1: return turb ? pf_turbulence1f(p[0], oct, lac, gain, fw) : pf_fbm1f(p[0], oct, lac, gain, fw);
    case 2: return turb ? pf_turbulence2f(p[0], p[1], oct, lac, gain, fw)
                        : pf_fbm2f(p[0], p[1], oct, lac, gain, fw);
    case 3: return turb ? pf_turbulence3f(p[0], p[1], p[2], oct, lac, gain, fw)
                        : pf_fbm3f(p[0], p[1], p[2], oct, lac, gain, fw);
    default: return turb ? pf_turbulence4f(p[0], p[1], p[2], p[3], oct, lac, gain, fw)
                         : pf_fbm4f(p[0], p[1], p[2], p[3], oct, lac, gain, fw);
    }
}

static float noise(int n, const float *p)
{
    switch (n) {
    case 1: return pf_noise1f(p[0]);
    case 2: return pf_noise2f(p[0], p[1]);
    case 3: return pf_noise3f(p[0], p[1], p[2]);
    default: return pf_noise4f(p[0], p[1], p[2], p[3]);
    }
}

/* |fbm| <= MAX and 0 <= turbulence <= MAX for many parameter sets,
 * including negative gain, gain > 1 and filtering. */
static void test_ranges(void **state)
{
    (void)state;
    static const float gains[] = {0.5f, 0.7f, 1.0f, 1.6f, -0.6f};
    static const float lacs[] = {2.0f, 1.93f, 3.1f};
    static const float fws[] = {0.0f, 0.013f, 0.2f, 5.0f};
    int pts = quick ? 300 : 3000;
    for (int n = 1; n <= 4; n++) {
        double mx = 0, tmin = 1e9, tmax = 0;
        for (int i = 0; i < pts; i++) {
            float p[4];
            for (int k = 0; k < 4; k++)
                p[k] = (float)urand(-300, 300);
            for (size_t g = 0; g < 5; g++)
                for (size_t l = 0; l < 3; l++) {
                    int oct = 1 + (int)(rnd() % 9);
                    float fw = fws[rnd() % 4];
                    double f = fbm(n, 0, p, oct, lacs[l], gains[g], fw);
                    double t = fbm(n, 1, p, oct, lacs[l], gains[g], fw);
                    mx = fmax(mx, fabs(f));
                    tmin = fmin(tmin, t);
                    tmax = fmax(tmax, t);
                }
        }
        printf("# %dD: max|fbm| %.4f, turbulence in [%.4f, %.4f], bound %.4f\n", n, mx, tmin, tmax,
               maxes[n]);
        assert_true(mx <= maxes[n]);
        assert_true(tmin >= 0 && tmax <= maxes[n]);
    }
    /* one octave is the noise itself; zero octaves give 0 */
    float p[4] = {1.3f, 2.7f, -3.1f, 0.4f};
    for (int n = 1; n <= 4; n++) {
        assert_true(fbm(n, 0, p, 1, 2.0f, 0.5f, 0.0f) == noise(n, p));
        assert_true(fbm(n, 0, p, 0, 2.0f, 0.5f, 0.0f) == 0.0f);
        assert_true(fbm(n, 1, p, 1, 2.0f, 0.5f, 0.0f) == fabsf(noise(n, p)));
    }
}

/* The documented formula, summed here in double from the plain noise. */
static void test_formula(void **state)
{
    (void)state;
    static const double off[4] = {0.7548777, 0.5698403, 0.4301597, 0.3247179};
    double worst = 0;
    for (int n = 1; n <= 4; n++)
        for (int i = 0; i < 2000; i++) {
            float p[4];
            for (int k = 0; k < 4; k++)
                p[k] = (float)urand(-50, 50);
            int oct = 1 + (int)(rnd() % 8);
            float lac = (float)urand(1.5, 3), gain = (float)urand(0.3, 0.9);
            /* f_k = lac^k as the library forms it (a float running product:
             * the input of a high octave is sensitive to its last bits) */
            double s = 0, norm = 0, a = 1;
            float f = 1;
            for (int k = 0; k < oct; k++) {
                float q[4];
                for (int j = 0; j < n; j++)
                    q[j] = p[j] * f + (float)k * (float)off[j];
                s += a * noise(n, q);
                norm += a;
                a *= gain;
                f *= lac;
            }
            worst = fmax(worst, fabs(s / norm - fbm(n, 0, p, oct, lac, gain, 0.0f)));
        }
    printf("# fbm vs formula: %.3g\n", worst);
    assert_true(worst < 1e-5);
}

static void test_band_weight(void **state)
{
    (void)state;
    assert_true(pf_noise_band_weight(1.0f, 0.0f) == 1.0f);
    assert_true(pf_noise_band_weight(1.0f, -1.0f) == 1.0f);
    assert_true(pf_noise_band_weight(1.0f, NAN) == 1.0f);
    assert_true(pf_noise_band_weight(1.0f, 0.25f) == 1.0f);
    assert_true(pf_noise_band_weight(16.0f, 1.0f / 64) == 1.0f);
    assert_true(pf_noise_band_weight(1.0f, 0.5f) == 0.0f);
    assert_true(pf_noise_band_weight(2.0f, 0.5f) == 0.0f);
    assert_true(fabsf(pf_noise_band_weight(1.0f, 0.375f) - 0.5f) < 1e-6f);
    /* monotone and continuous (steps of 1e-5 in r move it by < 2e-4) */
    float prev = 1.0f;
    for (int i = 0; i <= 40000; i++) {
        float w = pf_noise_band_weight(1.0f, 0.2f + (float)i * 1e-5f);
        assert_true(w <= prev && prev - w < 2e-4f);
        prev = w;
    }
}

/* A footprint wider than every octave leaves fbm at 0 and turbulence at
 * E|n|; with lacunarity 2 and a power-of-two footprint the octaves switch
 * off cleanly, so the filtered sum equals the plain sum of the kept octaves
 * over the full normaliser. */
static void test_filter_limits(void **state)
{
    (void)state;
    for (int n = 1; n <= 4; n++) {
        float p[4] = {12.3f, -4.56f, 7.89f, 0.12f};
        assert_true(fbm(n, 0, p, 8, 2.0f, 0.5f, 100.0f) == 0.0f);
        assert_true(fabsf(fbm(n, 1, p, 8, 2.0f, 0.5f, 100.0f) - absmean[n]) < 1e-6f);
        /* width 1/32: octaves 1, 2, 4, 8 kept whole (f·w <= 1/4), 16 gone */
        double kept = fbm(n, 0, p, 4, 2.0f, 0.5f, 0.0f) * (1 + 0.5 + 0.25 + 0.125);
        double all = 2 - 0x1p-7; /* Σ_{k<8} 2^-k */
        assert_true(fabs(fbm(n, 0, p, 8, 2.0f, 0.5f, 1.0f / 32) - kept / all) < 1e-6);
    }
}

/* E|n| over the period, re-measured with 2^22 points (standard error
 * ~6e-5); the constants must match to 4 standard errors plus rounding. */
static void test_absmean(void **state)
{
    (void)state;
    int pts = quick ? 1 << 16 : 1 << 22;
    for (int n = 1; n <= 4; n++) {
        double s = 0, s2 = 0;
        for (int i = 0; i < pts; i++) {
            float p[4];
            for (int k = 0; k < 4; k++)
                p[k] = (float)urand(0, 256);
            double v = fabs(noise(n, p));
            s += v;
            s2 += v * v;
        }
        double m = s / pts, se = sqrt(s2 / pts - m * m) / sqrt(pts);
        printf("# %dD: E|n| = %.5f +- %.1e (constant %.4f)\n", n, m, se, absmean[n]);
        assert_true(fabs(m - absmean[n]) <= 4 * se + 5e-5);
    }
}

/* Hostile parameters (issue 11, item 14; pfnoise.h documents the rules):
 * the reported cases, then random mixes of huge, infinite and ordinary
 * coordinates with extreme octave counts, lacunarities, gains and filter
 * widths -- every result finite and inside the documented range. */
static void test_hostile(void **state)
{
    (void)state;
    /* the reported cases */
    float r = pf_fbm2f(0.3f, 0.4f, 129, 2.0f, 0.5f, 0.0f);
    assert_true(isfinite(r) && fabsf(r) <= PF_NOISE2_MAX);
    assert_true(r == pf_fbm2f(0.3f, 0.4f, PF_NOISE_MAX_OCTAVES, 2.0f, 0.5f, 0.0f)); /* clamped */
    r = pf_fbm3f(FLT_MAX, 1.0f, 2.0f, 8, 2.0f, 0.5f, 0.0f);
    assert_true(isfinite(r) && fabsf(r) <= PF_NOISE3_MAX);
    /* an overflowing octave counts as filtered out: octave 0 of FLT_MAX is
     * finite, octave 1 (f = 2) overflows */
    float n0 = pf_noise1f(FLT_MAX);
    assert_true(pf_fbm1f(FLT_MAX, 2, 2.0f, 0.5f, 0.0f) == n0 / 1.5f);
    assert_true(pf_turbulence1f(FLT_MAX, 2, 2.0f, 0.5f, 0.0f) ==
                (fabsf(n0) + 0.5f * PF_NOISE1_ABSMEAN) / 1.5f);
    /* NaN in, NaN out */
    assert_true(isnan(pf_fbm3f(NAN, 1.0f, 2.0f, 4, 2.0f, 0.5f, 0.0f)));
    assert_true(isnan(pf_fbm2f(1.0f, 2.0f, 4, NAN, 0.5f, 0.0f)));
    assert_true(isnan(pf_turbulence2f(1.0f, 2.0f, 4, 2.0f, INFINITY, 0.0f)));

    static const float coords[] = {FLT_MAX, -FLT_MAX, INFINITY, -INFINITY, 1e30f, -3e9f, 0.3f, 0.0f};
    static const int octs[] = {1, 8, 64, 65, 1000, INT_MAX, 0, -5};
    static const float lacs[] = {2.0f, 10.0f, 1e30f, INFINITY, 0.5f, -2.0f, 1.0f, 0.0f};
    static const float gains[] = {0.5f, 1.0f, 2.0f, 1e20f, FLT_MAX, -FLT_MAX, 0.0f, -1.5f};
    static const float fws[] = {0.0f, 0.01f, INFINITY, NAN, -1.0f, 1e-30f, 3.0f, 0.5f};
    int pts = quick ? 200 : 4000;
    for (int n = 1; n <= 4; n++)
        for (int i = 0; i < pts; i++) {
            float p[4];
            for (int k = 0; k < 4; k++)
                p[k] = coords[rnd() % 8];
            int oct = octs[rnd() % 8];
            float lac = lacs[rnd() % 8], gain = gains[rnd() % 8], fw = fws[rnd() % 8];
            float f = fbm(n, 0, p, oct, lac, gain, fw), t = fbm(n, 1, p, oct, lac, gain, fw);
            if (!(isfinite(f) && fabsf(f) <= maxes[n] && isfinite(t) && t >= 0.0f &&
                  t <= maxes[n]))
                fail_msg("%dD (%g %g %g %g) oct %d lac %g gain %g fw %g: fbm %g turb %g", n,
                         (double)p[0], (double)p[1], (double)p[2], (double)p[3], oct,
                         (double)lac, (double)gain, (double)fw, (double)f, (double)t);
        }
}

/* Gains above 1 (the sums rescale as they go): still the formula, summed
 * here in double, and finite where the plain float sum would overflow. */
static void test_large_gain(void **state)
{
    (void)state;
    static const double off[4] = {0.7548777, 0.5698403, 0.4301597, 0.3247179};
    double worst = 0;
    for (int n = 1; n <= 4; n++)
        for (int i = 0; i < 500; i++) {
            float p[4];
            for (int k = 0; k < 4; k++)
                p[k] = (float)urand(-5, 5);
            int oct = 1 + (int)(rnd() % 12);
            float lac = (float)urand(1.2, 1.9), gain = (float)urand(1.1, 40);
            double s = 0, norm = 0, a = 1;
            float f = 1;
            for (int k = 0; k < oct; k++) {
                float q[4];
                for (int j = 0; j < n; j++)
                    q[j] = p[j] * f + (float)k * (float)off[j];
                s += a * noise(n, q);
                norm += a;
                a *= gain;
                f *= lac;
            }
            worst = fmax(worst, fabs(s / norm - fbm(n, 0, p, oct, lac, gain, 0.0f)));
        }
    printf("# fbm vs formula, gain > 1: %.3g\n", worst);
    assert_true(worst < 1e-5);
    /* 1e20^40 overflows float (and double): the sum is the last octave's */
    float p[4] = {0.3f, 1.7f, 2.2f, 0.9f};
    for (int n = 1; n <= 4; n++) {
        float v = fbm(n, 0, p, 40, 1.01f, 1e20f, 0.0f);
        assert_true(isfinite(v) && fabsf(v) <= maxes[n]);
    }
}

int main(void)
{
    quick = getenv("PF_QUICK") != NULL;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_ranges),        cmocka_unit_test(test_formula),
        cmocka_unit_test(test_band_weight),   cmocka_unit_test(test_filter_limits),
        cmocka_unit_test(test_absmean),       cmocka_unit_test(test_hostile),
        cmocka_unit_test(test_large_gain),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
