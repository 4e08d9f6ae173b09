/* pfbench: speed against error, pfmath side by side with glibc, libmvec and
 * SLEEF, measured in one run on the same inputs (issue 7).
 *
 * Split in several files so that the part the numbers depend on can be tested
 * on its own (tests/test_bench.c):
 *   pfbench_err.c    per-function input domains, the seeded sampler, the
 *                    error measurement (the same statistic as ref/sweep.c)
 *                    and the Pareto front
 *   pfbench_peers.c  glibc scalar, libmvec and SLEEF candidates
 *   pfbench_ours.c   pfmath candidates, looked up by name in libpfmath.so,
 *                    and the table of fixed-point rows
 *   pfbench_fixed.c  calling and measuring the fixed-point functions
 *   pfbench.c        the timing harness and the Markdown/CSV writers
 * tests/bench-plot.sh draws the pictures from the CSV. */
#ifndef PFBENCH_H
#define PFBENCH_H

#include "sweep.h"

#include <stddef.h>
#include <stdint.h>

/* ---- input domains (pfbench_err.c) ---- */

typedef enum {
    PFB_UNIFORM,    /* uniform in [lo, hi] */
    PFB_LOGUNIFORM, /* log-uniform in [lo, hi], 0 < lo < hi */
    PFB_LOGSYM,     /* random sign, magnitude log-uniform in [lo, hi] */
    PFB_BITS,       /* pf_sweep_random's stream: uniformly random finite bit patterns */
} pfb_dist;

typedef struct {
    pf_func f;
    const char *tag;    /* short id used in file names: "pi", "1e4", ... */
    const char *desc;   /* human-readable, "[-pi, pi]" */
    pfb_dist dist;
    double lo, hi;
    pfb_dist dist2;     /* second argument (atan2's x); ignored for arity 1 */
    double lo2, hi2;
} pfb_domain;

/* The declared per-function domains, in table order; *n gets the count. */
const pfb_domain *pfb_domains(int *n);

/* n inputs of d drawn from splitmix64(seed); x2 (may be NULL for arity 1)
   gets the second argument.  Deterministic: the first k of an n-sample are
   the k-sample.  PFB_BITS reproduces pf_sweep_random(seed) exactly. */
void pfb_sample(const pfb_domain *d, uint64_t seed, float *x, float *x2, size_t n);

/* ---- error measurement (pfbench_err.c) ---- */

/* One result: the same rule as pf_sweep_one (ref/sweep.c), but for a value
   the caller already computed, so vector peers are measured on the values
   their vector entry points return. */
void pfb_err_record(pf_sweep_stats *s, pf_func f, float x, float x2, float got);

/* got[i] against f(x[i], x2[i]) (x2 may be NULL for arity 1), OpenMP-parallel
   over chunks merged in input order: max_ulp and worst_x are those of the
   serial pass; sum_ulp may differ in the last bits (summation order). */
void pfb_err_arrays(pf_sweep_stats *s, pf_func f, const float *x, const float *x2,
                    const float *got, size_t n);

/* on[i] = 1 when no other point is at least as good in both t and e and
   better in one (lower is better).  Points with a non-finite t or e (absent
   candidates) are never on the front and never dominate. */
void pfb_pareto(const double *t, const double *e, int n, int *on);

/* median, min and max of v[0..n-1] (v is sorted in place) */
void pfb_median(double *v, int n, double *med, double *min, double *max);

/* measured + unit into buf with two decimals, or more (up to six) while
   those would print the same text as want: a missed goal never reads as
   met, nor a met one as missed */
void pfb_goal_fmt(char *buf, size_t n, double measured, double want, const char *unit);

/* ---- candidates (pfbench_peers.c, pfbench_ours.c) ---- */

typedef void (*pfb_arr1)(const float *x, float *y, size_t n);
typedef void (*pfb_arr2)(const float *y, const float *x, float *out, size_t n);

typedef struct {
    char name[32];   /* "pfmath", "pfmath-fast", "glibc", "libmvec", "sleef-u10", ... */
    char isa[16];    /* "scalar", "sse2", "avx2", "avx512", "dispatch" */
    int ours;        /* 1 for pfmath rows */
    int fast;        /* pfmath fast variant, or SLEEF u35 */
    pf_fn1 s1;       /* scalar form (latency, and the throughput loop when   */
    pf_fn2 s2;       /* there is no array form); NULL for vector candidates  */
    pfb_arr1 a1;     /* array form: what the throughput and the error are measured on */
    pfb_arr2 a2;
    char absent[64]; /* non-empty: the candidate cannot run here, and why */
} pfb_cand;

#define PFB_MAX_CANDS 48

/* peers for f, appended to c[*n]: every kind (glibc scalar, libmvec AVX2 and
   AVX-512, SLEEF u10 and u35 for AVX2 and AVX-512) once; a kind that the
   peer library lacks or this CPU cannot run comes with absent set */
void pfb_peers(pf_func f, pfb_cand *c, int *n);

/* pfmath: opens lib (dlopen); 0 on success.  Rows for a function appear when
   its symbols exist, so the bench follows the library as it grows. */
int pfb_ours_open(const char *lib, char *err, size_t errlen);
void pfb_ours(pf_func f, pfb_cand *c, int *n);
/* 1 when the per-ISA clones of the array forms were found (ELF .symtab) */
int pfb_ours_have_clones(void);

/* the scalar/array pairs wrapped into an array form, for scalar candidates:
   a plain loop calling s1 (s2) through the pointer */
void pfb_loop1(pf_fn1 f, const float *x, float *y, size_t n);
void pfb_loop2(pf_fn2 f, const float *y, const float *x, float *out, size_t n);

/* ---- fixed point (pfbench_ours.c): rows appear when the symbols exist ---- */

typedef enum { PFB_I16, PFB_U16, PFB_I32, PFB_U32 } pfb_store;

typedef struct {
    pf_func f;
    const char *sym;        /* scalar symbol; the array form is sym "_array" */
    const char *in_type, *out_type;  /* as pfmathgen spells them */
    pfb_store in_st, out_st;
    int in_exp, out_exp;    /* value = stored * 2^-exp */
    double lo, hi;          /* input domain (real values) */
} pfb_fixed_row;

const pfb_fixed_row *pfb_fixed_rows(int *n);
/* the symbols of row r in the opened library, or NULL */
void *pfb_fixed_scalar(const pfb_fixed_row *r);
void *pfb_fixed_array(const pfb_fixed_row *r);

#endif
