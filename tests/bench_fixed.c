/* bench_fixed: ns per element of the library's fixed-point functions
 * (exact and fast, scalar and array forms) beside the float exact and fast
 * variants of the same function, in the same run, over the same 2^16 real
 * inputs (for the 16-bit functions: every stored input, shuffled).  sqrt has
 * no pfmath float version: sqrtf stands in, its array a loop that GCC
 * vectorizes (this file is built with -O3 -fno-math-errno, see
 * mk/fixedgen.mk) with the same target_clones as the library's arrays.
 * The last two columns are the ratios the issue asks for (issue 14): time
 * of the float array / time of the fixed array, fast and exact.
 * Not a test: timings depend on the machine and its load.
 * Each pass over the 2^16 inputs is timed alone (CLOCK_MONOTONIC) and a
 * figure is the fastest pass: a pass that another job's time slice or
 * interrupt hit is dropped rather than averaged in.  The eight candidates
 * of a row take turns, 7 rounds of `repetitions` passes each, so that a
 * slow stretch of the machine falls on all of them, not on one side of a
 * ratio.  (Until 2026-12-07: the fastest of 7 rounds' averages, each
 * candidate's rounds in a row, two decimals; a 10% change did not show on
 * a loaded 2-core machine.)  Usage: bench_fixed [repetitions] (default
 * 100).  Prints a Markdown table.
 * Built twice (mk/fixedgen.mk): bench_fixed runs the library's own dispatch
 * (the widest clone this CPU has), bench_fixed_avx2 the same sources as a
 * CPU with x86-64-v3 but no AVX-512 runs them (PF_BENCH_AVX2), so both
 * ISAs' ratios come from one machine. */
#include "funcset.h"
#include "pfcli.h"
#include "pfmath.h"
#include "pfmath_fixed.h"
#include "pfref.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

enum { N = 1 << 16 };
/* 64-byte aligned (a cache line, an AVX-512 vector): neither side's loads
   split lines, whatever the compiler would have chosen */
static _Alignas(64) float xf[N], yf[N];
static _Alignas(64) int32_t xi[N], yi[N]; /* room for any storage type */
static volatile int64_t sink;

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t); /* the vDSO's: a pass is ~10 us */
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

typedef void (*runner)(const void *fn, const void *x, void *y, size_t n);

/* one candidate of a row: its runner, function pointer, input and output */
typedef struct {
    runner r;
    const void *fn, *x;
    void *y;
} cand;

/* t[k] = ns per element of c[k]'s fastest pass; candidates with r NULL
   get NAN.  Rounds take the candidates in turn. */
static void time_all(const cand *c, int nc, int reps, double *t)
{
    for (int k = 0; k < nc; k++)
        t[k] = c[k].r ? 1e30 : NAN;
    for (int round = 0; round < 7; round++)
        for (int k = 0; k < nc; k++) {
            if (!c[k].r)
                continue;
            for (int i = 0; i < reps; i++) {
                double t0 = now();
                c[k].r(c[k].fn, c[k].x, c[k].y, N);
                double dt = (now() - t0) / N * 1e9;
                sink += ((const char *)c[k].y)[i & (N - 1)];
                if (dt < t[k])
                    t[k] = dt;
            }
        }
}

/* scalar loops through the right pointer type (noinline: a plain call per
   element, as a caller without the array form would write it) and array
   calls */
#define RUNNERS(tag, IT, OT)                                                                   \
    __attribute__((noinline, unused)) static void sc_##tag(const void *fn, const void *x, void *y, size_t n) \
    {                                                                                          \
        OT (*f)(IT);                                                                           \
        memcpy(&f, fn, sizeof f);                                                              \
        const IT *a = x;                                                                       \
        OT *b = y;                                                                             \
        for (size_t i = 0; i < n; i++)                                                         \
            b[i] = f(a[i]);                                                                    \
    }                                                                                          \
    __attribute__((unused)) static void ar_##tag(const void *fn, const void *x, void *y, size_t n) \
    {                                                                                          \
        void (*f)(const IT *, OT *, size_t);                                                   \
        memcpy(&f, fn, sizeof f);                                                              \
        f(x, y, n);                                                                            \
    }
/* every storage pair a PF_FIXED row can name (unused ones are fine) */
#define RUNNERS_FROM(i) RUNNERS(i##i16, PF_FS_CTYPE(i), int16_t) RUNNERS(i##u16, PF_FS_CTYPE(i), uint16_t) \
                        RUNNERS(i##i32, PF_FS_CTYPE(i), int32_t) RUNNERS(i##u32, PF_FS_CTYPE(i), uint32_t)
RUNNERS_FROM(i16)
RUNNERS_FROM(u16)
RUNNERS_FROM(i32)
RUNNERS_FROM(u32)
RUNNERS(ff, float, float)

static float libm_sqrtf(float x) { return sqrtf(x); }
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(__AVX2__)
__attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#endif
static void libm_sqrtf_array(const float *restrict x, float *restrict y, size_t n)
{
    for (size_t i = 0; i < n; i++)
        y[i] = sqrtf(x[i]);
}

typedef struct {
    const char *fn;
    int bits, in_signed, in_exp;
    double lo, hi; /* 32-bit inputs: domain of the real values */
    runner sc, ar;
    void (*fx)(void), (*fxa)(void), (*fxf)(void), (*fxfa)(void);
    pf_func id;
} row;

#define FX(nm) (void (*)(void))pf_##nm, (void (*)(void))pf_##nm##_array, (void (*)(void))pf_##nm##_fast, \
               (void (*)(void))pf_##nm##_fast_array
/* the PF_FIXED rows of libpfmath/functions.def */
static const row rows[] = {
#define PF_FIXED(n, f, id, ist, isg, isz, ie, ost, osg, osz, oe, lsb, lo, hi)                                  \
    {#f, PF_FS_BITS(ist), isg, ie, lo, hi, sc_##ist##ost, ar_##ist##ost, FX(n), id},
#include "functions.def"
};
/* "fixed<15,12> -> fixed<15,14>" ("fixed<31,16>" when both agree, below) */
static const char *row_types[] = {
#define PF_FIXED(n, f, id, ist, isg, isz, ie, ost, osg, osz, oe, lsb, lo, hi)                                  \
    PF_FS_TYPE(isg, isz, ie) " -> " PF_FS_TYPE(osg, osz, oe),
#include "functions.def"
};

/* the float peers of a fixed-point function: pfmath's exact and fast float
   variants (the PF_FLOAT rows); sqrt has none, libm's sqrtf stands in */
typedef struct {
    float (*fe)(float), (*ff)(float);
    void (*fea)(const float *, float *, size_t), (*ffa)(const float *, float *, size_t);
} peers;
static int float_peers(pf_func id, peers *p)
{
    static const struct {
        pf_func id;
        int arity;
        peers p;
    } fl[] = {
#define FL1(g) {pf_##g##f, pf_##g##f_fast, pf_##g##f_array, pf_##g##f_fast_array}
#define FL2(g) {NULL, NULL, NULL, NULL}
#define PF_FLOAT(n, fid, ar, u, lo, hi) {fid, ar, FL##ar(n)},
#include "functions.def"
    };
    for (size_t i = 0; i < sizeof fl / sizeof fl[0]; i++)
        if (fl[i].id == id && fl[i].arity == 1) {
            *p = fl[i].p;
            return 0;
        }
    if (id == PF_SQRT) {
        *p = (peers){libm_sqrtf, libm_sqrtf, libm_sqrtf_array, libm_sqrtf_array};
        return 0;
    }
    return -1;
}

static uint64_t rng = 0x2545f4914f6cdd1dull;
static uint64_t next(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return rng;
}

int main(int argc, char **argv)
{
    int reps = (int)pfcli_bench_count(argc, argv, "bench_fixed",
                                      "usage: bench_fixed [REPETITIONS]\n"
                                      "ns per element of the library's fixed-point functions beside the float\n"
                                      "variants (a Markdown table); each figure the fastest single pass over\n"
                                      "the 2^16 inputs of 7 rounds of REPETITIONS passes, 1..100000 (default\n"
                                      "100), the candidates of a row taking turns.\n",
                                      1, 100000, 100);
#if defined(PF_BENCH_AVX2)
    const char *isa = "as on an AVX2 CPU (x86-64-v3 code: the generated files built for it, the 16-bit "
                      "kernels' own AVX2 loops)";
#else
    const char *isa = "the library's dispatch on this CPU (its widest clone)";
#endif
    printf("ns per element, the fastest pass over 2^16 inputs of 7 rounds of %d passes, candidates in turn; %s\n\n",
           reps, isa);
    printf("| function | types | fixed exact scalar | fixed exact array | fixed fast scalar | fixed fast array "
           "| float exact scalar | float exact array | float fast scalar | float fast array "
           "| fast: float/fixed array | exact: float/fixed array |\n");
    printf("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (size_t r = 0; r < sizeof rows / sizeof rows[0]; r++) {
        const row *w = &rows[r];
        /* inputs: every 16-bit stored value shuffled, or uniform reals */
        for (int i = 0; i < N; i++) {
            int64_t v;
            if (w->bits == 16)
                v = w->in_signed ? i - 32768 : i;
            else
                v = (int64_t)llround(ldexp(w->lo + (w->hi - w->lo) * (double)(next() >> 11) * 0x1p-53, w->in_exp));
            xi[i] = (int32_t)v;
        }
        if (w->bits == 16) {
            for (int i = N - 1; i > 0; i--) {
                int j = (int)(next() % (uint64_t)(i + 1));
                int32_t t = xi[i];
                xi[i] = xi[j];
                xi[j] = t;
            }
        }
        static _Alignas(64) int16_t x16[N];
        for (int i = 0; i < N; i++) {
            x16[i] = (int16_t)(uint16_t)xi[i];
            xf[i] = (float)ldexp((double)xi[i], -w->in_exp);
        }
        const void *x = w->bits == 16 ? (const void *)x16 : (const void *)xi;
        double t[8];
        peers p;
        int fl = float_peers(w->id, &p) == 0; /* else no float version to compare with */
        const cand c[8] = {
            {w->sc, &w->fx, x, yi},           {w->ar, &w->fxa, x, yi},
            {w->sc, &w->fxf, x, yi},          {w->ar, &w->fxfa, x, yi},
            {fl ? sc_ff : NULL, &p.fe, xf, yf}, {fl ? ar_ff : NULL, &p.fea, xf, yf},
            {fl ? sc_ff : NULL, &p.ff, xf, yf}, {fl ? ar_ff : NULL, &p.ffa, xf, yf},
        };
        time_all(c, 8, reps, t);
        char types[96];
        const char *ty = row_types[r], *arrow = strstr(ty, " -> ");
        size_t k = arrow ? (size_t)(arrow - ty) : strlen(ty);
        if (arrow && strlen(arrow + 4) == k && !strncmp(ty, arrow + 4, k))
            snprintf(types, sizeof types, "%.*s", (int)k, ty);
        else
            snprintf(types, sizeof types, "%s", ty);
        printf("| %s | %s |", w->fn, types);
        for (int k = 0; k < 8; k++)
            printf(" %.3f |", t[k]);
        printf(" %.2f | %.2f |\n", t[7] / t[3], t[5] / t[1]);
        fflush(stdout);
    }
    return 0;
}
