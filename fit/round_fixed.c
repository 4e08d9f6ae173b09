/* Pin-and-refit rounding to fixed point at imposed exponents (round_fixed.h). */
#include "round_fixed.h"

#include "basis.h"

#include <math.h>
#include <stdio.h>

int64_t fit_fixed_stored(fit_real v, int e)
{
    fit_real s = v * (fit_real)ldexp(1.0, e);
    fit_real a = s < 0 ? -s : s;
    fit_real f = (fit_real)(long long)a; /* floor(|s|), |s| < 2^62 */
    fit_real d = a - f;
    long long r = (long long)f;
    if (d > (fit_real)0.5 || (d == (fit_real)0.5 && (r & 1)))
        r++;
    return s < 0 ? -r : r;
}

static int too_big(fit_real v, int e)
{
    fit_real s = v * (fit_real)ldexp(1.0, e);
    return !(s < (fit_real)0x1p62 && s > -(fit_real)0x1p62);
}

static int structural_zero(const fit_problem *pb, int k)
{
    return (pb->parity == FIT_PARITY_ODD && k % 2 == 0) || (pb->parity == FIT_PARITY_EVEN && k % 2 == 1);
}

static int round_one(fit_poly *p, int k, const int *exps, int64_t *stored, char *err, size_t errlen)
{
    if (too_big(p->c[k], exps[k])) {
        snprintf(err, errlen, "coefficient c%d = %.6g does not fit 62 bits at lsb 2^-%d", k,
                 (double)p->c[k], exps[k]);
        return -1;
    }
    int64_t s = fit_fixed_stored(p->c[k], exps[k]);
    p->c[k] = (fit_real)s / (fit_real)ldexp(1.0, exps[k]);
    if (stored)
        stored[k] = s;
    return 0;
}

int fit_round_fixed(const fit_problem *pb, const int *exps, fit_refit_fn refit, fit_poly *inout,
                    int64_t *stored, char *err, size_t errlen)
{
    fit_problem q = *pb;
    for (int k = 0; k <= pb->order; k++) {
        if (structural_zero(pb, k))
            continue;
        if (q.ncon >= FIT_MAX_CON || q.ncon >= basis_count(&q))
            break;
        if (fit_coef_determined(&q, k))
            continue;
        if (too_big(inout->c[k], exps[k]))
            return round_one(inout, k, exps, stored, err, errlen);
        fit_constraint *c = &q.con[q.ncon++];
        c->kind = FIT_CON_COEF;
        c->index = k;
        c->value = (fit_real)fit_fixed_stored(inout->c[k], exps[k]) / (fit_real)ldexp(1.0, exps[k]);
        if (refit(&q, inout, err, errlen) != 0) {
            char tmp[200];
            snprintf(tmp, sizeof tmp, "%s", err);
            snprintf(err, errlen, "re-fit after rounding c%d: %s", k, tmp);
            return -1;
        }
    }
    /* everything pinned is already a multiple of its lsb; this rounds the
       coefficients the constraints determined (and the unpinned rest) */
    for (int k = 0; k <= pb->order; k++) {
        if (structural_zero(pb, k)) {
            inout->c[k] = 0;
            if (stored)
                stored[k] = 0;
            continue;
        }
        if (round_one(inout, k, exps, stored, err, errlen) != 0)
            return -1;
    }
    return 0;
}
