#include "sweep.h"

#include <math.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
#ifdef _OPENMP
#include <omp.h>
#endif

static float asfloat(uint32_t u) { float f; memcpy(&f, &u, 4); return f; }
static uint32_t asuint(float f) { uint32_t u; memcpy(&u, &f, 4); return u; }

void pf_sweep_init(pf_sweep_stats *s)
{
    memset(s, 0, sizeof *s);
    s->worst_x = s->worst_x2 = s->worst_got = NAN;
}

static int bin_of(double e)
{
    static const double edge[PF_HIST_BINS - 1] = {0, 0.5, 1, 2, 4, 16, 256};
    for (int i = 0; i < PF_HIST_BINS - 1; i++)
        if (e <= edge[i])
            return i;
    return PF_HIST_BINS - 1;
}

const char *pf_sweep_bin_label(int i)
{
    static const char *l[PF_HIST_BINS] = {"0 (exact)", "(0, 0.5]", "(0.5, 1]", "(1, 2]",
                                          "(2, 4]", "(4, 16]", "(16, 256]", "> 256 or wrong special"};
    return l[i];
}

void pf_sweep_merge(pf_sweep_stats *a, const pf_sweep_stats *b)
{
    if (b->count == 0)
        return;
    /* ties keep the smaller bit pattern, so parallel sweeps are deterministic */
    if (b->max_ulp > a->max_ulp || a->count == 0 ||
        (b->max_ulp == a->max_ulp && asuint(b->worst_x) < asuint(a->worst_x))) {
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

void pf_sweep_got(pf_sweep_stats *s, pf_func f, float got, float x, float x2)
{
    int cr;
    double e = pfref_ulp_err_cr(f, got, x, x2, &cr);
    s->count++;
    s->cr += cr;
    if (isfinite(e))
        s->sum_ulp += e;
    s->hist[cr && e == 0 ? 0 : bin_of(e == 0 ? 1e-300 : e)]++;
    if (s->count == 1 || e > s->max_ulp) {
        s->max_ulp = e;
        s->worst_x = x;
        s->worst_x2 = x2;
        s->worst_got = got;
    }
}

void pf_sweep_one(pf_sweep_stats *s, pf_func f, pf_fn1 fn1, pf_fn2 fn2, float x, float x2)
{
    pf_sweep_got(s, f, fn2 ? fn2(x, x2) : fn1(x), x, x2);
}

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

void pf_sweep_bits(pf_sweep_stats *s, pf_func f, pf_fn1 fn1, pf_fn2 fn2, uint32_t lo, uint32_t hi,
                   int progress)
{
    const uint64_t n = (uint64_t)hi - lo + 1, chunk = 1u << 16;
    const uint64_t nchunks = (n + chunk - 1) / chunk;
    uint64_t done = 0;
    double t0 = now(), tlast = t0;
    pf_sweep_stats tot = *s;
#pragma omp parallel
    {
        pf_sweep_stats loc;
        pf_sweep_init(&loc);
#pragma omp for schedule(dynamic, 1)
        for (uint64_t c = 0; c < nchunks; c++) {
            uint64_t b0 = lo + c * chunk, b1 = b0 + chunk - 1;
            if (b1 > hi)
                b1 = hi;
            for (uint64_t b = b0; b <= b1; b++)
                pf_sweep_one(&loc, f, fn1, fn2, asfloat((uint32_t)b), 1.0f);
            if (progress) {
#pragma omp critical(pf_progress)
                {
                    done += b1 - b0 + 1;
                    double t = now();
                    if (t - tlast > 2) {
                        tlast = t;
                        double frac = (double)done / (double)n;
                        fprintf(stderr, "\r  %5.1f%%  %.0f s elapsed, about %.0f s left   ", 100 * frac,
                                t - t0, (t - t0) * (1 - frac) / frac);
                    }
                }
            }
        }
#pragma omp critical(pf_merge)
        pf_sweep_merge(&tot, &loc);
    }
    if (progress)
        fprintf(stderr, "\r%60s\r", "");
    *s = tot;
}

/* splitmix64: a fixed, documented generator so sweeps are reproducible */
static uint64_t splitmix(uint64_t *st)
{
    uint64_t z = (*st += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

void pf_sweep_random(pf_sweep_stats *s, pf_func f, pf_fn1 fn1, pf_fn2 fn2, uint64_t seed, uint64_t n)
{
    uint64_t st = seed;
    for (uint64_t i = 0; i < n; i++) {
        uint64_t r = splitmix(&st);
        uint32_t b = (uint32_t)r, b2 = (uint32_t)(r >> 32);
        if ((b & 0x7f800000u) == 0x7f800000u)
            b ^= 0x40000000u; /* keep it finite: specials are in the directed list */
        if ((b2 & 0x7f800000u) == 0x7f800000u)
            b2 ^= 0x40000000u;
        pf_sweep_one(s, f, fn1, fn2, asfloat(b), asfloat(b2));
    }
}

static void directed_list(float *v, int *n)
{
    int k = 0;
    const uint32_t bits[] = {
        0x00000000u, 0x00000001u, 0x00000002u, 0x007fffffu, 0x00400000u, 0x00800000u, 0x00800001u,
        0x3f800000u, 0x3f7fffffu, 0x3f7ffffeu, 0x3f800001u, 0x3f800002u, 0x3f7ffff0u, 0x3f800010u,
        0x3f000000u, 0x3fffffffu, 0x40000000u, 0x3f3504f3u, 0x3fb504f3u, 0x3f3504f2u, 0x3fb504f4u,
        0x7f7fffffu, 0x7f800000u, 0x7fc00000u, 0x7fa00000u,
        0x3fc90fdbu, 0x40490fdbu, 0x40c90fdbu, 0x64078678u /* the float nearest 1e22 */,
        0x42b17218u, 0x42b17217u, 0xc2cff1b5u, 0xc2ce8ed0u, 0x42fe0000u, 0xc3150000u,
    };
    for (size_t i = 0; i < sizeof bits / sizeof bits[0]; i++) {
        v[k++] = asfloat(bits[i]);
        v[k++] = asfloat(bits[i] ^ 0x80000000u);
    }
    for (int e = -149; e <= 127; e++) {
        v[k++] = ldexpf(1.0f, e);
        v[k++] = -ldexpf(1.0f, e);
    }
    *n = k;
}

void pf_sweep_directed(pf_sweep_stats *s, pf_func f, pf_fn1 fn1, pf_fn2 fn2)
{
    float v[1024];
    int n;
    directed_list(v, &n);
    if (!fn2) {
        for (int i = 0; i < n; i++)
            pf_sweep_one(s, f, fn1, fn2, v[i], 1.0f);
    } else {
        for (int i = 0; i < n; i += 7)
            for (int j = 0; j < n; j += 7)
                pf_sweep_one(s, f, fn1, fn2, v[i], v[j]);
    }
}

double pf_sweep_mean(const pf_sweep_stats *s) { return s->count ? s->sum_ulp / s->count : 0; }
double pf_sweep_cr_percent(const pf_sweep_stats *s) { return s->count ? 100.0 * s->cr / s->count : 0; }

void pf_sweep_print(FILE *out, const char *title, pf_func f, const pf_sweep_stats *s)
{
    float want = pfref_f(f, s->worst_x, s->worst_x2);
    fprintf(out, "%s: %llu inputs\n", title, (unsigned long long)s->count);
    fprintf(out, "  max ULP   %.4f\n  mean ULP  %.4f\n  correctly rounded  %.3f%%\n",
            s->max_ulp, pf_sweep_mean(s), pf_sweep_cr_percent(s));
    if (pfref_arity(f) == 2)
        fprintf(out, "  worst     %s(%a, %a)  [0x%08x, 0x%08x]  got %a  want %a\n", pfref_name(f),
                s->worst_x, s->worst_x2, asuint(s->worst_x), asuint(s->worst_x2), s->worst_got, want);
    else
        fprintf(out, "  worst     %s(%a)  [0x%08x]  got %a  want %a\n", pfref_name(f), s->worst_x,
                asuint(s->worst_x), s->worst_got, want);
    fprintf(out, "  histogram (ULP error: count)\n");
    for (int i = 0; i < PF_HIST_BINS; i++)
        if (s->hist[i])
            fprintf(out, "    %-24s %llu\n", pf_sweep_bin_label(i), (unsigned long long)s->hist[i]);
}

void pf_sweep_reduced_range(pf_func f, uint32_t *lo, uint32_t *hi)
{
    switch (f) {
    case PF_LOG:
    case PF_LOG2:
        *lo = 0x3f000000u; /* [0.5, 2): both reductions' m range, 2^24 floats */
        *hi = 0x3fffffffu;
        break;
    case PF_EXP:
    case PF_EXP2:
        *lo = 0x3e800000u; /* [0.25, 2): every reduced r of exp and exp2, both signs of r */
        *hi = 0x3fffffffu;
        break;
    case PF_SIN: case PF_COS: case PF_TAN:
        *lo = 0x3c000000u; /* [2^-7, 2pi] */
        *hi = 0x40c90fdbu;
        break;
    case PF_ATAN:
    case PF_ATAN2:
        *lo = 0x3c000000u; /* [2^-7, 2^7]: both sides of the fold at |x| = 1 */
        *hi = 0x43000000u;
        break;
    default:
        *lo = 0x3c000000u;
        *hi = 0x3f800000u;
        break;
    }
}
