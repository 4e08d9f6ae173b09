/* The double fast path: glibc's double functions on float inputs.
 *
 * We rely on glibc (>= 2.28) log, log2, exp, exp2 (ARM optimized-routines
 * code, designed error bounds 0.52-0.55 ulp), sin, cos, tan, asin, acos,
 * atan, atan2 (IBM Accurate Mathematical Library; since the slow paths were
 * removed, < 1 ulp, and sin/cos/tan reduce huge arguments with Payne-Hanek,
 * so tan near its poles and sin(1e38f) are as accurate as anywhere) and sqrt
 * (correctly rounded by IEEE 754).  glibc's libm-test-ulps lists at most 1-2
 * ulp for all of them, and P. Zimmermann's survey "Accuracy of Mathematical
 * Functions" (hal-03141101) finds < 1 ulp.  A float input is exact in double
 * and no float input brings a result near double's subnormal range except
 * exp/exp2 of very negative x (handled by pfref__round_d).
 *
 * Why that suffices: a float ulp is 2^29 double-ulps.  The users of this
 * estimate only assume it is within PFREF_DREL = 2^-43 relative (512
 * double-ulps) of the exact value, and send anything within that distance of
 * a rounding decision to MPFR.  tests/test_ref.c checks the estimate against
 * MPFR on random and hard inputs.
 */
#include "pfref_impl.h"

double pfref_exact_d(pf_func f, float x, float x2)
{
    return pfref__glibc(f, x, f == PF_ATAN2 ? x2 : 0.0);
}
