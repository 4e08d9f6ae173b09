/* pfnoise-bench: ns per sample of the noise evaluators against stb_perlin
 * (Debian's libstb-dev, stb_perlin_noise3 compiled from its header with the
 * same flags, see mk/noise.mk) in the same run, with the plain port of
 * Perlin's reference code (tests/noise_baseline.c) as a reference line.
 *
 * Timing: thread CPU time (CLOCK_THREAD_CPUTIME_ID, so time spent
 * descheduled on a loaded machine does not count) of one pass over N
 * points; the kernels are interleaved (one pass of each, REPS times over)
 * and each cell is the median of its REPS passes.  Ratios are stb's time /
 * ours from the same run: > 1 means pfmath is faster.
 *
 * Point sets: "random", uniform in [-128, 128)^3; "grid", a coherent
 * 64 x 32 x 32 raster with spacing 0.0731 (x fastest, as a shader walks a
 * tile).  2D forms read x and y of the same sets; stb has no 2D noise, so
 * they are compared with stb's 3D noise at z = 0.
 *
 *   build/pfnoise-bench [reps]      (default 15) */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "noise_baseline.h"
#include "pfcli.h"
#include "pfnoise.h"

#ifdef PF_HAVE_STB
/* Declarations only: the implementation is its own object (mk/noise.mk
 * compiles the header with STB_PERLIN_IMPLEMENTATION), so stb is called
 * across a translation unit like the library, not inlined into the loop. */
#include <stb/stb_perlin.h>
#endif

enum { N = 1 << 16, OCT = 6 };
static float fx[N], fy[N], fz[N], fo[N], fg[3 * N];
static int32_t qx[N], qy[N], qz[N];
static int16_t qo[N];
static double sink;

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* Each kernel starts on its own 64-byte line: packed small indirect-call
 * targets once made an unchanged kernel 2.5x slower (branch-target
 * aliasing, AMD). */
#if defined(__GNUC__)
#define KERNEL __attribute__((aligned(64), noinline)) static void
#else
#define KERNEL static void
#endif

#ifdef PF_HAVE_STB
KERNEL k_stb3(void)
{
    for (int i = 0; i < N; i++)
        fo[i] = stb_perlin_noise3(fx[i], fy[i], fz[i], 0, 0, 0);
}
KERNEL k_stb2(void)
{
    for (int i = 0; i < N; i++)
        fo[i] = stb_perlin_noise3(fx[i], fy[i], 0.0f, 0, 0, 0);
}
KERNEL k_stbfbm(void)
{
    for (int i = 0; i < N; i++)
        fo[i] = stb_perlin_fbm_noise3(fx[i], fy[i], fz[i], 2.0f, 0.5f, OCT);
}
#endif
KERNEL k_port3(void)
{
    for (int i = 0; i < N; i++)
        fo[i] = (float)noise_baseline3(fx[i], fy[i], fz[i]);
}
KERNEL k_f3(void)
{
    for (int i = 0; i < N; i++)
        fo[i] = pf_noise3f(fx[i], fy[i], fz[i]);
}
KERNEL k_fa3(void) { pf_noise3f_array(NULL, fo, fx, fy, fz, N); }
KERNEL k_f2(void)
{
    for (int i = 0; i < N; i++)
        fo[i] = pf_noise2f(fx[i], fy[i]);
}
KERNEL k_fa2(void) { pf_noise2f_array(NULL, fo, fx, fy, N); }
KERNEL k_fd3(void)
{
    for (int i = 0; i < N; i++)
        fo[i] = pf_noise3f_d(fx[i], fy[i], fz[i], fg + 3 * i);
}
KERNEL k_fbm3(void)
{
    for (int i = 0; i < N; i++)
        fo[i] = pf_fbm3f(fx[i], fy[i], fz[i], OCT, 2.0f, 0.5f, 0.0f);
}
KERNEL k_q3(void)
{
    for (int i = 0; i < N; i++)
        qo[i] = pf_noise3_q15(qx[i], qy[i], qz[i]);
}
KERNEL k_qa3(void) { pf_noise3_q15_array(NULL, qo, qx, qy, qz, N); }
KERNEL k_qfa3(void) { pf_noise3_q15_fast_array(NULL, qo, qx, qy, qz, N); }

typedef void (*kernel)(void);
struct row {
    const char *name, *peer; /* peer: what the ratio compares with */
    kernel k, stb;
    double per; /* divide the time by this (fbm: per octave) */
};

#ifdef PF_HAVE_STB
#define STB(k) k
#else
#define STB(k) NULL
#endif
static const struct row rows[] = {
    {"stb_perlin_noise3 (peer)", "", NULL, STB(k_stb3), 1},
    {"Perlin's reference, C port (double)", "stb_perlin_noise3", k_port3, STB(k_stb3), 1},
    {"pf_noise3f scalar", "stb_perlin_noise3", k_f3, STB(k_stb3), 1},
    {"pf_noise3f_array", "stb_perlin_noise3", k_fa3, STB(k_stb3), 1},
    {"pf_noise2f scalar", "stb_perlin_noise3 at z = 0", k_f2, STB(k_stb2), 1},
    {"pf_noise2f_array", "stb_perlin_noise3 at z = 0", k_fa2, STB(k_stb2), 1},
    {"pf_noise3f_d scalar (value + gradient)", "stb_perlin_noise3 (value only)", k_fd3,
     STB(k_stb3), 1},
    {"pf_fbm3f, per octave (6 octaves)", "stb_perlin_fbm_noise3, per octave", k_fbm3,
     STB(k_stbfbm), OCT},
    {"pf_noise3_q15 scalar (fixed)", "stb_perlin_noise3", k_q3, STB(k_stb3), 1},
    {"pf_noise3_q15_array (fixed)", "stb_perlin_noise3", k_qa3, STB(k_stb3), 1},
    {"pf_noise3_q15_fast_array (fixed)", "stb_perlin_noise3", k_qfa3, STB(k_stb3), 1},
};
enum { NROWS = sizeof rows / sizeof rows[0] };

/* Distinct kernels, timed interleaved. */
static kernel ks[2 * NROWS];
static int nk;
static int kindex(kernel k)
{
    for (int i = 0; i < nk; i++)
        if (ks[i] == k)
            return i;
    ks[nk] = k;
    return nk++;
}

static int cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static uint64_t rs = 0x2545f4914f6cdd1du;
static float urand(void) /* uniform in [-128, 128) */
{
    rs ^= rs << 13;
    rs ^= rs >> 7;
    rs ^= rs << 17;
    return (float)((double)(rs >> 40) * 0x1p-24 * 256.0 - 128.0);
}

static void points(int grid)
{
    for (int i = 0; i < N; i++) {
        if (grid) {
            fx[i] = -2.3f + (float)(i & 63) * 0.0731f;
            fy[i] = 1.7f + (float)((i >> 6) & 31) * 0.0731f;
            fz[i] = 0.4f + (float)(i >> 11) * 0.0731f;
        } else {
            fx[i] = urand();
            fy[i] = urand();
            fz[i] = urand();
        }
        qx[i] = (int32_t)(fx[i] * 65536.0f);
        qy[i] = (int32_t)(fy[i] * 65536.0f);
        qz[i] = (int32_t)(fz[i] * 65536.0f);
    }
}

/* Median ns per sample of every kernel over `reps` interleaved passes. */
static void measure(int reps, double *med)
{
    double *t = malloc((size_t)(reps * nk) * sizeof *t);
    for (int i = 0; i < nk; i++) /* warm up */
        ks[i]();
    for (int r = 0; r < reps; r++)
        for (int i = 0; i < nk; i++) {
            double t0 = now();
            ks[i]();
            t[i * reps + r] = (now() - t0) / N * 1e9;
            sink += fo[r % N] + qo[r % N];
        }
    for (int i = 0; i < nk; i++) {
        qsort(t + i * reps, (size_t)reps, sizeof *t, cmp);
        med[i] = t[i * reps + reps / 2];
    }
    free(t);
}

int main(int argc, char **argv)
{
    int reps = (int)pfcli_bench_count(argc, argv, "pfnoise-bench",
                                      "usage: pfnoise-bench [PASSES]\n"
                                      "ns per sample of the noise evaluators beside stb_perlin, the median of\n"
                                      "PASSES interleaved passes, 1..100000 (default 15).\n",
                                      1, 100000, 15);
    for (int i = 0; i < NROWS; i++) {
        if (rows[i].k)
            kindex(rows[i].k);
        if (rows[i].stb)
            kindex(rows[i].stb);
    }
    const char *isa = "x86-64 (SSE2)";
#if defined(__x86_64__) && defined(__GNUC__)
    __builtin_cpu_init();
    if (__builtin_cpu_supports("avx512f"))
        isa = "x86-64-v4 (AVX-512)";
    else if (__builtin_cpu_supports("avx2"))
        isa = "x86-64-v3 (AVX2)";
#endif
    double med[2][2 * NROWS];
    for (int grid = 0; grid < 2; grid++) {
        points(grid);
        measure(reps, med[grid]);
    }
    printf("pfnoise-bench: ns per sample (thread CPU time), median of %d interleaved passes "
           "over %d points; dispatched forms run their widest body for %s%s\n\n",
           reps, N, isa,
#ifdef PF_HAVE_STB
           ""
#else
           "; stb_perlin not found (install libstb-dev): no ratios"
#endif
    );
    printf("| function | ns random | ns grid | compared with | stb / pf random | stb / pf "
           "grid |\n|---|---|---|---|---|---|\n");
    for (int i = 0; i < NROWS; i++) {
        const struct row *w = &rows[i];
        kernel k = w->k ? w->k : w->stb;
        if (!k)
            continue;
        double a = med[0][kindex(k)] / w->per, b = med[1][kindex(k)] / w->per;
        printf("| %s | %.2f | %.2f | %s |", w->name, a, b, w->peer);
        if (w->k && w->stb)
            printf(" %.2fx | %.2fx |\n", med[0][kindex(w->stb)] / w->per / a,
                   med[1][kindex(w->stb)] / w->per / b);
        else
            printf("  |  |\n");
    }
    printf("\n(fbm rows: time of one 6-octave sum / 6, lacunarity 2, gain 1/2, no filter.  "
           "checksum %g)\n",
           sink);
    return 0;
}
