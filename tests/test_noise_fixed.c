/* pfnoise fixed point: the fade is pf_fx_horner32 with the formats that
 * fit/bitwidth.c derives (re-derived here and checked bit for bit), agreement
 * with the float noise within 1 LSB of fixed<15,15>, the frac-bits core,
 * array == scalar, lattice zeros and period 256, and golden hashes that pin
 * the bits across compilers, flags and CPUs (this test runs in the -O2 and
 * in the -O1 sanitizer builds against the same constants). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bitwidth.h"
#include "pffixed.h"
#include "pfnoise.h"

static int quick;

static uint64_t rng_state = 0x13198a2e03707344u;
static uint64_t rnd(void)
{
    uint64_t z = (rng_state += 0x9e3779b97f4a7c15u);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
    return z ^ (z >> 31);
}

static int32_t qn(int n, const int32_t *q, int frac)
{
    switch (n) {
    case 1: return pf_noise1_q(NULL, q[0], frac);
    case 2: return pf_noise2_q(NULL, q[0], q[1], frac);
    case 3: return pf_noise3_q(NULL, q[0], q[1], q[2], frac);
    default: return pf_noise4_q(NULL, q[0], q[1], q[2], q[3], frac);
    }
}

static int16_t q15(int n, const int32_t *q)
{
    switch (n) {
    case 1: return pf_noise1_q15(q[0]);
    case 2: return pf_noise2_q15(q[0], q[1]);
    case 3: return pf_noise3_q15(q[0], q[1], q[2]);
    default: return pf_noise4_q15(q[0], q[1], q[2], q[3]);
    }
}

/* The float noise at the same point: Q16.16 -> float is exact for the low
 * 24 bits, and dropping the higher bits is a multiple of the period 256. */
static float fl(int n, const int32_t *q)
{
    float p[4];
    for (int k = 0; k < n; k++)
        p[k] = (float)((int32_t)((uint32_t)q[k] << 8) >> 8) / 65536.0f;
    switch (n) {
    case 1: return pf_noise1f(p[0]);
    case 2: return pf_noise2f(p[0], p[1]);
    case 3: return pf_noise3f(p[0], p[1], p[2]);
    default: return pf_noise4f(p[0], p[1], p[2], p[3]);
    }
}

/* Fade formats from pf_bw_horner: coefficients of 6t⁵ − 15t⁴ + 10t³ as
 * exact fixed<4,0>, t unsigned fixed<16,16>, result fixed<23,23> — the
 * finest result format whose every step fits pf_fx_horner32's 31 bits. */
static int32_t fade_c[6];
static int8_t fade_s[5];

static int derive_fade(int out_exp, int *widest)
{
    static const int coef[6] = {0, 0, 0, 10, -15, 6};
    pf_type c[6], x = pf_type_fixed(0, 16, 16), out = pf_type_fixed(1, out_exp, out_exp);
    pf_bw_step st[6];
    for (int i = 0; i < 6; i++)
        c[i] = pf_type_fixed(1, 4, 0);
    if (pf_bw_horner(c, 5, x, out, st))
        return -1;
    *widest = 0;
    for (int k = 0; k <= 5; k++) {
        *widest = st[k].p.size > *widest ? st[k].p.size : *widest;
        fade_c[k] = coef[k] * (1 << st[k].p.exp);
        if (k < 5)
            fade_s[k] = (int8_t)st[k].shift;
    }
    return 0;
}

static void test_fade_formats(void **state)
{
    (void)state;
    int widest;
    assert_int_equal(derive_fade(24, &widest), 0);
    assert_true(widest > 31); /* one bit finer no longer fits int32 */
    assert_int_equal(derive_fade(23, &widest), 0);
    assert_true(widest <= 31);
    /* 1D noise rebuilt from pf_fx_horner32 with those formats must equal the
     * library bit for bit, for every one of the 2^16 fractions. */
    const pf_noise_table *t = pf_noise_default_table();
    double worst_fade = 0;
    for (int cell = -3; cell <= 3; cell++) {
        for (int32_t frac = 0; frac < 65536; frac++) {
            int32_t x = cell * 65536 + frac;
            int32_t f = pf_fx_horner32(frac, fade_c, fade_s, 5);
            double tt = frac / 65536.0;
            worst_fade = fmax(worst_fade, fabs(f * 0x1p-23 - tt * tt * tt * (tt * (tt * 6 - 15) + 10)));
            uint32_t code = t->g1[(uint32_t)cell & 255u];
            int32_t n0 = ((int32_t)(code & 31) - 8) * (frac * 1024);
            int32_t n1 = ((int32_t)((code >> 16) & 31) - 8) * ((frac - 65536) * 1024);
            int32_t ref = n0 + pf_mulshift32(f, n1 - n0, 23);
            if (pf_noise1_q(NULL, x, 28) != ref)
                fail_msg("x = %d: %d != %d", x, pf_noise1_q(NULL, x, 28), ref);
        }
    }
    printf("# fixed fade: max error %.3g (2^%.1f)\n", worst_fade, log2(worst_fade));
    assert_true(worst_fade < 0x1p-21);
}

/* Within 1 LSB of round(float·2^15) saturated to int16: the fixed result is
 * < 2^-17 from the exact noise (pfnoise_fixed.c), the float one ~1e-6. */
static void test_agrees_with_float(void **state)
{
    (void)state;
    int n_pts = quick ? 1 << 14 : 1 << 20;
    for (int n = 1; n <= 4; n++) {
        int worst = 0;
        long saturated = 0;
        double worst28 = 0;
        for (int i = 0; i < n_pts; i++) {
            int32_t q[4];
            for (int k = 0; k < 4; k++)
                q[k] = (int32_t)(uint32_t)rnd();
            float f = fl(n, q);
            double e = rint((double)f * 32768.0);
            if (e > 32767 || e < -32768)
                saturated++;
            e = fmin(32767, fmax(-32768, e));
            int d = abs((int)e - q15(n, q));
            worst = d > worst ? d : worst;
            worst28 = fmax(worst28, fabs(qn(n, q, 28) * 0x1p-28 - f));
        }
        printf("# %dD: max |q15 - float| = %d LSB, |Q28 - float| = %.3g, %ld saturated\n", n,
               worst, worst28, saturated);
        assert_true(worst <= 1);
        assert_true(worst28 <= 3e-6);
    }
}

/* The frac-bits core is one RNE of the Q28 value; saturation only in the
 * Q0.15 form. */
static void test_frac_core(void **state)
{
    (void)state;
    for (int i = 0; i < 20000; i++) {
        int32_t q[4];
        for (int k = 0; k < 4; k++)
            q[k] = (int32_t)(uint32_t)rnd();
        int n = 1 + (int)(rnd() % 4);
        int32_t v28 = qn(n, q, 28);
        for (int frac = 0; frac <= 28; frac++) {
            int64_t r = pf_fx_convert(v28, pf_fmt_make(1, 31, 28), pf_fmt_make(1, 31, frac));
            assert_int_equal(qn(n, q, frac), r);
        }
        int64_t r15 = pf_fx_convert(v28, pf_fmt_make(1, 31, 28), pf_fmt_make(1, 15, 15));
        assert_int_equal(q15(n, q), r15);
    }
    /* out-of-range frac clamps */
    int32_t q[4] = {12345, 67890, -55555, 31337};
    assert_int_equal(qn(3, q, -5), qn(3, q, 0));
    assert_int_equal(qn(3, q, 40), qn(3, q, 28));
}

static void test_array_equals_scalar(void **state)
{
    (void)state;
    enum { LEN = 777 };
    static int32_t x[LEN], y[LEN], z[LEN], o32[LEN];
    static int16_t o16[LEN];
    for (int i = 0; i < LEN; i++) {
        x[i] = (int32_t)(uint32_t)rnd();
        y[i] = (int32_t)(uint32_t)rnd();
        z[i] = (int32_t)(uint32_t)rnd();
    }
    pf_noise2_q15_array(NULL, o16, x, y, LEN);
    for (int i = 0; i < LEN; i++)
        assert_int_equal(o16[i], pf_noise2_q15(x[i], y[i]));
    pf_noise3_q15_array(NULL, o16, x, y, z, LEN);
    for (int i = 0; i < LEN; i++)
        assert_int_equal(o16[i], pf_noise3_q15(x[i], y[i], z[i]));
    for (int frac = 0; frac <= 28; frac += 7) {
        pf_noise2_q_array(NULL, o32, x, y, LEN, frac);
        for (int i = 0; i < LEN; i++)
            assert_int_equal(o32[i], pf_noise2_q(NULL, x[i], y[i], frac));
        pf_noise3_q_array(NULL, o32, x, y, z, LEN, frac);
        for (int i = 0; i < LEN; i++)
            assert_int_equal(o32[i], pf_noise3_q(NULL, x[i], y[i], z[i], frac));
    }
    /* a seeded table */
    pf_noise_table t;
    pf_noise_table_seed(&t, 7);
    pf_noise3_q_array(&t, o32, x, y, z, LEN, 28);
    for (int i = 0; i < LEN; i++)
        assert_int_equal(o32[i], pf_noise3_q(&t, x[i], y[i], z[i], 28));
}

static void test_lattice_and_period(void **state)
{
    (void)state;
    for (int n = 1; n <= 4; n++) {
        for (int i = 0; i < 20000; i++) {
            int32_t q[4], r[4];
            for (int k = 0; k < 4; k++)
                q[k] = (int32_t)((uint32_t)rnd() & 0xffff0000u); /* integers */
            assert_int_equal(qn(n, q, 28), 0);
            for (int k = 0; k < 4; k++)
                q[k] = (int32_t)(uint32_t)rnd();
            memcpy(r, q, sizeof r);
            int ax = (int)(rnd() % (uint64_t)n); /* + 256k, wrapping like the hardware */
            r[ax] = (int32_t)((uint32_t)r[ax] + (uint32_t)((rnd() % 64) << 24));
            assert_int_equal(qn(n, q, 28), qn(n, r, 28));
        }
    }
}

/* The 2D bound is attained: a permutation that gives the cell at the origin
 * gradients (1,1), (-1,1), (1,-1), (-1,-1) pointing at its centre makes
 * n(1/2, 1/2) = 1 exactly, in float and in Q28, and the Q0.15 form
 * saturates to 32767 there. */
static void test_bound_attained_and_saturation(void **state)
{
    (void)state;
    /* 2D hash p[p[X] + Y], gradient h & 7: 0 (1,1), 1 (-1,1), 2 (1,-1), 3 (-1,-1) */
    static const int want[][2] = {{0, 10}, {1, 20}, {10, 8}, {11, 2}, {20, 1}, {21, 3}};
    uint8_t perm[256];
    int used_i[256] = {0}, used_v[256] = {0};
    for (size_t k = 0; k < sizeof want / sizeof *want; k++) {
        perm[want[k][0]] = (uint8_t)want[k][1];
        used_i[want[k][0]] = used_v[want[k][1]] = 1;
    }
    for (int i = 0, v = 0; i < 256; i++) {
        if (used_i[i])
            continue;
        while (used_v[v])
            v++;
        perm[i] = (uint8_t)v;
        used_v[v] = 1;
    }
    pf_noise_table t;
    assert_int_equal(pf_noise_table_init(&t, perm), 0);
    assert_true(pf_noise2f_t(&t, 0.5f, 0.5f) == 1.0f);
    assert_int_equal(pf_noise2_q(&t, 32768, 32768, 28), 1 << 28);
    assert_int_equal(pf_noise2_q(&t, 32768, 32768, 15), 32768);
    int16_t o;
    int32_t x = 32768, y = 32768;
    pf_noise2_q15_array(&t, &o, &x, &y, 1);
    assert_int_equal(o, 32767);
}

/* FNV-1a over the Q28 and Q0.15 results on a fixed scatter of 4096 points
 * per dimension covering the whole int32 input range.  The constants pin
 * the bit patterns: they may change only with a deliberate change of the
 * fixed-point algorithm (then the agreement tests above must still pass). */
static uint64_t fnv(uint64_t h, uint32_t v)
{
    for (int b = 0; b < 4; b++) {
        h ^= (v >> (8 * b)) & 0xff;
        h *= 0x100000001b3u;
    }
    return h;
}

static void test_golden_hashes(void **state)
{
    (void)state;
    static const uint64_t golden[5] = {0, 0x1e1d94d3b872e423u, 0xd92f9f2fb3ceeaefu,
                                       0xcf5550c8c5986efbu, 0x580df2da118c70cfu};
    int ok = 1;
    for (int n = 1; n <= 4; n++) {
        uint64_t h = 0xcbf29ce484222325u;
        for (uint32_t i = 0; i < 4096; i++) {
            int32_t q[4];
            for (int k = 0; k < 4; k++)
                q[k] = (int32_t)(i * 2654435761u ^ ((uint32_t)k * 0x9e3779b9u + (i << 7)));
            h = fnv(h, (uint32_t)qn(n, q, 28));
            h = fnv(h, (uint32_t)(uint16_t)q15(n, q));
        }
        printf("# %dD golden hash 0x%016llxu\n", n, (unsigned long long)h);
        ok &= h == golden[n];
    }
    assert_true(ok);
}

int main(void)
{
    quick = getenv("PF_QUICK") != NULL;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_fade_formats),        cmocka_unit_test(test_agrees_with_float),
        cmocka_unit_test(test_frac_core),           cmocka_unit_test(test_array_equals_scalar),
        cmocka_unit_test(test_lattice_and_period),  cmocka_unit_test(test_golden_hashes),
        cmocka_unit_test(test_bound_attained_and_saturation),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
