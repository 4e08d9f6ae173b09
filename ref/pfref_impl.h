/* Internals shared by the ref/ sources; not part of pfref's API. */
#ifndef PFREF_IMPL_H
#define PFREF_IMPL_H

#include "pfref.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

/* ---- MPFR environment: exponent range and flags, per thread. ---- */

typedef struct {
    mpfr_exp_t emin, emax;
    mpfr_flags_t flags;
} pfref__env;

/* Saves the calling thread's exponent range and flags and sets [emin, emax].
   Aborts unless MPFR keeps that state per thread (a TLS build). */
void pfref__env_enter(pfref__env *save, mpfr_exp_t emin, mpfr_exp_t emax);
void pfref__env_leave(const pfref__env *save);

/* binary32 in MPFR's convention (x = m * 2^e, 1/2 <= m < 1): the largest
   float is just below 2^128, the smallest subnormal is 2^-149 = 0.5 * 2^-148. */
#define PFREF_F32_EMIN (-148)
#define PFREF_F32_EMAX 128

/* y = f(x, x2) rounded to nearest at y's precision, in the current range. */
int pfref__mpfr_flt(pf_func f, mpfr_t y, float x, float x2);

/* ---- bits ---- */

static inline uint32_t pfref__fbits(float x)
{
    uint32_t u;
    memcpy(&u, &x, sizeof u);
    return u;
}

static inline uint64_t pfref__dbits(double x)
{
    uint64_t u;
    memcpy(&u, &x, sizeof u);
    return u;
}

/* 1 when got is the same result as c (same bits, or both NaN). */
static inline int pfref__same(float c, float got)
{
    if (isnan(c) || isnan(got))
        return isnan(c) && isnan(got);
    return pfref__fbits(c) == pfref__fbits(got);
}

/* ---- the double fast path ---- */

/* glibc's double function; see pfref_glibc.c for why it is accurate enough. */
static inline double pfref__glibc(pf_func f, double x, double x2)
{
    switch (f) {
    case PF_LOG:   return log(x);
    case PF_LOG2:  return log2(x);
    case PF_EXP:   return exp(x);
    case PF_EXP2:  return exp2(x);
    case PF_SIN:   return sin(x);
    case PF_COS:   return cos(x);
    case PF_TAN:   return tan(x);
    case PF_ASIN:  return asin(x);
    case PF_ACOS:  return acos(x);
    case PF_ATAN:  return atan(x);
    case PF_ATAN2: return atan2(x, x2);
    case PF_SQRT:  return sqrt(x);
    default:       return NAN;
    }
}

/* Relative bound we allow for glibc's error, as a multiple of |d|: 2^-43 is
   512 double-ulps, hundreds of times glibc's documented bounds (<= 1-2 ulp).
   In float terms it is between 2^-20 and 2^-19 ulp, so about 2^-19 of
   random inputs land within it of a midpoint and need MPFR. */
#define PFREF_DREL 0x1p-43

/* Decides the binary32 round-to-nearest-even of an exact value v from a
   double d with |d - v| <= PFREF_DREL * |d| (or |v| < 2^-199 when
   |d| < 2^-200).  Returns 1 and sets *out when every value in that interval
   rounds to the same float (rounding is monotonic, so checking both ends
   suffices; computing d -+ m moves an end by at most half a double-ulp,
   nothing against the slack between m and glibc's real error), 0 when MPFR
   must decide.  d = +-inf comes from a pole or
   from overflow beyond double's range, where the float result is that
   infinity too; NaN (a domain error) is NaN. */
static inline int pfref__round_d(double d, float *out)
{
    double a = fabs(d);
    if (isnan(d)) {
        *out = NAN;
        return 1;
    }
    if (isinf(d)) {
        *out = (float)d;
        return 1;
    }
    if (a < 0x1p-200) {
        /* Exact zero (sign per Annex F) or double underflow (exp, exp2 only,
           always positive): far below the first float midpoint 2^-150. */
        *out = copysignf(0.0f, (float)d);
        return 1;
    }
    double m = a * PFREF_DREL;
    float lo = (float)(d - m), hi = (float)(d + m);
    if (pfref__fbits(lo) != pfref__fbits(hi))
        return 0;
    *out = lo;
    return 1;
}

/* Fast attempt at the correctly rounded result.  Returns 1 and sets *c
   (and *d, the double estimate) when decided without MPFR. */
static inline int pfref__fast_cr(pf_func f, float x, float x2, float *c, double *d)
{
    int two = (f == PF_ATAN2);
    if (isnan(x) || (two && isnan(x2))) {
        *c = NAN;     /* every function here propagates NaN, atan2 included */
        *d = NAN;
        return 1;
    }
    if (isinf(x) || (two && isinf(x2)))
        return 0;     /* rare: let MPFR apply the Annex F rules */
    *d = pfref__glibc(f, x, x2);
    return pfref__round_d(*d, c);
}

#endif
