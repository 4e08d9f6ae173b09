/* Correctly rounded binary32 results. */
#include "pfref_impl.h"

/* MPFR rounds correctly at any precision (its own Ziv loop raises the working
   precision as far as a hard case needs, and reduces huge sin/cos/tan
   arguments exactly), so computing straight at 24 bits is exact rounding.
   IEEE binary32 is then emulated as MPFR's manual prescribes: the binary32
   exponent range makes the function itself overflow to inf or underflow,
   and mpfr_subnormalize re-rounds to the subnormal grid using the ternary
   value, which avoids double rounding. */
float pfref_f(pf_func f, float x, float x2)
{
    pfref__env env;
    mpfr_t y;
    mpfr_init2(y, 24);
    pfref__env_enter(&env, PFREF_F32_EMIN, PFREF_F32_EMAX);
    int t = pfref__mpfr_flt(f, y, x, x2);
    mpfr_subnormalize(y, t, MPFR_RNDN);
    float r = mpfr_get_flt(y, MPFR_RNDN);   /* exact: y is a binary32 value */
    pfref__env_leave(&env);
    mpfr_clear(y);
    return isnan(r) ? NAN : r;
}

float pfref_f_fast(pf_func f, float x, float x2)
{
    float c;
    double d;
    if (pfref__fast_cr(f, x, x2, &c, &d))
        return c;
    return pfref_f(f, x, x2);
}

int pfref_is_cr(pf_func f, float got, float x, float x2)
{
    return pfref__same(pfref_f_fast(f, x, x2), got);
}
