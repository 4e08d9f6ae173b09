/* ULP error of a binary32 result. */
#include "pfref_impl.h"

/* Errors this close to 0.5 or 1.0 are recomputed with MPFR so that
   comparisons with those thresholds are exact.  The double estimate's own
   error in ULP units is <= 2^-43 * 2^24 = 2^-19 even with the pessimistic
   PFREF_DREL (about 2^-28 with glibc's real < 1 double-ulp). */
#define W 0x1p-16

/* ulp as defined in pfref.h, from k = floor(log2|exact|). */
static double ulp_scale(long k)
{
    if (k < -126)
        k = -126;
    if (k > 127)
        k = 127;
    return ldexp(1.0, (int)(23 - k));   /* 1/ulp */
}

/* Special rules of pfref.h given the correctly rounded result c.  Returns
   1 and sets *e when they decide. */
static int special(float c, float got, int raw, double *e)
{
    if (isnan(c) || isnan(got)) {
        *e = (isnan(c) && isnan(got)) ? 0.0 : INFINITY;
        return 1;
    }
    int same = pfref__fbits(c) == pfref__fbits(got);
    if (same && (!raw || isinf(c))) {
        *e = 0.0;
        return 1;
    }
    if (isinf(c) || isinf(got) || (c == 0 && got == 0 && !same)) {
        *e = INFINITY;
        return 1;
    }
    return 0;
}

static double slow(pf_func f, float got, float x, float x2, int raw, int *cr)
{
    double e;
    float c = pfref_f(f, x, x2);
    *cr = pfref__same(c, got);
    if (special(c, got, raw, &e))
        return e;
    /* Both finite.  128 bits: e comes out with relative error ~2^-127. */
    pfref__env env;
    mpfr_t y, g;
    mpfr_init2(y, 128);
    mpfr_init2(g, 24);
    pfref__env_enter(&env, mpfr_get_emin_min(), mpfr_get_emax_max());
    /* Toward zero, so that y stays in the exact value's binade even when
       that is within 2^-128 of a power of two (exp(-2^-130) = 1 - 2^-130).
       c finite means |exact| < 2^128; an exact zero (sin(0), log(1)) or an
       underflow beyond MPFR's huge range (exp(-1e38)) both count as 0. */
    mpfr_t mx, mx2;
    mpfr_inits2(24, mx, mx2, (mpfr_ptr)0);
    mpfr_set_flt(mx, x, MPFR_RNDN);
    mpfr_set_flt(mx2, x2, MPFR_RNDN);
    pfref_mpfr(f, y, mx, mx2, MPFR_RNDZ);
    mpfr_clears(mx, mx2, (mpfr_ptr)0);
    long k = mpfr_zero_p(y) ? -126 : (long)mpfr_get_exp(y) - 1;   /* may be ~ -2^40 */
    mpfr_set_flt(g, got, MPFR_RNDN);
    mpfr_sub(y, g, y, MPFR_RNDN);
    e = fabs(mpfr_get_d(y, MPFR_RNDN)) * ulp_scale(k);
    pfref__env_leave(&env);
    mpfr_clears(y, g, (mpfr_ptr)0);
    return e;
}

static double ulp_err(pf_func f, float got, float x, float x2, int raw, int *cr)
{
    float c;
    double d, e;
    if (!pfref__fast_cr(f, x, x2, &c, &d))
        return slow(f, got, x, x2, raw, cr);
    *cr = pfref__same(c, got);
    if (special(c, got, raw, &e))
        return e;
    /* c finite, so d is finite with |d| < 2^128. */
    uint64_t b = pfref__dbits(d) & ~(1ull << 63);
    int k = (int)(b >> 52) - 1023;
    uint64_t frac = b & ((1ull << 52) - 1);
    /* Within 2^-40 of a power of two the exact value may lie in the other
       binade, where the ulp differs by 2.  That matters unless got is c,
       which is then that power of two p: if d and the exact value are on
       opposite sides of p, both |p - d| and |p - exact| are below
       |d - exact|, so either reading is as accurate as d itself (and
       cos(tiny) = 1, exp(tiny) = 1 stay on the fast path). */
    if (k >= -126 && (frac < (1ull << 12) || frac > (1ull << 52) - (1ull << 13))
        && !*cr)
        return slow(f, got, x, x2, raw, cr);
    e = fabs((double)got - d) * ulp_scale(k);
    if (fabs(e - 0.5) < W || fabs(e - 1.0) < W)
        return slow(f, got, x, x2, raw, cr);
    return e;
}

double pfref_ulp_err(pf_func f, float got, float x, float x2)
{
    int cr;
    return ulp_err(f, got, x, x2, 0, &cr);
}

double pfref_ulp_err_raw(pf_func f, float got, float x, float x2)
{
    int cr;
    return ulp_err(f, got, x, x2, 1, &cr);
}

double pfref_ulp_err_cr(pf_func f, float got, float x, float x2, int *cr)
{
    return ulp_err(f, got, x, x2, 1, cr);
}
