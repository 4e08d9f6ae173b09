/* Scalar exact forms against glibc, by how predictable the inputs are.
 *
 * pfmath's scalar forms are branch-free (asin, acos, atan compute both
 * halves of their domain and select; exp, log, ... branch only on rare
 * inputs), glibc's asinf, acosf and atanf branch on |x|.  A loop over the
 * same few thousand inputs lets the CPU's branch predictor learn glibc's
 * branches; a longer random stream does not.  So the scalar ratio of issue
 * 12 depends on n, the number of distinct inputs the loop cycles through:
 * this program times both on n = 4096, 65536 (pfbench's NTIME) and 2^20
 * inputs of each one-argument domain of pfbench, drawn by pfbench's own
 * sampler (pfb_sample), each candidate best of 9 runs of 2^20 calls, the
 * two interleaved, and prints glibc time / pfmath time (> 1: pfmath
 * faster) with the two times in ns per call.  The two candidates are
 * pfbench's "glibc" and "pfmath" scalar rows (pfb_peers, pfb_ours: LIB by
 * dlopen, each call through a pointer).
 * Usage: bench_scalar LIB (build/libpfmath.so); `make bench` runs it. */
#include "pfbench.h"
#include "pfref.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

#define NMAX ((size_t)1 << 20)

/* ns per call over NMAX calls cycling through the first n inputs, one run */
static double run(pf_fn1 f, const float *x, float *y, size_t n)
{
    size_t passes = NMAX / n;
    double t = now();
    for (size_t k = 0; k < passes; k++)
        pfb_loop1(f, x, y, n);
    return (now() - t) * 1e9 / ((double)passes * (double)n);
}

/* the scalar candidate called name among f's rows */
static pf_fn1 scalar_of(const pfb_cand *c, int n, const char *name)
{
    for (int i = 0; i < n; i++)
        if (!c[i].absent[0] && !strcmp(c[i].name, name) && !strcmp(c[i].isa, "scalar"))
            return c[i].s1;
    return NULL;
}

int main(int argc, char **argv)
{
    if (argc != 2 || argv[1][0] == '-') {
        fprintf(stderr, "usage: bench_scalar LIB (the path of libpfmath.so)\n");
        return 2;
    }
    char err[512];
    if (pfb_ours_open(argv[1], err, sizeof err) != 0) {
        fprintf(stderr, "bench_scalar: %s\n", err);
        return 1;
    }
    static const size_t ns[] = {4096, 65536, NMAX};
    float *x = malloc(NMAX * sizeof *x), *y = malloc(NMAX * sizeof *y);
    if (!x || !y) {
        fprintf(stderr, "bench_scalar: out of memory\n");
        return 1;
    }
    int nd;
    const pfb_domain *d = pfb_domains(&nd);
    printf("| function, domain | n = 4096 | n = 65536 | n = 2^20 |\n|---|---|---|---|\n");
    for (int k = 0; k < nd; k++) {
        if (pfref_arity(d[k].f) != 1)
            continue;
        pfb_cand c[PFB_MAX_CANDS];
        int nc = 0;
        pfb_peers(d[k].f, c, &nc);
        pfb_ours(d[k].f, c, &nc);
        pf_fn1 gl = scalar_of(c, nc, "glibc"), ours = scalar_of(c, nc, "pfmath");
        if (!gl || !ours)
            continue;
        pfb_sample(&d[k], 1, x, NULL, NMAX);
        printf("| %s %s |", pfref_name(d[k].f), d[k].desc);
        for (size_t j = 0; j < sizeof ns / sizeof ns[0]; j++) {
            double g = 1e30, p = 1e30;
            for (int rep = 0; rep < 9; rep++) {
                double a = run(gl, x, y, ns[j]), b = run(ours, x, y, ns[j]);
                g = a < g ? a : g;
                p = b < p ? b : p;
            }
            printf(" %.2f (%.2f / %.2f) |", g / p, g, p);
        }
        printf("\n");
        fflush(stdout);
    }
    free(x);
    free(y);
    return ferror(stdout) ? 1 : 0;
}
