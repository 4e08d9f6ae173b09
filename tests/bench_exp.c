/* bench_exp: ns per element of pf_expf / pf_exp2f (exact and fast; array
 * and scalar forms) against glibc's expf / exp2f called in a loop, over the
 * same 2^16 inputs in the same run.  Not a test: timings depend on the
 * machine.  Usage: bench_exp [repetitions]  (default 200)
 * Each figure is the fastest of 7 rounds of `repetitions` passes, timed by
 * the thread's CPU clock so that time the thread spends descheduled on a
 * shared machine does not count (cache sharing still does).
 *
 * bench_exp --fast-bound [threads]: the fast variants' bound over every
 * float instead (exp, exp2, log, log2; about a minute each on 2 cores), see
 * fast_bound_all below. */
#include "pfcli.h"
#include "pfmath.h"

#include <math.h>
#include <pthread.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
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

/* ---- the fast bound over all 2^32 floats ----
 * Every input x, through the array form (bit-identical to the scalar one):
 * the result must be within max(2^-10 |f(x)|, 2^-11) of f(x) (issue 13's
 * bound), f(x) from glibc's double function on x, the reference
 * ref/pfref_exact_d uses (within a double ulp: far below the bound).  Where
 * f(x) rounds to +-inf or is +-inf, or is NaN, the result must be the same
 * infinity or a NaN. */
typedef struct {
    arr_fn fn;
    double (*ref)(double);
    uint64_t lo, hi;
    double worst;
    uint32_t worst_x;
    uint64_t bad;
} fb_job;

static void *fb_run(void *arg)
{
    fb_job *j = arg;
    enum { B = 4096 };
    float x[B], y[B];
    for (uint64_t b = j->lo; b < j->hi; b += B) {
        for (int i = 0; i < B; i++) {
            uint32_t u = (uint32_t)(b + (uint64_t)i);
            memcpy(&x[i], &u, 4);
        }
        j->fn(x, y, B);
        for (int i = 0; i < B; i++) {
            double f = j->ref(x[i]), g = y[i], e;
            if (isnan(f) || fabs(f) >= 0x1.ffffffp127)
                e = (isnan(f) ? isnan(g) : g == (f > 0 ? INFINITY : -INFINITY)) ? 0 : INFINITY;
            else
                e = fabs(g - f) / fmax(0x1p-10 * fabs(f), 0x1p-11); /* <= 1: within the bound */
            if (!(e <= 1))
                j->bad++;
            if (!(e <= j->worst)) {
                j->worst = e;
                memcpy(&j->worst_x, &x[i], 4);
            }
        }
    }
    return NULL;
}

static int fast_bound_all(int nthreads)
{
    struct { const char *name; arr_fn fn; double (*ref)(double); } fs[] = {
        {"exp", pf_expf_fast_array, exp},
        {"exp2", pf_exp2f_fast_array, exp2},
        {"log", pf_logf_fast_array, log},
        {"log2", pf_log2f_fast_array, log2},
    };
    int fail = 0;
    if (nthreads < 1 || nthreads > 64)
        nthreads = 2;
    for (size_t k = 0; k < sizeof fs / sizeof fs[0]; k++) {
        fb_job jobs[64];
        pthread_t th[64];
        uint64_t per = ((1ull << 32) / (uint64_t)nthreads + 4095) & ~4095ull;
        for (int t = 0; t < nthreads; t++) {
            uint64_t lo = per * (uint64_t)t, hi = lo + per > (1ull << 32) ? 1ull << 32 : lo + per;
            jobs[t] = (fb_job){fs[k].fn, fs[k].ref, lo, hi, 0, 0, 0};
            pthread_create(&th[t], NULL, fb_run, &jobs[t]);
        }
        double worst = 0;
        uint32_t wx = 0;
        uint64_t bad = 0;
        for (int t = 0; t < nthreads; t++) {
            pthread_join(th[t], NULL);
            bad += jobs[t].bad;
            if (!(jobs[t].worst <= worst))
                worst = jobs[t].worst, wx = jobs[t].worst_x;
        }
        float w;
        memcpy(&w, &wx, 4);
        printf("pf_%sf_fast: all 2^32 floats, worst error %.4f of the bound max(2^-10 |f|, 2^-11) "
               "at x = %a (0x%08x); %llu inputs over it\n",
               fs[k].name, worst, (double)w, wx, (unsigned long long)bad);
        fail |= bad != 0;
    }
    return fail;
}

int main(int argc, char **argv)
{
    static const char usage[] =
        "usage: bench_exp [REPETITIONS]      ns per element of pf_expf, pf_exp2f (exact, fast;\n"
        "                                    array, scalar) beside glibc; REPETITIONS 1..100000\n"
        "                                    (default 200)\n"
        "       bench_exp --fast-bound [THREADS]  the fast variants' bound over every float\n"
        "                                    (exp, exp2, log, log2); THREADS 1..256 (default 2)\n";
    if (argc > 1 && !strcmp(argv[1], "--fast-bound"))
        return fast_bound_all((int)pfcli_bench_count(argc - 1, argv + 1, "bench_exp", usage, 1, 256, 2));
    int reps = (int)pfcli_bench_count(argc, argv, "bench_exp", usage, 1, 100000, 200);
    bench("exp", -87, 88, glibc_expf, pf_expf, pf_expf_fast, pf_expf_array, pf_expf_fast_array, reps);
    bench("exp2", -126, 127, glibc_exp2f, pf_exp2f, pf_exp2f_fast, pf_exp2f_array,
          pf_exp2f_fast_array, reps);
    return 0;
}
