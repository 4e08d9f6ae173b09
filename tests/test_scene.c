/* Scene-driven generation: every examples/NAME.scene generates, its code
 * compiles, every function meets its listed target in a sweep against
 * MPFR, and nothing the scene did not ask for is emitted.  Noise lines
 * (noise1..noise4, fixed point, variant optional) are sampled against the
 * exact noise (ref/pfref_noise.c). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include "compile.h"
#include "fixedtype.h"
#include "pfnoise.h"
#include "pfref_noise.h"
#include "sweep.h"
#include "testutil.h"
#include "tu_exec.h"

#include <ctype.h>
#include <dirent.h>
#include <dlfcn.h>
#include <math.h>

typedef struct {
    char func[32], variant[16], tin[64], tout[64];
} entry;

static const char *take_type(const char *p, char *out, size_t n)
{
    while (isspace((unsigned char)*p))
        p++;
    if (!strncmp(p, "float", 5)) {
        snprintf(out, n, "float");
        return p + 5;
    }
    const char *gt = strchr(p, '>');
    if (!gt || (size_t)(gt - p + 1) >= n)
        return NULL;
    memcpy(out, p, (size_t)(gt - p + 1));
    out[gt - p + 1] = 0;
    return gt + 1;
}

/* an independent reading of the scene format (not the generator's parser) */
static int read_scene(const char *path, entry *e)
{
    FILE *f = fopen(path, "r");
    assert_non_null(f);
    char line[512];
    int n = 0;
    while (fgets(line, sizeof line, f)) {
        char *h = strchr(line, '#');
        if (h)
            *h = 0;
        char *p = line;
        while (isspace((unsigned char)*p))
            p++;
        if (!*p)
            continue;
        int k = sscanf(p, "%31s %15s", e[n].func, e[n].variant);
        assert_int_equal(k, 2);
        if (!strncmp(e[n].func, "noise", 5) && strcmp(e[n].variant, "exact")) {
            /* noise lines may leave the variant out (exact is the only one) */
            assert_string_not_equal(e[n].variant, "fast");
            strcpy(e[n].variant, "exact");
            p = strstr(p, e[n].func) + strlen(e[n].func);
        } else {
            p = strstr(p, e[n].variant) + strlen(e[n].variant);
        }
        p = (char *)take_type(p, e[n].tin, sizeof e[n].tin);
        assert_non_null(p);
        assert_non_null(take_type(p, e[n].tout, sizeof e[n].tout));
        n++;
    }
    fclose(f);
    return n;
}

/* scene names: the prefix (the scene file's name and '_') instead of pf_ */
static void name_of(const char *prefix, const entry *x, const pf_type *in, const pf_type *out, char *buf, size_t n)
{
    char fn[40];
    snprintf(fn, sizeof fn, "%.31s%s", x->func, strcmp(x->variant, "fast") ? "" : "_fast");
    if (in->is_float) {
        snprintf(buf, n, "%s%.31sf%s", prefix, x->func, strcmp(x->variant, "fast") ? "" : "_fast");
        return;
    }
    snprintf(buf, n, "%s%s_%c%d_%s%d_%c%d_%s%d", prefix, fn,
             in->is_signed ? 's' : 'u', in->size, in->exp < 0 ? "m" : "", abs(in->exp),
             out->is_signed ? 's' : 'u', out->size, out->exp < 0 ? "m" : "", abs(out->exp));
}

static void check_float(void *h, const char *name, const entry *x)
{
    pf_func f = (pf_func)pfref_lookup(x->func);
    void *p = dlsym(h, name);
    assert_non_null(p);
    pf_fn1 f1 = NULL;
    pf_fn2 f2 = NULL;
    if (pfref_arity(f) == 2)
        *(void **)&f2 = p;
    else
        *(void **)&f1 = p;
    if (!strcmp(x->variant, "exact")) {
        pf_sweep_stats s;
        pf_sweep_init(&s);
        if (!f2) {
            uint32_t lo, hi;
            pf_sweep_reduced_range(f, &lo, &hi);
            pf_sweep_bits(&s, f, f1, NULL, lo, hi, 0);
        }
        pf_sweep_random(&s, f, f1, f2, 11, 1u << 20);
        pf_sweep_directed(&s, f, f1, f2);
        print_message("  %-24s exact: max %.3f ULP over %llu inputs\n", name, s.max_ulp,
                      (unsigned long long)s.count);
        assert_true(s.max_ulp <= 1.0);
    } else {
        /* fast: 2^-10 relative, or 2^-11 absolute where the value is small */
        uint64_t st = 3;
        double worst = 0;
        for (int i = 0; i < 1 << 18; i++) {
            st = st * 6364136223846793005ull + 1442695040888963407ull;
            float xv = (float)((double)(st >> 11) / 9007199254740992.0 * 20 - 10);
            st = st * 6364136223846793005ull + 1442695040888963407ull;
            float yv = (float)((double)(st >> 11) / 9007199254740992.0 * 20 - 10);
            double ex = pfref_exact_d(f, xv, yv);
            if (!isfinite(ex))
                continue;
            float got = f2 ? f2(xv, yv) : f1(xv);
            double e = fabs(got - ex) / fmax(fabs(ex), 0.5);
            if (e > worst)
                worst = e;
        }
        print_message("  %-24s fast: max error %.3g (relative, absolute below 0.5)\n", name, worst);
        assert_true(worst <= 0x1p-10);
    }
}

static int64_t call_fixed(void *p, const pf_type *in, const pf_type *out, int64_t v)
{
#define CALL(TI, TO) return (int64_t)((TO(*)(TI))p)((TI)v)
#define OUTS(TI)                                                                                   \
    switch (out->storage_bits * 2 + out->is_signed) {                                              \
    case 17: CALL(TI, int8_t);                                                                     \
    case 16: CALL(TI, uint8_t);                                                                    \
    case 33: CALL(TI, int16_t);                                                                    \
    case 32: CALL(TI, uint16_t);                                                                   \
    case 65: CALL(TI, int32_t);                                                                    \
    default: CALL(TI, uint32_t);                                                                   \
    }
    switch (in->storage_bits * 2 + in->is_signed) {
    case 17: OUTS(int8_t);
    case 16: OUTS(uint8_t);
    case 33: OUTS(int16_t);
    case 32: OUTS(uint16_t);
    case 65: OUTS(int32_t);
    default: OUTS(uint32_t);
    }
#undef OUTS
#undef CALL
}

static int64_t call_noise(void *p, int n, const pf_type *in, const pf_type *out, const int64_t *q)
{
#define CALLN(TI, TO)                                                                              \
    switch (n) {                                                                                   \
    case 1: return (int64_t)((TO(*)(TI))p)((TI)q[0]);                                              \
    case 2: return (int64_t)((TO(*)(TI, TI))p)((TI)q[0], (TI)q[1]);                                \
    case 3: return (int64_t)((TO(*)(TI, TI, TI))p)((TI)q[0], (TI)q[1], (TI)q[2]);                  \
    default: return (int64_t)((TO(*)(TI, TI, TI, TI))p)((TI)q[0], (TI)q[1], (TI)q[2], (TI)q[3]);   \
    }
#define OUTSN(TI)                                                                                  \
    switch (out->storage_bits * 2 + out->is_signed) {                                              \
    case 17: CALLN(TI, int8_t);                                                                    \
    case 16: CALLN(TI, uint8_t);                                                                   \
    case 33: CALLN(TI, int16_t);                                                                   \
    case 32: CALLN(TI, uint16_t);                                                                  \
    case 65: CALLN(TI, int32_t);                                                                   \
    default: CALLN(TI, uint32_t);                                                                  \
    }
    switch (in->storage_bits * 2 + in->is_signed) {
    case 17: OUTSN(int8_t);
    case 16: OUTSN(uint8_t);
    case 33: OUTSN(int16_t);
    case 32: OUTSN(uint16_t);
    case 65: OUTSN(int32_t);
    default: OUTSN(uint32_t);
    }
#undef OUTSN
#undef CALLN
}

/* every input of a <= 16-bit type: exact < 1 LSB, fast <= max(2^-10 rel, 4 LSB),
 * against MPFR with the documented saturation (true result clamped to the range;
 * log of 0 or of a negative gives the most negative value). */
static void check_fixed(void *h, const char *name, const entry *x, const pf_type *in, const pf_type *out)
{
    pf_func f = (pf_func)pfref_lookup(x->func);
    void *p = dlsym(h, name);
    assert_non_null(p);
    assert_true(in->storage_bits <= 16);
    double worst = 0;
    int64_t lo = pf_type_min_stored(in), hi = pf_type_max_stored(in);
    for (int64_t v = lo; v <= hi; v++) {
        double xv = ldexp((double)v, -in->exp);
        int64_t got = call_fixed(p, in, out, v);
        double ex = pfref_exact_dd(f, xv, 1.0);
        if (isnan(ex) || (isinf(ex) && ex < 0)) {
            if (f == PF_LOG || f == PF_LOG2)
                assert_true(got == pf_type_min_stored(out));
            continue;
        }
        double cl = fmin(fmax(ex, pf_type_min(out)), pf_type_max(out));
        double e = fabs(ldexp((double)got, -out->exp) - cl) / pf_type_lsb(out);
        double bound = !strcmp(x->variant, "exact") ? 1.0 : fmax(4.0, 0x1p-10 * fabs(cl) / pf_type_lsb(out));
        if (e / bound > worst)
            worst = e / bound;
        if (!(e < bound || (strcmp(x->variant, "exact") && e <= bound)))
            print_message("  %s(%g) = %g, want %g (%.3f LSB)\n", name, xv, ldexp((double)got, -out->exp), cl, e);
        assert_true(!strcmp(x->variant, "exact") ? e < bound : e <= bound);
    }
    print_message("  %-24s %s: every input, worst error %.3f of its bound\n", name, x->variant, worst);
}

/* gradient noise (noise1..noise4): sampled against the exact noise
 * (ref/pfref_noise.c, MPFR, the library's default lattice) within 1 LSB,
 * 0 at lattice points; scene.h's prototype agrees with the definition */
static void check_noise(void *h, const char *name, const entry *x, const pf_type *in, const pf_type *out,
                        const char *dir)
{
    int n = x->func[5] - '0';
    assert_true(n >= 1 && n <= 4);
    void *p = dlsym(h, name);
    assert_non_null(p);
    /* scene.h's prototypes agree with the definitions: one translation unit */
    char tu[1200], inc[1200];
    snprintf(tu, sizeof tu, "%s/check_%s.c", dir, name);
    snprintf(inc, sizeof inc, "#include \"scene.h\"\n#include \"%s.c\"\n", name);
    FILE *f = fopen(tu, "w");
    assert_non_null(f);
    fputs(inc, f);
    fclose(f);
    const char *cc[] = {"cc", "-std=c17", "-Wall", "-Wextra", "-Werror", "-fsyntax-only", tu, NULL};
    tu_run_result *r = malloc(sizeof *r);
    tu_execvp_in(NULL, cc, r);
    if (r->status)
        print_message("%s", r->err);
    assert_int_equal(r->status, 0);
    free(r);
    unlink(tu);
    int64_t lo = pf_type_min_stored(in), hi = pf_type_max_stored(in), olo = pf_type_min_stored(out),
            ohi = pf_type_max_stored(out);
    const pf_noise_table *t = pf_noise_default_table();
    uint64_t s = 99;
    double worst = 0;
    for (int i = 0; i < 3000; i++) {
        int64_t q[4] = {0, 0, 0, 0};
        for (int k = 0; k < n; k++) {
            s = s * 6364136223846793005ull + 1442695040888963407ull;
            q[k] = lo + (int64_t)((s >> 20) % (uint64_t)(hi - lo + 1));
            if (i % 3 == 0) /* lattice points: the noise is 0 there */
                q[k] = (int64_t)(((s >> 40) % 16) - 8) * ((int64_t)1 << in->exp);
            if (q[k] < lo || q[k] > hi)
                q[k] = 0;
        }
        int64_t got = call_noise(p, n, in, out, q);
        if (i % 3 == 0)
            assert_true(got == 0);
        double e = pfref_noise_err_lsb(n, t, q, in->exp, got, out->exp, olo, ohi);
        worst = fmax(worst, e);
        assert_true(e < 1);
    }
    print_message("  %-24s noise%d: 3000 sampled inputs, max error %.3f LSB\n", name, n, worst);
}

static void test_example_scenes(void **st)
{
    (void)st;
    DIR *d = opendir("examples");
    assert_non_null(d);
    struct dirent *de;
    int scenes = 0;
    while ((de = readdir(d))) {
        size_t l = strlen(de->d_name);
        if (l < 7 || strcmp(de->d_name + l - 6, ".scene"))
            continue;
        char scene[300], dir[] = "/tmp/pfscene.XXXXXX", out[64];
        if (l > 200)
            continue;
        snprintf(scene, sizeof scene, "examples/%.200s", de->d_name);
        assert_non_null(mkdtemp(dir));
        snprintf(out, sizeof out, "%s/out", dir);
        tu_run_result *r = malloc(sizeof *r);
        tu_runl(r, "pfmathgen", "--scene", scene, "-o", out, NULL);
        print_message("%s: pfmathgen exit %d %s\n", scene, r->status, r->err);
        assert_int_equal(r->status, 0);
        entry e[64];
        int n = read_scene(scene, e);
        char prefix[64];
        snprintf(prefix, sizeof prefix, "%.*s_", (int)(l - 6), de->d_name);
        /* exactly the listed functions: one .c each, plus scene.h and report.txt */
        int nfiles = 0;
        char *files[70];
        DIR *od = opendir(out);
        assert_non_null(od);
        for (struct dirent *fe; (fe = readdir(od));) {
            size_t fl = strlen(fe->d_name);
            if (fl > 2 && !strcmp(fe->d_name + fl - 2, ".c") && nfiles < 64) {
                files[nfiles] = malloc(strlen(out) + fl + 2);
                sprintf(files[nfiles++], "%s/%s", out, fe->d_name);
            }
        }
        closedir(od);
        assert_int_equal(nfiles, n);
        /* compile all of it together; the global symbols are exactly the names asked for */
        char so[700], incl[700];
        snprintf(so, sizeof so, "%s/scene.so", out);
        snprintf(incl, sizeof incl, "-I%s", out);
        const char *cc[80] = {"cc", "-std=c17", "-O2", "-Wall", "-Wextra", "-Werror", "-fPIC", "-shared", incl, "-o", so};
        int k = 11;
        for (int i = 0; i < nfiles; i++)
            cc[k++] = files[i];
        cc[k++] = "-lm";
        cc[k] = NULL;
        tu_execvp_in(NULL, cc, r);
        if (r->status)
            print_message("%s", r->err);
        assert_int_equal(r->status, 0);
        for (int i = 0; i < nfiles; i++)
            free(files[i]);
        const char *nm[] = {"nm", "-D", "--defined-only", so, NULL};
        tu_execvp_in(NULL, nm, r);
        assert_int_equal(r->status, 0);
        char syms[4096] = "";
        for (char *line = strtok(r->out, "\n"); line; line = strtok(NULL, "\n")) {
            char addr[64], kind[8], sym[256];
            if (sscanf(line, "%63s %7s %255s", addr, kind, sym) == 3 && strchr("TWi", kind[0]) && !strchr(sym, '.')) {
                strncat(syms, sym, sizeof syms - strlen(syms) - 2);
                strcat(syms, "\n");
            }
        }
        free(r);
        int nsyms = tu_count_lines(syms);
        assert_int_equal(nsyms, 2 * n); /* f and f_array */
        void *h = dlopen(so, RTLD_NOW | RTLD_LOCAL);
        assert_non_null(h);
        for (int i = 0; i < n; i++) {
            pf_type in, ot;
            char err[200], name[160];
            assert_int_equal(pf_type_parse(e[i].tin, &in, err, sizeof err), 0);
            assert_int_equal(pf_type_parse(e[i].tout, &ot, err, sizeof err), 0);
            name_of(prefix, &e[i], &in, &ot, name, sizeof name);
            /* never libpfmath's own names: a program links both */
            assert_true(strncmp(name, "pf_", 3) != 0);
            char want[200];
            snprintf(want, sizeof want, "%s\n", name);
            assert_non_null(strstr(syms, want));
            if (in.is_float)
                check_float(h, name, &e[i]);
            else if (!strncmp(e[i].func, "noise", 5))
                check_noise(h, name, &e[i], &in, &ot, out);
            else
                check_fixed(h, name, &e[i], &in, &ot);
        }
        dlclose(h);
        tu_rm_tree(dir);
        scenes++;
    }
    closedir(d);
    assert_true(scenes >= 2);
}

static void test_bad_scenes(void **st)
{
    (void)st;
    const char *bad[] = {"sin exact float\n", "frob exact float float\n", "sin exact float fixed<15,14>\n",
                         "sin exact fixed<15 fixed<15,14>\n", "sin exact float float\nsin exact float float\n",
                         "# nothing\n", "noise3 fast fixed<15,12> fixed<15,14>\n", "noise3 float float\n",
                         "noise fixed<15,12> fixed<15,14>\n", "noise2 exact fixed<15,0> fixed<15,14>\n"};
    char scene[96], out[96];
    tu_scratch(scene, "bad.scene");
    tu_scratch(out, "bad-out");
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        FILE *f = fopen(scene, "w");
        fputs(bad[i], f);
        fclose(f);
        tu_rm_tree(out);
        tu_run_result *r = malloc(sizeof *r);
        tu_runl(r, "pfmathgen", "--scene", scene, "-o", out, NULL);
        assert_int_equal(r->status, 2);
        assert_int_equal(tu_count_lines(r->err), 1);
        assert_int_not_equal(access(out, F_OK), 0);
        free(r);
    }
    unlink(scene);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_bad_scenes),
        cmocka_unit_test(test_example_scenes),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
