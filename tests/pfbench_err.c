/* pfbench: input domains, the seeded sampler, the error statistic, Pareto. */
#include "pfbench.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The domains of issue 7: the PF_BENCH rows of libpfmath/functions.def
   (sin/cos/tan where the reduction is one step and where it is not, and so
   on; the table says why each). */
static const pfb_domain domains[] = {
#define PF_BENCH(n, id, tag, desc, dist, lo, hi, dist2, lo2, hi2)                                             \
    {id, tag, desc, PFB_##dist, lo, hi, PFB_##dist2, lo2, hi2},
#include "functions.def"
};

const pfb_domain *pfb_domains(int *n)
{
    *n = (int)(sizeof domains / sizeof domains[0]);
    return domains;
}

static float asfloat(uint32_t u) { float f; memcpy(&f, &u, 4); return f; }

/* splitmix64, the generator of ref/sweep.c (so PFB_BITS is its stream) */
static uint64_t splitmix(uint64_t *st)
{
    uint64_t z = (*st += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

/* a value of dist in [lo, hi], rounded to float and clamped to the rounded
   ends (rounding lo + (hi - lo) u can land one float outside) */
static float draw(pfb_dist dist, double lo, double hi, uint64_t *st)
{
    uint64_t r = splitmix(st);
    double u = (double)(r >> 11) * 0x1p-53; /* [0, 1) */
    double v;
    switch (dist) {
    case PFB_LOGUNIFORM:
        v = exp(log(lo) + (log(hi) - log(lo)) * u);
        break;
    case PFB_LOGSYM:
        u = (double)(r >> 12) * 0x1p-52;
        v = exp(log(lo) + (log(hi) - log(lo)) * u);
        if (r & 1)
            v = -v;
        break;
    default:
        v = lo + (hi - lo) * u;
        break;
    }
    float f = (float)v, flo = (float)lo, fhi = (float)hi;
    if (dist == PFB_LOGSYM) {
        float a = fabsf(f);
        a = a < flo ? flo : a > fhi ? fhi : a;
        return copysignf(a, f);
    }
    return f < flo ? flo : f > fhi ? fhi : f;
}

void pfb_sample(const pfb_domain *d, uint64_t seed, float *x, float *x2, size_t n)
{
    uint64_t st = seed;
    int two = pfref_arity(d->f) == 2 && x2;
    for (size_t i = 0; i < n; i++) {
        if (d->dist == PFB_BITS) {
            /* exactly pf_sweep_random's loop body */
            uint64_t r = splitmix(&st);
            uint32_t b = (uint32_t)r, b2 = (uint32_t)(r >> 32);
            if ((b & 0x7f800000u) == 0x7f800000u)
                b ^= 0x40000000u;
            if ((b2 & 0x7f800000u) == 0x7f800000u)
                b2 ^= 0x40000000u;
            x[i] = asfloat(b);
            if (x2)
                x2[i] = two ? asfloat(b2) : 1.0f;
            continue;
        }
        x[i] = draw(d->dist, d->lo, d->hi, &st);
        if (x2)
            x2[i] = two ? draw(d->dist2, d->lo2, d->hi2, &st) : 1.0f;
    }
}

/* ---- the error statistic ---- */

/* pf_sweep_one without the call: the sweep's own recording rule.
   tests/test_bench.c checks that the two agree input by input. */
void pfb_err_record(pf_sweep_stats *s, pf_func f, float x, float x2, float got)
{
    pf_sweep_got(s, f, got, x, x2);
}

/* chunk results are merged in input order with the serial rule (a later
   chunk wins only with a strictly larger error), so max and worst input do
   not depend on the number of threads */
static void merge_ordered(pf_sweep_stats *a, const pf_sweep_stats *b)
{
    if (b->count == 0)
        return;
    if (a->count == 0 || b->max_ulp > a->max_ulp) {
        a->max_ulp = b->max_ulp;
        a->worst_x = b->worst_x;
        a->worst_x2 = b->worst_x2;
        a->worst_got = b->worst_got;
    }
    a->count += b->count;
    a->cr += b->cr;
    a->sum_ulp += b->sum_ulp;
    for (int i = 0; i < PF_HIST_BINS; i++)
        a->hist[i] += b->hist[i];
}

void pfb_err_arrays(pf_sweep_stats *s, pf_func f, const float *x, const float *x2,
                    const float *got, size_t n)
{
    const size_t chunk = 1u << 14;
    const size_t nch = (n + chunk - 1) / chunk;
    pf_sweep_stats *part = calloc(nch ? nch : 1, sizeof *part);
    if (!part)
        abort();
#pragma omp parallel for schedule(dynamic, 1)
    for (size_t c = 0; c < nch; c++) {
        pf_sweep_init(&part[c]);
        size_t i1 = (c + 1) * chunk < n ? (c + 1) * chunk : n;
        for (size_t i = c * chunk; i < i1; i++)
            pfb_err_record(&part[c], f, x[i], x2 ? x2[i] : 1.0f, got[i]);
    }
    for (size_t c = 0; c < nch; c++)
        merge_ordered(s, &part[c]);
    free(part);
}

void pfb_pareto(const double *t, const double *e, int n, int *on)
{
    for (int i = 0; i < n; i++) {
        on[i] = isfinite(t[i]) && isfinite(e[i]);
        for (int j = 0; j < n && on[i]; j++) {
            if (j == i || !isfinite(t[j]) || !isfinite(e[j]))
                continue;
            if (t[j] <= t[i] && e[j] <= e[i] && (t[j] < t[i] || e[j] < e[i]))
                on[i] = 0;
        }
    }
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

void pfb_median(double *v, int n, double *med, double *min, double *max)
{
    if (n <= 0) {
        *med = *min = *max = NAN;
        return;
    }
    qsort(v, (size_t)n, sizeof *v, cmp_double);
    *min = v[0];
    *max = v[n - 1];
    *med = n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/* measured as text beside a goal: two decimals, more while the text would
   read as the goal itself (0.997 against 1.00 is "0.997", not "1.00", so a
   row can never say 1.00x next to MISS), at most six */
void pfb_goal_fmt(char *buf, size_t n, double measured, double want, const char *unit)
{
    int d = 2;
    for (; d < 6 && measured != want; d++) {
        char a[48], b[48];
        snprintf(a, sizeof a, "%.*f", d, measured);
        snprintf(b, sizeof b, "%.*f", d, want);
        if (strcmp(a, b) != 0)
            break;
    }
    snprintf(buf, n, "%.*f%s", d, measured, unit);
}
