/* pfbench: the accuracy ladder's rows and the Pareto checks (issue 13). */
#ifndef PFBENCH_LADDER_H
#define PFBENCH_LADDER_H

#include "pfbench.h"

#include <stdio.h>

/* pfb_cand.ours of a ladder row (1: libpfmath's exact and fast rows) */
#define PFB_OURS_LADDER 2

/* the ladder library (build/libpfladder.so); 0 on success */
int pfb_ladder_open(const char *lib, char *err, size_t errlen);
/* rows "pfmath-L<U>" for f's levels found in it, appended to c[*n] */
void pfb_ladder(pf_func f, pfb_cand *c, int *n);
/* the scalar form of a ladder row (for the array = scalar bits check) */
void *pfb_ladder_scalar(pf_func f, const pfb_cand *c);

/* One point of a picture: a candidate's median ns per element and max ULP. */
typedef struct {
    const char *name, *isa;
    int ours;
    double t, e;
} pfb_point;

/* The Pareto checks of one function and domain (tests/pfbench_ladder_pareto.c):
   for each vector peer point (libmvec, SLEEF: ISA avx2 or avx512) some
   pfmath point of the same ISA with max error <= the peer's and time <= the
   peer's.  Writes one table row per peer point to md ("pass" or "MISS" and
   the ratio peer ns / ns of the fastest pfmath point at least as accurate)
   and adds to *pass, *miss. */
void pfb_pareto_checks(FILE *md, const char *fn, const char *dom, const pfb_point *p, int n, int *pass,
                       int *miss);

/* The ladder's table: each ladder row of an AVX2 or AVX-512 clone beside the
   vector peer of the same ISA nearest to it in max error (log scale). */
void pfb_ladder_table(FILE *md, const char *fn, const char *dom, const pfb_point *p, int n);

#endif
