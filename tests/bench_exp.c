/* bench_exp: ns per element of pf_expf / pf_exp2f (exact and fast; array
 * and scalar forms) against glibc's expf / exp2f called in a loop, over the
 * same 2^16 inputs in the same run.  Not a test: timings depend on the
 * machine.  Usage: bench_exp [repetitions]  (default 200)
 * Each figure is the fastest of 7 rounds of `repetitions` passes, timed by
 * the thread's CPU clock so that time the thread spends descheduled on a
 * shared machine does not count (cache sharing still does). */
#include "pfmath.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

enum { N = 1 << 16 };
static float xin[N], yout[N];
static volatile float sink;

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

typedef void (*arr_fn)(const float *, float *, size_t);
typedef float (*sc_fn)(float);

/* a scalar function applied element by element; noinline keeps the call
   from being specialised into a vector loop the library does not offer */
__attribute__((noinline)) static void loop_scalar(sc_fn f, const float *x, float *y, size_t n)
{
    for (size_t i = 0; i < n; i++)
        y[i] = f(x[i]);
}

static double time_it(arr_fn a, sc_fn s, int reps)
{
    double best = 1e30;
    for (int round = 0; round < 7; round++) {
        double t0 = now();
        for (int r = 0; r < reps; r++) {
            if (a)
                a(xin, yout, N);
            else
                loop_scalar(s, xin, yout, N);
            sink = yout[r & (N - 1)];
        }
        double t = (now() - t0) / ((double)reps * N) * 1e9;
        if (t < best)
            best = t;
    }
    return best;
}

static float glibc_expf(float x) { return expf(x); }
static float glibc_exp2f(float x) { return exp2f(x); }

static void bench(const char *name, double lo, double hi, sc_fn glibc, sc_fn ex, sc_fn fa,
                  arr_fn exa, arr_fn faa, int reps)
{
    uint64_t s = 42;
    for (int i = 0; i < N; i++) {
        s = s * 6364136223846793005ull + 1442695040888963407ull;
        xin[i] = (float)(lo + (hi - lo) * (double)(s >> 11) * 0x1p-53);
    }
    double g = time_it(NULL, glibc, reps);
    double es = time_it(NULL, ex, reps), fs = time_it(NULL, fa, reps);
    double ea = time_it(exa, NULL, reps), fa_ = time_it(faa, NULL, reps);
    printf("%-5s inputs uniform in [%g, %g]\n", name, lo, hi);
    printf("  glibc %-6s scalar loop  %6.3f ns/elem\n", name, g);
    printf("  exact  scalar %6.3f ns  array %6.3f ns  (array: %5.2fx glibc)\n", es, ea, g / ea);
    printf("  fast   scalar %6.3f ns  array %6.3f ns  (array: %5.2fx glibc)\n", fs, fa_, g / fa_);
    printf("  fast/exact speed-up on arrays: %.2fx (scalar: %.2fx)\n", ea / fa_, es / fs);
}

int main(int argc, char **argv)
{
    int reps = argc > 1 ? atoi(argv[1]) : 200;
    if (reps < 1)
        reps = 1;
    bench("exp", -87, 88, glibc_expf, pf_expf, pf_expf_fast, pf_expf_array, pf_expf_fast_array, reps);
    bench("exp2", -126, 127, glibc_exp2f, pf_exp2f, pf_exp2f_fast, pf_exp2f_array,
          pf_exp2f_fast_array, reps);
    return 0;
}
