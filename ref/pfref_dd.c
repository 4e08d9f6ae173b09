/* Double-argument references and fixed-point (LSB) errors. */
#include "pfref_impl.h"

double pfref_exact_dd(pf_func f, double x, double x2)
{
    pfref__env env;
    mpfr_t y, mx, mx2;
    mpfr_init2(y, 128);
    mpfr_inits2(53, mx, mx2, (mpfr_ptr)0);
    pfref__env_enter(&env, mpfr_get_emin_min(), mpfr_get_emax_max());
    mpfr_set_d(mx, x, MPFR_RNDN);
    mpfr_set_d(mx2, x2, MPFR_RNDN);
    pfref_mpfr(f, y, mx, mx2, MPFR_RNDN);
    /* 128 -> 53 bits: double rounding can only matter within 2^-75 of a
       double midpoint, and is then still within 1 double-ulp. */
    double r = mpfr_get_d(y, MPFR_RNDN);
    pfref__env_leave(&env);
    mpfr_clears(y, mx, mx2, (mpfr_ptr)0);
    return isnan(r) ? NAN : r;
}

/* Errors this close to 0.5 or 1.0 LSB are recomputed with MPFR.  With
   |f(x)| * 2^out_exp < 2^32 the double estimate is off by at most
   PFREF_DREL * 2^32 = 2^-11 LSB pessimistically, 2^-21 really (glibc's
   < 0.55 double-ulp). */
#define W 0x1p-10
#define SCALED_MAX 0x1p32

static double lsb_slow(pf_func f, int64_t got_stored, int out_exp, double x, double x2)
{
    pfref__env env;
    mpfr_t y, g, mx, mx2;
    /* 256 bits: the result scaled by 2^out_exp may be ~2^64 and the
       difference is still wanted to far better than 1e-6. */
    mpfr_init2(y, 256);
    mpfr_init2(g, 64);
    mpfr_inits2(53, mx, mx2, (mpfr_ptr)0);
    pfref__env_enter(&env, mpfr_get_emin_min(), mpfr_get_emax_max());
    mpfr_set_d(mx, x, MPFR_RNDN);
    mpfr_set_d(mx2, x2, MPFR_RNDN);
    pfref_mpfr(f, y, mx, mx2, MPFR_RNDN);
    double e;
    if (mpfr_nan_p(y)) {
        e = NAN;
    } else if (mpfr_inf_p(y)) {
        e = INFINITY;
    } else {
        mpfr_mul_2si(y, y, out_exp, MPFR_RNDN);     /* exact */
        mpfr_set_sj(g, got_stored, MPFR_RNDN);      /* exact: 64 bits */
        mpfr_sub(y, g, y, MPFR_RNDN);
        e = fabs(mpfr_get_d(y, MPFR_RNDN));
    }
    pfref__env_leave(&env);
    mpfr_clears(y, g, mx, mx2, (mpfr_ptr)0);
    return e;
}

double pfref_lsb_err(pf_func f, int64_t got_stored, int out_exp, double x, double x2)
{
    if (f == PF_ATAN2 ? (isfinite(x) && isfinite(x2)) : isfinite(x)) {
        double d = pfref__glibc(f, x, x2);
        if (isnan(d))
            return NAN;      /* domain error, as glibc decides it exactly */
        if (isfinite(d) && out_exp > -1000 && out_exp < 1000
            && got_stored > -(1ll << 53) && got_stored < (1ll << 53)) {
            double s = ldexp(d, out_exp);
            if (fabs(s) < SCALED_MAX) {
                /* got_stored is exact in double; the difference rounds
                   with relative error 2^-53. */
                double e = fabs((double)got_stored - s);
                if (!(fabs(e - 0.5) < W || fabs(e - 1.0) < W))
                    return e;
            }
        }
    }
    return lsb_slow(f, got_stored, out_exp, x, x2);
}
