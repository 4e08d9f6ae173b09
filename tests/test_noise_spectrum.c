/* Band limit of the noise and of the filtered fractal sums, measured with a
 * radix-2 FFT written here (no new dependency).
 *
 * Noise: a 2D slice over one whole period (256 x 256 lattice units) at 8
 * samples per unit, so the sampled field is exactly periodic and the DFT has
 * no leakage; the share of the (non-DC) energy at radial frequency above
 * 1 cycle/unit must be < 6 % and above 2 cycles/unit < 0.1 %.
 *
 * fbm/turbulence with a filter width w: rows of one whole period sampled at
 * 128 samples/unit (lacunarity 2, so every octave is periodic in 256); a
 * sampling grid of spacing w aliases what lies above its Nyquist frequency
 * 1/(2w) along an axis, so the share of energy with |f_x| > 1/(2w) must be
 * < 0.1 %.  The same sums without the filter must exceed it (the test can
 * see aliasing). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "pfnoise.h"

/* In-place iterative radix-2 FFT of length n (a power of 2), stride s. */
static void fft(double *re, double *im, size_t n, size_t s)
{
    for (size_t i = 1, j = 0; i < n; i++) {
        size_t bit = n >> 1;
        for (; j & bit; bit >>= 1)
            j ^= bit;
        j |= bit;
        if (i < j) {
            double t = re[i * s];
            re[i * s] = re[j * s];
            re[j * s] = t;
            t = im[i * s];
            im[i * s] = im[j * s];
            im[j * s] = t;
        }
    }
    for (size_t len = 2; len <= n; len <<= 1) {
        double ang = -2 * M_PI / (double)len;
        for (size_t k = 0; k < len / 2; k++) {
            double wr = cos(ang * (double)k), wi = sin(ang * (double)k);
            for (size_t i = k; i < n; i += len) {
                size_t a = i * s, b = (i + len / 2) * s;
                double xr = re[b] * wr - im[b] * wi, xi = re[b] * wi + im[b] * wr;
                re[b] = re[a] - xr;
                im[b] = im[a] - xi;
                re[a] += xr;
                im[a] += xi;
            }
        }
    }
}

/* The FFT itself: a pure tone lands in one bin, and Parseval holds. */
static void test_fft(void **state)
{
    (void)state;
    enum { N = 1024 };
    static double re[N], im[N];
    double e = 0;
    for (int i = 0; i < N; i++) {
        re[i] = cos(2 * M_PI * 37 * i / N) + 0.5 * sin(2 * M_PI * 100 * i / N);
        im[i] = 0;
        e += re[i] * re[i];
    }
    fft(re, im, N, 1);
    double ef = 0;
    for (int i = 0; i < N; i++)
        ef += re[i] * re[i] + im[i] * im[i];
    assert_true(fabs(ef / N - e) < 1e-9 * e);
    assert_true(fabs(re[37] - N / 2.0) < 1e-9 && fabs(im[100] + N / 4.0) < 1e-9);
    assert_true(fabs(re[36]) < 1e-9 && fabs(im[36]) < 1e-9);
}

/* Shares of non-DC energy above f1 and f2 cycles/unit of an n x n field
 * covering `period` units, radially. */
static void radial_shares(double *re, double *im, size_t n, double period, double f1,
                          double f2, double *s1, double *s2)
{
    for (size_t r = 0; r < n; r++)
        fft(re + r * n, im + r * n, n, 1);
    for (size_t c = 0; c < n; c++)
        fft(re + c, im + c, n, n);
    double tot = 0, a1 = 0, a2 = 0;
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++) {
            if (!i && !j)
                continue;
            double ki = (double)(i < n / 2 ? (long)i : (long)i - (long)n) / period;
            double kj = (double)(j < n / 2 ? (long)j : (long)j - (long)n) / period;
            double f = sqrt(ki * ki + kj * kj), e = re[i * n + j] * re[i * n + j] +
                                                   im[i * n + j] * im[i * n + j];
            tot += e;
            a1 += f > f1 ? e : 0;
            a2 += f > f2 ? e : 0;
        }
    *s1 = a1 / tot;
    *s2 = a2 / tot;
}

static void slice_test(int dim)
{
    const size_t n = 2048; /* 8 samples per unit over the period 256 */
    double *re = malloc(n * n * sizeof *re), *im = calloc(n * n, sizeof *im);
    float *x = malloc(n * sizeof *x), *y = malloc(n * sizeof *y), *z = malloc(n * sizeof *z),
          *out = malloc(n * sizeof *out);
    assert_non_null(re);
    assert_non_null(im);
    for (size_t r = 0; r < n; r++) {
        for (size_t c = 0; c < n; c++) {
            x[c] = (float)c / 8.0f;
            y[c] = (float)r / 8.0f;
            z[c] = 0.37f;
        }
        if (dim == 2)
            pf_noise2f_array(NULL, out, x, y, n);
        else
            pf_noise3f_array(NULL, out, x, y, z, n);
        for (size_t c = 0; c < n; c++)
            re[r * n + c] = out[c];
    }
    double s1, s2;
    radial_shares(re, im, n, 256.0, 1.0, 2.0, &s1, &s2);
    printf("# %dD slice: energy above 1 cycle/unit %.3f %%, above 2 cycles/unit %.2e %%\n", dim,
           100 * s1, 100 * s2);
    assert_true(s1 < 0.06);
    assert_true(s2 < 0.001);
    free(re);
    free(im);
    free(x);
    free(y);
    free(z);
    free(out);
}

static void test_noise2_band(void **state)
{
    (void)state;
    slice_test(2);
}

static void test_noise3_band(void **state)
{
    (void)state;
    slice_test(3);
}

/* Share of energy with |f_x| > fn along rows of a 2D or 3D fbm/turbulence
 * slice: one period (256 units) per row at 128 samples/unit. */
static double row_share(int dim, int turb, int octaves, float gain, float fw, double fn)
{
    const size_t n = 32768;
    const int rows = 12;
    double *re = malloc(n * sizeof *re), *im = malloc(n * sizeof *im), tot = 0, hi = 0;
    for (int r = 0; r < rows; r++) {
        float y = 3.1f + 21.7f * (float)r, z = 0.43f + 1.9f * (float)r;
        double mean = 0;
        for (size_t c = 0; c < n; c++) {
            float x = (float)c / 128.0f;
            float v = dim == 2 ? (turb ? pf_turbulence2f(x, y, octaves, 2.0f, gain, fw)
                                       : pf_fbm2f(x, y, octaves, 2.0f, gain, fw))
                               : (turb ? pf_turbulence3f(x, y, z, octaves, 2.0f, gain, fw)
                                       : pf_fbm3f(x, y, z, octaves, 2.0f, gain, fw));
            re[c] = v;
            im[c] = 0;
            mean += v;
        }
        fft(re, im, n, 1);
        for (size_t k = 1; k < n; k++) {
            double f = (double)(k < n / 2 ? (long)k : (long)n - (long)k) / 256.0;
            double e = re[k] * re[k] + im[k] * im[k];
            tot += e;
            hi += f > fn ? e : 0;
        }
    }
    free(re);
    free(im);
    return hi / tot;
}

static void test_fbm_band(void **state)
{
    (void)state;
    /* footprints: a power of two (octaves switch off cleanly) and others
     * that leave one octave partly faded; gain 1 is the hardest case (the
     * top octaves carry as much energy as the bottom ones). */
    static const float widths[] = {1.0f / 32, 1.0f / 23, 1.0f / 12, 0.1f};
    static const float gains[] = {0.5f, 1.0f};
    for (int dim = 2; dim <= 3; dim++)
        for (int turb = 0; turb <= 1; turb++)
            for (size_t w = 0; w < sizeof widths / sizeof *widths; w++)
                for (size_t g = 0; g < 2; g++) {
                    if (turb && g == 0 && w % 2)
                        continue; /* keep the run short */
                    double fn = 0.5 / widths[w];
                    double s = row_share(dim, turb, 10, gains[g], widths[w], fn);
                    printf("# %s%dD gain %.1f width 1/%.1f: above Nyquist %.2e %%\n",
                           turb ? "turbulence" : "fbm", dim, gains[g], 1 / widths[w], 100 * s);
                    assert_true(s < 0.001);
                }
    /* unfiltered, the same sums alias: the measurement can fail */
    double s = row_share(2, 0, 10, 0.5f, 0.0f, 0.5 * 8);
    printf("# fbm2D unfiltered, Nyquist of width 1/8: %.2f %%\n", 100 * s);
    assert_true(s > 0.001);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_fft),
        cmocka_unit_test(test_noise2_band),
        cmocka_unit_test(test_noise3_band),
        cmocka_unit_test(test_fbm_band),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
