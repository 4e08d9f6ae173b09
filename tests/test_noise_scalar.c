/* The scalar noise forms against the array forms, and the table argument.
 *
 * The scalar forms are a separate body built for one point at a time
 * (corners in vector lanes, pfnoise_impl.h); their contract is to be
 * bit-identical to the array forms, which are the reference here: the
 * same default or seeded table, every dimension, points drawn from random
 * ranges and from special values (±0, subnormals, cell edges, 2^22..2^24
 * where floats become integers, huge values, ±inf, NaN) mixed per
 * coordinate.  NaN results must be NaN on both sides (payloads are not
 * part of the contract).
 *
 * A NULL table means the default one in every _t form (issue 11, item 7).
 * PF_QUICK=1 (sanitizer runs) shrinks the samples. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "pfnoise.h"
#include "pfnoise_impl.h"

static int quick;

/* 3D has several scalar bodies (SSE2 and, on x86-64-v3/v4 CPUs, AVX2
 * compiled for each, picked at load time); body3 = 0 checks the public
 * entry points, 1 the SSE2 body, 2 and 3 the AVX2 body's v3 and v4
 * compilations (only where the CPU has them). */
static int body3;

static uint64_t rng_state = 0x9e3779b97f4a7c15u;
static uint64_t rnd(void) /* splitmix64 */
{
    uint64_t z = (rng_state += 0x9e3779b97f4a7c15u);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
    return z ^ (z >> 31);
}
static double urand(double lo, double hi) { return lo + (hi - lo) * (double)(rnd() >> 11) * 0x1p-53; }

static float special(void)
{
    static const float v[] = {0.0f, -0.0f, 0x1p-149f, -0x1p-149f, 0x1p-126f, 1e-30f, -1e-30f,
                              0x1.fffffep-110f, -0x1.234566p-112f,
                              0.5f, -0.5f, 1.0f, -1.0f, 0x1.fffffep-1f, -0x1.fffffep-1f,
                              255.0f, 256.0f, -256.0f, 0x1p22f - 0.5f, 0x1p22f, -0x1p22f,
                              0x1p23f - 0.5f, 0x1p23f, -0x1p23f, 0x1p23f + 1.0f, 0x1p24f + 2.0f,
                              -0x1p24f - 2.0f, 1e30f, -1e30f, FLT_MAX, -FLT_MAX, INFINITY,
                              -INFINITY, NAN, -NAN};
    return v[rnd() % (sizeof v / sizeof v[0])];
}

static float coord(void)
{
    switch (rnd() % 8) {
    case 0: return special();
    case 1: { /* next to a lattice line, either side */
        float k = (float)((int)urand(-600, 600));
        return nextafterf(k, (rnd() & 1) ? INFINITY : -INFINITY);
    }
    case 2: return (float)urand(-1e7, 1e7);
    case 3: return (float)urand(-1e-3, 1e-3);
    default: return (float)urand(-300, 300);
    }
}

/* body3 = 2: the AVX2 body for x86-64-v3, 3: its x86-64-v4 compilation */
static float scalar3_avx2(const pf_noise_table *t, const float *p)
{
#if PF_NOISE3_DISPATCH
    if (body3 == 3)
        return pf_noise3f_t_avx512_(t, p[0], p[1], p[2]);
    return pf_noise3f_t_avx2_(t, p[0], p[1], p[2]);
#else
    (void)t, (void)p;
    return NAN; /* never called: has_body() is 0 */
#endif
}

static int has_body(int b)
{
#if PF_NOISE3_DISPATCH
    __builtin_cpu_init();
    return b == 1 || (b == 2 ? __builtin_cpu_supports("x86-64-v3")
                             : __builtin_cpu_supports("x86-64-v4"));
#else
    return b == 1;
#endif
}

static float scalar(const pf_noise_table *t, int n, const float *p)
{
    if (!t)
        switch (n) {
        case 1: return pf_noise1f(p[0]);
        case 2: return pf_noise2f(p[0], p[1]);
        case 3: return body3 == 1 ? pf_noise3f_sse2_(p[0], p[1], p[2])
                       : body3    ? scalar3_avx2(NULL, p)
                                  : pf_noise3f(p[0], p[1], p[2]);
        default: return pf_noise4f(p[0], p[1], p[2], p[3]);
        }
    if (n == 3 && body3)
        return body3 == 1 ? pf_noise3f_t_sse2_(t, p[0], p[1], p[2]) : scalar3_avx2(t, p);
    switch (n) {
    case 1: return pf_noise1f_t(t, p[0]);
    case 2: return pf_noise2f_t(t, p[0], p[1]);
    case 3: return pf_noise3f_t(t, p[0], p[1], p[2]);
    default: return pf_noise4f_t(t, p[0], p[1], p[2], p[3]);
    }
}

static void array(const pf_noise_table *t, int n, float *out, float *const *p, size_t len)
{
    switch (n) {
    case 1: pf_noise1f_array(t, out, p[0], len); break;
    case 2: pf_noise2f_array(t, out, p[0], p[1], len); break;
    case 3: pf_noise3f_array(t, out, p[0], p[1], p[2], len); break;
    default: pf_noise4f_array(t, out, p[0], p[1], p[2], p[3], len); break;
    }
}

static int same(float a, float b)
{
    if (isnan(a) || isnan(b))
        return isnan(a) && isnan(b);
    return memcmp(&a, &b, sizeof a) == 0;
}

/* dimensions lo..hi */
static void check_table(const pf_noise_table *t, int lo, int hi)
{
    enum { LEN = 4096 };
    static float p[4][LEN], out[LEN];
    float *pp[4] = {p[0], p[1], p[2], p[3]};
    int rounds = quick ? 4 : 64; /* 2^18 points per dimension */
    for (int n = lo; n <= hi; n++)
        for (int r = 0; r < rounds; r++) {
            for (int i = 0; i < LEN; i++)
                for (int k = 0; k < 4; k++)
                    p[k][i] = coord();
            array(t, n, out, pp, LEN);
            for (int i = 0; i < LEN; i++) {
                float q[4] = {p[0][i], p[1][i], p[2][i], p[3][i]};
                float s = scalar(t, n, q);
                if (!same(s, out[i]))
                    fail_msg("%dD (%a, %a, %a, %a): scalar %a, array %a", n, (double)q[0],
                             (double)q[1], (double)q[2], (double)q[3], (double)s,
                             (double)out[i]);
            }
        }
}

/* Every combination of a few integral and half-integral coordinates, signed
 * zeros included: at lattice points the result is a signed zero, whose
 * sign must match too. */
static void check_lattice(const pf_noise_table *t, int lo, int hi)
{
    static const float v[] = {0.0f, -0.0f, 1.0f, -1.0f, 0.5f, -0.5f, 255.0f, -256.0f, 0x1p21f};
    enum { K = sizeof v / sizeof v[0], LEN = K * K * K * K };
    static float p[4][LEN], out[LEN];
    float *pp[4] = {p[0], p[1], p[2], p[3]};
    for (int i = 0; i < LEN; i++)
        for (int k = 0, j = i; k < 4; k++, j /= K)
            p[k][i] = v[j % K];
    for (int n = lo; n <= hi; n++) {
        array(t, n, out, pp, LEN);
        for (int i = 0; i < LEN; i++) {
            float q[4] = {p[0][i], p[1][i], p[2][i], p[3][i]};
            float s = scalar(t, n, q);
            if (!same(s, out[i]))
                fail_msg("%dD (%a, %a, %a, %a): scalar %a, array %a", n, (double)q[0],
                         (double)q[1], (double)q[2], (double)q[3], (double)s, (double)out[i]);
        }
    }
}

static void test_scalar_equals_array_default(void **state)
{
    (void)state;
    check_lattice(NULL, 1, 4);
    check_table(NULL, 1, 4);
}

static void test_scalar_equals_array_seeded(void **state)
{
    (void)state;
    static pf_noise_table t;
    pf_noise_table_seed(&t, 2026);
    check_lattice(&t, 1, 4);
    check_table(&t, 1, 4);
}

/* Each 3D body on its own (the public entry runs only one of them here). */
static void test_each_3d_body(void **state)
{
    (void)state;
    static pf_noise_table t;
    pf_noise_table_seed(&t, 7);
    for (body3 = 1; body3 <= 3; body3++) {
        if (!has_body(body3)) {
            print_message("no x86-64-v%d CPU: body %d not checked\n", body3 + 1, body3);
            continue;
        }
        check_lattice(NULL, 3, 3);
        check_table(NULL, 3, 3);
        check_lattice(&t, 3, 3);
        check_table(&t, 3, 3);
    }
    body3 = 0;
}

/* Perlin's reference value through every scalar entry of the 3D noise. */
static void test_reference_value(void **state)
{
    (void)state;
    float a = pf_noise3f(3.14f, 42.0f, 7.0f);
    assert_true(fabs(a - 0.13691995878400012) < 2e-6);
    assert_true(same(pf_noise3f_t(pf_noise_default_table(), 3.14f, 42.0f, 7.0f), a));
    assert_true(same(pf_noise3f_t(NULL, 3.14f, 42.0f, 7.0f), a));
}

/* NULL = the default table, for the value and the gradient forms. */
static void test_null_table(void **state)
{
    (void)state;
    for (int i = 0; i < (quick ? 200 : 5000); i++) {
        float x = (float)urand(-300, 300), y = (float)urand(-300, 300),
              z = (float)urand(-300, 300), w = (float)urand(-300, 300);
        assert_true(same(pf_noise1f_t(NULL, x), pf_noise1f(x)));
        assert_true(same(pf_noise2f_t(NULL, x, y), pf_noise2f(x, y)));
        assert_true(same(pf_noise3f_t(NULL, x, y, z), pf_noise3f(x, y, z)));
        assert_true(same(pf_noise4f_t(NULL, x, y, z, w), pf_noise4f(x, y, z, w)));
        float g[4], h[4];
        assert_true(same(pf_noise1f_d_t(NULL, x, g), pf_noise1f_d(x, h)));
        assert_true(same(g[0], h[0]));
        assert_true(same(pf_noise2f_d_t(NULL, x, y, g), pf_noise2f_d(x, y, h)));
        assert_memory_equal(g, h, 2 * sizeof g[0]);
        assert_true(same(pf_noise3f_d_t(NULL, x, y, z, g), pf_noise3f_d(x, y, z, h)));
        assert_memory_equal(g, h, 3 * sizeof g[0]);
        assert_true(same(pf_noise4f_d_t(NULL, x, y, z, w, g), pf_noise4f_d(x, y, z, w, h)));
        assert_memory_equal(g, h, 4 * sizeof g[0]);
    }
}

int main(void)
{
    quick = getenv("PF_QUICK") != NULL;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_scalar_equals_array_default),
        cmocka_unit_test(test_scalar_equals_array_seeded),
        cmocka_unit_test(test_each_3d_body),
        cmocka_unit_test(test_reference_value),
        cmocka_unit_test(test_null_table),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
