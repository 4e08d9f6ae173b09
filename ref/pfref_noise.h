/* pfref_noise: the gradient noise of libpfmath/pfnoise.h evaluated exactly
 * (MPFR) at dyadic points, the reference for the generated fixed-point noise
 * (pfmathgen --func noise…).
 *
 * Independent of every evaluator: the cell and the fraction come from
 * integer division, the gradients are re-derived from the lattice hash by
 * the definitions in pfnoise_table.c's comment (not read from its code
 * tables), and the noise is the weighted corner sum
 *     n(t) = Σ_c W_c(t) g_c·(t − c),  W_c = Π_i (c_i ? f(t_i) : 1 − f(t_i)),
 *     f(t) = 6t⁵ − 15t⁴ + 10t³
 * (1D: g·d/4, 4D: ·2/3), not nested lerps.  Only the permutation is read
 * from the table.  With the point p_i = q_i·2^-exp every term is a dyadic
 * rational of at most ~(5N + 1)(exp + 5) bits, so the sum is exact at the
 * working precision; 4D's ·2/3 is then the only rounding, at that
 * precision (> 300 bits). */
#ifndef PFREF_NOISE_H
#define PFREF_NOISE_H

#include <stdint.h>
#include <mpfr.h>

#include "pfnoise.h"

/* working precision (bits) for dimension n and input exponent exp */
mpfr_prec_t pfref_noise_prec(int n, int exp);

/* r = noise (dimension n = 1..4, table t, not NULL) at p_i = q[i]·2^-exp,
 * 1 <= exp <= 62, any int64 q[i]; r is set to pfref_noise_prec(n, exp)
 * bits (it must be initialised; its precision is changed). */
void pfref_noise_mpfr(mpfr_t r, int n, const pf_noise_table *t, const int64_t *q, int exp);

/* the same rounded to double */
double pfref_noise(int n, const pf_noise_table *t, const int64_t *q, int exp);

/* RNE(noise·2^oexp) saturated to [lo, hi]: the correctly rounded stored
 * output of a fixed<…, oexp> type with that stored range */
int64_t pfref_noise_round(int n, const pf_noise_table *t, const int64_t *q, int exp, int oexp,
                          int64_t lo, int64_t hi);

/* |got − clamp(noise·2^oexp, lo, hi)|: the error of a stored output got in
 * LSB of the output, against the exact noise saturated to the output range */
double pfref_noise_err_lsb(int n, const pf_noise_table *t, const int64_t *q, int exp, int64_t got,
                           int oexp, int64_t lo, int64_t hi);

#endif
