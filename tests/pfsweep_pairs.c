/* pfsweep --all for two-argument functions (atan2): 2^64 inputs cannot all be
 * swept, so --all means a dense seeded sample of pairs plus every pair of a
 * list of special values.
 *
 * Half of the random pairs take independent random bit patterns (the quotient
 * of two such floats is mostly huge or tiny: results at +-pi/2, near 0 or
 * +-pi, quotients under- or overflowing float); the other half put y's
 * exponent within 26 binades of x's, so min/max(|y|,|x|) lands in [2^-27, 1]
 * where the polynomial is evaluated, for all four quadrants and both orders
 * of |y| and |x|.  The special list: +-0, +-inf, NaN, every power of two
 * 2^-149..2^127, the largest float and the floats next to 1, each with both
 * signs; all ordered pairs of it (about 3.5e5) are swept.
 *
 * Each chunk of 2^16 pairs draws from its own splitmix64 stream seeded from
 * (seed, chunk), so the pairs do not depend on the number of threads. */
#include "sweep.h"

#include <math.h>
#include <string.h>

int pfsweep_pairs(pf_sweep_stats *s, pf_func f, pf_fn2 fn, uint64_t seed, uint64_t n);

static float asf(uint32_t u) { float x; memcpy(&x, &u, 4); return x; }

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

static void pair(uint64_t *st, float *y, float *x)
{
    uint64_t r1 = mix(st), r2 = mix(st);
    uint32_t bx = keep_finite((uint32_t)r1), by;
    if (r2 & 1) {
        by = keep_finite((uint32_t)(r1 >> 32));
    } else {
        int ex = (int)(bx >> 23 & 0xff), ey = ex + (int)((r2 >> 1) % 53) - 26;
        ey = ey < 0 ? 0 : ey > 254 ? 254 : ey;
        by = (uint32_t)(r2 >> 8 & 1) << 31 | (uint32_t)ey << 23 | (uint32_t)(r2 >> 32 & 0x7fffff);
    }
    *y = asf(by);
    *x = asf(bx);
}

static int special_list(float *v)
{
    int k = 0;
    const uint32_t bits[] = {0x00000000u, 0x7f800000u, 0x7fc00000u, 0x7f7fffffu,
                             0x3f7fffffu, 0x3f800001u, 0x007fffffu};
    for (size_t i = 0; i < sizeof bits / sizeof bits[0]; i++) {
        v[k++] = asf(bits[i]);
        v[k++] = asf(bits[i] | 0x80000000u);
    }
    for (int e = -149; e <= 127; e++) {
        v[k++] = ldexpf(1.0f, e);
        v[k++] = -ldexpf(1.0f, e);
    }
    return k;
}

/* Sweeps n random pairs and all special pairs into s; returns the number of
   special pairs. */
int pfsweep_pairs(pf_sweep_stats *s, pf_func f, pf_fn2 fn, uint64_t seed, uint64_t n)
{
    static float v[1024];
    int nv = special_list(v);
    const uint64_t chunk = 1u << 16, nchunks = (n + chunk - 1) / chunk;
    pf_sweep_stats tot = *s;
#pragma omp parallel
    {
        pf_sweep_stats loc;
        pf_sweep_init(&loc);
#pragma omp for schedule(dynamic, 1) nowait
        for (uint64_t c = 0; c < nchunks; c++) {
            uint64_t st = seed * 0x2545f4914f6cdd1dull + c;
            uint64_t m = c + 1 < nchunks ? chunk : n - c * chunk;
            for (uint64_t i = 0; i < m; i++) {
                float y, x;
                pair(&st, &y, &x);
                pf_sweep_one(&loc, f, NULL, fn, y, x);
            }
        }
#pragma omp for schedule(dynamic, 1)
        for (int i = 0; i < nv; i++)
            for (int j = 0; j < nv; j++)
                pf_sweep_one(&loc, f, NULL, fn, v[i], v[j]);
#pragma omp critical(pf_pairs_merge)
        pf_sweep_merge(&tot, &loc);
    }
    *s = tot;
    return nv * nv;
}
