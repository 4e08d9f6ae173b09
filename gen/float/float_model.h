/* Rounding-error model for float polynomial evaluation, shared by the
 * specs' model hooks (gen/float/funcs.h: pf_spec.model).
 *
 * Horner with fmaf: s_n = c_n, s_k = fmaf(s_{k+1}, z, c_k), one rounding a
 * step, so with u = 2^-24 the running error obeys
 *     |e_k| <= |e_{k+1}| |z| + |s_{k+1}| dz + u |s_k|
 * where dz bounds the error of the Horner variable itself (z = r*r rounded
 * for odd/even fits: dz = u |z|).  A step done in double-float (hi + lo,
 * pf_two_prod/pf_two_sum) has its rounding replaced by uc = 2^-44 (a
 * conservative figure for one double-float multiply-add, whose exact error is
 * below 2^-46 relative).  The bound is evaluated at many points of the domain
 * (the polynomial is smooth, so the grid's max is the model's figure; the
 * exhaustive sweep of the emitted code is the proof). */
#ifndef PF_FLOAT_MODEL_H
#define PF_FLOAT_MODEL_H

#include "fit.h"

typedef struct {
    double abs_max;   /* max over the domain of the bound on |fl(p(r)) - p(r)| */
    double rel_max;   /* max over the domain of that bound / |p(r)| */
    double at;        /* where rel_max is reached */
} pf_fm_bound;

/* p: the emitted polynomial (coefficients c[0..order] in r); parity as in
 * fit.h (odd: r * q(r^2), even: q(r^2), none: q(r)); [a, b] the domain in r;
 * ncomp: how many of the last Horner steps are double-float; rel_r: relative
 * error of r itself (0 when the reduction is exact). */
pf_fm_bound pf_fm_horner(const fit_poly *p, int order, int parity, double a, double b, int ncomp,
                         double rel_r);

#endif
