/* The ladder's log and log2 rows between exact and fast (gen/float/funcs_log.c):
 * "mid" (log2: r^2 q fits log2(1+r) - r/ln2, nothing compensated) and
 * "mid-double" (p(r) by Horner in double, one rounding to float) and
 * "tab" (a 16-entry table of 1/c and log c in double, a short polynomial)
 * and "tabf" (the same subintervals in float lanes, nothing compensated) and
 * "tabc" (tabf's tables with the reduced argument and the big sum exact) and
 * "tabl" (two tables, INVC near-exact logs; log2: one rounding).  Each is
 * generated at the order the ladder picks for a level (the L2, L0.6 and
 * L0.55 files of `make ladder`), compiled, and measured against MPFR (ref/)
 * on a sample that includes the hard inputs: the floats around the
 * reduction's binade edges (m = sqrt(2)/2 at k = -1, 0, 1, 2, where k + log m
 * cancels to +-1/2 and the result's ulp halves), around 1 (tiny r),
 * subnormals and powers of two.  The measured maximum must be within both
 * the level and the error model's bound (so a model that under-counts a
 * rounding fails here), and the array form must give the scalar bits.
 * The exhaustive proof (every float) is the ladder's own confirmation
 * (`make ladder`; one level is 1-3 minutes, too long for `make test`). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include "compile.h"
#include "tu_compile.h"
#include "generate.h"
#include "pfref.h"
#include "sweep.h"
#include "ladder_check.h"

#include <dlfcn.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef TABC_ORDER
#define TABC_ORDER 5
#endif

static float asfloat(uint32_t u)
{
    float x;
    memcpy(&x, &u, 4);
    return x;
}

/* every float within d of x's bits */
static void around(pf_sweep_stats *st, pf_func f, pf_fn1 s1, float x, uint32_t d)
{
    uint32_t b;
    memcpy(&b, &x, 4);
    for (uint32_t u = b - d; u != b + d; u++)
        pf_sweep_one(st, f, s1, NULL, asfloat(u), 1.0f);
}

static void check(const char *func, const char *variant, int order, double U)
{
    char err[512], name[64];
    snprintf(name, sizeof name, "tll_%s_%s_%d", func, variant, order);
    for (char *c = name; *c; c++)
        *c = *c == '-' ? '_' : *c;
    pf_gen_req rq = {.func = func, .variant = variant, .name = name, .method = "minimax", .order = order};
    pf_gen_result r;
    if (pf_generate(&rq, &r, err, sizeof err) != 0)
        fail_msg("%s %s order %d: %s", func, variant, order, err);
    assert_true(r.has_scheme);
    void *h = pf_compile_load(r.csrc, r.clen, err, sizeof err);
    if (!h)
        fail_msg("%s", err);
    pf_fn1 s1;
    lc_array1 a1;
    lc_syms1(h, name, &s1, &a1);
    pf_func f = (pf_func)pfref_lookup(func);
    pf_sweep_stats st;
    pf_sweep_init(&st);
    pf_sweep_random(&st, f, s1, NULL, 4242, 1u << 17);
    uint32_t lo, hi;
    pf_sweep_reduced_range(f, &lo, &hi);
    for (uint64_t b = lo; b <= hi; b += 97)
        pf_sweep_one(&st, f, s1, NULL, asfloat((uint32_t)b), 1.0f);
    for (int k = -1; k <= 2; k++)
        around(&st, f, s1, ldexpf(0x1.6a09e6p-1f, k), 1u << 12);
    around(&st, f, s1, 1.0f, 1u << 14);
    /* the table rows' subinterval edges (z's bits from OFF = 0x3f330000 by
       2^19), at k = -1, 0, 1 */
    for (int k = -1; k <= 1; k++)
        for (uint32_t i = 0; i <= 16; i++)
            around(&st, f, s1, ldexpf(asfloat(0x3f330000u + (i << 19)), k), 1u << 8);
    around(&st, f, s1, 0x1p-126f, 1u << 10);
    for (int k = -149; k <= 127; k++)
        pf_sweep_one(&st, f, s1, NULL, ldexpf(1.0f, k), 1.0f);
    print_message("%s: max %.3f ULP at %a (level %g, model %.3f)\n", name, st.max_ulp, (double)st.worst_x, U,
                  r.scheme.bound_ulp);
    assert_true(r.scheme.bound_ulp <= U);
    assert_true(st.max_ulp <= r.scheme.bound_ulp);
    /* the array form: the scalar bits, specials and subnormals included */
    enum { N = 8192 };
    static float x[N], y[N];
    for (int i = 0; i < N; i++)
        x[i] = asfloat((uint32_t)(i * 524287u + 977u));
    x[0] = 0.0f, x[1] = -0.0f, x[2] = INFINITY, x[3] = -1.0f, x[4] = NAN, x[5] = 0x1p-149f, x[6] = 1.0f;
    lc_array_is_scalar(s1, a1, x, y, N);
    /* the float table rows carry their own AVX2 loop, which the ifunc skips
       on an AVX-512 CPU: built again with PF_LOGTF_TEST_V3 it takes it.
       Not in the sanitized copy of this test: $CC (no sanitizer) compiling
       the source the plain copy compiles, then that loop against the scalar
       form on the same inputs, neither of them sanitized code; the plain
       copy's check is the same, input for input */
    int sanitized = tu_sanitized();
    /* on a CPU without AVX-512 (x86-64-v4), a1 above is that loop already
       (the template's dispatch), checked on the same inputs */
    char after[512];
    snprintf(after, sizeof after,
             "    if (__builtin_cpu_supports(\"x86-64-v3\"))\n        return %s_array_v3;\n#endif\n"
             "    if (__builtin_cpu_supports(\"x86-64-v4\"))\n        return %s_array_v4;\n"
             "    if (__builtin_cpu_supports(\"x86-64-v3\"))\n        return %s_array_v3;\n",
             name, name, name);
    if (tu_macro_picks_same(r.csrc, "PF_LOGTF_TEST_V3", after))
        print_message("  AVX2 loop: the array form's own on this CPU (no x86-64-v4), checked above\n");
    else if (!sanitized && strstr(r.csrc, "PF_LOGTF_TEST_V3") && __builtin_cpu_supports("x86-64-v3")) {
        void *h3 = tu_compile_load_def("#define PF_LOGTF_TEST_V3 1\n", r.csrc, r.clen, err, sizeof err);
        if (!h3)
            fail_msg("%s", err);
        pf_fn1 s3;
        lc_array1 a3;
        lc_syms1(h3, name, &s3, &a3);
        lc_array_is_scalar(s1, a3, x, y, N);
        dlclose(h3);
    }
    dlclose(h);
    pf_gen_free(&r);
}

/* the orders the ladder picks (the L0.6 and L0.55 files of make ladder; mid
   at order 10 was log2's L2 before the tabl row) */
static void test_log2_mid(void **st) { (void)st; check("log2", "mid", 10, 2); }
static void test_log2_double(void **st) { (void)st; check("log2", "mid-double", 10, 0.6); }
static void test_log_double(void **st) { (void)st; check("log", "mid-double", 11, 0.55); }
/* the table rows (double, gen/templates/log_tab.c.in) at their default order */
static void test_log2_tab(void **st) { (void)st; check("log2", "tab", 5, 0.51); }
static void test_log_tab(void **st) { (void)st; check("log", "tab", 5, 0.51); }
/* the float table rows (gen/templates/log_tabf.c.in) at order 4, within
   log2's L3 and log's L4 levels (the ladder keeps the fast rows there: their
   cost, gen/float/funcs_log.c TABF_COST) */
static void test_log2_tabf(void **st) { (void)st; check("log2", "tabf", 4, 3); }
static void test_log_tabf(void **st) { (void)st; check("log", "tabf", 4, 4); }
/* the lean log2 row (gen/templates/log_tabl.c.in: two tables, INVC chosen
   so that -log2(INVC) sits near the grid 2^-16) at the orders the ladder
   picks for its levels (4: L2, L3, L4; 5 within 1.6) */
static void test_log2_tabl(void **st) { (void)st; check("log2", "tabl", 4, 2); }
static void test_log2_tabl5(void **st) { (void)st; check("log2", "tabl", 5, 1.6); }
/* log's (k on its own, a second rounding): order 4 at its L4 level */
static void test_log_tabl(void **st) { (void)st; check("log", "tabl", 4, 4); }
/* the compensated float table rows at the order the ladder picks for L0.6 (log,
   log2) and L0.55 (log2) */
static void test_log2_tabc(void **st) { (void)st; check("log2", "tabc", TABC_ORDER, 0.55); }
static void test_log_tabc(void **st) { (void)st; check("log", "tabc", TABC_ORDER, 0.6); }

int main(void)
{
    const struct CMUnitTest t[] = {
        cmocka_unit_test(test_log2_mid),
        cmocka_unit_test(test_log2_double),
        cmocka_unit_test(test_log_double),
        cmocka_unit_test(test_log2_tab),
        cmocka_unit_test(test_log_tab),
        cmocka_unit_test(test_log2_tabf),
        cmocka_unit_test(test_log_tabf),
        cmocka_unit_test(test_log2_tabl),
        cmocka_unit_test(test_log2_tabl5),
        cmocka_unit_test(test_log_tabl),
        cmocka_unit_test(test_log2_tabc),
        cmocka_unit_test(test_log_tabc),
    };
    return cmocka_run_group_tests(t, NULL, NULL);
}
