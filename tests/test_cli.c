/* pfmathgen's command line: bad input is exit 2 with one line on stderr and
 * no output file; good input is deterministic and reports what it emitted. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include "testutil.h"
#include "tu_exec.h"

#include <sys/stat.h>
#include <unistd.h>

static tu_run_result R;

/* the tests' files, in a directory of this run's own (mkdtemp in main), so
   that two runs at once (two clones' make test) do not share paths */
static char tdir[] = "/tmp/pf-cli-XXXXXX";
static const char *tpath(char *buf, size_t n, const char *name)
{
    snprintf(buf, n, "%s/%s", tdir, name);
    return buf;
}

/* args: NULL-terminated; run without a shell, with -o FILE appended */
static void expect_usage_error_v(const char *const *args)
{
    char ob[64];
    const char *out = tpath(ob, sizeof ob, "pfmathgen-cli-test.c");
    unlink(out);
    const char *v[40];
    int n = 0;
    char shown[1024] = "";
    for (; args[n] && n < 36; n++) {
        v[n] = args[n];
        snprintf(shown + strlen(shown), sizeof shown - strlen(shown), " '%s'", args[n]);
    }
    v[n++] = "-o";
    v[n++] = out;
    v[n] = NULL;
    tu_runv("pfmathgen", v, &R);
    print_message("pfmathgen%s -> %d: %s", shown, R.status, R.err);
    assert_int_equal(R.status, 2);
    assert_int_equal(tu_count_lines(R.err), 1);
    assert_non_null(strstr(R.err, "pfmathgen: "));
    struct stat sb;
    assert_int_not_equal(stat(out, &sb), 0); /* nothing written */
    assert_int_equal(R.out[0], 0);
}
#define expect_usage_error(...) expect_usage_error_v((const char *const[]){__VA_ARGS__, NULL})

static void test_bad_input(void **st)
{
    (void)st;
    expect_usage_error("--func", "logg", "--order", "10");
    expect_usage_error("--func", "log", "--order", "0");
    expect_usage_error("--func", "log", "--order", "31");
    expect_usage_error("--func", "log", "--order", "10x");
    expect_usage_error("--func", "log", "--order", "");
    /* the whole argument is the number, as "5 " already was (and as
       pfsweep's numbers): strtol skipped a leading blank and took a '+' */
    expect_usage_error("--func", "log", "--order", " 5");
    expect_usage_error("--func", "log", "--order", "+5");
    expect_usage_error("--func", "log", "--order", "\n5");
    expect_usage_error("--func", "log", "--variant", "quick");
    expect_usage_error("--func", "log", "--reduction", "nope");
    expect_usage_error("--func", "log", "--frobnicate");
    expect_usage_error("--func", "log", "--name", "9lives");
    expect_usage_error("--func", "log", "--type", "double");
    expect_usage_error("--func", "log", "--method", "remez");
    expect_usage_error("--order", "10");
    expect_usage_error("--func", "log", "extra");
    expect_usage_error("--func");
    /* too low for the fast variant's six constraints */
    expect_usage_error("--func", "log", "--variant", "fast", "--order", "3");
    /* a message quoting a user's newline is still one line */
    expect_usage_error("--func", "lo\ng");
}

/* issue 11 item 12: a repeated option is an error, not "the last one wins" */
static void test_repeated_options(void **st)
{
    (void)st;
    expect_usage_error("--func", "log", "--func", "sin");
    expect_usage_error("--func", "log", "--order", "5", "--order", "6");
    expect_usage_error("--func", "log", "--json", "--json");
    expect_usage_error("--func", "log", "--no-sweep", "--no-sweep");
    expect_usage_error("--func", "log", "--output", "/tmp/pf-cli-a.c"); /* with the -o appended */
    expect_usage_error("--func", "sin", "--type", "fixed<15,12>", "--type", "fixed<15,12>");
    expect_usage_error("--func", "noise2", "--type", "fixed<15,12>", "--seed", "1", "--seed", "2");
    expect_usage_error("--func", "log", "--max-rel-err", "1e-4", "--max-abs-err", "1e-4");
    assert_non_null(strstr(R.err, "only one of"));
}

/* --seed as pfsweep's and pfbench's numbers: decimal or 0x hex, the whole
 * argument.  strtoull(s, 0) read "010" as octal 8 (another lattice than
 * the user's 10, silently) and took a leading blank or '+'. */
static void test_seed(void **st)
{
    (void)st;
    const char *bad[] = {" 1", "+1", "1 ", "-1", "", "0x", "0x-1", "1e3", "18446744073709551616"};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++)
        expect_usage_error("--func", "noise2", "--type", "fixed<15,12>", "--seed", bad[i]);
    tu_runl(&R, "pfmathgen", "--func", "noise2", "--type", "fixed<15,12>", "--seed", "010", NULL);
    assert_int_equal(R.status, 0);
    assert_non_null(strstr(R.out, "pf_noise_table_seed(10)"));
    tu_runl(&R, "pfmathgen", "--func", "noise2", "--type", "fixed<15,12>", "--seed", "0x10", NULL);
    assert_int_equal(R.status, 0);
    assert_non_null(strstr(R.out, "pf_noise_table_seed(16)"));
    tu_runl(&R, "pfmathgen", "--func", "noise2", "--type", "fixed<15,12>", "--seed", "18446744073709551615", NULL);
    assert_int_equal(R.status, 0);
}

/* issue 11 item 11: --name is a C identifier, not a keyword, and never cut */
static void test_names(void **st)
{
    (void)st;
    const char *kw[] = {"int", "while", "_Bool", "restrict", "_Static_assert", "inline", "main", "__x", "_Foo"};
    for (size_t i = 0; i < sizeof kw / sizeof kw[0]; i++)
        expect_usage_error("--func", "log", "--name", kw[i]);
    expect_usage_error("--func", "sin", "--type", "fixed<15,12>", "--name", "float");
    expect_usage_error("--func", "noise3", "--type", "fixed<15,12>", "--name", "char");
    expect_usage_error("--func", "log", "--name", "caf\xc3\xa9");
    /* names of the headers the emitted C includes, or reserved for them:
       logf compiled and replaced libm's; memcpy failed after the fit */
    const char *libc[] = {"logf", "sqrtf", "log", "expl", "fmaf", "memcpy", "strlen", "NAN", "INT64_C",
                          "uint8_t", "size_t", "_x"};
    for (size_t i = 0; i < sizeof libc / sizeof libc[0]; i++)
        expect_usage_error("--func", "log", "--variant", "fast", "--no-sweep", "--name", libc[i]);
    expect_usage_error("--func", "sqrt", "--type", "ufixed<8,8>", "--no-sweep", "--name", "sqrtf");
    /* noise's NAME1 .. NAME4: expm1 */
    expect_usage_error("--func", "noise", "--type", "fixed<15,12>", "--out-type", "fixed<15,14>", "--no-sweep",
                       "--name", "expm");
    /* names that only start or end like them are names */
    const char *fine[] = {"logfx", "my_logf", "expf_fast", "str_2", "uint8", "INT64"};
    for (size_t i = 0; i < sizeof fine / sizeof fine[0]; i++) {
        tu_runl(&R, "pfmathgen", "--func", "log", "--variant", "fast", "--no-sweep", "--name", fine[i], NULL);
        assert_int_equal(R.status, 0);
    }
    char longname[160];
    memset(longname, 'a', 128);
    longname[128] = 0;
    expect_usage_error("--func", "log", "--name", longname);
    assert_non_null(strstr(R.err, "at most 100"));
    /* the longest allowed name is used whole */
    longname[100] = 0;
    tu_runl(&R, "pfmathgen", "--func", "log", "--variant", "fast", "--no-sweep", "--name", longname, NULL);
    assert_int_equal(R.status, 0);
    char decl[200];
    snprintf(decl, sizeof decl, "float %s(float x)", longname);
    assert_non_null(strstr(R.out, decl));
}

static void test_help(void **st)
{
    (void)st;
    tu_runl(&R, "pfmathgen", "--help", NULL);
    assert_int_equal(R.status, 0);
    assert_non_null(strstr(R.out, "usage: pfmathgen"));
    assert_non_null(strstr(R.out, "--order"));
}

/* Same command, byte-identical file; the file carries its provenance. */
static void test_deterministic(void **st)
{
    (void)st;
    size_t n1, n2;
    char pa[64], pb[64], cmd[160];
    tpath(pa, sizeof pa, "pf-det-a.c");
    tpath(pb, sizeof pb, "pf-det-b.c");
    tu_runl(&R, "pfmathgen", "--func", "log", "--order", "10", "-o", pa, NULL);
    assert_int_equal(R.status, 0);
    rename(pa, pb);
    tu_runl(&R, "pfmathgen", "--func", "log", "--order", "10", "-o", pa, NULL);
    assert_int_equal(R.status, 0);
    char *a = tu_slurp(pa, &n1), *b = tu_slurp(pb, &n2);
    assert_non_null(a);
    assert_non_null(b);
    assert_int_equal(n1, n2);
    assert_memory_equal(a, b, n1);
    snprintf(cmd, sizeof cmd, "pfmathgen --func log --order 10 -o %s", pa);
    assert_non_null(strstr(a, cmd));
    assert_non_null(strstr(a, "Order:       10"));
    assert_non_null(strstr(a, "Constraints: p(0) = 0, p'(0) = 1"));
    assert_non_null(strstr(a, "Max relative error"));
    assert_non_null(strstr(a, "Sweep:"));
    assert_non_null(strstr(a, "0x1p+0f,")); /* c1 = 1 in hex-float */
    unlink(pa);
    unlink(pb);
    free(a);
    free(b);
}

static double json_num(const char *s, const char *key)
{
    char k[64];
    snprintf(k, sizeof k, "\"%s\": ", key);
    const char *p = strstr(s, k);
    assert_non_null(p);
    return strtod(p + strlen(k), NULL);
}

static void test_json(void **st)
{
    (void)st;
    tu_runl(&R, "pfmathgen", "--func", "log", "--order", "10", "--json", NULL);
    assert_int_equal(R.status, 0);
    assert_int_equal(tu_count_lines(R.out), 1);
    const char *keys[] = {"\"func\": \"log\"", "\"variant\": \"exact\"", "\"type\": \"float\"",
                          "\"order\": 10", "\"domain\":", "\"coefficients\": [\"0x0p+0\", \"0x1p+0\"",
                          "\"max_rel_error\":", "\"sweep\":", "\"max_ulp\":", "\"mean_ulp\":",
                          "\"count\":", "\"worst_input\":"};
    for (size_t i = 0; i < sizeof keys / sizeof keys[0]; i++)
        assert_non_null(strstr(R.out, keys[i]));
    /* the seed: order 10 is "within floating point precision" (2^-24) */
    double e = json_num(R.out, "max_rel_error");
    assert_true(e > 0 && e < 0x1p-24);
    assert_true(json_num(R.out, "max_ulp") <= 1.0);
    tu_runl(&R, "pfmathgen", "--func", "log", "--order", "10", "--reduction", "seed", "--json", NULL);
    assert_int_equal(R.status, 0);
    e = json_num(R.out, "max_rel_error");
    assert_true(e > 0 && e < 0x1p-24);
}

/* --target with fixed types: the smallest order whose emitted polynomial is
 * within half an LSB of the type (absolute), and the order below is not. */
/* "-o -" is standard output as no -o is (it wrote a file named '-'); a plot
 * is SVG, so --plot x.png is refused (it wrote SVG into x.png) */
static void test_dash_and_plot_names(void **st)
{
    (void)st;
    expect_usage_error("--func", "log", "--order", "6", "--plot", "x.png");
    expect_usage_error("--func", "log", "--order", "6", "--plot", "-");
    char here[4096];
    assert_non_null(getcwd(here, sizeof here));
    assert_int_equal(chdir(tdir), 0);
    tu_runv("pfmathgen", (const char *const[]){"--func", "log", "--order", "6", "--no-sweep", "-o", "-", NULL}, &R);
    struct stat sb;
    int dash = stat("-", &sb);
    assert_int_equal(R.status, 0);
    assert_int_equal(strncmp(R.out, "/* pf_logf: ", 12), 0);
    assert_int_not_equal(dash, 0);
    tu_runv("pfmathgen", (const char *const[]){"--func", "log", "--order", "6", "--json", "-o", "-", NULL}, &R);
    dash = stat("-", &sb);
    assert_int_equal(chdir(here), 0);
    assert_int_equal(R.status, 2);
    assert_int_equal(tu_count_lines(R.err), 1);
    assert_int_equal(R.out[0], 0);
    assert_int_not_equal(dash, 0);
}

/* --json with -o when standard output is full (/dev/full): the run fails
 * (exit 1, one line) and -o's file is not written; before, the C file was
 * written and then the JSON failed */
static void test_json_stdout_full(void **st)
{
    (void)st;
    int full = open("/dev/full", O_WRONLY);
    if (full < 0)
        skip();
    static const char *const cases[][12] = {
        {"--func", "log", "--order", "6", "--no-sweep", "--json", "-o", NULL},
        {"--func", "exp", "--type", "fixed<15,11>", "--out-type", "ufixed<16,8>", "--no-sweep", "--json", "-o", NULL},
    };
    for (size_t c = 0; c < 2; c++) {
        char ob[64], eb[64], prog[PATH_MAX];
        const char *out = tpath(ob, sizeof ob, "json-full.c"), *errf = tpath(eb, sizeof eb, "json-full.err");
        unlink(out);
        tu_prog_path("pfmathgen", prog, sizeof prog);
        const char *v[16] = {prog};
        size_t n = 1;
        for (size_t i = 0; cases[c][i]; i++)
            v[n++] = cases[c][i];
        v[n++] = out;
        v[n] = NULL;
        pid_t pid = fork();
        if (pid == 0) {
            int e = open(errf, O_WRONLY | O_CREAT | O_TRUNC, 0600);
            dup2(full, 1);
            dup2(e, 2);
            execv(prog, (char *const *)v);
            _exit(127);
        }
        int stt = 0;
        assert_true(pid > 0 && waitpid(pid, &stt, 0) == pid);
        struct stat sb;
        assert_true(WIFEXITED(stt));
        assert_int_equal(WEXITSTATUS(stt), 1);
        assert_int_not_equal(stat(out, &sb), 0);
        char msg[2048] = "";
        FILE *f = fopen(errf, "r");
        assert_non_null(f);
        size_t k = fread(msg, 1, sizeof msg - 1, f);
        msg[k] = 0;
        fclose(f);
        unlink(errf);
        assert_int_equal(tu_count_lines(msg), 1);
        assert_non_null(strstr(msg, "standard output"));
    }
    close(full);
}

static void test_target_fixed(void **st)
{
    (void)st;
    const struct {
        const char *type;
        double half_lsb;
    } t[] = {{"fixed<15,14>", 0x1p-15}, {"unsigned fixed<8,8>", 0x1p-9}, {"fixed<31,16>", 0x1p-17}};
    for (size_t i = 0; i < sizeof t / sizeof t[0]; i++) {
        tu_runl(&R, "pfmathgen", "--func", "log", "--no-sweep", "--json", "--target", t[i].type, NULL);
        assert_int_equal(R.status, 0);
        double e = json_num(R.out, "max_abs_error"), below = json_num(R.out, "order_below_error");
        print_message("--target %s: order %d, max abs error %.3g (half LSB %.3g), order below %.3g\n", t[i].type,
                      (int)json_num(R.out, "order"), e, t[i].half_lsb, below);
        assert_true(e <= t[i].half_lsb);
        assert_true(below > t[i].half_lsb);
    }
    expect_usage_error("--func", "log", "--target", "fixed<15");
    expect_usage_error("--func", "log", "--target", "float", "--max-rel-err", "1e-4");
    expect_usage_error("--func", "log", "--order", "3", "--target", "float");
    expect_usage_error("--func", "log", "--max-rel-err", "2^-80");
}

int main(void)
{
    if (!mkdtemp(tdir)) {
        perror("mkdtemp");
        return 1;
    }
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_bad_input),
        cmocka_unit_test(test_repeated_options),
        cmocka_unit_test(test_seed),
        cmocka_unit_test(test_names),
        cmocka_unit_test(test_help),
        cmocka_unit_test(test_deterministic),
        cmocka_unit_test(test_json),
        cmocka_unit_test(test_target_fixed),
        cmocka_unit_test(test_dash_and_plot_names),
        cmocka_unit_test(test_json_stdout_full),
    };
    int rc = cmocka_run_group_tests(tests, NULL, NULL);
    rmdir(tdir);
    return rc;
}
