/* pfnoise-bench: ns per sample of the noise evaluators, next to the plain
 * port of Perlin's reference code (tests/noise_baseline.c) in the same run.
 * Each cell is the median of REPS timed samples over N points (each sample
 * repeats the pass until it takes >= 0.25 ms: short enough to fit inside a
 * scheduler time slice on a loaded machine).  Prints a markdown table.
 *
 *   build/pfnoise-bench [reps]      (default 21) */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "noise_baseline.h"
#include "pfnoise.h"

enum { N = 4096 };
static float fx[N], fy[N], fz[N], fo[N];
static int32_t qx[N], qy[N], qz[N];
static int16_t qo[N];
static double sink;

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

typedef void (*kernel)(void);

/* Each kernel starts on its own 64-byte line: with the wrappers packed
 * together, adding two kernels once made the (unchanged) fixed 3D array
 * column 2.5x slower on the development machine (AMD, AVX-512), presumably
 * branch-target aliasing between the small indirect-call targets. */
#if defined(__GNUC__)
#define KERNEL __attribute__((aligned(64), noinline)) static
#else
#define KERNEL static
#endif

KERNEL void k_base2(void)
{
    for (int i = 0; i < N; i++)
        fo[i] = (float)noise_baseline3(fx[i], fy[i], 0.0);
}
KERNEL void k_base3(void)
{
    for (int i = 0; i < N; i++)
        fo[i] = (float)noise_baseline3(fx[i], fy[i], fz[i]);
}
KERNEL void k_basef2(void)
{
    for (int i = 0; i < N; i++)
        fo[i] = noise_baseline3f(fx[i], fy[i], 0.0f);
}
KERNEL void k_basef3(void)
{
    for (int i = 0; i < N; i++)
        fo[i] = noise_baseline3f(fx[i], fy[i], fz[i]);
}
KERNEL void k_f2(void)
{
    for (int i = 0; i < N; i++)
        fo[i] = pf_noise2f(fx[i], fy[i]);
}
KERNEL void k_f3(void)
{
    for (int i = 0; i < N; i++)
        fo[i] = pf_noise3f(fx[i], fy[i], fz[i]);
}
KERNEL void k_fa2(void) { pf_noise2f_array(NULL, fo, fx, fy, N); }
KERNEL void k_fa3(void) { pf_noise3f_array(NULL, fo, fx, fy, fz, N); }
KERNEL void k_q2(void)
{
    for (int i = 0; i < N; i++)
        qo[i] = pf_noise2_q15(qx[i], qy[i]);
}
KERNEL void k_q3(void)
{
    for (int i = 0; i < N; i++)
        qo[i] = pf_noise3_q15(qx[i], qy[i], qz[i]);
}
KERNEL void k_qa2(void) { pf_noise2_q15_array(NULL, qo, qx, qy, N); }
KERNEL void k_qa3(void) { pf_noise3_q15_array(NULL, qo, qx, qy, qz, N); }
KERNEL void k_qfa2(void) { pf_noise2_q15_fast_array(NULL, qo, qx, qy, N); }
KERNEL void k_qfa3(void) { pf_noise3_q15_fast_array(NULL, qo, qx, qy, qz, N); }

static int cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static int reps = 21;

static double measure(kernel k)
{
    int inner = 1;
    for (;;) { /* calibrate: one timed sample >= 0.25 ms */
        double t0 = now();
        for (int i = 0; i < inner; i++)
            k();
        if (now() - t0 >= 2.5e-4 || inner > (1 << 20))
            break;
        inner *= 2;
    }
    double *t = malloc((size_t)reps * sizeof *t);
    for (int r = 0; r < reps; r++) {
        double t0 = now();
        for (int i = 0; i < inner; i++)
            k();
        t[r] = (now() - t0) / inner / N * 1e9;
        sink += fo[r % N] + qo[r % N];
    }
    qsort(t, (size_t)reps, sizeof *t, cmp);
    double m = t[reps / 2];
    free(t);
    return m;
}

static uint64_t rs = 0x2545f4914f6cdd1du;
static float urand256(void)
{
    rs ^= rs << 13;
    rs ^= rs >> 7;
    rs ^= rs << 17;
    return (float)((rs >> 40) * 0x1p-24 * 256.0);
}

static void points(int grid)
{
    for (int i = 0; i < N; i++) {
        if (grid) { /* a 64 x 64 raster at 8 samples per unit, as a shader would */
            fx[i] = 10.0f + (float)(i & 63) * 0.125f;
            fy[i] = 20.0f + (float)(i >> 6) * 0.125f;
            fz[i] = 30.3f;
        } else {
            fx[i] = urand256();
            fy[i] = urand256();
            fz[i] = urand256();
        }
        qx[i] = (int32_t)(fx[i] * 65536.0f);
        qy[i] = (int32_t)(fy[i] * 65536.0f);
        qz[i] = (int32_t)(fz[i] * 65536.0f);
    }
}

int main(int argc, char **argv)
{
    if (argc > 1)
        reps = atoi(argv[1]) > 0 ? atoi(argv[1]) : reps;
    const char *isa = "x86-64 (SSE2)";
#if defined(__x86_64__) && defined(__GNUC__)
    __builtin_cpu_init();
    if (__builtin_cpu_supports("avx512f"))
        isa = "x86-64-v4 (AVX-512) clone";
    else if (__builtin_cpu_supports("avx2"))
        isa = "x86-64-v3 (AVX2) clone";
#endif
    printf("pfnoise-bench: ns per sample, median of %d runs over %d points; array forms "
           "use the %s\n\n",
           reps, N, isa);
    printf("| points | Perlin port (double) | Perlin port (float) | pf float scalar | pf float "
           "array | pf fixed Q15 scalar | pf fixed Q15 array | pf fixed Q15 fast array | float "
           "array vs port | fixed array vs port | fast fixed array vs float array |\n");
    printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (int dim = 2; dim <= 3; dim++)
        for (int grid = 1; grid >= 0; grid--) {
            points(grid);
            double b = measure(dim == 2 ? k_base2 : k_base3);
            double bf = measure(dim == 2 ? k_basef2 : k_basef3);
            double s = measure(dim == 2 ? k_f2 : k_f3);
            double a = measure(dim == 2 ? k_fa2 : k_fa3);
            double qs = measure(dim == 2 ? k_q2 : k_q3);
            double qa = measure(dim == 2 ? k_qa2 : k_qa3);
            double qf = measure(dim == 2 ? k_qfa2 : k_qfa3);
            printf("| %dD %s | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.1fx | %.1fx | "
                   "%.2fx |\n",
                   dim, grid ? "grid" : "random", b, bf, s, a, qs, qa, qf, b / a, b / qa, a / qf);
        }
    printf("\n(2D Perlin port: his 3D noise at z = 0, the usual way to get 2D from it.  "
           "Ratios: port (double) time / array time; last column: float array time / fast "
           "fixed array time, >= 1 when the fast fixed form is at least as fast.)  checksum %g\n",
           sink);
    return 0;
}
