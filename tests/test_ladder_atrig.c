/* The atrig family's ladder-only rows on the accuracy ladder (gen/templates/
 * {asin,acos}_mid.c.in, {asin,atan,atan2}_lite.c.in, atan2_lean.c.in,
 * gen/float/funcs_atrig.c): pfmathgen --max-ulp picks the template the tests
 * below name where they say it must (its cost is below the others', its
 * model within the level), and what it emits is within the level against
 * MPFR (ref/) on inputs the search's sample did not use: the hard regions of
 * each reduction (around |x| = 1/2, where S = sqrtf(2 - 2|x|) ~ 1 rounds
 * hardest and asin is pi/6; toward |x| = 1; asin near 0.84, where
 * pi/2 - S crosses 1 above the result; atan around |x| = 1, the fold, where
 * z reaches 1; atan2 around |y| = |x| in every quadrant and the axes), the
 * directed list and a fresh random sample.  The array form gives the scalar
 * form's bits.  Confirmation here is --confirm sample; the exhaustive proof
 * is `pfmathgen --max-ulp U`
 * without it (minutes per level, not in `make test`). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include "compile.h"
#include "sweep.h"
#include "ladder_check.h"
#include "testutil.h"
#include "tu_exec.h"

#include <dlfcn.h>

static tu_run_result R;

/* generate f at U (sampled confirmation) into path; returns the file's text */
static char *gen(const char *f, const char *u, const char *name, const char *path)
{
    unlink(path);
    tu_runl(&R, "pfmathgen", "--func", f, "--max-ulp", u, "--name", name, "--confirm", "sample", "-o",
            path, NULL);
    print_message("pfmathgen --func %s --max-ulp %s -> %d\n", f, u, R.status);
    assert_int_equal(R.status, 0);
    char *src = tu_slurp(path, NULL);
    assert_non_null(src);
    return src;
}

static float bits(uint32_t u)
{
    float f;
    memcpy(&f, &u, 4);
    return f;
}

static uint32_t ubits(float f)
{
    uint32_t u;
    memcpy(&u, &f, 4);
    return u;
}

/* every float within n of c's bit pattern, both signs */
static void around(pf_sweep_stats *st, pf_func f, pf_fn1 fn, float c, uint32_t n)
{
    uint32_t u = ubits(c);
    for (uint32_t b = u - n; b <= u + n; b++) {
        pf_sweep_one(st, f, fn, NULL, bits(b), 1.0f);
        pf_sweep_one(st, f, fn, NULL, -bits(b), 1.0f);
    }
}

static void *load(const char *path)
{
    char err[512];
    void *h = pf_compile_load_file(path, err, sizeof err);
    if (!h)
        fail_msg("%s", err);
    return h;
}

static void check_unary(const char *f, const char *u, double U, const char *tmpl)
{
    char name[64], path[128];
    snprintf(name, sizeof name, "lad_%s_l%.0f", f, 100 * U);
    snprintf(path, sizeof path, "%s/%s.c", tu_scratch_dir(), f);
    char *src = gen(f, u, name, path);
    assert_non_null(strstr(src, tmpl));   /* the named template was chosen */
    free(src);
    void *h = load(path);
    pf_fn1 s1;
    lc_array1 a1;
    lc_syms1(h, name, &s1, &a1);
    pf_func fid = (pf_func)pfref_lookup(f);
    pf_sweep_stats st;
    pf_sweep_init(&st);
    pf_sweep_directed(&st, fid, s1, NULL);
    pf_sweep_random(&st, fid, s1, NULL, 4242, 1u << 18);
    if (!strcmp(f, "atan")) {
        around(&st, fid, s1, 1.0f, 1u << 16);
        around(&st, fid, s1, 0x1p-12f, 1u << 10);
        around(&st, fid, s1, 0x1p12f, 1u << 10);
    } else {
        around(&st, fid, s1, 0.5f, 1u << 16);
        around(&st, fid, s1, 1.0f - 0x1p-10f, 1u << 12);
        around(&st, fid, s1, 0x1p-12f, 1u << 10);
        /* asin near 0.84: pi/2 - 2s crosses 1 while the result is below it
           (the lite row's rounding of khi + u is then a whole ULP) */
        around(&st, fid, s1, 0x1.ad44e8p-1f, 1u << 12);
    }
    print_message("%s: max %.3f ULP (level %g) at %a\n", name, st.max_ulp, U, (double)st.worst_x);
    assert_true(st.max_ulp <= U);
    enum { N = 4096 };
    static float x[N], y[N];
    for (int i = 0; i < N; i++)
        x[i] = i % 2 ? bits((uint32_t)(i * 1048573u + 12345u)) : bits(0x3f000000u + (uint32_t)i - N / 2);
    lc_array_is_scalar(s1, a1, x, y, N);
    dlclose(h);
    unlink(path);
}

static void test_asin_mid(void **st)
{
    (void)st;
    check_unary("asin", "2", 2, "mid template");
}

/* acos's 1.25 level (mk/ladder.mk: SLEEF u35 is at 1.28) */
static void test_acos_mid(void **st)
{
    (void)st;
    check_unary("acos", "1.25", 1.25, "mid template");
}

/* asin's 2.5 level (mk/ladder.mk: SLEEF u35 is at 2.4): the lite row */
static void test_asin_lite(void **st)
{
    (void)st;
    check_unary("asin", "2.5", 2.5, "lite template");
}

/* atan at 2: the lite row (the mid template's terms without its Fast2Sum) */
static void test_atan_lite(void **st)
{
    (void)st;
    check_unary("atan", "2", 2, "lite template");
}

/* atan2 at level u (U): the template tmpl */
static void check_atan2(const char *u, double U, const char *tmpl)
{
    char name[64], arr[80];
    snprintf(name, sizeof name, "lad_atan2_l%.0f", 100 * U);
    snprintf(arr, sizeof arr, "%s_array", name);
    char path[96];
    tu_scratch(path, "atan2.c");
    char *src = gen("atan2", u, name, path);
    assert_non_null(strstr(src, tmpl));
    free(src);
    void *h = load(path);
    pf_fn2 s2;
    void (*a2)(const float *, const float *, float *, size_t);
    *(void **)&s2 = dlsym(h, name);
    *(void **)&a2 = dlsym(h, arr);
    assert_non_null(s2);
    assert_non_null(a2);
    pf_sweep_stats st;
    pf_sweep_init(&st);
    pf_sweep_directed(&st, PF_ATAN2, NULL, s2);
    pf_sweep_random(&st, PF_ATAN2, NULL, s2, 4242, 1u << 18);
    /* |y| ~ |x| (t ~ 1, z ~ 1) and the axes, in every quadrant */
    for (int i = -2048; i <= 2048; i++)
        for (int q = 0; q < 4; q++) {
            float y = bits(ubits(1.5f) + (uint32_t)(i * 37)), x = 1.5f;
            float y2 = bits(ubits(3.0f) + (uint32_t)(i * 1001)), x2 = 0x1p-20f;
            pf_sweep_one(&st, PF_ATAN2, NULL, s2, q & 1 ? -y : y, q & 2 ? -x : x);
            pf_sweep_one(&st, PF_ATAN2, NULL, s2, q & 1 ? -y2 : y2, q & 2 ? -x2 : x2);
            pf_sweep_one(&st, PF_ATAN2, NULL, s2, q & 1 ? -x2 : x2, q & 2 ? -y2 : y2);
        }
    print_message("%s: max %.3f ULP (level %g) at (%a, %a)\n", name, st.max_ulp, U, (double)st.worst_x,
                  (double)st.worst_x2);
    assert_true(st.max_ulp <= U);
    enum { N = 4096 };
    static float y[N], x[N], r[N];
    for (int i = 0; i < N; i++) {
        y[i] = bits((uint32_t)(i * 1048573u + 12345u));
        x[i] = bits((uint32_t)(i * 2654435761u));
    }
    a2(y, x, r, N);
    for (int i = 0; i < N; i++) {
        float s = s2(y[i], x[i]);
        assert_memory_equal(&s, &r[i], 4);
    }
    dlclose(h);
    unlink(path);
}

/* atan2 at 2: the lite row; at 3 (mk/ladder.mk): the lean row, one fmaf */
static void test_atan2_lite(void **st)
{
    (void)st;
    check_atan2("2", 2, "lite template");
}

static void test_atan2_lean(void **st)
{
    (void)st;
    check_atan2("3", 3, "lean template");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_asin_mid),
        cmocka_unit_test(test_acos_mid),
        cmocka_unit_test(test_asin_lite),
        cmocka_unit_test(test_atan_lite),
        cmocka_unit_test(test_atan2_lite),
        cmocka_unit_test(test_atan2_lean),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
