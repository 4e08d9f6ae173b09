/* exp and exp2, end to end: the C that pfmathgen emits is compiled inside
 * the test and swept against MPFR; the library's copies every float of the
 * reduced domain and of the underflow and overflow regions; the hard
 * cases; the fast variants' error bound and slope continuity across every
 * fold of the reduction; array forms against scalar forms. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include "compile.h"
#include "pfmath.h"
#include "sweep.h"
#include "tu_exec.h"
#include "tu_model.h"

#include <dlfcn.h>
#include <float.h>
#include <math.h>

static float asf(uint32_t u) { float f; memcpy(&f, &u, 4); return f; }
static uint32_t asu(float f) { uint32_t u; memcpy(&u, &f, 4); return u; }

static void *emit_and_load(const char *args, const char *sym, void **fn)
{
    char a[512], err[512], path[64];
    tu_scratch(path, "exp.c");
    snprintf(a, sizeof a, "%s -o %s", args, path);
    tu_run_result *r = malloc(sizeof *r);
    tu_runs("pfmathgen", a, r);
    if (r->status != 0)
        print_message("pfmathgen %s: %s\n", a, r->err);
    assert_int_equal(r->status, 0);
    free(r);
    void *h = pf_compile_load_file(path, err, sizeof err);
    if (!h)
        print_message("%s\n", err);
    assert_non_null(h);
    unlink(path);
    *fn = dlsym(h, sym);
    assert_non_null(*fn);
    return h;
}

/* every float in [a, b] (same sign, a <= b) */
static void sweep_interval(pf_sweep_stats *s, pf_func f, pf_fn1 fn, float a, float b)
{
    uint32_t ua = asu(a), ub = asu(b);
    if (signbit(a))
        pf_sweep_bits(s, f, fn, NULL, ub, ua, 0);
    else
        pf_sweep_bits(s, f, fn, NULL, ua, ub, 0);
}

/* n floats either side of x (and x); serial: many small ranges */
static void sweep_around(pf_sweep_stats *s, pf_func f, pf_fn1 fn, float x, uint32_t n)
{
    uint32_t u = asu(x);
    for (uint32_t b = u - n; b != u + n + 1; b++)
        pf_sweep_one(s, f, fn, NULL, asf(b), 1.0f);
}

/* The reduced domain, from both signs: every float with |x| in [2^-4, 2)
   (k = -3..3, so r covers [-ln2/2, ln2/2] resp. [-1/2, 1/2] densely and
   from both neighbouring k at each fold). */
static void sweep_reduced(pf_sweep_stats *s, pf_func f, pf_fn1 fn)
{
    sweep_interval(s, f, fn, 0x1p-4f, 0x1.fffffep0f);
    sweep_interval(s, f, fn, -0x1.fffffep0f, -0x1p-4f);
}

/* Gradual underflow and overflow: every float whose result is subnormal or
   on the edge of +0, and every float around the overflow threshold. */
static void sweep_edges(pf_sweep_stats *s, pf_func f, pf_fn1 fn)
{
    if (f == PF_EXP) {
        sweep_interval(s, f, fn, -105.0f, -87.0f); /* exp(-87.34) = 2^-126 */
        sweep_interval(s, f, fn, 88.0f, 89.0f);    /* 0x1.62e42ep+6 = 88.72 */
    } else {
        sweep_interval(s, f, fn, -151.0f, -125.0f);
        sweep_interval(s, f, fn, 127.0f, 129.0f);
    }
}

static void check_bound(const char *what, pf_func f, const pf_sweep_stats *s)
{
    pf_sweep_print(stdout, what, f, s);
    assert_true(s->max_ulp <= 1.0);
}

static void test_emitted_exact(void **st)
{
    (void)st;
    static const struct { const char *args, *sym; pf_func f; } cases[] = {
        {"--func exp", "pf_expf", PF_EXP},
        {"--func exp2", "pf_exp2f", PF_EXP2},
    };
    for (int i = 0; i < 2; i++) {
        void *fn;
        void *h = emit_and_load(cases[i].args, cases[i].sym, &fn);
        pf_fn1 f = (pf_fn1)(uintptr_t)fn;
        pf_sweep_stats s;
        pf_sweep_init(&s);
        sweep_interval(&s, cases[i].f, f, 0x1p-2f, 0x1.fffffep0f); /* k = 0..2 */
        pf_sweep_directed(&s, cases[i].f, f, NULL);
        check_bound(cases[i].sym, cases[i].f, &s);
        /* Annex F */
        assert_true(f(0.0f) == 1.0f && f(-0.0f) == 1.0f);
        assert_true(f(-INFINITY) == 0.0f && !signbit(f(-INFINITY)));
        assert_true(isinf(f(INFINITY)) && f(INFINITY) > 0);
        assert_true(isnan(f(NAN)) && isnan(f(-NAN)));
        dlclose(h);
    }
}

static void library_exact(pf_func f, pf_fn1 fn, const char *name)
{
    pf_sweep_stats s;
    pf_sweep_init(&s);
    sweep_reduced(&s, f, fn);
    sweep_edges(&s, f, fn);
    pf_sweep_random(&s, f, fn, NULL, 11, 1u << 20);
    pf_sweep_directed(&s, f, fn, NULL);
    check_bound(name, f, &s);
}

static void test_library_exact(void **st)
{
    (void)st;
    library_exact(PF_EXP, pf_expf, "libpfmath pf_expf (reduced domain, underflow, overflow, sample)");
    library_exact(PF_EXP2, pf_exp2f, "libpfmath pf_exp2f (reduced domain, underflow, overflow, sample)");
}

/* The hard cases, within 1 ULP of MPFR: exp near +-88.7 and the
   zero threshold, exp2 near 128, -126, -149, -150, tiny |x| (the 1 + x
   region), and the folds of the reduction. */
static void test_hard_cases(void **st)
{
    (void)st;
    pf_sweep_stats s;
    pf_sweep_init(&s);
    /* overflow threshold: the largest x with a finite result is 0x1.62e42ep+6 */
    sweep_around(&s, PF_EXP, pf_expf, 0x1.62e42ep+6f, 1u << 16);
    assert_true(isfinite(pf_expf(0x1.62e42ep+6f)) && isinf(pf_expf(0x1.62e430p+6f)));
    sweep_around(&s, PF_EXP, pf_expf, -0x1.5d58a0p+6f, 1u << 16); /* exp = 2^-126 */
    sweep_around(&s, PF_EXP, pf_expf, -0x1.9fe368p+6f, 1u << 16); /* exp = 2^-150 */
    sweep_around(&s, PF_EXP, pf_expf, -0x1.9d1da0p+6f, 1u << 16); /* exp = 2^-149 */
    pf_sweep_stats s2;
    pf_sweep_init(&s2);
    for (int e = -151; e <= 129; e++) /* 128, -126, -149, -150 and every other power */
        sweep_around(&s2, PF_EXP2, pf_exp2f, (float)e, 4096);
    for (int e = -126; e <= -20; e++) {
        sweep_around(&s, PF_EXP, pf_expf, ldexpf(1.0f, e), 4096);
        sweep_around(&s, PF_EXP, pf_expf, -ldexpf(1.0f, e), 4096);
        sweep_around(&s2, PF_EXP2, pf_exp2f, ldexpf(1.0f, e), 4096);
        sweep_around(&s2, PF_EXP2, pf_exp2f, -ldexpf(1.0f, e), 4096);
    }
    for (int k = -151; k <= 128; k++) {
        sweep_around(&s, PF_EXP, pf_expf, (float)((k + 0.5) * M_LN2), 4096);
        sweep_around(&s2, PF_EXP2, pf_exp2f, k + 0.5f, 4096);
    }
    check_bound("hard cases, exp", PF_EXP, &s);
    check_bound("hard cases, exp2", PF_EXP2, &s2);
    /* exp2 of an integer is exact: r = 0 and p(0) = 1, in both variants */
    for (int e = -149; e <= 127; e++) {
        assert_true(pf_exp2f((float)e) == ldexpf(1.0f, e));
        assert_true(pf_exp2f_fast((float)e) == ldexpf(1.0f, e));
    }
    assert_true(pf_exp2f(-150.0f) == 0.0f && pf_exp2f_fast(-150.0f) == 0.0f); /* tie to even */
    assert_true(isinf(pf_exp2f(128.0f)) && isinf(pf_exp2f_fast(128.0f)));
}

/* Relative error of a fast variant at x against glibc's double function
   (within a double ulp of exact).  A subnormal result carries the spacing
   of subnormals whatever the polynomial does, so the bound there is
   2^-10 |exp| + 2^-150 (half that spacing: the final rounding).  +inf must
   come exactly where the correctly rounded result is +inf. */
static double fast_err(pf_func f, pf_fn1 fn, float x)
{
    double ex = pfref_exact_d(f, x, 1);
    double got = fn(x);
    if (isinf(got) || isinf(ex)) /* inf only where the correctly rounded result is inf */
        return (isinf(got) && got > 0) == (ex >= 0x1p128 * (1 - 0x1p-25)) ? 0 : INFINITY;
    double d = fabs(got - ex);
    if (ex < 0x1p-126)
        return d <= 0x1p-10 * ex + 0x1p-150 ? 0 : INFINITY;
    return d / ex;
}

static void fast_bound(pf_func f, pf_fn1 fn)
{
    double worst = 0;
    float wx = 0;
    /* every 3rd float of the reduced domain, every 64th of the rest up to
       the thresholds and beyond, a seeded full-range sample */
    for (uint32_t b = 0x3d800000u; b < 0x40000000u; b += 3)
        for (int sg = 0; sg < 2; sg++) {
            float x = asf(b | (uint32_t)sg << 31);
            double e = fast_err(f, fn, x);
            if (e > worst)
                worst = e, wx = x;
        }
    for (uint32_t b = 0; b < 0x43200000u; b += 64)
        for (int sg = 0; sg < 2; sg++) {
            float x = asf(b | (uint32_t)sg << 31);
            double e = fast_err(f, fn, x);
            if (e > worst)
                worst = e, wx = x;
        }
    uint64_t s = 99;
    for (int i = 0; i < 1 << 20; i++) {
        s = s * 6364136223846793005ull + 1442695040888963407ull;
        float x = asf((uint32_t)(s >> 32) & 0xff7fffffu);
        double e = fast_err(f, fn, x);
        if (e > worst)
            worst = e, wx = x;
    }
    print_message("%s fast: max rel error %.3g (2^%.2f) at %a\n", pfref_name(f), worst, log2(worst), wx);
    assert_true(worst <= 0x1p-10);
}

/* Slope continuity across the folds x = (k + 1/2) ln2 (exp) and k + 1/2
   (exp2), where k changes: one-sided second-order difference quotients over
   steps h agree.  Both have truncation error -h^2/3 f''' to first order, so
   their difference is the slope jump plus O(h^3) plus rounding: each value
   is within a few ulps (float Horner), 8 values weighted by 3+4+1 over 2h. */
static void seams(pf_func f, pf_fn1 fn)
{
    double worst = 0;
    for (int k = -120; k <= 120; k++) {
        float xs = f == PF_EXP ? (float)((k + 0.5) * M_LN2) : (float)k + 0.5f;
        float h = 0x1p-6f;
        double y0 = fn(xs), l1 = fn(xs - h), l2 = fn(xs - 2 * h), r1 = fn(xs + h), r2 = fn(xs + 2 * h);
        double left = (3 * y0 - 4 * l1 + l2) / (2 * h);
        double right = (-3 * y0 + 4 * r1 - r2) / (2 * h);
        double slope = f == PF_EXP ? y0 : M_LN2 * y0;
        double tol = 4 * 8 * y0 * 0x1p-24 / (2 * h) + 2 * (double)h * h * h * slope;
        double jump = fabs(left - right);
        if (jump / slope > worst)
            worst = jump / slope;
        if (jump > tol)
            print_message("%s fast: slope jump %.3g (relative %.3g) at the fold near %a\n", pfref_name(f),
                          jump, jump / slope, (double)xs);
        assert_true(jump <= tol);
    }
    print_message("%s fast: largest relative slope jump across folds %.3g\n", pfref_name(f), worst);
}

static void test_library_fast(void **st)
{
    (void)st;
    fast_bound(PF_EXP, pf_expf_fast);
    fast_bound(PF_EXP2, pf_exp2f_fast);
    seams(PF_EXP, pf_expf_fast);
    seams(PF_EXP2, pf_exp2f_fast);
    /* Annex F for the fast variants too (tests/special/exp.txt has more) */
    assert_true(pf_expf_fast(0.0f) == 1.0f && pf_exp2f_fast(-0.0f) == 1.0f);
    assert_true(pf_expf_fast(-INFINITY) == 0.0f && isinf(pf_expf_fast(INFINITY)));
    assert_true(isnan(pf_expf_fast(NAN)) && isnan(pf_exp2f_fast(NAN)));
    /* gradual underflow: results below 2^-126 are subnormals, not flushed */
    assert_true(pf_expf_fast(-100.0f) > 0 && pf_expf_fast(-100.0f) < FLT_MIN);
    assert_true(pf_exp2f_fast(-140.5f) > 0 && pf_exp2f_fast(-140.5f) < FLT_MIN);
}

/* The array forms compute exactly what the scalar forms do. */
static void test_arrays_match_scalar(void **st)
{
    (void)st;
    enum { N = 4099 };
    static float x[N], y[N];
    uint64_t s = 5;
    for (int i = 0; i < N; i++) {
        s = s * 6364136223846793005ull + 1442695040888963407ull;
        /* half random bit patterns (NaN, inf, huge), half in [-160, 160] */
        x[i] = i & 1 ? asf((uint32_t)(s >> 32)) : (float)((int64_t)(s >> 11) * 0x1p-53 * 320 - 160);
    }
    void (*arr[4])(const float *, float *, size_t) = {pf_expf_array, pf_expf_fast_array,
                                                       pf_exp2f_array, pf_exp2f_fast_array};
    float (*sc[4])(float) = {pf_expf, pf_expf_fast, pf_exp2f, pf_exp2f_fast};
    for (int f = 0; f < 4; f++) {
        arr[f](x, y, N);
        for (int i = 0; i < N; i++) {
            float z = sc[f](x[i]);
            assert_true(memcmp(&z, &y[i], 4) == 0 || (isnan(z) && isnan(y[i])));
        }
    }
}

/* The scalar forms branch to the body without selects when k (x/ln2 resp.
   x rounded) is in [-126, 127], tested on z's bits: at the ends of that
   band 2^k is still normal but y 2^k may be subnormal (k = -126, y < 1) or
   near the top, and the branch must give the full body's bits there.  Every
   float of the band's edges (|x| from the old limit, 87 resp. 126, to past
   the new one, 88.5 resp. 128), and across the overflow and subnormal
   thresholds, against the array form, whose blocks there hold lanes that
   are not ordinary and so run the full body. */
static void test_scalar_branch_edges(void **st)
{
    (void)st;
    enum { B = 4096 };
    static float x[B], y[B];
    void (*arr[4])(const float *, float *, size_t) = {pf_expf_array, pf_expf_fast_array,
                                                       pf_exp2f_array, pf_exp2f_fast_array};
    float (*sc[4])(float) = {pf_expf, pf_expf_fast, pf_exp2f, pf_exp2f_fast};
    for (int f = 0; f < 4; f++) {
        float a = f < 2 ? 87.0f : 126.0f, b = f < 2 ? 88.5f : 128.0f;
        long n = 0, dif = 0;
        for (int sg = 0; sg < 2; sg++) {
            uint32_t ua = asu(sg ? -a : a), ub = asu(sg ? -b : b);
            for (uint32_t u = ua; u <= ub;) {
                int m = 0;
                for (; m < B && u <= ub; m++, u++)
                    x[m] = asf(u);
                x[0] = 1e30f; /* not ordinary: the block takes the full body */
                arr[f](x, y, (size_t)m);
                for (int i = 1; i < m; i++, n++) {
                    float w = sc[f](x[i]);
                    dif += memcmp(&w, &y[i], 4) != 0;
                }
            }
        }
        print_message("scalar branch edges, function %d: %ld floats, %ld differ\n", f, n, dif);
        assert_true(n > 100000);
        assert_int_equal(dif, 0);
    }
}

/* The array forms take a shorter body for blocks (of 128) whose every lane
   is ordinary (exp: x in [-87, 88], exp2: [-126, 127]; there 2^k is an
   add to y's exponent bits, right only while k is in [-126, 127] and the
   result normal), the full one otherwise: on such inputs, the ends
   included, with a rare lane now and then (just past either end, where
   that add would give garbage, and the special values; at a block's first,
   middle and last position, and in the partial last block), every lane
   still gets the scalar form's bits, in place too. */
static void test_arrays_two_paths(void **st)
{
    (void)st;
    enum { N = 128 * 40 + 77 };
    static float x[N], y[N], z[N];
    static const int at[] = {0, 63, 127, 128 * 3 + 5, 128 * 7 + 127, 128 * 9, 128 * 20 + 64,
                             128 * 30 + 1, 128 * 33 + 90, 128 * 36 + 17, N - 77, N - 1};
    void (*arr[4])(const float *, float *, size_t) = {pf_expf_array, pf_expf_fast_array,
                                                       pf_exp2f_array, pf_exp2f_fast_array};
    float (*sc[4])(float) = {pf_expf, pf_expf_fast, pf_exp2f, pf_exp2f_fast};
    for (int f = 0; f < 4; f++) {
        float lo = f < 2 ? -87.0f : -126.0f, hi = f < 2 ? 88.0f : 127.0f;
        const float rare[] = {nextafterf(hi, INFINITY), nextafterf(lo, -INFINITY), hi + 0.7f, lo - 0.7f,
                              NAN, -NAN, INFINITY, -INFINITY, 1e30f, -1e30f, 2 * hi, 2 * lo};
        uint64_t s = 11;
        for (int i = 0; i < N; i++) {
            s = s * 6364136223846793005ull + 1442695040888963407ull;
            float u = (float)((int64_t)(s >> 11) * 0x1p-53 * (hi - lo) + lo);
            x[i] = i % 97 == 5 ? hi : i % 89 == 7 ? lo : fminf(fmaxf(u, lo), hi);
        }
        for (int j = 0; j < (int)(sizeof at / sizeof at[0]); j++)
            x[at[j]] = rare[j];
        arr[f](x, y, N);
        memcpy(z, x, sizeof z);
        arr[f](z, z, N);
        for (int i = 0; i < N; i++) {
            float w = sc[f](x[i]);
            assert_true(memcmp(&w, &y[i], 4) == 0 || (isnan(w) && isnan(y[i])));
            assert_true(memcmp(&w, &z[i], 4) == 0 || (isnan(w) && isnan(z[i])));
        }
    }
}

static const char *MODEL_ARGS[] = {"--func exp --no-sweep -o /dev/null", "--func exp2 --no-sweep -o /dev/null"};
#define NMODEL 2
#define MODEL_LOW "--func exp --order 5 --no-sweep -o /dev/null"

static void test_error_model(void **st)
{
    (void)st;
    tu_check_models(MODEL_ARGS, NMODEL, MODEL_LOW);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_emitted_exact), cmocka_unit_test(test_library_exact),
        cmocka_unit_test(test_hard_cases),    cmocka_unit_test(test_library_fast),
        cmocka_unit_test(test_arrays_match_scalar), cmocka_unit_test(test_arrays_two_paths),
        cmocka_unit_test(test_scalar_branch_edges),
        cmocka_unit_test(test_error_model),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
