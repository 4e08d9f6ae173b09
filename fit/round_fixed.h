/* Coefficient rounding to fixed point with a given lsb per coefficient.
 *
 * fit_round's FIT_COEF_FIXED picks each coefficient's exponent from its
 * magnitude (the finest that keeps fixed_bits bits).  Generated fixed-point
 * code needs the opposite: the exponent is imposed by the Horner step that
 * adds the coefficient (the bit-width analysis, fit/bitwidth.h), and a
 * coefficient with a finer lsb than its step would be rounded twice.  So the
 * caller gives the exponent of every coefficient and this rounds c_k to a
 * multiple of 2^-exps[k], Sollya-style as fit_round does: lowest degree
 * first, pin, re-fit the others around it (refit = fit_lsq or fit_minimax). */
#ifndef PF_ROUND_FIXED_H
#define PF_ROUND_FIXED_H

#include "fit.h"

#include <stdint.h>

/* RNE(v * 2^e) as an integer; |v * 2^e| must be below 2^62. */
int64_t fit_fixed_stored(fit_real v, int e);

/* Rounds inout->c[k] (k = 0..order, structural zeros of the parity left at
 * 0) to multiples of 2^-exps[k]; stored[k] (may be NULL) receives
 * c[k] * 2^exps[k].  Returns 0, or -1 with a one-line reason in err (a
 * re-fit failed, or a coefficient does not fit 62 bits at its exponent). */
int fit_round_fixed(const fit_problem *pb, const int *exps, fit_refit_fn refit, fit_poly *inout,
                    int64_t *stored, char *err, size_t errlen);

#endif
