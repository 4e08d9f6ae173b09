/* Error sweeps of fixed-point functions against the MPFR references
 * (ref/pfref.h): error in LSBs of the output type, max and mean, worst
 * input, histogram, and the fast variants' bound.  Used by pfmathgen (the
 * sweep of the code it emits), pfsweep --type/--out-type, and the tests.
 *
 * A fixed-point function takes and returns stored integers:
 *     OUT f(IN x)    and    void f_array(const IN *x, OUT *y, size_t n)
 * with IN, OUT among int8/16/32_t and uint8/16/32_t (pf_fmt_storage_bits
 * and signedness of the formats).
 *
 * The reference result of input x is f(x) saturated to the output range,
 * with the values the generated functions define where f has none:
 * log(x <= 0), log2(x <= 0) -> the most negative output; sqrt(x < 0) -> 0.
 * The error is |got - reference| in output LSBs.  Saturation is defined
 * behaviour, so an input whose exact result lies outside the range is in
 * error only by its distance from the range's end. */
#ifndef PF_SWEEP_FIXED_H
#define PF_SWEEP_FIXED_H

#include "pffixed.h"
#include "pfref.h"

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

/* ---- calling emitted functions through correctly typed pointers ---- */

typedef struct {
    void *scalar, *array; /* dlsym results (array may be NULL) */
    pf_fmt in, out;
} pf_fx_fn;

/* 1 when both formats have storage of at most 32 bits */
int pf_fx_fn_supported(pf_fmt in, pf_fmt out);
/* y[i] = f(x[i]) through the array form (the scalar form if there is none);
   x[i] must lie in the input format's stored range */
void pf_fx_call_array(const pf_fx_fn *fn, const int64_t *x, int64_t *y, size_t n);
int64_t pf_fx_call_scalar(const pf_fx_fn *fn, int64_t x);
/* the same through the array form called in place (its output array is its
   input array), in pieces of at most 256; 0 when that cannot be done (the
   two formats' storage differs in size, or there is no array form) */
int pf_fx_call_array_inplace(const pf_fx_fn *fn, const int64_t *x, int64_t *y, size_t n);

/* ---- reference and error ---- */

/* 1 when the value of f at stored input x lies outside out's range (or is
   one of the defined values above): the function saturates there */
int pf_fx_saturates(pf_func f, pf_fmt in, pf_fmt out, int64_t x);
/* |y - reference| in LSBs of out (see above) */
double pf_fx_err(pf_func f, pf_fmt in, pf_fmt out, int64_t x, int64_t y);
/* the fast variants' allowance at x: max(2^-10 |reference|, 4 LSB), in LSBs */
double pf_fx_fast_allow(pf_func f, pf_fmt in, pf_fmt out, int64_t x);

/* ---- statistics ---- */

#define PF_FX_HIST_BINS 7
typedef struct {
    uint64_t count;
    double max_err, sum_err;
    int64_t worst_x, worst_y;     /* smallest input reaching max_err */
    double max_ratio;             /* max err / fast allowance */
    int64_t worst_ratio_x;
    uint64_t over_fast;           /* inputs beyond the fast allowance */
    uint64_t saturated;           /* inputs whose reference is saturated or defined */
    uint64_t mismatch;            /* scalar and array forms disagree */
    uint64_t hist[PF_FX_HIST_BINS];
} pf_fx_stats;

void pf_fx_stats_init(pf_fx_stats *s);
/* into += from; merging in a fixed order gives the same sums every run */
void pf_fx_stats_merge(pf_fx_stats *into, const pf_fx_stats *from);
/* one evaluated input */
void pf_fx_stats_add(pf_fx_stats *s, pf_func f, pf_fmt in, pf_fmt out, int64_t x, int64_t y);
const char *pf_fx_bin_label(int i);
double pf_fx_mean(const pf_fx_stats *s);

/* every stored input in [lo, hi], through the array form; the scalar form is
   checked against it on every input when check_scalar is set.  OpenMP
   threads over 2^16-input chunks (merged in order: deterministic);
   progress on stderr when progress is set. */
void pf_fx_sweep_range(pf_fx_stats *s, pf_func f, const pf_fx_fn *fn, int64_t lo, int64_t hi,
                       int check_scalar, int progress);
/* n seeded inputs uniform over the stored range, plus the range's ends and
   0, +-1 */
void pf_fx_sweep_random(pf_fx_stats *s, pf_func f, const pf_fx_fn *fn, uint64_t seed, uint64_t n);

/* the stats in the pfsweep layout, ending with one line
   "TOTAL max_lsb=... mean_lsb=... worst=... count=..." */
void pf_fx_stats_print(FILE *o, const char *title, pf_func f, pf_fmt in, pf_fmt out, const pf_fx_stats *s,
                       int fast);

#endif
