/* Scalar exact forms against glibc, by how predictable the inputs are.
 *
 * pfmath's scalar forms are branch-free (asin, acos, atan compute both
 * halves of their domain and select; exp, log, ... branch only on rare
 * inputs), glibc's asinf, acosf and atanf branch on |x|.  A loop over the
 * same few thousand inputs lets the CPU's branch predictor learn glibc's
 * branches; a longer random stream does not.  So the scalar ratio of issue
 * 12 depends on n, the number of distinct inputs the loop cycles through:
 * this program times both on n = 4096, 65536 (pfbench's NTIME) and 2^20
 * random inputs of pfbench's domains, each candidate best of 9 runs of
 * 2^20 calls, the two candidates interleaved, and prints glibc time /
 * pfmath time (> 1: pfmath faster) with the two times in ns per call.
 * pfmath's forms come from LIB by dlopen, as pfbench takes them (the
 * shared library, built at -O3, each call through a pointer as glibc's).
 * Usage: bench_scalar LIB (build/libpfmath.so); `make bench` runs it. */
#include <dlfcn.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

typedef float (*fn1)(float);

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

#define NMAX ((size_t)1 << 20)
static float *xs, *ys;

/* ns per call over passes * n calls, one run */
static double run(fn1 f, size_t n)
{
    size_t passes = NMAX / n;
    double t = now();
    for (size_t k = 0; k < passes; k++)
        for (size_t i = 0; i < n; i++)
            ys[i] = f(xs[i]);
    return (now() - t) * 1e9 / ((double)passes * (double)n);
}

static uint64_t splitmix(uint64_t *st)
{
    uint64_t z = (*st += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

int main(int argc, char **argv)
{
    if (argc != 2 || argv[1][0] == '-') {
        fprintf(stderr, "usage: bench_scalar LIB (the path of libpfmath.so)\n");
        return 2;
    }
    void *lib = dlopen(argv[1], RTLD_NOW | RTLD_LOCAL);
    if (!lib) {
        fprintf(stderr, "bench_scalar: cannot load %s\n", argv[1]);
        return 1;
    }
    /* pfbench's domains: uniform, or log-uniform magnitude (sym: random sign) */
    static const struct {
        const char *name;
        fn1 glibc;
        const char *ours;
        double lo, hi;
        int logu, sym;
    } F[] = {
        {"sin", sinf, "pf_sinf", -3.14159265358979, 3.14159265358979, 0, 0},
        {"cos", cosf, "pf_cosf", -3.14159265358979, 3.14159265358979, 0, 0},
        {"tan", tanf, "pf_tanf", -3.14159265358979, 3.14159265358979, 0, 0},
        {"asin", asinf, "pf_asinf", -1, 1, 0, 0},
        {"acos", acosf, "pf_acosf", -1, 1, 0, 0},
        {"atan", atanf, "pf_atanf", 1e-3, 1e3, 1, 1},
        {"exp", expf, "pf_expf", -87, 87, 0, 0},
        {"exp2", exp2f, "pf_exp2f", -126, 126, 0, 0},
        {"log", logf, "pf_logf", 1e-30, 1e30, 1, 0},
        {"log2", log2f, "pf_log2f", 1e-30, 1e30, 1, 0},
    };
    static const size_t ns[] = {4096, 65536, NMAX};
    xs = malloc(NMAX * sizeof *xs);
    ys = malloc(NMAX * sizeof *ys);
    if (!xs || !ys) {
        fprintf(stderr, "bench_scalar: out of memory\n");
        return 1;
    }
    printf("| function | n = 4096 | n = 65536 | n = 2^20 |\n|---|---|---|---|\n");
    for (size_t k = 0; k < sizeof F / sizeof F[0]; k++) {
        uint64_t st = 42;
        for (size_t i = 0; i < NMAX; i++) {
            uint64_t r = splitmix(&st);
            double u = (double)(r >> 11) * 0x1p-53, v;
            if (F[k].logu)
                v = exp(log(F[k].lo) + (log(F[k].hi) - log(F[k].lo)) * u);
            else
                v = F[k].lo + (F[k].hi - F[k].lo) * u;
            xs[i] = (float)(F[k].sym && (r & 1) ? -v : v);
        }
        fn1 ours;
        void *sym = dlsym(lib, F[k].ours);
        if (!sym) {
            fprintf(stderr, "bench_scalar: %s has no %s\n", argv[1], F[k].ours);
            return 1;
        }
        memcpy(&ours, &sym, sizeof ours);
        printf("| %s |", F[k].name);
        for (size_t j = 0; j < sizeof ns / sizeof ns[0]; j++) {
            double g = 1e30, p = 1e30;
            for (int rep = 0; rep < 9; rep++) {
                double a = run(F[k].glibc, ns[j]), b = run(ours, ns[j]);
                g = a < g ? a : g;
                p = b < p ? b : p;
            }
            printf(" %.2f (%.2f / %.2f) |", g / p, g, p);
        }
        printf("\n");
        fflush(stdout);
    }
    free(xs);
    free(ys);
    dlclose(lib);
    return ferror(stdout) ? 1 : 0;
}
