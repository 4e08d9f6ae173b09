/* pfmathgen --max-ulp (the accuracy ladder, gen/float/ladder.h): bad values and
 * option clashes are exit 2 with one line and nothing written; what it emits
 * meets its bound on a fresh sample against MPFR (ref/), its array form
 * gives the scalar form's bits, its provenance records the search, a looser
 * bound never costs more, and an unreachable bound is "impossible target".
 *
 * The exhaustive confirmation takes minutes per level (2^32 floats), too
 * long for `make test`: here the search runs with --confirm sample, which
 * changes only step 3 of the search (a larger sample instead of every
 * float).  The exhaustive path is exercised by `make ladder`. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include "compile.h"
#include "pfbench_ladder.h"
#include "sweep.h"
#include "testutil.h"
#include "tu_exec.h"

#include <dlfcn.h>
#include <sys/stat.h>

static tu_run_result R;

static void expect_error_v(const char *const *args, const char *what)
{
    char out[96];
    tu_scratch(out, "err.c");
    unlink(out);
    const char *v[40];
    int n = 0;
    for (; args[n] && n < 36; n++)
        v[n] = args[n];
    v[n++] = "-o";
    v[n++] = out;
    v[n] = NULL;
    tu_runv("pfmathgen", v, &R);
    print_message("%s -> %d: %s", args[3] ? args[3] : args[1], R.status, R.err);
    assert_int_equal(R.status, 2);
    assert_int_equal(tu_count_lines(R.err), 1);
    assert_non_null(strstr(R.err, what));
    struct stat sb;
    assert_int_not_equal(stat(out, &sb), 0);
}
#define expect_error(what, ...) expect_error_v((const char *const[]){__VA_ARGS__, NULL}, what)

static void test_bad_values(void **st)
{
    (void)st;
    const char *bad[] = {"0.4", "0", "-1", "nan", "inf", "-inf", "1e400", "", "abc", "2^-2", "4x", " 4", "2^", NULL};
    for (int i = 0; bad[i]; i++)
        expect_error("bad --max-ulp", "--func", "exp", "--max-ulp", bad[i]);
    expect_error("bad --confirm", "--func", "exp", "--max-ulp", "4", "--confirm", "some");
}

static void test_clashes(void **st)
{
    (void)st;
    expect_error("--order", "--func", "exp", "--max-ulp", "4", "--order", "5");
    expect_error("--max-rel-err", "--func", "exp", "--max-ulp", "4", "--max-rel-err", "1e-4");
    expect_error("--max-abs-err", "--func", "exp", "--max-ulp", "4", "--max-abs-err", "1e-4");
    expect_error("--target", "--func", "exp", "--max-ulp", "4", "--target", "float");
    expect_error("--variant", "--func", "exp", "--max-ulp", "4", "--variant", "fast");
    expect_error("--no-sweep", "--func", "exp", "--max-ulp", "4", "--no-sweep");
    expect_error("fixed-point", "--func", "exp", "--max-ulp", "4", "--type", "fixed<15,11>");
    expect_error("fixed-point", "--func", "sin", "--type", "fixed<15,12>", "--max-ulp", "2");
    expect_error("--confirm is for --max-ulp", "--func", "exp", "--confirm", "sample");
    expect_error("--scene", "--scene", "x.scene", "--max-ulp", "4");
    expect_error("given twice", "--func", "exp", "--max-ulp", "4", "--max-ulp", "2");
}

/* generate f at U (sampled confirmation) into path; returns the file's text */
static char *gen(const char *f, const char *u, const char *name, const char *path)
{
    unlink(path);
    tu_runl(&R, "pfmathgen", "--func", f, "--max-ulp", u, "--name", name, "--confirm", "sample", "-o", path, NULL);
    print_message("pfmathgen --func %s --max-ulp %s -> %d\n", f, u, R.status);
    assert_int_equal(R.status, 0);
    char *src = tu_slurp(path, NULL);
    assert_non_null(src);
    return src;
}

static int cost_in(const char *src)
{
    const char *p = strstr(src, ", cost ");
    assert_non_null(p);
    return atoi(p + 7);
}

/* the emitted function within U on 2^18 random floats (a seed the search
   did not use) and the reduced range's every 64th float, against MPFR; the
   array form gives the scalar bits on the same inputs */
static void check_emitted(const char *path, const char *name, const char *f, double U)
{
    char err[512];
    void *h = pf_compile_load_file(path, err, sizeof err);
    if (!h)
        fail_msg("%s", err);
    char arr[160];
    snprintf(arr, sizeof arr, "%s_array", name);
    pf_fn1 s1;
    void (*a1)(const float *, float *, size_t);
    *(void **)&s1 = dlsym(h, name);
    *(void **)&a1 = dlsym(h, arr);
    assert_non_null(s1);
    assert_non_null(a1);
    pf_func fid = (pf_func)pfref_lookup(f);
    pf_sweep_stats st;
    pf_sweep_init(&st);
    pf_sweep_random(&st, fid, s1, NULL, 777, 1u << 18);
    uint32_t lo, hi;
    pf_sweep_reduced_range(fid, &lo, &hi);
    for (uint64_t b = lo; b <= hi; b += 64) {
        float x;
        uint32_t u = (uint32_t)b;
        memcpy(&x, &u, 4);
        pf_sweep_one(&st, fid, s1, NULL, x, 1.0f);
    }
    print_message("%s: max %.3f ULP (bound %g) at %a\n", name, st.max_ulp, U, (double)st.worst_x);
    assert_true(st.max_ulp <= U);
    enum { N = 4096 };
    static float x[N], y[N];
    for (int i = 0; i < N; i++) {
        uint32_t u = (uint32_t)(i * 1048573u + 12345u);
        memcpy(&x[i], &u, 4);
    }
    a1(x, y, N);
    for (int i = 0; i < N; i++) {
        float s = s1(x[i]);
        assert_memory_equal(&s, &y[i], 4);
    }
    dlclose(h);
}

static void test_emitted_meets_bound(void **st)
{
    (void)st;
    /* per-process paths: the normal and the ASan build run this at once */
    char p2[96], p8192[96];
    tu_scratch(p2, "exp2-2.c");
    tu_scratch(p8192, "exp2-8192.c");
    /* exp2: a cheap fit; two levels, the looser one no dearer */
    char *a = gen("exp2", "2", "lad_exp2_2", p2);
    char *b = gen("exp2", "2^13", "lad_exp2_8192", p8192);
    assert_non_null(strstr(a, "Regenerate:  pfmathgen --func exp2 --max-ulp 2 "));
    assert_non_null(strstr(a, " * Ladder:      --max-ulp 2: the cheapest of "));
    assert_non_null(strstr(a, " * Confirmed:   max "));
    assert_non_null(strstr(a, "sampled, not exhaustive (--confirm sample)"));
    assert_true(cost_in(b) <= cost_in(a));
    check_emitted(p2, "lad_exp2_2", "exp2", 2);
    check_emitted(p8192, "lad_exp2_8192", "exp2", 8192);
    /* deterministic: the same command writes the same bytes */
    char *a2 = gen("exp2", "2", "lad_exp2_2", p2);
    assert_string_equal(a, a2);
    free(a);
    free(a2);
    free(b);
    unlink(p2);
    unlink(p8192);
}

/* the default name spells U so that it reads back as U: 2.0000001 was
 * named as 2 (%g), one name for two functions */
static void test_default_names(void **st)
{
    (void)st;
    static const char *const cases[][2] = {
        {"2", "pf_exp2f_u2("}, {"2.0000001", "pf_exp2f_u2p0000001("}, {"2.5", "pf_exp2f_u2p5("}};
    char p[96];
    tu_scratch(p, "exp2-name.c");
    for (int i = 0; i < 3; i++) {
        unlink(p);
        tu_runl(&R, "pfmathgen", "--func", "exp2", "--max-ulp", cases[i][0], "--confirm", "sample", "-o", p, NULL);
        assert_int_equal(R.status, 0);
        char *src = tu_slurp(p, NULL);
        assert_non_null(src);
        print_message("--max-ulp %s: %s %s\n", cases[i][0], cases[i][1], strstr(src, cases[i][1]) ? "found" : "missing");
        assert_non_null(strstr(src, cases[i][1]));
        free(src);
    }
    unlink(p);
}

static void test_impossible(void **st)
{
    (void)st;
    /* correct rounding: no polynomial scheme here is predicted to reach it */
    expect_error("impossible target", "--func", "exp2", "--max-ulp", "0.5", "--confirm", "sample");
}

/* pfbench's Pareto check (tests/pfbench_ladder_pareto.c) on made-up points:
   only a pfmath point of the same ISA, at least as accurate, counts */
static void test_pareto_checks(void **st)
{
    (void)st;
    pfb_point p[] = {
        {"sleef-u35", "avx512", 0, 2.0, 3.0},   {"pfmath", "avx512", 1, 3.0, 0.9},
        {"pfmath-L4", "avx512", 2, 1.5, 3.2},   {"pfmath-L4", "avx2", 2, 0.5, 1.0},
        {"glibc", "scalar", 0, 9.0, 0.5},       {"sleef-u10", "avx2", 0, 1.0, 0.9},
    };
    char *text = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&text, &len);
    int pass = 0, miss = 0;
    pfb_pareto_checks(f, "exp", "d", p, 6, &pass, &miss);
    fclose(f);
    print_message("%s", text);
    /* u35/512: only pfmath/512 (3 ns) is as accurate: MISS at 0.67x; u10/256:
       no pfmath/256 point within 0.9 ULP; glibc scalar is not a vector peer */
    assert_int_equal(pass, 0);
    assert_int_equal(miss, 2);
    assert_non_null(strstr(text, "| sleef-u35 | 2 ns, 3 ULP | pfmath: 3 ns, 0.9 ULP | 0.67x | **MISS** |"));
    assert_non_null(strstr(text, "none as accurate"));
    free(text);
    p[2].e = 2.5; /* L4/512 now as accurate as u35 and faster */
    p[3].e = 0.8; /* L4/256 within u10's error and faster */
    text = NULL;
    f = open_memstream(&text, &len);
    pass = miss = 0;
    pfb_pareto_checks(f, "exp", "d", p, 6, &pass, &miss);
    fclose(f);
    assert_int_equal(pass, 2);
    assert_int_equal(miss, 0);
    assert_non_null(strstr(text, "pfmath-L4: 1.5 ns, 2.5 ULP | 1.33x | pass |"));
    free(text);
}

int main(void)
{
    const struct CMUnitTest t[] = {
        cmocka_unit_test(test_bad_values),
        cmocka_unit_test(test_clashes),
        cmocka_unit_test(test_emitted_meets_bound),
        cmocka_unit_test(test_impossible),
        cmocka_unit_test(test_default_names),
        cmocka_unit_test(test_pareto_checks),
    };
    return cmocka_run_group_tests(t, NULL, NULL);
}
