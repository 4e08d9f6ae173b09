/* ns per element of asin, acos, atan, atan2 from libpfmath (array and scalar
 * forms, exact and fast) against glibc's asinf, ... in a scalar loop, all in
 * the same run over the same 2^16 inputs.  Prints a table; the fast/exact
 * ratio is of the array forms.  Not part of `make test` (timings depend on
 * the machine and its load): run build/<dir>/bench_atrig [repetitions]. */
#include "pfcli.h"
#include "pfmath.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

enum { N = 1 << 16 };
static float in1[N], in2[N], out[N];
static volatile float sink;

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t); /* time descheduled on a shared machine does not count */
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

/* the best of reps runs, in ns per element (thread CPU time, and the
   minimum, so that other processes on the machine count as little as
   possible) */
#define TIME(expr)                                                                                \
    ({                                                                                            \
        double best_ = 1e30;                                                                      \
        for (int r_ = 0; r_ < reps; r_++) {                                                       \
            double t0_ = now();                                                                   \
            expr;                                                                                 \
            double t_ = now() - t0_;                                                              \
            best_ = t_ < best_ ? t_ : best_;                                                      \
        }                                                                                         \
        sink = out[N / 2];                                                                        \
        1e9 * best_ / N;                                                                          \
    })

#define LOOP1(f) for (int i_ = 0; i_ < N; i_++) out[i_] = f(in1[i_])
#define LOOP2(f) for (int i_ = 0; i_ < N; i_++) out[i_] = f(in1[i_], in2[i_])

static void row(const char *name, double glibc, double ex_arr, double ex_sc, double fa_arr, double fa_sc)
{
    printf("| %-6s | %7.2f | %7.2f | %7.2f | %7.2f | %7.2f | %5.2fx |\n", name, glibc, ex_arr, ex_sc,
           fa_arr, fa_sc, ex_arr / fa_arr);
}

int main(int argc, char **argv)
{
    int reps = (int)pfcli_bench_count(argc, argv, "bench_atrig",
                                      "usage: bench_atrig [REPETITIONS]\n"
                                      "ns per element of asin, acos, atan, atan2 (pfmath exact and fast, array and\n"
                                      "scalar) beside glibc over the same 2^16 inputs; REPETITIONS 1..100000\n"
                                      "(default 50).\n",
                                      1, 100000, 50);
    uint64_t s = 42;
    for (int i = 0; i < N; i++) {
        s = s * 6364136223846793005ull + 1442695040888963407ull;
        in1[i] = (float)((double)(s >> 11) * 0x1p-53 * 2 - 1); /* [-1, 1) */
        s = s * 6364136223846793005ull + 1442695040888963407ull;
        in2[i] = (float)((double)(s >> 11) * 0x1p-53 * 2 - 1);
    }
    printf("ns per element, %d inputs, best of %d runs (asin, acos: x in [-1, 1); atan: x*8; "
           "atan2: y, x in [-1, 1))\n\n",
           N, reps);
    printf("| func   | glibc   | exact[] | exact   | fast[]  | fast    | fast/exact[] |\n");
    printf("|--------|---------|---------|---------|---------|---------|--------|\n");
    row("asin", TIME(LOOP1(asinf)), TIME(pf_asinf_array(in1, out, N)), TIME(LOOP1(pf_asinf)),
        TIME(pf_asinf_fast_array(in1, out, N)), TIME(LOOP1(pf_asinf_fast)));
    row("acos", TIME(LOOP1(acosf)), TIME(pf_acosf_array(in1, out, N)), TIME(LOOP1(pf_acosf)),
        TIME(pf_acosf_fast_array(in1, out, N)), TIME(LOOP1(pf_acosf_fast)));
    for (int i = 0; i < N; i++)
        in1[i] *= 8; /* both sides of the fold at |x| = 1 */
    row("atan", TIME(LOOP1(atanf)), TIME(pf_atanf_array(in1, out, N)), TIME(LOOP1(pf_atanf)),
        TIME(pf_atanf_fast_array(in1, out, N)), TIME(LOOP1(pf_atanf_fast)));
    for (int i = 0; i < N; i++)
        in1[i] /= 8;
    row("atan2", TIME(LOOP2(atan2f)), TIME(pf_atan2f_array(in1, in2, out, N)), TIME(LOOP2(pf_atan2f)),
        TIME(pf_atan2f_fast_array(in1, in2, out, N)), TIME(LOOP2(pf_atan2f_fast)));
    return 0;
}
