/* pfmathgen --func noise…: command-line errors (exit 2, one line, nothing
 * written); type pairs generated, compiled with -Wall -Wextra -Werror,
 * loaded and compared with the exact noise (ref/pfref_noise.c, MPFR) on
 * lattice points, cell edges ± 1 lsb, negative values, the period-256 wrap,
 * the type's extremes and random points (every error < 1 LSB); exact zeros
 * at lattice points; period 256; the array forms equal the scalar ones;
 * agreement with the library's pf_noiseN_q15 for Q16.16 -> Q15; --seed
 * lattices; byte-identical output for the same command.  The reference is
 * itself checked against the library's float noise. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include "fixedtype.h"
#include "pfnoise.h"
#include "pfref_noise.h"
#include "tu_exec.h"

#include <dlfcn.h>
#include <math.h>

static tu_run_result R;

static uint64_t rng = 0x243f6a8885a308d3u;
static uint64_t rnd(void)
{
    uint64_t z = (rng += 0x9e3779b97f4a7c15u);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
    return z ^ (z >> 31);
}

/* ---- calling a generated function of any storage pair ---- */

static int kind(const pf_type *t) { return (t->storage_bits == 8 ? 0 : t->storage_bits == 16 ? 2 : 4) + !t->is_signed; }

#define CALL(TI, TO)                                                                                         \
    switch (n) {                                                                                             \
    case 1: return (int64_t)((TO(*)(TI))fp)((TI)q[0]);                                                       \
    case 2: return (int64_t)((TO(*)(TI, TI))fp)((TI)q[0], (TI)q[1]);                                         \
    case 3: return (int64_t)((TO(*)(TI, TI, TI))fp)((TI)q[0], (TI)q[1], (TI)q[2]);                           \
    default: return (int64_t)((TO(*)(TI, TI, TI, TI))fp)((TI)q[0], (TI)q[1], (TI)q[2], (TI)q[3]);            \
    }
#define OUTS(TI)                                                                                             \
    switch (ko) {                                                                                            \
    case 0: CALL(TI, int8_t);                                                                                \
    case 1: CALL(TI, uint8_t);                                                                               \
    case 2: CALL(TI, int16_t);                                                                               \
    case 3: CALL(TI, uint16_t);                                                                              \
    case 4: CALL(TI, int32_t);                                                                               \
    default: CALL(TI, uint32_t);                                                                             \
    }

static int64_t call(void *fp, int n, const pf_type *in, const pf_type *out, const int64_t *q)
{
    int ko = kind(out);
    switch (kind(in)) {
    case 0: OUTS(int8_t);
    case 1: OUTS(uint8_t);
    case 2: OUTS(int16_t);
    case 3: OUTS(uint16_t);
    case 4: OUTS(int32_t);
    default: OUTS(uint32_t);
    }
}

/* ---- generation ---- */

static int gen(const char *args, const char *path)
{
    char a[1024];
    unlink(path);
    snprintf(a, sizeof a, "%s -o %s", args, path);
    tu_runs("pfmathgen", a, &R);
    if (R.status != 0)
        print_message("pfmathgen %s: exit %d\n%s", a, R.status, R.err);
    return R.status;
}

/* compiled as a user would, warnings as errors; opt "-O0" or "-O2" (the
 * generator measured its -O2 build; -O0 here also checks that the bits do
 * not depend on the flags, and compiles ten times faster) */
static void *load(const char *c, const char *so, const char *opt)
{
    tu_argv *a = calloc(1, sizeof *a);
    tu_run_result *r = malloc(sizeof *r);
    assert_non_null(a);
    assert_non_null(r);
    tu_argv_words(a, "cc -std=c17");
    tu_argv_words(a, opt);
    tu_argv_words(a, "-Wall -Wextra -Werror -fPIC -shared -o");
    tu_argv_add(a, so);
    tu_argv_add(a, c);
    tu_execvp_in(NULL, a->v, r);
    if (r->status != 0)
        print_message("cc %s %s: exit %d\n%s%s", opt, c, r->status, r->out, r->err);
    assert_int_equal(r->status, 0);
    free(a);
    free(r);
    void *h = dlopen(so, RTLD_NOW | RTLD_LOCAL);
    assert_non_null(h);
    return h;
}

/* special coordinates: lattice points ± 1 lsb, cell middles, the period
 * wrap (±256 cells), negatives, the type's extremes */
static int specials(const pf_type *in, int64_t *v)
{
    int64_t lo = pf_type_min_stored(in), hi = pf_type_max_stored(in);
    int m = 0, F = in->exp;
    static const int cells[] = {-300, -256, -255, -3, -1, 0, 1, 2, 7, 255, 256, 257, 300};
    for (size_t c = 0; c < sizeof cells / sizeof cells[0]; c++)
        for (int j = 0; j < 4; j++) {
            if (ldexp(fabs((double)cells[c]), F) > 4e18)
                continue;
            int64_t x = cells[c] * ((int64_t)1 << F) + (j == 3 ? ((int64_t)1 << (F - 1)) : j - 1);
            if (x >= lo && x <= hi)
                v[m++] = x;
        }
    v[m++] = lo;
    v[m++] = lo + 1;
    v[m++] = hi - 1;
    v[m++] = hi;
    return m;
}

/* every sampled error < 1 LSB against MPFR; lattice points give 0 */
static double check_dim(void *h, const char *name, int n, const pf_type *in, const pf_type *out,
                        const pf_noise_table *tab, int npts)
{
    void *fp = dlsym(h, name);
    assert_non_null(fp);
    int64_t lo = pf_type_min_stored(in), hi = pf_type_max_stored(in), sp[64];
    uint64_t range = (uint64_t)(hi - lo) + 1;
    int ns = specials(in, sp);
    int64_t olo = pf_type_min_stored(out), ohi = pf_type_max_stored(out);
    double worst = 0;
    for (int i = 0; i < npts; i++) {
        int64_t q[4] = {0, 0, 0, 0};
        for (int k = 0; k < n; k++)
            q[k] = i % 2 ? sp[rnd() % (uint64_t)ns] : lo + (int64_t)(rnd() % range);
        int64_t got = call(fp, n, in, out, q);
        double e = pfref_noise_err_lsb(n, tab, q, in->exp, got, out->exp, olo, ohi);
        if (!(e < 1))
            fail_msg("%s(%lld, %lld, %lld, %lld) = %lld: %.4f LSB", name, (long long)q[0], (long long)q[1],
                     (long long)q[2], (long long)q[3], (long long)got, e);
        worst = fmax(worst, e);
        /* the correctly rounded value is at most one step away */
        int64_t cr = pfref_noise_round(n, tab, q, in->exp, out->exp, olo, ohi);
        assert_true(llabs(cr - got) <= 1);
    }
    /* lattice points: exactly 0 */
    for (int i = 0; i < 64; i++) {
        int64_t q[4];
        for (int k = 0; k < n; k++) {
            int64_t c = (int64_t)(rnd() % 600) - 300;
            q[k] = ldexp(fabs((double)c), in->exp) < 4e18 ? c * ((int64_t)1 << in->exp) : 0;
            if (q[k] < lo || q[k] > hi)
                q[k] = 0;
        }
        assert_int_equal(call(fp, n, in, out, q), 0);
    }
    return worst;
}

/* period 256: the same bits one period (2^(F+8) stored) apart */
static void check_period(void *h, const char *name, int n, const pf_type *in, const pf_type *out)
{
    void *fp = dlsym(h, name);
    int64_t lo = pf_type_min_stored(in), hi = pf_type_max_stored(in), P = (int64_t)1 << (in->exp + 8);
    if (hi - lo < P)
        return;
    for (int i = 0; i < 2000; i++) {
        int64_t q[4], q2[4];
        int k = i % n;
        for (int j = 0; j < n; j++)
            q[j] = q2[j] = lo + (int64_t)(rnd() % ((uint64_t)(hi - lo) + 1));
        q[k] = lo + (int64_t)(rnd() % (uint64_t)(hi - lo - P + 1));
        q2[k] = q[k] + P;
        assert_true(call(fp, n, in, out, q) == call(fp, n, in, out, q2));
    }
}

/* a file NAME in this run's scratch directory (tu_exec.h); four paths live
 * at once, enough for one call's arguments */
static const char *nzp(const char *name)
{
    static char pool[4][96];
    static unsigned k;
    char *b = pool[k++ % 4];
    snprintf(b, sizeof pool[0], "%s/nzg-%s", tu_scratch_dir(), name);
    return b;
}

typedef struct {
    const char *in, *out;
    int npts;
} pair;

static void run_pair(const pair *p, const char *funcs, int seed)
{
    pf_type in, out;
    char err[200], args[512], c[96], so[96], name[160];
    assert_int_equal(pf_type_parse(p->in, &in, err, sizeof err), 0);
    assert_int_equal(pf_type_parse(p->out, &out, err, sizeof err), 0);
    static int run; /* a fresh .so path per run: dlopen caches by path */
    run++;
    snprintf(c, sizeof c, "%s/nzg-%d.c", tu_scratch_dir(), run);
    snprintf(so, sizeof so, "%s/nzg-%d.so", tu_scratch_dir(), run);
    snprintf(args, sizeof args, "--func %s --type '%s' --out-type '%s' --name nz%s", funcs, p->in, p->out,
             seed ? " --seed 7" : "");
    assert_int_equal(gen(args, c), 0);
    char *src = tu_slurp(c, NULL);
    assert_non_null(src);
    /* the provenance: command and a measured error below 1 LSB per function */
    assert_non_null(strstr(src, "Regenerate:  pfmathgen --func"));
    int nm = 0;
    for (const char *m = strstr(src, "Measured:    max "); m; m = strstr(m + 1, "Measured:    max ")) {
        assert_true(atof(m + 17) < 1);
        nm++;
    }
    assert_int_equal(nm, strcmp(funcs, "noise") ? 1 : 4);
    free(src);
    void *h = load(c, so, "-O0");
    pf_noise_table seeded;
    pf_noise_table_seed(&seeded, 7);
    const pf_noise_table *tab = seed ? &seeded : pf_noise_default_table();
    for (int n = 1; n <= 4; n++) {
        if (strcmp(funcs, "noise"))
            if (funcs[5] - '0' != n)
                continue;
        snprintf(name, sizeof name, strcmp(funcs, "noise") ? "nz" : "nz%d", n);
        double w = check_dim(h, name, n, &in, &out, tab, p->npts);
        check_period(h, name, n, &in, &out);
        print_message("  %s -> %s noise%d%s: max %.4f LSB over %d points\n", p->in, p->out, n,
                      seed ? " (seed 7)" : "", w, p->npts);
    }
    dlclose(h);
    unlink(c);
    unlink(so);
}

static void test_pairs(void **st)
{
    (void)st;
    static const pair pairs[] = {
        {"fixed<31,16>", "fixed<15,15>", 1500},  /* the library's pair */
        {"fixed<15,12>", "fixed<7,7>", 1500},    /* 16 -> 8 bits */
        {"ufixed<16,8>", "fixed<15,14>", 1500},  /* unsigned input */
        {"fixed<31,24>", "fixed<31,20>", 1500},  /* 64-bit words */
        {"fixed<7,3>", "fixed<15,12>", 1500},    /* 8-bit storage in */
        {"fixed<31,31>", "fixed<7,7>", 1000},    /* pure-fraction input, 8-bit output saturating at +1 (unsigned
                                                    outputs are refused since 2026-12-07: test_cli_errors) */
        {"ufixed<32,28>", "fixed<31,22>", 1000}, /* 32-bit unsigned, F > 24, widest output for it */
    };
    for (size_t i = 0; i < sizeof pairs / sizeof pairs[0]; i++)
        run_pair(&pairs[i], i < 4 ? "noise" : i == 4 ? "noise2" : i == 5 ? "noise3" : "noise4", 0);
}

static void test_seed(void **st)
{
    (void)st;
    pair p = {"fixed<15,8>", "fixed<15,14>", 1000};
    run_pair(&p, "noise3", 1);
    /* a different lattice from the default: the tables differ */
    assert_int_equal(gen("--func noise3 --type 'fixed<15,8>' --out-type 'fixed<15,14>' --seed 7 --no-sweep",
                         nzp("s1.c")),
                     0);
    assert_int_equal(gen("--func noise3 --type 'fixed<15,8>' --out-type 'fixed<15,14>' --no-sweep", nzp("s0.c")), 0);
    char *a = tu_slurp(nzp("s1.c"), NULL), *b = tu_slurp(nzp("s0.c"), NULL);
    char *ta = strstr(a, "pf_nz_hash[512]"), *tb = strstr(b, "pf_nz_hash[512]");
    assert_non_null(ta);
    assert_non_null(tb);
    assert_true(strcmp(ta, tb) != 0);
    free(a);
    free(b);
    unlink(nzp("s0.c"));
    unlink(nzp("s1.c"));
}

/* Q16.16 -> Q15: within 1 LSB of the library's pf_noiseN_q15 (both are
 * within 1 LSB of the exact noise, so integers at most 1 apart) */
static void test_library_q15(void **st)
{
    (void)st;
    assert_int_equal(gen("--func noise --type 'fixed<31,16>' --out-type 'fixed<15,15>'", nzp("lib.c")), 0);
    void *h = load(nzp("lib.c"), nzp("lib.so"), "-O2");
    void *h0 = load(nzp("lib.c"), nzp("lib0.so"), "-O0 -fno-inline");
    int16_t (*g4)(int32_t, int32_t, int32_t, int32_t) =
        (int16_t(*)(int32_t, int32_t, int32_t, int32_t))dlsym(h0, "pf_noise4_q16_q15");
    int16_t (*g2)(int32_t, int32_t) = (int16_t(*)(int32_t, int32_t))dlsym(h0, "pf_noise2_q16_q15");
    assert_true(g4 && g2);
    int16_t (*f1)(int32_t) = (int16_t(*)(int32_t))dlsym(h, "pf_noise1_q16_q15");
    int16_t (*f2)(int32_t, int32_t) = (int16_t(*)(int32_t, int32_t))dlsym(h, "pf_noise2_q16_q15");
    int16_t (*f3)(int32_t, int32_t, int32_t) = (int16_t(*)(int32_t, int32_t, int32_t))dlsym(h, "pf_noise3_q16_q15");
    int16_t (*f4)(int32_t, int32_t, int32_t, int32_t) =
        (int16_t(*)(int32_t, int32_t, int32_t, int32_t))dlsym(h, "pf_noise4_q16_q15");
    void (*a3)(const int32_t *, const int32_t *, const int32_t *, int16_t *, size_t) =
        (void (*)(const int32_t *, const int32_t *, const int32_t *, int16_t *, size_t))dlsym(
            h, "pf_noise3_q16_q15_array");
    assert_true(f1 && f2 && f3 && f4 && a3);
    int worst[5] = {0}, same = 0;
    enum { K = 1 << 15 };
    static int32_t x[K], y[K], z[K], w[K];
    static int16_t o[K];
    for (int i = 0; i < K; i++) {
        x[i] = (int32_t)(uint32_t)rnd(), y[i] = (int32_t)(uint32_t)rnd();
        z[i] = (int32_t)(uint32_t)rnd(), w[i] = (int32_t)(uint32_t)rnd();
        int d[5] = {0, abs(f1(x[i]) - pf_noise1_q15(x[i])), abs(f2(x[i], y[i]) - pf_noise2_q15(x[i], y[i])),
                    abs(f3(x[i], y[i], z[i]) - pf_noise3_q15(x[i], y[i], z[i])),
                    abs(f4(x[i], y[i], z[i], w[i]) - pf_noise4_q15(x[i], y[i], z[i], w[i]))};
        for (int n = 1; n <= 4; n++)
            worst[n] = d[n] > worst[n] ? d[n] : worst[n];
        same += d[3] == 0;
        /* the same bits at -O0 */
        assert_int_equal(g4(x[i], y[i], z[i], w[i]), f4(x[i], y[i], z[i], w[i]));
        assert_int_equal(g2(x[i], y[i]), f2(x[i], y[i]));
    }
    a3(x, y, z, o, K);
    for (int i = 0; i < K; i++)
        assert_int_equal(o[i], f3(x[i], y[i], z[i]));
    print_message("  vs pf_noiseN_q15: max |diff| %d %d %d %d LSB; 3D identical on %.1f%%\n", worst[1], worst[2],
                  worst[3], worst[4], 100.0 * same / K);
    for (int n = 1; n <= 4; n++)
        assert_true(worst[n] <= 1);
    dlclose(h);
    dlclose(h0);
    unlink(nzp("lib.c"));
    unlink(nzp("lib.so"));
    unlink(nzp("lib0.so"));
}

static void test_deterministic(void **st)
{
    (void)st;
    const char *args = "--func noise2 --type 'fixed<15,12>' --out-type 'fixed<15,14>'";
    /* the same command (its -o is in the provenance) */
    assert_int_equal(gen(args, nzp("d1.c")), 0);
    char *a = tu_slurp(nzp("d1.c"), NULL);
    assert_int_equal(gen(args, nzp("d1.c")), 0);
    char *b = tu_slurp(nzp("d1.c"), NULL);
    assert_non_null(a);
    assert_non_null(b);
    assert_string_equal(a, b);
    /* integer only, nothing from libpfmath */
    char *code = tu_strip_comments(a);
    assert_null(strstr(code, "float"));
    assert_null(strstr(code, "double"));
    assert_null(strstr(code, "math.h"));
    assert_null(strstr(code, "#include \"pf"));
    assert_non_null(strstr(code, "#include <stdint.h>"));
    free(code);
    free(a);
    free(b);
    unlink(nzp("d1.c"));
}

static void test_cli_errors(void **st)
{
    (void)st;
    static const struct {
        const char *args, *want;
    } bad[] = {
        {"--func noise3 --type float", "pf_noise"},
        {"--func noise --type float --out-type float", "pf_noise"},
        {"--func noise3 --type 'fixed<31,16>' --out-type float", "pf_noise"},
        {"--func noise2", "--type"},
        {"--func noise2 --type 'fixed<31,16>' --order 5", "--order"},
        {"--func noise2 --type 'fixed<31,16>' --method minimax", "--method"},
        {"--func noise2 --type 'fixed<31,16>' --variant fast", "exact"},
        {"--func noise2 --type 'fixed<31,16>' --max-rel-err 1e-3", "--max-rel-err"},
        {"--func noise2 --type 'fixed<15,0>'", "identically 0"},
        {"--func noise1 --type 'fixed<15,-3>' --out-type 'fixed<15,15>'", "identically 0"},
        {"--func noise4 --type 'fixed<31,16>' --out-type 'fixed<31,31>'", "LSB"},
        {"--func noise --type 'fixed<40,16>' --out-type 'fixed<15,15>'", "32 bits"},
        {"--func noise3 --type 'fixed<31,16>' --seed x", "--seed"},
        {"--func noise3 --type 'fixed<31,16' --out-type 'fixed<15,15>'", "--type"},
        {"--func noise3 --type 'fixed<31,16>' --bogus", "unknown option"},
        /* unsigned outputs saturated every negative value to 0, silently */
        {"--func noise2 --type 'fixed<31,16>' --out-type 'ufixed<16,15>'", "unsigned"},
        {"--func noise --type 'ufixed<16,8>' --out-type 'unsigned fixed<8,7>'", "unsigned"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        const char *path = nzp("bad.c");
        int st2 = gen(bad[i].args, path);
        if (st2 != 2 || tu_count_lines(R.err) != 1 || !strstr(R.err, bad[i].want))
            fail_msg("'%s': exit %d, stderr '%s' (want one line with '%s')", bad[i].args, st2, R.err, bad[i].want);
        assert_int_not_equal(access(path, F_OK), 0);
    }
    /* the impossible request says how far off it is */
    gen("--func noise4 --type 'fixed<31,16>' --out-type 'fixed<31,31>'", nzp("bad.c"));
    assert_non_null(strstr(R.err, "2^-32"));
    /* --help lists noise */
    tu_runs("pfmathgen", "--func noise3 --type 'fixed<31,16>' --help", &R);
    assert_int_equal(R.status, 0);
    assert_non_null(strstr(R.out, "noise1, noise2, noise3, noise4"));
}

/* the reference against the library's float noise (independent code):
 * within float rounding at random points */
static void test_reference(void **st)
{
    (void)st;
    const pf_noise_table *t = pf_noise_default_table();
    double worst = 0;
    for (int i = 0; i < 4000; i++) {
        int n = 1 + i % 4;
        int64_t q[4];
        float p[4];
        for (int k = 0; k < n; k++) {
            q[k] = (int64_t)(rnd() % (1u << 25)) - (1 << 24); /* |x| <= 256, 16 fraction bits: exact in float */
            p[k] = (float)q[k] / 65536.0f;
        }
        double r = pfref_noise(n, t, q, 16);
        float f = n == 1 ? pf_noise1f(p[0])
                  : n == 2 ? pf_noise2f(p[0], p[1])
                  : n == 3 ? pf_noise3f(p[0], p[1], p[2])
                           : pf_noise4f(p[0], p[1], p[2], p[3]);
        worst = fmax(worst, fabs(r - f));
    }
    print_message("  reference vs pf_noiseNf: max |diff| %.3g\n", worst);
    assert_true(worst < 1e-5);
    /* Perlin's published value: noise3(3.14, 42, 7) = 0.13691995878400012
       at the dyadic point nearest (3.14 in 40 fraction bits) */
    int64_t q[3] = {(int64_t)llround(3.14 * 0x1p40), (int64_t)42 << 40, (int64_t)7 << 40};
    assert_true(fabs(pfref_noise(3, t, q, 40) - 0.13691995878400012) < 1e-9);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_reference),     cmocka_unit_test(test_cli_errors),
        cmocka_unit_test(test_deterministic), cmocka_unit_test(test_library_q15),
        cmocka_unit_test(test_seed),          cmocka_unit_test(test_pairs),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
