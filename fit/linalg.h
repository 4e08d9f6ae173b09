/* Dense linear algebra in binary128 for the fitter (internal). */
#ifndef PF_LINALG_H
#define PF_LINALG_H

#include "fit.h"

fit_real la_sqrt(fit_real x);
fit_real la_fabs(fit_real x);
fit_real la_qr(fit_real *A, int m, int n, fit_real *V, fit_real *beta);
void la_apply_qt(const fit_real *V, const fit_real *beta, int m, int n, fit_real *y);
void la_apply_q(const fit_real *V, const fit_real *beta, int m, int n, fit_real *y);
void la_back_subst(const fit_real *A, int m, int n, const fit_real *y, fit_real *x);
void la_forward_subst_t(const fit_real *A, int m, int n, const fit_real *y, fit_real *x);
int la_lse(const fit_real *A, int m, int n, const fit_real *b,
           const fit_real *C, int p, const fit_real *d, fit_real *x);
fit_real la_rowspace_dist(const fit_real *C, int p, int n, const fit_real *e);

#endif
