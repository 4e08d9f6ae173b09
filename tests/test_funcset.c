/* The function set is declared once (libpfmath/functions.def); everything
 * that lists it by hand must agree with it, or this test fails:
 *  - pfmath.h and pfmath_fixed.h declare every row's functions with the
 *    row's types (checked at compile time: a typed pointer to each symbol)
 *    and nothing else named pf_ (checked on the header text);
 *  - libpfmath/generated/ holds exactly the rows' sources (the library is
 *    built from every .c there, so a stray file would ship);
 *  - make's LIB_GEN and FX_LIB (mk/funcset.awk's reading of the table,
 *    which make regen and tests/check-regen*.sh run) equal the C
 *    preprocessor's reading of the same rows;
 *  - ref/ knows each row's function under that name and arity, and no
 *    row's exact bound is wider than the headers' 1 ULP / 1 LSB;
 *  - a fixed row's name is pfmathgen's default name for its function and
 *    types, and its storage tags are the types' storage;
 *  - libpfmath.so exports every row's four symbols. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "fixedgen.h"
#include "fixedtype.h"
#include "funcset.h"
#include "pfmath.h"
#include "pfmath_fixed.h"
#include "pfref.h"
#include "testutil.h"

#include <ctype.h>
#include <dirent.h>
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef PF_ROOT
#define PF_ROOT "."
#endif

/* ---- the rows, as C reads them ---- */
typedef struct {
    const char *name;
    pf_func id;
    int arity;
    double exact_ulp;
} frow;
static const frow frows[] = {
#define PF_FLOAT(n, id, ar, u, lo, hi) {#n, id, ar, u},
#include "functions.def"
};
#define NF ((int)(sizeof frows / sizeof frows[0]))

typedef struct {
    const char *name, *func, *in, *out;
    pf_func id;
    const char *in_st, *out_st;
    double exact_lsb;
} xrow;
static const xrow xrows[] = {
#define PF_FIXED(n, f, id, ist, isg, isz, ie, ost, osg, osz, oe, lsb, lo, hi)                                  \
    {#n, #f, PF_FS_TYPE(isg, isz, ie), PF_FS_TYPE(osg, osz, oe), id, #ist, #ost, lsb},
#include "functions.def"
};
#define NX ((int)(sizeof xrows / sizeof xrows[0]))

static int in_list(const char *s, const char *const *v, int n)
{
    for (int i = 0; i < n; i++)
        if (!strcmp(s, v[i]))
            return i;
    return -1;
}

/* the expected symbol names: float rows give pf_<n>f, pf_<n>f_fast (and the
   _array forms when arrays), fixed rows pf_<n>, pf_<n>_fast (...) */
static int expected_syms(char (*out)[64], int max, int floats, int fixed, int arrays)
{
    int k = 0;
    for (int i = 0; floats && i < NF; i++)
        for (int fast = 0; fast <= 1; fast++)
            for (int a = 0; a <= arrays; a++)
                if (k < max)
                    snprintf(out[k++], 64, "pf_%sf%s%s", frows[i].name, fast ? "_fast" : "", a ? "_array" : "");
    for (int i = 0; fixed && i < NX; i++)
        for (int fast = 0; fast <= 1; fast++)
            for (int a = 0; a <= arrays; a++)
                if (k < max)
                    snprintf(out[k++], 64, "pf_%s%s%s", xrows[i].name, fast ? "_fast" : "", a ? "_array" : "");
    return k;
}

/* compile time: each row declared with its types (an undeclared symbol or
   another type is an error under -Werror: the assignments convert
   implicitly) */
#define DECL1(f)                                                                                           \
    {                                                                                                      \
        float (*s)(float) = f;                                                                             \
        void (*a)(const float *, float *, size_t) = f##_array;                                             \
        n += s && a;                                                                                       \
    }
#define DECL2(f)                                                                                           \
    {                                                                                                      \
        float (*s)(float, float) = f;                                                                      \
        void (*a)(const float *, const float *, float *, size_t) = f##_array;                              \
        n += s && a;                                                                                       \
    }
#define DECLX(f, IT, OT)                                                                                   \
    {                                                                                                      \
        OT (*s)(IT) = f;                                                                                   \
        void (*a)(const IT *, OT *, size_t) = f##_array;                                                   \
        n += s && a;                                                                                       \
    }
static void test_declarations(void **st)
{
    (void)st;
    int n = 0;
#define PF_FLOAT(nm, id, ar, u, lo, hi) DECL##ar(pf_##nm##f) DECL##ar(pf_##nm##f_fast)
#define PF_FIXED(nm, f, id, ist, isg, isz, ie, ost, osg, osz, oe, lsb, lo, hi)                                 \
    DECLX(pf_##nm, PF_FS_CTYPE(ist), PF_FS_CTYPE(ost)) DECLX(pf_##nm##_fast, PF_FS_CTYPE(ist), PF_FS_CTYPE(ost))
#include "functions.def"
    assert_int_equal(n, 2 * (NF + NX));
}

/* every identifier pf_... outside preprocessor lines of a header, once each,
   must be one of want[] and every want[] must be there */
static int check_header(const char *rel, char (*want)[64], int nwant)
{
    char path[PATH_MAX];
    snprintf(path, sizeof path, "%s/%s", PF_ROOT, rel);
    char *raw = tu_slurp(path, NULL);
    assert_non_null(raw);
    char *s = tu_strip_comments(raw);
    free(raw);
    int *seen = calloc((size_t)nwant, sizeof *seen), bad = 0;
    const char **wv = malloc((size_t)nwant * sizeof *wv);
    for (int i = 0; i < nwant; i++)
        wv[i] = want[i];
    int bol = 1, pp = 0;
    for (char *p = s; *p;) {
        if (*p == '\n') {
            /* a directive continues over backslash-newlines */
            pp = pp && p > s && p[-1] == '\\';
            bol = 1, p++;
            continue;
        }
        if (bol && !isspace((unsigned char)*p))
            pp = pp || *p == '#';
        if (!isspace((unsigned char)*p))
            bol = 0;
        if ((isalpha((unsigned char)*p) || *p == '_') && (p == s || !(isalnum((unsigned char)p[-1]) || p[-1] == '_'))) {
            char *e = p;
            while (isalnum((unsigned char)*e) || *e == '_')
                e++;
            char id[128];
            snprintf(id, sizeof id, "%.*s", (int)(e - p), p);
            if (!pp && !strncmp(id, "pf_", 3)) {
                int k = in_list(id, wv, nwant);
                if (k < 0) {
                    print_message("%s declares %s, which libpfmath/functions.def has no row for\n", rel, id);
                    bad++;
                } else if (seen[k]++) {
                    print_message("%s declares %s twice\n", rel, id);
                    bad++;
                }
            }
            p = e;
            continue;
        }
        p++;
    }
    for (int i = 0; i < nwant; i++)
        if (!seen[i]) {
            print_message("%s lacks %s (a row of libpfmath/functions.def)\n", rel, want[i]);
            bad++;
        }
    free(seen);
    free(wv);
    free(s);
    return bad;
}

static void test_headers(void **st)
{
    (void)st;
    static char want[512][64];
    /* pfmath.h names the scalar forms (PF_DECLARE1/2 adds _array) */
    int n = expected_syms(want, 512, 1, 0, 0);
    int bad = check_header("libpfmath/pfmath.h", want, n);
    n = expected_syms(want, 512, 0, 1, 1);
    bad += check_header("libpfmath/pfmath_fixed.h", want, n);
    assert_int_equal(bad, 0);
}

static void test_generated_dir(void **st)
{
    (void)st;
    static char want[512][64];
    int n = expected_syms(want, 512, 1, 1, 0);
    const char **wv = malloc((size_t)n * sizeof *wv);
    /* pf_<n>f[_fast].c and pf_fx_<n>[_fast].c */
    for (int i = 0; i < n; i++) {
        char t[80];
        if (i < 2 * NF)
            snprintf(t, sizeof t, "%.60s.c", want[i]);
        else
            snprintf(t, sizeof t, "pf_fx_%.54s.c", want[i] + 3);
        memcpy(want[i], t, 64);
        want[i][63] = 0;
        wv[i] = want[i];
    }
    int *seen = calloc((size_t)n, sizeof *seen), bad = 0;
    char path[PATH_MAX];
    snprintf(path, sizeof path, "%s/libpfmath/generated", PF_ROOT);
    DIR *d = opendir(path);
    assert_non_null(d);
    for (struct dirent *e; (e = readdir(d));) {
        size_t l = strlen(e->d_name);
        if (l < 2 || strcmp(e->d_name + l - 2, ".c"))
            continue;
        int k = in_list(e->d_name, wv, n);
        if (k < 0) {
            print_message("libpfmath/generated/%s has no row in libpfmath/functions.def (it would ship)\n",
                          e->d_name);
            bad++;
        } else
            seen[k] = 1;
    }
    closedir(d);
    for (int i = 0; i < n; i++)
        if (!seen[i]) {
            print_message("libpfmath/generated/%s missing (make regen)\n", want[i]);
            bad++;
        }
    print_message("%d generated sources for %d float and %d fixed-point rows\n", n, NF, NX);
    free(seen);
    free(wv);
    assert_int_equal(bad, 0);
}

static void test_make_lists(void **st)
{
    (void)st;
#if defined(PF_MK_LIB_GEN) && defined(PF_MK_FX_LIB)
    static char lib_gen[8192], fx_lib[8192];
    size_t k = 0;
    for (int i = 0; i < NF; i++)
        k += (size_t)snprintf(lib_gen + k, sizeof lib_gen - k, "%s%s:exact %s:fast", i ? " " : "", frows[i].name,
                              frows[i].name);
    k = 0;
    for (int i = 0; i < NX; i++)
        k += (size_t)snprintf(fx_lib + k, sizeof fx_lib - k, "%s%s/%s/%s/%s", i ? " " : "", xrows[i].name,
                              xrows[i].func, xrows[i].in, xrows[i].out);
    print_message("make LIB_GEN: %s\nmake FX_LIB:  %s\n", PF_MK_LIB_GEN, PF_MK_FX_LIB);
    assert_string_equal(PF_MK_LIB_GEN, lib_gen);
    assert_string_equal(PF_MK_FX_LIB, fx_lib);
#else
    print_message("built without make's lists (PF_MK_LIB_GEN, PF_MK_FX_LIB)\n");
    skip();
#endif
}

static void test_ref_names(void **st)
{
    (void)st;
    for (int i = 0; i < NF; i++) {
        /* the headers' promise: exact is within 1 ULP (1 LSB) everywhere; a
           row may tighten the bound make sweep checks, never widen it */
        assert_true(frows[i].exact_ulp > 0 && frows[i].exact_ulp <= 1.0);
        assert_string_equal(pfref_name(frows[i].id), frows[i].name);
        assert_int_equal(pfref_arity(frows[i].id), frows[i].arity);
    }
    for (int i = 0; i < NX; i++) {
        assert_true(xrows[i].exact_lsb > 0 && xrows[i].exact_lsb <= 1.0);
        assert_string_equal(pfref_name(xrows[i].id), xrows[i].func);
        assert_int_equal(pfref_arity(xrows[i].id), 1);
    }
}

/* a fixed row's name is the one pfmathgen gives by default (make regen-fixed
   passes no --name), and its storage tags are its types' storage */
static void test_fixed_names(void **st)
{
    (void)st;
    int bad = 0;
    for (int i = 0; i < NX; i++) {
        pf_type t[2];
        char err[200], nm[128], want[128], tag[8];
        const char *ty[2] = {xrows[i].in, xrows[i].out}, *stv[2] = {xrows[i].in_st, xrows[i].out_st};
        for (int k = 0; k < 2; k++) {
            assert_int_equal(pf_type_parse(ty[k], &t[k], err, sizeof err), 0);
            snprintf(tag, sizeof tag, "%c%d", t[k].is_signed ? 'i' : 'u', t[k].storage_bits);
            if (strcmp(tag, stv[k])) {
                print_message("pf_%s: %s is stored in %s, the row says %s\n", xrows[i].name, ty[k], tag, stv[k]);
                bad++;
            }
        }
        pf_fixed_default_name(xrows[i].func, &t[0], &t[1], 0, nm, sizeof nm);
        snprintf(want, sizeof want, "pf_%s", xrows[i].name);
        if (strcmp(nm, want)) {
            print_message("row %s: pfmathgen names --func %s --type '%s' --out-type '%s' %s\n", xrows[i].name,
                          xrows[i].func, xrows[i].in, xrows[i].out, nm);
            bad++;
        }
    }
    assert_int_equal(bad, 0);
}

static void test_library_exports(void **st)
{
    (void)st;
    char p[PATH_MAX];
    tu_prog_path("libpfmath.so", p, sizeof p);
    void *h = dlopen(p, RTLD_NOW | RTLD_LOCAL);
    if (!h)
        print_message("dlopen %s: %s\n", p, dlerror());
    assert_non_null(h);
    static char want[512][64];
    int n = expected_syms(want, 512, 1, 1, 1), bad = 0;
    for (int i = 0; i < n; i++)
        if (!dlsym(h, want[i])) {
            print_message("%s does not export %s\n", p, want[i]);
            bad++;
        }
    print_message("%d symbols exported\n", n - bad);
    dlclose(h);
    assert_int_equal(bad, 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_declarations), cmocka_unit_test(test_headers),
        cmocka_unit_test(test_generated_dir), cmocka_unit_test(test_make_lists),
        cmocka_unit_test(test_ref_names),     cmocka_unit_test(test_fixed_names),
        cmocka_unit_test(test_library_exports),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
