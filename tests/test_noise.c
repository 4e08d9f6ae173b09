/* pfnoise float evaluators: Perlin's published reference value, agreement
 * with a plain port of his code, lattice zeros, documented ranges (with the
 * bound itself recomputed from the library's gradient tables), mean,
 * C1 continuity, analytic gradients vs finite differences, array == scalar,
 * period 256, permutation tables.  PF_QUICK=1 (sanitizer runs) shrinks the
 * random samples. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "noise_baseline.h"
#include "pfnoise.h"

static int quick;

static uint64_t rng_state = 0x243f6a8885a308d3u;
static uint64_t rnd(void) /* splitmix64 */
{
    uint64_t z = (rng_state += 0x9e3779b97f4a7c15u);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
    return z ^ (z >> 31);
}
/* uniform in [lo, hi) */
static double urand(double lo, double hi) { return lo + (hi - lo) * (double)(rnd() >> 11) * 0x1p-53; }

static const float maxes[5] = {0, PF_NOISE1_MAX, PF_NOISE2_MAX, PF_NOISE3_MAX, PF_NOISE4_MAX};

static float eval(int n, const float *p)
{
    switch (n) {
    case 1: return pf_noise1f(p[0]);
    case 2: return pf_noise2f(p[0], p[1]);
    case 3: return pf_noise3f(p[0], p[1], p[2]);
    default: return pf_noise4f(p[0], p[1], p[2], p[3]);
    }
}

static float eval_d(int n, const float *p, float *g)
{
    switch (n) {
    case 1: return pf_noise1f_d(p[0], g);
    case 2: return pf_noise2f_d(p[0], p[1], g);
    case 3: return pf_noise3f_d(p[0], p[1], p[2], g);
    default: return pf_noise4f_d(p[0], p[1], p[2], p[3], g);
    }
}

static void eval_array(int n, float *out, float *const *p, size_t len)
{
    switch (n) {
    case 1: pf_noise1f_array(NULL, out, p[0], len); break;
    case 2: pf_noise2f_array(NULL, out, p[0], p[1], len); break;
    case 3: pf_noise3f_array(NULL, out, p[0], p[1], p[2], len); break;
    default: pf_noise4f_array(NULL, out, p[0], p[1], p[2], p[3], len); break;
    }
}

/* Perlin, "Improving Noise" (2002), reference Java code: noise(3.14, 42, 7)
 * = 0.13691995878400012.  The double port must give it to the last bits;
 * the float function sees 3.14f (3.14 + 1.05e-7), and |∂n/∂x| <= 4, so it
 * may differ by 4.2e-7 plus its own rounding (~1e-6, see next test). */
static void test_perlin_reference(void **state)
{
    (void)state;
    const double ref = 0.13691995878400012;
    noise_baseline_set_perm(NULL);
    assert_true(fabs(noise_baseline3(3.14, 42, 7) - ref) <= 1e-15);
    assert_true(fabs(pf_noise3f(3.14f, 42.0f, 7.0f) - ref) <= 2e-6);
    /* the same through a user-supplied permutation */
    pf_noise_table t;
    assert_int_equal(pf_noise_table_init(&t, pf_noise_perlin_perm), 0);
    assert_true(fabs(pf_noise3f_t(&t, 3.14f, 42.0f, 7.0f) - ref) <= 2e-6);
    assert_memory_equal(&t, pf_noise_default_table(), sizeof t);
}

/* The branch-free 3D evaluator against the line-by-line port (double, same
 * float inputs), for the default and for seeded permutations.  Float
 * rounding: terms of size <= 3 are added a handful of times (ulp 2.4e-7). */
static void test_vs_baseline(void **state)
{
    (void)state;
    int n = quick ? 20000 : 400000;
    for (int s = 0; s < 3; s++) {
        /* s == 0: the library's default table against the port's own copy
         * of Perlin's permutation (a typo in either shows up here) */
        pf_noise_table t = *pf_noise_default_table();
        if (s != 0)
            pf_noise_table_seed(&t, (uint64_t)s * 12345u);
        noise_baseline_set_perm(s ? t.perm : NULL);
        double worst = 0;
        for (int i = 0; i < n; i++) {
            float x = (float)urand(-1000, 1000), y = (float)urand(-1000, 1000),
                  z = (float)urand(-1000, 1000);
            double e = fabs(pf_noise3f_t(&t, x, y, z) - noise_baseline3(x, y, z));
            if (e > worst)
                worst = e;
        }
        /* the fixed-point core at the same points (Q16.16 is exact in
         * double): pfnoise_fixed.c bounds its Q28 error by 2^-17 */
        double worst_q = 0;
        for (int i = 0; i < n / 4; i++) {
            int32_t q[3];
            for (int k = 0; k < 3; k++)
                q[k] = (int32_t)(rnd() % 0x7ffffffu) - 0x3ffffff;
            double e = fabs(pf_noise3_q(&t, q[0], q[1], q[2], 28) * 0x1p-28 -
                            noise_baseline3(q[0] / 65536.0, q[1] / 65536.0, q[2] / 65536.0));
            worst_q = fmax(worst_q, e);
        }
        printf("# seed %d: max |float - Perlin port| = %.3g, |Q28 - port| = %.3g\n", s, worst,
               worst_q);
        assert_true(worst <= 4e-6);
        assert_true(worst_q <= 0x1p-17);
    }
    noise_baseline_set_perm(NULL);
}

static void test_lattice_zero(void **state)
{
    (void)state;
    for (int n = 1; n <= 4; n++) {
        for (int i = 0; i < 20000; i++) {
            float p[4], g[4];
            for (int k = 0; k < 4; k++)
                p[k] = (float)((int64_t)(rnd() % 2000001) - 1000000);
            assert_true(eval(n, p) == 0.0f);
            assert_true(eval_d(n, p, g) == 0.0f);
        }
    }
}

/* ≥ 2^22 random points per dimension inside [-MAX, MAX] (the bound B of
 * pfnoise_table.c); the largest |n| seen must also come near the bound for
 * 1D-3D (a wrongly scaled function would pass the first check), and the mean
 * must be 0 within 5 standard errors (the exact mean over a period is 0:
 * each gradient's contributions to its 2^N cells cancel by reflection). */
static void test_range_and_mean(void **state)
{
    (void)state;
    /* Observed maxima need the worst gradient combination in some cell: near
     * certain in 1D/2D, likely close in 3D, hopeless for 16 corners in 4D. */
    static const float reach[5] = {0, 0.99f, 0.98f, 0.95f, 0.70f};
    size_t len = quick ? (size_t)1 << 18 : (size_t)1 << 22;
    float *p[4], *out = malloc(len * sizeof *out);
    for (int k = 0; k < 4; k++)
        p[k] = malloc(len * sizeof *p[k]);
    for (int n = 1; n <= 4; n++) {
        for (size_t i = 0; i < len; i++)
            for (int k = 0; k < n; k++)
                p[k][i] = (float)urand(0, 256);
        eval_array(n, out, p, len);
        double mx = 0, sum = 0, sum2 = 0;
        for (size_t i = 0; i < len; i++) {
            double v = out[i];
            mx = fmax(mx, fabs(v));
            sum += v;
            sum2 += v * v;
        }
        double mean = sum / (double)len, sd = sqrt(sum2 / (double)len - mean * mean);
        printf("# %dD: max|n| %.6f (bound %.4f), mean %.2e, sd %.4f\n", n, mx, maxes[n], mean,
               sd);
        assert_true(mx <= maxes[n]);
        if (!quick)
            assert_true(mx >= reach[n]);
        assert_true(fabs(mean) <= 5 * sd / sqrt((double)len));
    }
    for (int k = 0; k < 4; k++)
        free(p[k]);
    free(out);
}

/* The bound itself: B(t) = Σ_c W_c(t)·max_g g·(t − c) over the gradient set
 * read back from the library's own code tables (so a changed gradient set
 * or scale is caught).  Grid search over [0, 1/2]^N (B is symmetric under
 * t_i -> 1 − t_i), then coordinate ascent from the best point; the sup must
 * lie within 2e-4 below the documented constant (tight) and not above it. */
static double fade_d(double t) { return t * t * t * (t * (t * 6 - 15) + 10); }

static int gset[5][32][4], gcount[5];
static double gscale[5];

static void load_gradients(void)
{
    const pf_noise_table *t = pf_noise_default_table();
    gscale[1] = 0.25;
    gscale[2] = 1;
    gscale[3] = 1;
    gscale[4] = 2.0 / 3.0;
    for (int n = 1; n <= 4; n++) {
        gcount[n] = 0;
        for (int i = 0; i < 256; i++) {
            uint32_t code = (n == 1 ? t->g1 : n == 2 ? t->g2 : n == 3 ? t->g3 : t->g4)[i] & 0xffff;
            int g[4] = {0, 0, 0, 0};
            if (n == 1)
                g[0] = (int)(code & 31) - 8;
            else
                for (int k = 0; k < n; k++)
                    g[k] = (int)((code >> (2 * k)) & 3) - 1;
            int seen = 0;
            for (int j = 0; j < gcount[n]; j++)
                seen |= !memcmp(gset[n][j], g, sizeof g);
            if (!seen && gcount[n] < 32)
                memcpy(gset[n][gcount[n]++], g, sizeof g);
        }
    }
}

static double bound_B(int n, const double *t)
{
    double s = 0;
    for (int c = 0; c < (1 << n); c++) {
        double w = 1, d[4], best = -1e9;
        for (int i = 0; i < n; i++) {
            int b = (c >> i) & 1;
            double f = fade_d(t[i]);
            w *= b ? f : 1 - f;
            d[i] = t[i] - b;
        }
        for (int j = 0; j < gcount[n]; j++) {
            double v = 0;
            for (int i = 0; i < n; i++)
                v += gset[n][j][i] * d[i];
            best = fmax(best, v);
        }
        s += w * best;
    }
    return s * gscale[n];
}

static void test_range_bound(void **state)
{
    (void)state;
    load_gradients();
    assert_int_equal(gcount[1], 16);
    assert_int_equal(gcount[2], 8);
    assert_int_equal(gcount[3], 12);
    assert_int_equal(gcount[4], 32);
    for (int n = 1; n <= 4; n++) {
        int steps = n == 1 ? 512 : n == 2 ? 128 : n == 3 ? 48 : 16;
        double best = -1, bt[4] = {0}, t[4];
        long total = 1;
        for (int i = 0; i < n; i++)
            total *= steps + 1;
        for (long k = 0; k < total; k++) {
            long r = k;
            for (int i = 0; i < n; i++) {
                t[i] = 0.5 * (double)(r % (steps + 1)) / steps;
                r /= steps + 1;
            }
            double v = bound_B(n, t);
            if (v > best) {
                best = v;
                memcpy(bt, t, sizeof bt);
            }
        }
        for (double h = 0.5 / steps; h > 1e-9; h *= 0.5) {
            for (int improved = 1; improved;) {
                improved = 0;
                for (int i = 0; i < n; i++)
                    for (int sgn = -1; sgn <= 1; sgn += 2) {
                        double old = bt[i];
                        bt[i] = fmin(1, fmax(0, old + sgn * h));
                        double v = bound_B(n, bt);
                        if (v > best + 1e-15) {
                            best = v;
                            improved = 1;
                        } else
                            bt[i] = old;
                    }
            }
        }
        printf("# %dD: sup B = %.7f (documented %.4f)\n", n, best, maxes[n]);
        assert_true(best <= maxes[n]);
        assert_true(best >= maxes[n] - 2e-4);
    }
}

/* C1 across cell faces: one-sided difference quotients from both sides of
 * an integer coordinate agree to O(h), and so do the analytic gradients
 * just inside each cell.  A C0-only blend (or a hash mismatch between the
 * two cells, which breaks even continuity) fails by O(1). */
static void test_c1_continuity(void **state)
{
    (void)state;
    const float h = 0x1p-12f;
    double worst_fd = 0, worst_an = 0, worst_v = 0;
    for (int n = 1; n <= 4; n++) {
        for (int i = 0; i < 4000; i++) {
            float p[4], g0[4], g1[4];
            for (int k = 0; k < n; k++)
                p[k] = (float)(int)urand(-300, 300) + (float)((rnd() & 1023) * 0x1p-10);
            int ax = (int)(rnd() % (uint64_t)n);
            p[ax] = (float)(int)urand(-300, 300); /* on a cell face */
            float m[4], q[4];
            memcpy(m, p, sizeof m);
            memcpy(q, p, sizeof q);
            m[ax] -= h;
            q[ax] += h;
            double v = eval(n, p), left = (v - eval(n, m)) / h, right = (eval(n, q) - v) / h;
            worst_fd = fmax(worst_fd, fabs(left - right));
            eval_d(n, m, g0);
            eval_d(n, q, g1);
            for (int k = 0; k < n; k++)
                worst_an = fmax(worst_an, fabs(g0[k] - g1[k]));
            worst_v = fmax(worst_v, fabs(eval(n, m) - eval(n, q)));
        }
    }
    printf("# faces: |left - right| quotient %.3g, analytic %.3g, value %.3g\n", worst_fd,
           worst_an, worst_v);
    /* |∂²n| <= ~40, so the quotients differ by <= 40·h plus rounding/h. */
    assert_true(worst_fd <= 0.05);
    assert_true(worst_an <= 0.05);
    assert_true(worst_v <= 0.01);
}

/* Analytic gradient vs central differences at points on a 2^-12 grid (so
 * x ± h is exact): truncation h²/6·|∂³n| (~7e-5 with |∂³n| <= 100) plus
 * float rounding of n (~1e-6) / 2h (~3e-4). */
static void test_gradient_fd(void **state)
{
    (void)state;
    const float h = 0x1p-9f;
    double worst = 0, worst_val = 0;
    int n_pts = quick ? 2000 : 20000;
    for (int n = 1; n <= 4; n++) {
        for (int i = 0; i < n_pts; i++) {
            float p[4], g[4];
            for (int k = 0; k < n; k++)
                p[k] = (float)((int)urand(-4096 * 100, 4096 * 100)) * 0x1p-12f;
            float v = eval_d(n, p, g);
            worst_val = fmax(worst_val, fabs(v - eval(n, p)));
            for (int k = 0; k < n; k++) {
                float a[4], b[4];
                memcpy(a, p, sizeof a);
                memcpy(b, p, sizeof b);
                a[k] += h;
                b[k] -= h;
                double fd = ((double)eval(n, a) - eval(n, b)) / (2 * h);
                worst = fmax(worst, fabs(fd - g[k]));
            }
        }
    }
    printf("# gradient vs central difference: %.3g; value of _d vs plain: %.3g\n", worst,
           worst_val);
    assert_true(worst <= 1e-3);
    assert_true(worst_val <= 2e-6);
}

/* Array forms use the same code as the scalar ones and no FMA contraction:
 * bit-identical, for a length that leaves a vector remainder, for inputs
 * of every sign and size, and in place. */
static void test_array_equals_scalar(void **state)
{
    (void)state;
    enum { LEN = 1003 };
    static float p[4][LEN], out[LEN];
    float *pp[4] = {p[0], p[1], p[2], p[3]};
    for (int n = 1; n <= 4; n++) {
        for (int i = 0; i < LEN; i++)
            for (int k = 0; k < 4; k++)
                p[k][i] = (float)(i % 3 == 0 ? urand(-1e6, 1e6) : urand(-300, 300));
        eval_array(n, out, pp, LEN);
        for (int i = 0; i < LEN; i++) {
            float q[4] = {p[0][i], p[1][i], p[2][i], p[3][i]};
            float s = eval(n, q);
            assert_memory_equal(&s, &out[i], sizeof s);
        }
        /* in place: out == x */
        float ref0 = out[7];
        eval_array(n, p[0], pp, LEN);
        assert_memory_equal(&ref0, &p[0][7], sizeof ref0);
    }
}

/* Period 256 in every coordinate (coordinates on a 2^-8 grid, so x + 256k
 * is exact), and with a seeded table too. */
static void test_period(void **state)
{
    (void)state;
    pf_noise_table t;
    pf_noise_table_seed(&t, 99);
    for (int n = 1; n <= 4; n++) {
        for (int i = 0; i < 5000; i++) {
            float p[4], q[4];
            for (int k = 0; k < 4; k++)
                p[k] = (float)((int)urand(-256 * 1000, 256 * 1000)) * 0x1p-8f;
            memcpy(q, p, sizeof q);
            int ax = (int)(rnd() % (uint64_t)n);
            q[ax] += 256.0f * (float)((int)urand(-40, 40));
            assert_true(eval(n, p) == eval(n, q));
        }
        float a = pf_noise3f_t(&t, 1.25f, 7.5f, -3.75f), b = pf_noise3f_t(&t, 257.25f, 7.5f, 252.25f);
        assert_true(a == b);
    }
}

static void test_tables(void **state)
{
    (void)state;
    pf_noise_table t, u;
    uint8_t bad[256];
    memcpy(bad, pf_noise_perlin_perm, 256);
    bad[17] = bad[18];
    memset(&t, 0x5a, sizeof t);
    assert_int_equal(pf_noise_table_init(&t, bad), -1);
    assert_int_equal(t.perm[0], 0x5a); /* untouched */
    pf_noise_table_seed(&t, 1);
    pf_noise_table_seed(&u, 2);
    int seen[256] = {0}, differ = 0;
    for (int i = 0; i < 256; i++) {
        seen[t.perm[i]]++;
        differ += t.perm[i] != u.perm[i];
    }
    for (int i = 0; i < 256; i++)
        assert_int_equal(seen[i], 1);
    assert_true(differ > 200);
    pf_noise_table_seed(&u, 1);
    assert_memory_equal(&t, &u, sizeof t); /* deterministic */
    /* a seeded table changes the function, and init() of its perm rebuilds it */
    assert_true(pf_noise2f_t(&t, 0.5f, 0.5f) != pf_noise2f(0.5f, 0.5f) ||
                pf_noise2f_t(&t, 3.5f, 1.5f) != pf_noise2f(3.5f, 1.5f));
    pf_noise_table v;
    assert_int_equal(pf_noise_table_init(&v, t.perm), 0);
    assert_memory_equal(&t, &v, sizeof t);
}

int main(void)
{
    quick = getenv("PF_QUICK") != NULL;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_perlin_reference), cmocka_unit_test(test_vs_baseline),
        cmocka_unit_test(test_lattice_zero),     cmocka_unit_test(test_range_and_mean),
        cmocka_unit_test(test_range_bound),      cmocka_unit_test(test_c1_continuity),
        cmocka_unit_test(test_gradient_fd),      cmocka_unit_test(test_array_equals_scalar),
        cmocka_unit_test(test_period),           cmocka_unit_test(test_tables),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
