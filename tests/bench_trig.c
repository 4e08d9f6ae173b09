/* bench_trig: ns per element of sin, cos, tan from libpfmath (array and
 * scalar forms, exact and fast) against glibc's sinf, cosf, tanf, measured in
 * the same run over the same 2^16 inputs.  Not a test: `make
 * BUILD=build/x build/x/bench_trig && build/x/bench_trig [range]`, inputs
 * uniform in [-range, range] (default 100).  Each figure is the fastest of
 * many repetitions (the least disturbed by other processes). */
#include "pfcli.h"
#include "pfmath.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

enum { N = 1 << 16, REPS = 60 };

static float xin[N], yout[N];
static volatile float sink;

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

typedef float (*fn1)(float);
typedef void (*fnarr)(const float *, float *, size_t);

static double time_scalar(fn1 f)
{
    double best = 1e30;
    for (int r = 0; r < REPS; r++) {
        double t0 = now();
        for (int i = 0; i < N; i++)
            yout[i] = f(xin[i]);
        double t = now() - t0;
        sink = yout[r];
        if (t < best)
            best = t;
    }
    return best * 1e9 / N;
}

static double time_array(fnarr f)
{
    double best = 1e30;
    for (int r = 0; r < REPS; r++) {
        double t0 = now();
        f(xin, yout, N);
        double t = now() - t0;
        sink = yout[r];
        if (t < best)
            best = t;
    }
    return best * 1e9 / N;
}

/* glibc through a pointer, so the loop calls it like the scalar pf_ forms */
static float g_sin(float x) { return sinf(x); }
static float g_cos(float x) { return cosf(x); }
static float g_tan(float x) { return tanf(x); }

int main(int argc, char **argv)
{
    double range = 100;
    if (argc > 1 && (!strcmp(argv[1], "-h") || !strcmp(argv[1], "--help"))) {
        fputs("usage: bench_trig [RANGE]\n"
              "ns per element of sin, cos, tan (pfmath exact and fast, array and scalar)\n"
              "beside glibc over 2^16 inputs uniform in [-RANGE, RANGE]; RANGE a finite\n"
              "number > 0, at most 1e30 (default 100).\n",
              stdout);
        return 0;
    }
    /* atof took "--help" or "1e" as 0: a table over [-0, 0], silently */
    if (argc > 1 && (pfcli_real(argv[1], 0, 1e30, &range) != 0 || !(range > 0)))
        pfcli_refuse("bench_trig", "RANGE must be a finite number in (0, 1e30], not ", argv[1]);
    if (argc > 2)
        pfcli_refuse("bench_trig", "unexpected argument ", argv[2]);
    uint64_t s = 12345;
    for (int i = 0; i < N; i++) {
        s = s * 6364136223846793005ull + 1442695040888963407ull;
        xin[i] = (float)(((double)(s >> 11) * 0x1p-53 * 2 - 1) * range);
    }
    struct {
        const char *name;
        fn1 glibc, exact, fast;
        fnarr exact_arr, fast_arr;
    } fs[] = {
        {"sin", g_sin, pf_sinf, pf_sinf_fast, pf_sinf_array, pf_sinf_fast_array},
        {"cos", g_cos, pf_cosf, pf_cosf_fast, pf_cosf_array, pf_cosf_fast_array},
        {"tan", g_tan, pf_tanf, pf_tanf_fast, pf_tanf_array, pf_tanf_fast_array},
    };
    printf("ns/element over %d inputs uniform in [-%g, %g] (best of %d runs)\n", N, range, range, REPS);
    printf("%-5s %8s %8s %8s %8s %8s   %s\n", "func", "glibc", "exact", "exact[]", "fast",
           "fast[]", "fast[]/exact[] speedup");
    for (size_t k = 0; k < sizeof fs / sizeof fs[0]; k++) {
        double g = time_scalar(fs[k].glibc), e = time_scalar(fs[k].exact),
               ea = time_array(fs[k].exact_arr), f = time_scalar(fs[k].fast),
               fa = time_array(fs[k].fast_arr);
        printf("%-5s %8.3f %8.3f %8.3f %8.3f %8.3f   %.2fx\n", fs[k].name, g, e, ea, f, fa, ea / fa);
    }
    return 0;
}
