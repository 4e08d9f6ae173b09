/* Error sweeps of a float function against the MPFR references (ref/pfref.h):
 * ULP statistics, correctly-rounded share, worst input, histogram.  Used by
 * pfsweep, by pfmathgen's report and by the tests. */
#ifndef PF_SWEEP_H
#define PF_SWEEP_H

#include "pfref.h"

#include <stdint.h>
#include <stdio.h>

typedef float (*pf_fn1)(float);
typedef float (*pf_fn2)(float, float);

#define PF_HIST_BINS 8
typedef struct {
    uint64_t count, cr;
    double max_ulp, sum_ulp;
    float worst_x, worst_x2, worst_got;
    uint64_t hist[PF_HIST_BINS];   /* see pf_sweep_bin_label */
} pf_sweep_stats;

void pf_sweep_init(pf_sweep_stats *s);
void pf_sweep_merge(pf_sweep_stats *into, const pf_sweep_stats *from);
/* one input whose result is already computed (the bench times its own calls) */
void pf_sweep_got(pf_sweep_stats *s, pf_func f, float got, float x, float x2);
/* one input */
void pf_sweep_one(pf_sweep_stats *s, pf_func f, pf_fn1 fn1, pf_fn2 fn2, float x, float x2);
/* every float whose bit pattern is in [lo, hi] (OpenMP-parallel when built so) */
void pf_sweep_bits(pf_sweep_stats *s, pf_func f, pf_fn1 fn1, pf_fn2 fn2, uint32_t lo, uint32_t hi,
                   int progress);
/* n inputs with uniformly random bit patterns (finite, any sign), seeded */
void pf_sweep_random(pf_sweep_stats *s, pf_func f, pf_fn1 fn1, pf_fn2 fn2, uint64_t seed, uint64_t n);
/* the directed special and hard inputs every function is checked on */
void pf_sweep_directed(pf_sweep_stats *s, pf_func f, pf_fn1 fn1, pf_fn2 fn2);
const char *pf_sweep_bin_label(int i);
double pf_sweep_mean(const pf_sweep_stats *s);
double pf_sweep_cr_percent(const pf_sweep_stats *s);
void pf_sweep_print(FILE *out, const char *title, pf_func f, const pf_sweep_stats *s);
/* the reduced-domain bit range of a function's sweep, e.g. [0.5, 2) for log */
void pf_sweep_reduced_range(pf_func f, uint32_t *lo, uint32_t *hi);

#endif
