/* Every clone gives the same bits.
 *
 * The library's scalar and array forms are GCC target_clones (x86-64-v4,
 * x86-64-v3, default) behind an ifunc; the loader picks one, so a user on
 * another CPU runs other code.  The promise is that the choice never shows:
 * fmaf is correctly rounded on every level, no FMA contraction, no
 * reassociation.  This test holds the library to it: for every float
 * function (exact and fast) it calls the dispatched scalar form, each scalar
 * clone and each array clone the CPU can run, on a sample of inputs
 * (special values, every exponent by random bit patterns, the function's
 * own domain), and requires bit-identical results, NaN bits included; each
 * array clone again in place (the output array holding an input), which
 * pfmath.h allows.
 *
 * The clones are local symbols (pf_logf_array.arch_x86_64_v3, ...): they are
 * found in the shared object's static symbol table (.symtab) and called at
 * load base + st_value.  A library without that table (stripped, or built
 * by a compiler without target_clones) has nothing to compare: the test is
 * skipped then, and says so. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <dlfcn.h>
#include <elf.h>
#include <fcntl.h>
#include <link.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "elfsyms.h"
#include "testutil.h"

typedef float (*fn1)(float);
typedef float (*fn2)(float, float);
typedef void (*arr1)(const float *, float *, size_t);
typedef void (*arr2)(const float *, const float *, float *, size_t);

static void *lib;
static pf_elfsyms es; /* the library's .symtab (elfsyms.h) */

/* address of a defined function symbol (the clones are local), or NULL */
static void *sym_addr(const char *name) { return pf_elfsyms_func(&es, name); }

static int setup(void **state)
{
    (void)state;
    char p[PATH_MAX];
    tu_prog_path("libpfmath.so", p, sizeof p);
    lib = dlopen(p, RTLD_NOW | RTLD_LOCAL);
    if (!lib) {
        fprintf(stderr, "dlopen %s: %s\n", p, dlerror());
        return -1;
    }
    pf_elfsyms_load(&es, lib, p);
    __builtin_cpu_init();
    return 0;
}

/* ---- inputs ---- */
static uint64_t rng = 0x9e3779b97f4a7c15u;
static uint32_t next32(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return (uint32_t)(rng >> 16);
}
static float bits(uint32_t u)
{
    float f;
    memcpy(&f, &u, sizeof f);
    return f;
}
static uint32_t asu(float f)
{
    uint32_t u;
    memcpy(&u, &f, sizeof u);
    return u;
}

#define NIN 200000
#define NSPEC 64

static const float special[] = {
    0.0f, -0.0f, INFINITY, -INFINITY, NAN, -NAN, 1.0f, -1.0f, 0.5f, -0.5f, 2.0f, -2.0f,
    0x1p-149f, -0x1p-149f, 0x1p-126f, -0x1p-126f, 0x1.fffffep-127f, 0x1.fffffep+127f,
    -0x1.fffffep+127f, 0x1p-24f, 0x1p-12f, 0x1p24f, 0x1p63f, 0x1p100f, 0x1p127f,
    0x1.921fb6p+0f, -0x1.921fb6p+0f, 0x1.921fb6p+1f, 0x1.921fb6p+2f, 0x1.62e43p+6f,
    -0x1.9fe368p+6f, 0x1.5p+7f, -0x1.2cp+7f, 0x1.fffffep-1f, 0x1.000002p+0f,
    0x1.6a09e6p-1f, 0x1.a8279ap-2f, 0x1.3504f4p+1f, 0x1.000002p-1f, 0x1.fffffep-2f,
    1e30f, -1e30f, 1e4f, -1e4f, 3.0f, 0.1f, 88.7f, -103.9f, 128.0f, -150.0f,
};

/* the library's float functions: the PF_FLOAT rows of libpfmath/functions.def,
   with the domain of the uniform share of the sample */
typedef struct {
    const char *name;
    int arity;
    float lo, hi;
} func_row;
static const func_row funcs[] = {
#define PF_FLOAT(n, id, ar, u, lo, hi) {#n, ar, lo, hi},
#include "functions.def"
};

static void fill(const func_row *f, float *x, size_t n, int which)
{
    float lo = f->lo, hi = f->hi;
    size_t ns = sizeof special / sizeof special[0];
    for (size_t i = 0; i < n; i++) {
        uint32_t r = next32();
        if (i < ns * ns)   /* every special value, and for atan2 every pair of them */
            x[i] = which ? special[i % ns] : special[(i / ns) % ns];
        else if (i % 3 == 0)   /* any bit pattern: every exponent, NaN payloads */
            x[i] = bits(r);
        else if (i % 3 == 1)
            x[i] = lo + (hi - lo) * (float)(r >> 8) * 0x1p-24f;
        else   /* small neighbourhoods of the specials (seams, thresholds) */
            x[i] = bits(asu(special[r % ns]) + (r >> 26) - 32);
    }
}

/* ---- the comparison ---- */
static const char *levels[] = {"arch_x86_64_v4", "arch_x86_64_v3", "default"};
static int can_run(int l)
{
    return l == 0 ? __builtin_cpu_supports("x86-64-v4") : l == 1 ? __builtin_cpu_supports("x86-64-v3") : 1;
}

static int first_diff(const float *a, const float *b, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (memcmp(&a[i], &b[i], sizeof(float)))
            return (int)i;
    return -1;
}

/* the input at i, for messages: "x = ... (bits)" and, for atan2, y */
static const char *where(const float *x, const float *y, int two, int i)
{
    static char buf[96];
    int len = snprintf(buf, sizeof buf, "x = %a (%08x)", (double)x[i], asu(x[i]));
    if (two)
        snprintf(buf + len, sizeof buf - (size_t)len, ", y = %a", (double)y[i]);
    return buf;
}

/* compares every clone of pf_<f>f<sfx> and pf_<f>f<sfx>_array with the
   dispatched scalar form; returns the number of clones compared */
static int check_one(const func_row *f, const char *sfx, const float *x, const float *y,
                     float *ref, float *out)
{
    char name[96], cname[128];
    snprintf(name, sizeof name, "pf_%sf%s", f->name, sfx);
    int two = f->arity == 2;
    void *s = dlsym(lib, name);
    if (!s) {
        print_message("%s not in the library\n", name);
        return -1;
    }
    for (size_t i = 0; i < NIN; i++)
        ref[i] = two ? ((fn2)s)(y[i], x[i]) : ((fn1)s)(x[i]);
    int compared = 0;
    for (int l = 0; l < 3; l++) {
        if (!can_run(l))
            continue;
        for (int arr = 0; arr <= 1; arr++) {
            snprintf(cname, sizeof cname, "%s%s.%s", name, arr ? "_array" : "", levels[l]);
            void *c = sym_addr(cname);
            if (!c) {
                print_message("%s: no such clone\n", cname);
                return -1;
            }
            memset(out, 0, NIN * sizeof *out);
            if (arr && two)
                ((arr2)c)(y, x, out, NIN);
            else if (arr)
                ((arr1)c)(x, out, NIN);
            else
                for (size_t i = 0; i < NIN; i++)
                    out[i] = two ? ((fn2)c)(y[i], x[i]) : ((fn1)c)(x[i]);
            int d = first_diff(ref, out, NIN);
            if (d >= 0) {
                print_message("%s differs from %s at %s: %a vs %a\n", cname, name, where(x, y, two, d),
                              (double)out[d], (double)ref[d]);
                return -1;
            }
            /* in place (pfmath.h allows the output to be an input): the
               same bits again, the output array holding the input first */
            for (int arg = 0; arr && arg < (two ? 2 : 1); arg++) {
                memcpy(out, arg ? x : two ? y : x, NIN * sizeof *out);
                if (two && arg)
                    ((arr2)c)(y, out, out, NIN);
                else if (two)
                    ((arr2)c)(out, x, out, NIN);
                else
                    ((arr1)c)(out, out, NIN);
                d = first_diff(ref, out, NIN);
                if (d >= 0) {
                    print_message("%s in place (output = %s) differs from %s at %s: %a vs %a\n", cname,
                                  two && !arg ? "y" : "x", name, where(x, y, two, d), (double)out[d],
                                  (double)ref[d]);
                    return -1;
                }
            }
            compared++;
        }
    }
    return compared;
}

static void test_clones_identical(void **state)
{
    (void)state;
    if (!es.syms || !sym_addr("pf_logf.default")) {
        print_message("libpfmath.so has no clone symbols (stripped, or no target_clones)\n");
        skip();
    }
    float *x = malloc(NIN * sizeof *x), *y = malloc(NIN * sizeof *y);
    float *ref = malloc(NIN * sizeof *ref), *out = malloc(NIN * sizeof *out);
    assert_non_null(x), assert_non_null(y), assert_non_null(ref), assert_non_null(out);
    int bad = 0, total = 0;
    /* two samples: the mixed one, where nearly every block of the array
       forms holds a rare input, and one uniform in the function's domain
       only, so that the two-path tails' short path (blocks without a rare
       lane: exp, exp2, log, log2; no huge argument: sin, cos, tan) runs in
       every clone too */
    for (int pass = 0; pass < 2; pass++)
        for (size_t k = 0; k < sizeof funcs / sizeof funcs[0]; k++) {
            if (pass == 0) {
                fill(&funcs[k], x, NIN, 1);
                fill(&funcs[k], y, NIN, 0);
            } else
                for (size_t i = 0; i < NIN; i++) {
                    /* within +-80: exp's and exp2's ordinary range, where
                       no lane needs their overflow/underflow selects */
                    float lo = fmaxf(funcs[k].lo, -80.0f), hi = fminf(funcs[k].hi, 80.0f);
                    x[i] = lo + (hi - lo) * (float)(next32() >> 8) * 0x1p-24f;
                    y[i] = lo + (hi - lo) * (float)(next32() >> 8) * 0x1p-24f;
                }
            for (int fast = 0; fast <= 1; fast++) {
                int c = check_one(&funcs[k], fast ? "_fast" : "", x, y, ref, out);
                if (c < 0)
                    bad++;
                else
                    total += c;
            }
        }
    print_message("%d clone comparisons on %d inputs each (two samples)\n", total, NIN);
    free(x), free(y), free(ref), free(out);
    assert_int_equal(bad, 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_clones_identical),
    };
    return cmocka_run_group_tests(tests, setup, NULL);
}
