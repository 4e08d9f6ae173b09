/* The trig mid rows (gen/float/funcs_trig.c: float Cody-Waite with the tail
 * kept apart, gen/templates/sin_cw_float.c.in, tan_cw_float.c.in): the
 * ladder picks them for sin at 2 ULP (mid order 11; the model's exact final
 * subtraction, gen/float/funcs_trig.c mid_final), cos and tan at 3 ULP
 * (mid), and what it emits is within its level against MPFR (ref/) on the inputs that stress the
 * reduction: the five floats around every k pi/2 below 2^16 (the Cody-Waite
 * range) and just above it, the directed list (1e30, FLT_MAX, floats next
 * to multiples of pi/2 up to 2^127: Payne-Hanek), 2^18 random floats; its
 * array form gives the scalar bits, blocks with rare lanes included.  The
 * same check at 1 ULP must fail: these rows are not 1-ULP schemes, so a
 * check that passed there would be checking nothing.
 *
 * The search confirms on a sample here (--confirm sample, as make bench);
 * the exhaustive confirmation of the same levels is `make ladder` (minutes
 * per level; docs/trig.md quotes its results). */
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
#include <math.h>

static tu_run_result R;

static float asf(uint32_t u)
{
    float f;
    memcpy(&f, &u, 4);
    return f;
}

/* the floats around k pi/2 for k pi/2 < lim, both signs */
static void near_multiples(pf_sweep_stats *st, pf_func f, pf_fn1 fn, double lim)
{
    for (int k = 1; k * 1.5707963267948966 < lim; k++) {
        float c = (float)(k * 1.5707963267948966);
        uint32_t u;
        memcpy(&u, &c, 4);
        for (uint32_t d = u - 2; d <= u + 2; d++) {
            pf_sweep_one(st, f, fn, NULL, asf(d), 1.0f);
            pf_sweep_one(st, f, fn, NULL, -asf(d), 1.0f);
        }
    }
}

/* row: the variant the search must choose at level u, model: a phrase of its
   provenance; for the mid rows (row "mid") the sample must also exceed 1 ULP */
static void check_level(const char *func, const char *u, double U, const char *row, const char *model)
{
    char name[64], path[128];
    snprintf(name, sizeof name, "lad_%sf_mid", func);
    snprintf(path, sizeof path, "%s/%s-%s.c", tu_scratch_dir(), func, u);
    unlink(path);
    tu_runl(&R, "pfmathgen", "--func", func, "--max-ulp", u, "--name", name, "--confirm", "sample", "-o", path,
            NULL);
    print_message("pfmathgen --func %s --max-ulp %s -> %d\n", func, u, R.status);
    assert_int_equal(R.status, 0);
    char *src = tu_slurp(path, NULL);
    assert_non_null(src);
    /* the search chose the expected row, and the provenance carries its model */
    char tag[64];
    snprintf(tag, sizeof tag, ", %s", row);
    assert_non_null(strstr(src, tag));
    assert_non_null(strstr(src, model));
    free(src);

    char err[512];
    void *h = pf_compile_load_file(path, err, sizeof err);
    if (!h)
        fail_msg("%s", err);
    pf_fn1 s1;
    lc_array1 a1;
    lc_syms1(h, name, &s1, &a1);
    pf_func fid = (pf_func)pfref_lookup(func);
    pf_sweep_stats st;
    pf_sweep_init(&st);
    pf_sweep_directed(&st, fid, s1, NULL);
    near_multiples(&st, fid, s1, 0x1p16 * 1.02);
    pf_sweep_random(&st, fid, s1, NULL, 4242, 1u << 18);
    print_message("%s: max %.3f ULP (bound %g) at %a over %llu inputs\n", name, st.max_ulp, U, (double)st.worst_x,
                  (unsigned long long)st.count);
    assert_true(st.max_ulp <= U);
    /* the check can fail: a float scheme with one rounding in r is not
       within 1 ULP on these inputs */
    if (!strcmp(row, "mid"))
        assert_true(st.max_ulp > 1.0);

    enum { N = 4096 };
    static float x[N], y[N];
    for (int i = 0; i < N; i++)
        x[i] = asf((uint32_t)(i * 1048573u + 12345u)); /* every exponent: some rare lanes a block */
    for (int i = 0; i < 512; i++)
        x[i] = (float)(i * 0.7853981633974483 + 0.1); /* blocks with no rare lane */
    lc_array_is_scalar(s1, a1, x, y, N);
    dlclose(h);
    unlink(path);
}

static void test_sin_mid(void **st)
{
    (void)st;
    check_level("sin", "2", 2, "mid", "r carries one rounding");
}

static void test_cos_mid(void **st)
{
    (void)st;
    check_level("cos", "3", 3, "mid", "r carries one rounding");
}

static void test_tan_mid(void **st)
{
    (void)st;
    check_level("tan", "3", 3, "mid", "r carries one rounding");
}

/* below the float-lane exact row's 0.83 ULP (sleef-u10 sits at 0.78): the
   double-lane row */
static void test_sin_dbl(void **st)
{
    (void)st;
    check_level("sin", "0.75", 0.75, "exact-double", "Horner in double");
}

static void test_cos_dbl(void **st)
{
    (void)st;
    check_level("cos", "0.75", 0.75, "exact-double", "Horner in double");
}

int main(void)
{
    const struct CMUnitTest t[] = {
        cmocka_unit_test(test_sin_mid),
        cmocka_unit_test(test_cos_mid),
        cmocka_unit_test(test_tan_mid),
        cmocka_unit_test(test_sin_dbl),
        cmocka_unit_test(test_cos_dbl),
    };
    return cmocka_run_group_tests(t, NULL, NULL);
}
