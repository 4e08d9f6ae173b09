/* pfref: correctly rounded references (MPFR) and error measurement.
 *
 * Used by the sweep harness, the generator's report and the benchmark.
 * Everything here is thread-safe: MPFR variables are local to each call and
 * the binary32 exponent range is set and restored around each MPFR call
 * (MPFR's exponent range is per-thread in a TLS build, which is checked).
 *
 * Needs the default floating-point environment (round to nearest, no
 * flush-to-zero: do not link the caller with -ffast-math's crtfastmath).
 *
 * MPFR keeps per-thread caches (pi, log 2): a thread that ends before the
 * program should call mpfr_free_cache() first (LeakSanitizer reports them).
 *
 * Speed: pfref_ulp_err, pfref_is_cr, pfref_f_fast and pfref_lsb_err decide
 * from glibc's double functions (tens of ns) and call MPFR only when that
 * estimate cannot settle the answer (near a rounding boundary, near an error
 * threshold, special inputs): measured 1e-7 to 2e-6 of all floats for the
 * rounding decision.
 */
#ifndef PFREF_H
#define PFREF_H

#include <stdint.h>   /* before mpfr.h, which then declares its intmax_t functions */
#include <mpfr.h>

typedef enum { PF_LOG, PF_LOG2, PF_EXP, PF_EXP2, PF_SIN, PF_COS, PF_TAN,
               PF_ASIN, PF_ACOS, PF_ATAN, PF_ATAN2, PF_SQRT, PF_NFUNCS } pf_func;

const char *pfref_name(pf_func f);          /* "log", "atan2", ...; NULL if f is out of range */
int pfref_lookup(const char *name);          /* -1 if unknown */
int pfref_arity(pf_func f);                  /* 2 for atan2 (y, x), else 1 */

/* y = f(x) (atan2(x, x2) for PF_ATAN2: the first argument is y) rounded with
   rnd at y's precision, in the caller's MPFR exponent range; returns MPFR's
   ternary value.  x2 is ignored (may be NULL) for one-argument functions. */
int pfref_mpfr(pf_func f, mpfr_t y, const mpfr_t x, const mpfr_t x2, mpfr_rnd_t rnd);

/* Correctly rounded binary32 result, round to nearest even, IEEE/C99 Annex F
   semantics: subnormals, overflow to inf, NaN on domain errors, signed zeros,
   atan2's special cases, exact argument reduction for sin/cos/tan.  Always
   MPFR (0.2-3 us here); x2 is ignored unless f is PF_ATAN2. */
float pfref_f(pf_func f, float x, float x2);

/* Same result as pfref_f, via the double fast path (MPFR only near midpoints). */
float pfref_f_fast(pf_func f, float x, float x2);

/* A double close to the exact f(x): glibc's double function on the float
   input, which is within 1 double-ulp (see ref/pfref_glibc.c for why).  When
   the exact value is outside double's range the result is +-inf or 0. */
double pfref_exact_d(pf_func f, float x, float x2);

/* ULP error of got as an approximation of f(x): |got - exact| / ulp(exact),
   ulp(y) = 2^(max(floor(log2|y|), -126) - 23), and 2^(127-23) for |y| >= 2^128.
   Special rules, in order: got NaN and correct result NaN -> 0; exactly one
   NaN -> INFINITY; got == correctly rounded result (same bits, so inf and
   signed zeros included) -> 0; got inf and correct finite, or the reverse, or
   infinities of opposite signs -> INFINITY; got and correct result zeros of
   opposite signs -> INFINITY.  Otherwise the error is accurate to about
   4e-9 ULP (< 2e-6 even if glibc were off by 512 double-ulps), and exact
   (MPFR, 128 bits) whenever it is within 2^-16 of 0.5 or 1.0, so comparisons
   with 0.5 and 1 are always right. */
double pfref_ulp_err(pf_func f, float got, float x, float x2);

/* As pfref_ulp_err but without the "correctly rounded -> 0" rule for finite
   results: the plain distance |got - exact| / ulp(exact) (so <= 0.5 when got
   is correctly rounded).  NaN, infinity and zero-sign rules as above. */
double pfref_ulp_err_raw(pf_func f, float got, float x, float x2);

/* pfref_ulp_err_raw and pfref_is_cr in one call (one glibc evaluation, so
   about twice as fast as calling both): returns the raw error, *cr = 1 when
   got is the correctly rounded result. */
double pfref_ulp_err_cr(pf_func f, float got, float x, float x2, int *cr);

/* 1 when got is the correctly rounded result (same bits, or both NaN), else 0.
   Always right: MPFR decides whenever the double estimate is near a midpoint. */
int pfref_is_cr(pf_func f, float got, float x, float x2);

/* f at a double argument: MPFR at 128 bits, rounded to double.  Domain errors
   (log of < 0, sqrt of < 0, asin of |x| > 1, sin of inf, ...) give NAN; poles
   give +-inf (log(0) = -inf). */
double pfref_exact_dd(pf_func f, double x, double x2);

/* Fixed-point error in LSBs: value(got) = got_stored * 2^-out_exp, returns
   |got_stored * 2^-out_exp - f(x)| * 2^out_exp, where the input x (x, x2 for
   atan2) is the real number the caller's stored input denotes.  Uses glibc's
   double function when |f(x)| * 2^out_exp < 2^32 and |got_stored| < 2^53
   (then accurate to about 1e-6 LSB), MPFR otherwise and whenever the error is
   within 2^-10 of 0.5 or 1.0.  NAN for domain errors, INFINITY at poles. */
double pfref_lsb_err(pf_func f, int64_t got_stored, int out_exp, double x, double x2);

#endif
