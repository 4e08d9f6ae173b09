/* pfmathgen with fixed-point types, through its command line: the issue's
 * sin example emits integer-only C with the stored-integer signature and the
 * provenance block, is exhaustively within 1 LSB of MPFR, and is
 * deterministic; bad types and pairs are one-line errors (exit 2) that
 * write nothing; the fast variant is cheaper and within its bound. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include "compile.h"
#include "sweep_fixed.h"
#include "tu_exec.h"

#include <dlfcn.h>
#include <sys/stat.h>

static tu_run_result R;
static char dir[64];

static int run_gen(const char *args, const char *out)
{
    char a[1024];
    snprintf(a, sizeof a, "%s -o %s", args, out);
    tu_runs("pfmathgen", a, &R);
    if (R.status != 0)
        print_message("pfmathgen %s -> %d: %s\n", a, R.status, R.err);
    return R.status;
}

static int setup(void **st)
{
    (void)st;
    snprintf(dir, sizeof dir, "/tmp/pf-fxgen-XXXXXX");
    return mkdtemp(dir) ? 0 : -1;
}

static int teardown(void **st)
{
    (void)st;
    return tu_rm_tree(dir) == 0 ? 0 : -1;
}

static void test_sin_example(void **st)
{
    (void)st;
    char out[128];
    snprintf(out, sizeof out, "%s/my_sin.c", dir);
    const char *args = "--func sin --type 'fixed<15,12>' --out-type 'fixed<15,14>' --variant exact --name my_sin";
    assert_int_equal(run_gen(args, out), 0);
    char *src = tu_slurp(out, NULL);
    assert_non_null(src);
    /* integer-only C: no floating-point type, no <math.h>, in the code */
    char *code = tu_strip_comments(src);
    assert_null(strstr(code, "float"));
    assert_null(strstr(code, "double"));
    assert_null(strstr(code, "math.h"));
    assert_non_null(strstr(code, "int16_t my_sin(int16_t x)"));
    assert_non_null(strstr(code, "void my_sin_array(const int16_t *x, int16_t *y, size_t n)"));
    free(code);
    /* provenance: the regenerating command, types, method, the sweep */
    char cmdline[512];
    snprintf(cmdline, sizeof cmdline, " * Regenerate:  pfmathgen %s -o %s\n", args, out);
    assert_non_null(strstr(src, cmdline));
    assert_non_null(strstr(src, "sin for fixed<15,12> -> fixed<15,14> (int16_t -> int16_t), exact variant"));
    /* the register-table kernel (fixed_trig.c, kind 4): 16 or 32 segments */
    assert_non_null(strstr(src, " * Domain:      sin(pi/2 (j + tau) 2^-"));
    assert_non_null(strstr(src, "on tau in [0, 1)"));
    assert_non_null(strstr(src, " * Method:      per segment"));
    assert_non_null(strstr(src, " * Constraints: "));
    assert_non_null(strstr(src, " * Formats:     "));
    assert_non_null(strstr(src, " * Sweep:       max 0."));
    assert_non_null(strstr(src, "exhaustive: all"));
    /* the emitted code, compiled here, against MPFR on every input */
    char err[512];
    void *h = pf_compile_load_file(out, err, sizeof err);
    if (!h)
        print_message("%s\n", err);
    assert_non_null(h);
    pf_fx_fn fn = {dlsym(h, "my_sin"), dlsym(h, "my_sin_array"), pf_fmt_make(1, 15, 12), pf_fmt_make(1, 15, 14)};
    assert_non_null(fn.scalar);
    assert_non_null(fn.array);
    pf_fx_stats s;
    pf_fx_stats_init(&s);
    pf_fx_sweep_range(&s, PF_SIN, &fn, -32768, 32767, 1, 0);
    pf_fx_stats_print(stdout, "my_sin, every input", PF_SIN, fn.in, fn.out, &s, 0);
    assert_int_equal(s.count, 65536);
    assert_true(s.max_err < 1.0);
    assert_int_equal(s.mismatch, 0);
    /* a few values by hand: sin(0) = 0, sin(pi/2) = 1 (x = 6434 ~ 1.5708) */
    int16_t (*f)(int16_t);
    *(void **)&f = fn.scalar;
    assert_int_equal(f(0), 0);
    assert_int_equal(f(6434), 16384);
    assert_int_equal(f(-6434), -16384);
    dlclose(h);
    /* pfsweep --type/--out-type on the same file: exhaustive, same figures */
    char a[512];
    snprintf(a, sizeof a, "--func sin --type 'fixed<15,12>' --out-type 'fixed<15,14>' --source %s --name my_sin --max-lsb 1",
             out);
    tu_runs("pfsweep", a, &R);
    print_message("%s", R.out);
    assert_int_equal(R.status, 0);
    assert_non_null(strstr(R.out, "count=65536 over_fast=0 mismatch=0"));
    char tot[64];
    snprintf(tot, sizeof tot, "TOTAL max_lsb=%.6f", s.max_err);
    assert_non_null(strstr(R.out, tot));
    assert_non_null(strstr(R.out, "histogram"));
    /* a bound it does not meet: status 1 */
    snprintf(a, sizeof a, "--func sin --type 'fixed<15,12>' --out-type 'fixed<15,14>' --source %s --name my_sin --max-lsb 0.5",
             out);
    tu_runs("pfsweep", a, &R);
    assert_int_equal(R.status, 1);
    /* bad usage: status 2 */
    tu_runs("pfsweep", "--func sin --type 'fixed<15,12' --source x.c", &R);
    assert_int_equal(R.status, 2);
    tu_runs("pfsweep", "--func tan --type 'fixed<15,12>'", &R);
    assert_int_equal(R.status, 2);
    free(src);
}

static void test_deterministic(void **st)
{
    (void)st;
    char out[128];
    snprintf(out, sizeof out, "%s/det.c", dir);
    const char *args = "--func exp --type 'fixed<15,11>' --out-type 'ufixed<16,8>'";
    assert_int_equal(run_gen(args, out), 0);
    char *a = tu_slurp(out, NULL);
    assert_int_equal(run_gen(args, out), 0);
    char *b = tu_slurp(out, NULL);
    assert_non_null(a);
    assert_non_null(b);
    assert_string_equal(a, b);
    /* the default name and the unsigned output */
    assert_non_null(strstr(a, "uint16_t pf_exp_q11_uq8(int16_t x)"));
    free(a);
    free(b);
}

static void expect_error(const char *args)
{
    char a[1024], out[128];
    snprintf(out, sizeof out, "%s/bad.c", dir);
    unlink(out);
    snprintf(a, sizeof a, "%s -o %s", args, out);
    tu_runs("pfmathgen", a, &R);
    print_message("pfmathgen %s -> %d: %s", args, R.status, R.err);
    assert_int_equal(R.status, 2);
    assert_int_equal(tu_count_lines(R.err), 1);
    assert_non_null(strstr(R.err, "pfmathgen: "));
    struct stat sb;
    assert_int_not_equal(stat(out, &sb), 0);
    assert_int_equal(R.out[0], 0);
}

static void test_bad_types_and_pairs(void **st)
{
    (void)st;
    expect_error("--func sin --type 'fixed<15>'");
    expect_error("--func sin --type 'fixed<15,12' --out-type 'fixed<15,14>'");
    expect_error("--func sin --type 'fixed<15,12>' --out-type 'fixed<15,14>,'");
    expect_error("--func sin --type 'fixed<40,20>'");           /* 64-bit storage */
    expect_error("--func sin --type 'fixed<15,12>' --out-type 'ufixed<40,14>'");
    expect_error("--func sin --type float --out-type 'fixed<15,14>'"); /* float and fixed */
    expect_error("--func sin --type 'fixed<15,12>' --out-type float");
    expect_error("--func sin --type 'fixed<15,12>' --out-type 'ufixed<16,14>'"); /* sin < 0 */
    expect_error("--func cos --type 'fixed<15,12>' --out-type 'unsigned fixed<16,14>'");
    expect_error("--func log --type 'ufixed<16,8>' --out-type 'ufixed<16,11>'"); /* log < 0 */
    expect_error("--func log2 --type 'ufixed<16,8>' --out-type 'ufixed<16,11>'");
    expect_error("--func tan --type 'fixed<15,12>'");            /* no fixed-point tan */
    expect_error("--func sin --type 'fixed<15,12>' --target 'fixed<15,14>'");
    expect_error("--func sin --type 'fixed<15,12>' --variant quick");
    expect_error("--func sin --type 'fixed<15,12>' --order 0");
    expect_error("--func sin --type 'fixed<15,12>' --name 9lives");
    expect_error("--type 'fixed<15,12>'");
    /* the input's format is not the output's by default (it was, silently) */
    expect_error("--func sin --out-type 'fixed<15,14>'");
    expect_error("--func noise2 --out-type 'fixed<15,15>'");
    /* an order below what the exact bound needs */
    expect_error("--func sin --type 'fixed<15,12>' --out-type 'fixed<15,14>' --order 3");
}

/* The 16-bit table, segment and sqrtf kernels choose their own order and
 * coefficients: an --order or --method they would not use is refused (exit
 * 2, one line naming the option, no file), not silently dropped as before
 * 2026-12-07.  Kernels that fit a polynomial still take both. */
static void test_order_method_not_ignored(void **st)
{
    (void)st;
    static const char *const pairs[] = {
        "--func exp --type 'fixed<15,11>' --out-type 'ufixed<16,8>'",
        "--func exp2 --type 'fixed<15,11>' --out-type 'ufixed<16,8>' --variant fast",
        "--func log --type 'ufixed<16,8>' --out-type 'fixed<15,11>'",
        "--func log2 --type 'ufixed<16,8>' --out-type 'fixed<15,11>' --variant fast",
        "--func sqrt --type 'ufixed<16,8>' --out-type 'ufixed<16,12>'",
    };
    char a[512];
    for (size_t i = 0; i < sizeof pairs / sizeof pairs[0]; i++) {
        snprintf(a, sizeof a, "%s --order 3", pairs[i]);
        expect_error(a);
        assert_non_null(strstr(R.err, "--order does not apply"));
        snprintf(a, sizeof a, "%s --method lsq", pairs[i]);
        expect_error(a);
        assert_non_null(strstr(R.err, "--method does not apply"));
    }
    /* the fast sin quintic's coefficients come from a search, not a fit */
    expect_error("--func sin --type 'fixed<15,12>' --out-type 'fixed<15,14>' --variant fast --method minimax");
    assert_non_null(strstr(R.err, "--method does not apply"));
    /* with --order, sin takes the Horner kernel, which fits by the method asked */
    tu_runs("pfmathgen",
            "--func sin --type 'fixed<15,12>' --out-type 'fixed<15,14>' --variant fast --order 5 --method minimax "
            "--no-sweep --json",
            &R);
    assert_int_equal(R.status, 0);
    assert_non_null(strstr(R.out, "\"method\": \"minimax\""));
    tu_runs("pfmathgen", "--func exp --type 'fixed<31,16>' --method lsq --variant fast --no-sweep --json", &R);
    assert_int_equal(R.status, 0);
    assert_non_null(strstr(R.out, "\"method\": \"lsq\""));
}

static int json_int(const char *s, const char *key)
{
    const char *p = strstr(s, key);
    return p ? atoi(p + strlen(key)) : -1;
}

/* n of a kernel text's "n-entry tables" (0 if none) */
static int entries(const char *k)
{
    const char *e = strstr(k, "-entry");
    while (e && e > k && e[-1] >= '0' && e[-1] <= '9')
        e--;
    return e ? atoi(e) : 0;
}

/* The fast sin/cos quintic (fixed_trig.c, kind 6): sin(pi/2 t) ~ t p(t)
 * 2^-Eo, p = C1 - t^2 C3/2 + t^4 C5/4 (its multiply-highs' scales), read
 * from the emitted file's Formats line.  The fold puts mirrored pieces side by side at
 * t = 1, so the fast variant's seam rule asks value 1 and slope 0 there:
 * 4 C1 - 2 C3 + C5 = 4 2^Eo and 4 C1 - 6 C3 + 5 C5 = 0, exactly. */
static void seam_matched(const char *args, int Eo)
{
    char a[600], path[300];
    snprintf(path, sizeof path, "%s/seam.c", dir);
    snprintf(a, sizeof a, "%s --variant fast -o %s", args, path);
    tu_runs("pfmathgen", a, &R);
    assert_int_equal(R.status, 0);
    char *src = tu_slurp(path, NULL);
    assert_non_null(src);
    const char *fm = strstr(src, "Formats:");
    assert_non_null(fm);
    const char *p5 = strstr(fm, "C5 = "), *p3 = strstr(fm, "C3 = "), *p1 = strstr(fm, "C1 = ");
    assert_true(p5 && p3 && p1);
    long c5 = atol(p5 + 5), c3 = atol(p3 + 5), c1 = atol(p1 + 5);
    print_message("  seam: C1 %ld C3 %ld C5 %ld: value %ld/%ld, slope %ld\n", c1, c3, c5, 4 * c1 - 2 * c3 + c5,
                  4L << Eo, 4 * c1 - 6 * c3 + 5 * c5);
    assert_true(c1 > 0 && c3 > 0 && c5 > 0);
    assert_int_equal(4 * c1 - 2 * c3 + c5, 4L << Eo);
    assert_int_equal(4 * c1 - 6 * c3 + 5 * c5, 0);
    free(src);
    unlink(path);
}

static void test_fast_variant(void **st)
{
    (void)st;
    /* log2 from a signed input: the Horner form (ufixed<16,8> takes the table kernel, which has no order) */
    const char *types[] = {"--func sin --type 'fixed<15,12>' --out-type 'fixed<15,14>'",
                           "--func log2 --type 'fixed<15,8>' --out-type 'fixed<15,11>'"};
    for (int i = 0; i < 2; i++) {
        char a[512];
        snprintf(a, sizeof a, "%s --variant fast --json", types[i]);
        tu_runs("pfmathgen", a, &R);
        assert_int_equal(R.status, 0);
        int of = json_int(R.out, "\"order\": ");
        assert_int_equal(json_int(R.out, "\"over_fast\": "), 0);
        assert_non_null(strstr(R.out, "\"exhaustive\": true"));
        /* a kernel without one polynomial (sin's register tables): its text */
        char kf[400] = "";
        const char *k = strstr(R.out, "\"kernel\": \"");
        if (k)
            snprintf(kf, sizeof kf, "%.*s", (int)strcspn(k + 11, "\""), k + 11);
        snprintf(a, sizeof a, "%s --json", types[i]);
        tu_runs("pfmathgen", a, &R);
        assert_int_equal(R.status, 0);
        int oe = json_int(R.out, "\"order\": ");
        print_message("%s: fast order %d, exact order %d\n", types[i], of, oe);
        char ke[400] = "";
        k = strstr(R.out, "\"kernel\": \"");
        if (k)
            snprintf(ke, sizeof ke, "%.*s", (int)strcspn(k + 11, "\""), k + 11);
        if (oe < 0 && ke[0]) { /* exact: sin's register tables, a polynomial per segment */
            print_message("  exact kernel: %s\n", ke);
            assert_non_null(strstr(ke, " per segment"));
            if (of < 0 && kf[0] && strstr(kf, "no tables")) { /* fast: one polynomial, no lookups */
                print_message("  fast kernel: %s\n", kf);
                assert_true(atoi(kf) > 0 && strstr(kf, " per segment") == NULL);
                seam_matched(types[i], 14);
            } else if (of < 0 && kf[0]) { /* fast: tables too, fewer entries or a lower degree */
                print_message("  fast kernel: %s\n", kf);
                assert_non_null(strstr(kf, " per segment"));
                assert_true(entries(kf) > 0 && entries(kf) <= entries(ke));
                assert_true(entries(kf) < entries(ke) || atoi(kf) < atoi(ke));
            } else
                assert_true(of > 0);
        } else
            assert_true(of > 0 && of < oe);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sin_example),
        cmocka_unit_test(test_deterministic),
        cmocka_unit_test(test_bad_types_and_pairs),
        cmocka_unit_test(test_order_method_not_ignored),
        cmocka_unit_test(test_fast_variant),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
