/* fastsweep_atrig: the fast variants' bound on every float.
 *
 * Issue 13's fast bound is max(2^-10 relative, 2^-11 absolute): a result r
 * of f(x) passes when |r - f(x)| <= max(2^-10 |f(x)|, 2^-11).  This checks
 * pf_asinf_fast, pf_acosf_fast, pf_atanf_fast on all 2^32 floats and
 * pf_atan2f_fast on a dense seeded sample of pairs (half independent bit
 * patterns, half with exponents within 26 binades of each other, so the
 * quotient covers [2^-27, 1] in every quadrant) plus every pair of special
 * values.  The reference is ref/'s pfref_exact_d (glibc's double function,
 * within one double ULP: 2^-52, far below the bound).  NaN must give NaN.
 *   build/fastsweep_atrig [asin|acos|atan|atan2 ...] [--pairs N]
 * Exit status 1 when a bound is exceeded.  Not part of make test (minutes). */
#include "pfref.h"
#include "pfcli.h"
#include "pfmath.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static float asf(uint32_t u)
{
    float x;
    memcpy(&x, &u, 4);
    return x;
}

typedef struct {
    double worst;   /* max of error / allowance */
    float wy, wx;
    uint64_t bad;
} result;

/* error over allowance (<= 1 passes); NaN handling as documented above */
static double ratio(pf_func f, float got, float y, float x)
{
    double ex = pfref_exact_d(f, y, x);
    if (isnan(ex) || isnan(got))
        return isnan(ex) && isnan(got) ? 0 : INFINITY;
    return fabs((double)got - ex) / fmax(0x1p-10 * fabs(ex), 0x1p-11);
}

static void note(result *r, double q, float y, float x)
{
    if (q > 1)
        r->bad++;
    if (q > r->worst)
        r->worst = q, r->wy = y, r->wx = x;
}

static void merge(result *to, const result *from)
{
    to->bad += from->bad;
    if (from->worst > to->worst)
        to->worst = from->worst, to->wy = from->wy, to->wx = from->wx;
}

static result sweep1(pf_func f, float (*fn)(float))
{
    result all = {0};
#pragma omp parallel
    {
        result r = {0};
#pragma omp for schedule(dynamic, 1)
        for (int64_t hi = 0; hi < 1 << 16; hi++)
            for (uint32_t lo = 0; lo < 1u << 16; lo++) {
                float x = asf((uint32_t)hi << 16 | lo);
                note(&r, ratio(f, fn(x), x, 1), x, 0);
            }
#pragma omp critical
        merge(&all, &r);
    }
    return all;
}

static uint64_t mix(uint64_t *st)
{
    uint64_t z = (*st += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

static uint32_t keep_finite(uint32_t b)
{
    return (b & 0x7f800000u) == 0x7f800000u ? b ^ 0x40000000u : b;
}

static result sweep2(uint64_t n)
{
    result all = {0};
    /* every pair of specials: +-0, +-inf, NaN, powers of two, FLT_MAX, 1 -+ ulp */
    float sp[600];
    int ns = 0;
    const uint32_t bits[] = {0, 0x7f800000u, 0x7fc00000u, 0x7f7fffffu, 0x3f7fffffu, 0x3f800001u,
                             0x007fffffu};
    for (size_t i = 0; i < sizeof bits / sizeof bits[0]; i++)
        sp[ns++] = asf(bits[i]), sp[ns++] = asf(bits[i] | 0x80000000u);
    for (int e = -149; e <= 127; e++)
        sp[ns++] = ldexpf(1, e), sp[ns++] = -ldexpf(1, e);
    for (int i = 0; i < ns; i++)
        for (int j = 0; j < ns; j++)
            note(&all, ratio(PF_ATAN2, pf_atan2f_fast(sp[i], sp[j]), sp[i], sp[j]), sp[i], sp[j]);
    int64_t chunks = (int64_t)((n + 65535) >> 16);
#pragma omp parallel
    {
        result r = {0};
#pragma omp for schedule(dynamic, 16)
        for (int64_t c = 0; c < chunks; c++) {
            uint64_t st = 0x5eed0000ull ^ (uint64_t)c << 20;
            for (int k = 0; k < 65536; k++) {
                uint64_t r1 = mix(&st), r2 = mix(&st);
                uint32_t bx = keep_finite((uint32_t)r1), by;
                if (r2 & 1) {
                    by = keep_finite((uint32_t)(r1 >> 32));
                } else {
                    int ex = (int)(bx >> 23 & 0xff), ey = ex + (int)((r2 >> 1) % 53) - 26;
                    ey = ey < 0 ? 0 : ey > 254 ? 254 : ey;
                    by = (uint32_t)(r2 >> 8 & 1) << 31 | (uint32_t)ey << 23 |
                         (uint32_t)(r2 >> 32 & 0x7fffff);
                }
                float y = asf(by), x = asf(bx);
                note(&r, ratio(PF_ATAN2, pf_atan2f_fast(y, x), y, x), y, x);
            }
        }
#pragma omp critical
        merge(&all, &r);
    }
    return all;
}

int main(int argc, char **argv)
{
    const char *all[] = {"asin", "acos", "atan", "atan2"};
    const char *want[8];
    int nw = 0;
    uint64_t pairs = 1ull << 28;
    int seen_pairs = 0;
    unsigned long long np = pairs;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "-h") || !strcmp(argv[i], "--help")) {
            fputs("usage: fastsweep_atrig [asin|acos|atan|atan2 ...] [--pairs N]\n"
                  "The fast variants' bound max(2^-10 |f|, 2^-11) on every float (asin, acos,\n"
                  "atan) and on a dense seeded sample of N pairs, 1..2^32 (default 2^28), and\n"
                  "every special pair (atan2).  Default: all four.  Exit status 1 when a bound\n"
                  "is exceeded, 2 bad usage.\n",
                  stdout);
            return 0;
        }
        if (!strcmp(argv[i], "--pairs")) {
            /* strtoull took "-1" as 2^64-1 pairs and "abc" as 0 */
            if (seen_pairs++ || i + 1 == argc || pfcli_u64(argv[i + 1], 1, 1ull << 32, &np) != 0)
                pfcli_refuse("fastsweep_atrig", "--pairs takes one whole number 1..2^32, given once: ",
                             i + 1 < argc ? argv[i + 1] : "");
            pairs = np;
            i++;
        } else if (nw == 8) {
            pfcli_refuse("fastsweep_atrig", "at most 8 functions; unexpected ", argv[i]);
        } else {
            const char *w = argv[i];
            int known = 0;
            for (int k = 0; k < 4; k++)
                known |= !strcmp(w, all[k]);
            if (!known)
                pfcli_refuse("fastsweep_atrig", "unknown function (asin, acos, atan, atan2): ", w);
            want[nw++] = w;
        }
    }
    if (!nw)
        for (int i = 0; i < 4; i++)
            want[nw++] = all[i];
    int fail = 0;
    for (int i = 0; i < nw; i++) {
        result r;
        if (!strcmp(want[i], "asin"))
            r = sweep1(PF_ASIN, pf_asinf_fast);
        else if (!strcmp(want[i], "acos"))
            r = sweep1(PF_ACOS, pf_acosf_fast);
        else if (!strcmp(want[i], "atan"))
            r = sweep1(PF_ATAN, pf_atanf_fast);
        else if (!strcmp(want[i], "atan2"))
            r = sweep2(pairs);
        else {
            fprintf(stderr, "fastsweep_atrig: unknown function %s\n", want[i]);
            return 2;
        }
        printf("%s fast: max error %.4f of the allowance max(2^-10 |f|, 2^-11) at (%a, %a); "
               "%llu inputs over\n",
               want[i], r.worst, (double)r.wy, (double)r.wx, (unsigned long long)r.bad);
        fail |= r.bad != 0;
    }
    return fail;
}
