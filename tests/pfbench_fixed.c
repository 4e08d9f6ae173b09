/* pfbench: calling the fixed-point functions with their stored-integer
 * types.  A call through a pointer of another type is undefined, so each
 * (input storage, output storage) pair the default set uses gets its own
 * pointer type; the rest say "unsupported". */
#include "pfbench_fixed.h"

#include <math.h>
#include <string.h>

static size_t width(pfb_store s) { return s == PFB_I16 || s == PFB_U16 ? 2 : 4; }

size_t pfb_fx_width(pfb_store s) { return width(s); }

int64_t pfb_fx_get(pfb_store s, const void *buf, size_t i)
{
    switch (s) {
    case PFB_I16: { int16_t v; memcpy(&v, (const char *)buf + 2 * i, 2); return v; }
    case PFB_U16: { uint16_t v; memcpy(&v, (const char *)buf + 2 * i, 2); return v; }
    case PFB_I32: { int32_t v; memcpy(&v, (const char *)buf + 4 * i, 4); return v; }
    default: { uint32_t v; memcpy(&v, (const char *)buf + 4 * i, 4); return v; }
    }
}

static void put(pfb_store s, void *buf, size_t i, int64_t v)
{
    switch (s) {
    case PFB_I16: { int16_t w = (int16_t)v; memcpy((char *)buf + 2 * i, &w, 2); break; }
    case PFB_U16: { uint16_t w = (uint16_t)v; memcpy((char *)buf + 2 * i, &w, 2); break; }
    case PFB_I32: { int32_t w = (int32_t)v; memcpy((char *)buf + 4 * i, &w, 4); break; }
    default: { uint32_t w = (uint32_t)v; memcpy((char *)buf + 4 * i, &w, 4); break; }
    }
}

static uint64_t splitmix(uint64_t *st)
{
    uint64_t z = (*st += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

size_t pfb_fx_inputs(const pfb_fixed_row *r, uint64_t seed, void *buf, size_t n)
{
    if (width(r->in_st) == 2) {
        /* 16-bit inputs: every stored value, in a seeded random order so the
           timing does not see a monotone sweep */
        size_t m = n < 65536 ? n : 65536;
        for (size_t i = 0; i < m; i++)
            put(r->in_st, buf, i, r->in_st == PFB_I16 ? (int64_t)i - 32768 : (int64_t)i);
        uint64_t st = seed;
        for (size_t i = m; i > 1; i--) {
            size_t j = (size_t)(splitmix(&st) % i);
            int64_t a = pfb_fx_get(r->in_st, buf, i - 1), b = pfb_fx_get(r->in_st, buf, j);
            put(r->in_st, buf, i - 1, b);
            put(r->in_st, buf, j, a);
        }
        return m;
    }
    uint64_t st = seed;
    double scale = ldexp(1.0, r->in_exp);
    for (size_t i = 0; i < n; i++) {
        double u = (double)(splitmix(&st) >> 11) * 0x1p-53;
        double v = nearbyint((r->lo + (r->hi - r->lo) * u) * scale);
        double vmin = r->in_st == PFB_I32 ? -2147483648.0 : 0, vmax = r->in_st == PFB_I32 ? 2147483647.0 : 4294967295.0;
        put(r->in_st, buf, i, (int64_t)(v < vmin ? vmin : v > vmax ? vmax : v));
    }
    return n;
}

#define PAIRS(X)                                                                       \
    X(PFB_I16, PFB_I16, int16_t, int16_t)                                              \
    X(PFB_I16, PFB_U16, int16_t, uint16_t)                                             \
    X(PFB_U16, PFB_I16, uint16_t, int16_t)                                             \
    X(PFB_U16, PFB_U16, uint16_t, uint16_t)                                            \
    X(PFB_I32, PFB_I32, int32_t, int32_t)                                              \
    X(PFB_U32, PFB_U32, uint32_t, uint32_t)

int pfb_fx_array(const pfb_fixed_row *r, void *fn, const void *in, void *out, size_t n)
{
#define X(A, B, TA, TB)                                                                \
    if (r->in_st == A && r->out_st == B) {                                             \
        void (*f)(const TA *, TB *, size_t);                                           \
        *(void **)&f = fn;                                                             \
        f((const TA *)in, (TB *)out, n);                                               \
        return 0;                                                                      \
    }
    PAIRS(X)
#undef X
    return -1;
}

int pfb_fx_loop(const pfb_fixed_row *r, void *fn, const void *in, void *out, size_t n)
{
#define X(A, B, TA, TB)                                                                \
    if (r->in_st == A && r->out_st == B) {                                             \
        TB (*f)(TA);                                                                   \
        *(void **)&f = fn;                                                             \
        const TA *x = in;                                                              \
        TB *y = out;                                                                   \
        for (size_t i = 0; i < n; i++)                                                 \
            y[i] = f(x[i]);                                                            \
        return 0;                                                                      \
    }
    PAIRS(X)
#undef X
    return -1;
}

/* dependent chain: the next input is x[i] ^ (previous result & zero), with
   zero read from a volatile so the compiler must wait for the result */
int pfb_fx_chain(const pfb_fixed_row *r, void *fn, const void *in, size_t n, int64_t *sink)
{
    static volatile uint32_t zero_v = 0;
    uint32_t zero = zero_v;
#define X(A, B, TA, TB)                                                                \
    if (r->in_st == A && r->out_st == B) {                                             \
        TB (*f)(TA);                                                                   \
        *(void **)&f = fn;                                                             \
        const TA *x = in;                                                              \
        TB y = 0;                                                                      \
        for (size_t i = 0; i < n; i++)                                                 \
            y = f((TA)(x[i] ^ (TA)((uint32_t)y & zero)));                              \
        *sink = y;                                                                     \
        return 0;                                                                      \
    }
    PAIRS(X)
#undef X
    return -1;
}

void pfb_fx_err(const pfb_fixed_row *r, const void *in, const void *out, size_t n, double *max_lsb,
                double *mean_lsb, int64_t *worst_in)
{
    double mx = -1, sum = 0;
    size_t cnt = 0;
    *worst_in = 0;
    /* the output type's range, as real values */
    int sgn = r->out_st == PFB_I16 || r->out_st == PFB_I32;
    int bits = (int)width(r->out_st) * 8 - sgn;
    double hi = ldexp(ldexp(1.0, bits) - 1, -r->out_exp), lo = sgn ? -ldexp(1.0, bits - r->out_exp) : 0;
    for (size_t i = 0; i < n; i++) {
        int64_t xi = pfb_fx_get(r->in_st, in, i), yi = pfb_fx_get(r->out_st, out, i);
        double x = ldexp((double)xi, -r->in_exp);
        double fx = pfref_exact_dd(r->f, x, 0);
        if (!(fx >= lo && fx <= hi))
            continue; /* saturated by design (exp overflow, log(0), ...) */
        double e = pfref_lsb_err(r->f, yi, r->out_exp, x, 0);
        if (e > mx) {
            mx = e;
            *worst_in = xi;
        }
        if (isfinite(e)) {
            sum += e;
            cnt++;
        }
    }
    *max_lsb = mx < 0 ? NAN : mx;
    *mean_lsb = cnt ? sum / (double)cnt : NAN;
}
