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
 * Times are the thread's CPU time (so other load on the machine does not
 * count).  Usage: bench_fixed [repetitions]  (default 100); each figure is the fastest
 * of 7 rounds of `repetitions` passes.  Prints a Markdown table. */
#include "pfmath.h"
#include "pfmath_fixed.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

enum { N = 1 << 16 };
static float xf[N], yf[N];
static int32_t xi[N], yi[N]; /* room for any storage type */
static volatile int64_t sink;

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t); /* CPU time: robust to a loaded machine */
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

typedef void (*runner)(const void *fn, const void *x, void *y, size_t n);

static double time_it(runner r, const void *fn, const void *x, void *y, int reps)
{
    double best = 1e30;
    for (int round = 0; round < 7; round++) {
        double t0 = now();
        for (int k = 0; k < reps; k++) {
            r(fn, x, y, N);
            sink += ((const char *)y)[k & (N - 1)];
        }
        double t = (now() - t0) / ((double)reps * N) * 1e9;
        if (t < best)
            best = t;
    }
    return best;
}

/* scalar loops through the right pointer type (noinline: a plain call per
   element, as a caller without the array form would write it) and array
   calls */
#define RUNNERS(tag, IT, OT)                                                                   \
    __attribute__((noinline)) static void sc_##tag(const void *fn, const void *x, void *y, size_t n) \
    {                                                                                          \
        OT (*f)(IT);                                                                           \
        memcpy(&f, fn, sizeof f);                                                              \
        const IT *a = x;                                                                       \
        OT *b = y;                                                                             \
        for (size_t i = 0; i < n; i++)                                                         \
            b[i] = f(a[i]);                                                                    \
    }                                                                                          \
    static void ar_##tag(const void *fn, const void *x, void *y, size_t n)                     \
    {                                                                                          \
        void (*f)(const IT *, OT *, size_t);                                                   \
        memcpy(&f, fn, sizeof f);                                                              \
        f(x, y, n);                                                                            \
    }
RUNNERS(i16i16, int16_t, int16_t)
RUNNERS(i16u16, int16_t, uint16_t)
RUNNERS(u16i16, uint16_t, int16_t)
RUNNERS(u16u16, uint16_t, uint16_t)
RUNNERS(i32i32, int32_t, int32_t)
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
    const char *fn, *types;
    int bits, in_signed, in_exp;
    double lo, hi; /* 32-bit inputs: domain of the real values */
    runner sc, ar;
    void (*fx)(void), (*fxa)(void), (*fxf)(void), (*fxfa)(void);
    float (*fe)(float), (*ff)(float);
    void (*fea)(const float *, float *, size_t), (*ffa)(const float *, float *, size_t);
} row;

#define FX(nm) (void (*)(void))nm, (void (*)(void))nm##_array, (void (*)(void))nm##_fast, \
               (void (*)(void))nm##_fast_array
#define FL(g) pf_##g##f, pf_##g##f_fast, pf_##g##f_array, pf_##g##f_fast_array

static const row rows[] = {
    {"sin", "fixed<15,12> -> fixed<15,14>", 16, 1, 12, 0, 0, sc_i16i16, ar_i16i16, FX(pf_sin_q12_q14), FL(sin)},
    {"cos", "fixed<15,12> -> fixed<15,14>", 16, 1, 12, 0, 0, sc_i16i16, ar_i16i16, FX(pf_cos_q12_q14), FL(cos)},
    {"exp", "fixed<15,11> -> ufixed<16,8>", 16, 1, 11, 0, 0, sc_i16u16, ar_i16u16, FX(pf_exp_q11_uq8), FL(exp)},
    {"exp2", "fixed<15,11> -> ufixed<16,8>", 16, 1, 11, 0, 0, sc_i16u16, ar_i16u16, FX(pf_exp2_q11_uq8), FL(exp2)},
    {"log", "ufixed<16,8> -> fixed<15,11>", 16, 0, 8, 0, 0, sc_u16i16, ar_u16i16, FX(pf_log_uq8_q11), FL(log)},
    {"log2", "ufixed<16,8> -> fixed<15,11>", 16, 0, 8, 0, 0, sc_u16i16, ar_u16i16, FX(pf_log2_uq8_q11), FL(log2)},
    {"sqrt", "ufixed<16,8> -> ufixed<16,12>", 16, 0, 8, 0, 0, sc_u16u16, ar_u16u16, FX(pf_sqrt_uq8_uq12),
     libm_sqrtf, libm_sqrtf, libm_sqrtf_array, libm_sqrtf_array},
    {"sin", "fixed<31,16>", 32, 1, 16, -100, 100, sc_i32i32, ar_i32i32, FX(pf_sin_q16), FL(sin)},
    {"cos", "fixed<31,16>", 32, 1, 16, -100, 100, sc_i32i32, ar_i32i32, FX(pf_cos_q16), FL(cos)},
    {"exp", "fixed<31,16>", 32, 1, 16, -11, 10.3, sc_i32i32, ar_i32i32, FX(pf_exp_q16), FL(exp)},
    {"exp2", "fixed<31,16>", 32, 1, 16, -16, 14.9, sc_i32i32, ar_i32i32, FX(pf_exp2_q16), FL(exp2)},
    {"log", "fixed<31,16>", 32, 1, 16, 0x1p-16, 32767, sc_i32i32, ar_i32i32, FX(pf_log_q16), FL(log)},
    {"log2", "fixed<31,16>", 32, 1, 16, 0x1p-16, 32767, sc_i32i32, ar_i32i32, FX(pf_log2_q16), FL(log2)},
    {"sqrt", "fixed<31,16>", 32, 1, 16, 0, 32767, sc_i32i32, ar_i32i32, FX(pf_sqrt_q16), libm_sqrtf,
     libm_sqrtf, libm_sqrtf_array, libm_sqrtf_array},
};

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
    int reps = argc > 1 ? atoi(argv[1]) : 100;
    if (reps < 1)
        reps = 1;
    printf("ns per element, best of 7 rounds of %d passes over 2^16 inputs\n\n", reps);
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
        static int16_t x16[N];
        for (int i = 0; i < N; i++) {
            x16[i] = (int16_t)(uint16_t)xi[i];
            xf[i] = (float)ldexp((double)xi[i], -w->in_exp);
        }
        const void *x = w->bits == 16 ? (const void *)x16 : (const void *)xi;
        double t[8];
        t[0] = time_it(w->sc, &w->fx, x, yi, reps);
        t[1] = time_it(w->ar, &w->fxa, x, yi, reps);
        t[2] = time_it(w->sc, &w->fxf, x, yi, reps);
        t[3] = time_it(w->ar, &w->fxfa, x, yi, reps);
        t[4] = time_it(sc_ff, &w->fe, xf, yf, reps);
        t[5] = time_it(ar_ff, &w->fea, xf, yf, reps);
        t[6] = time_it(sc_ff, &w->ff, xf, yf, reps);
        t[7] = time_it(ar_ff, &w->ffa, xf, yf, reps);
        printf("| %s | %s |", w->fn, w->types);
        for (int k = 0; k < 8; k++)
            printf(" %.2f |", t[k]);
        printf(" %.2f | %.2f |\n", t[7] / t[3], t[5] / t[1]);
        fflush(stdout);
    }
    return 0;
}
