/* Coefficient rounding to the target format, Sollya-style by hand: round the
 * lowest-degree free coefficient, pin it, let the others re-fit around it,
 * and go up.  Low degrees first because their rounding error weighs most
 * (|c_k t^k| is largest for small k on the domains we use) and the later,
 * lighter coefficients can partly absorb it. */
#include "basis.h"
#include "fit.h"
#include "linalg.h"

#include <math.h>
#include <stdio.h>

fit_real fit_round_coef(fit_real v, fit_coeffmt fmt, int *exp)
{
    switch (fmt.fmt) {
    case FIT_COEF_FLOAT:
        return (fit_real)(float)v;
    case FIT_COEF_DOUBLE:
        return (fit_real)(double)v;
    case FIT_COEF_FIXED: {
        /* the largest exponent whose stored value still fits fixed_bits */
        if (v == 0) {
            if (exp)
                *exp = 0;
            return 0;
        }
        int e2;
        frexp((double)v, &e2); /* |v| in [2^(e2-1), 2^e2) */
        int ex = fmt.fixed_bits - e2;
        for (;;) {
            fit_real s = v * (fit_real)ldexp(1.0, ex);
            fit_real r = s < 0 ? -(fit_real)(long long)(-s + (fit_real)0.5)
                               : (fit_real)(long long)(s + (fit_real)0.5);
            if (la_fabs(r) < (fit_real)ldexp(1.0, fmt.fixed_bits)) {
                if (exp)
                    *exp = ex;
                return r / (fit_real)ldexp(1.0, ex);
            }
            ex--;
        }
    }
    default:
        return v;
    }
}

static int structural_zero(const fit_problem *pb, int k)
{
    return (pb->parity == FIT_PARITY_ODD && k % 2 == 0) ||
           (pb->parity == FIT_PARITY_EVEN && k % 2 == 1);
}

int fit_round(const fit_problem *pb, fit_coeffmt fmt, fit_refit_fn refit,
              fit_poly *inout, int *fixed_exp, char *err, size_t errlen)
{
    if (fmt.fmt == FIT_COEF_REAL)
        return 0;
    fit_problem q = *pb;
    for (int k = 0; k <= pb->order; k++) {
        if (structural_zero(pb, k))
            continue;
        if (q.ncon >= FIT_MAX_CON || q.ncon >= basis_count(&q))
            break;
        if (fit_coef_determined(&q, k))
            continue;
        fit_constraint *c = &q.con[q.ncon++];
        c->kind = FIT_CON_COEF;
        c->index = k;
        c->value = fit_round_coef(inout->c[k], fmt, NULL);
        if (refit(&q, inout, err, errlen) != 0) {
            char tmp[200];
            snprintf(tmp, sizeof tmp, "%s", err);
            snprintf(err, errlen, "re-fit after rounding c%d: %s", k, tmp);
            return -1;
        }
    }
    for (int k = 0; k <= pb->order; k++)
        inout->c[k] = fit_round_coef(inout->c[k], fmt, fixed_exp ? &fixed_exp[k] : NULL);
    return 0;
}
