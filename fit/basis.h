/* Chebyshev basis on the fit domain (internal to fit/). */
#ifndef PF_BASIS_H
#define PF_BASIS_H

#include "fit.h"

int basis_count(const fit_problem *pb);
void basis_eval(const fit_problem *pb, fit_real t, fit_real *phi, fit_real *dphi);
void basis_to_monomial(const fit_problem *pb, fit_real M[FIT_MAX_ORDER + 1][FIT_MAX_ORDER + 1]);
int fit_default_nodes(const fit_problem *pb);
int fit_coef_determined(const fit_problem *pb, int k);
void constraint_rows(const fit_problem *pb, int n, fit_real M[FIT_MAX_ORDER + 1][FIT_MAX_ORDER + 1], fit_real *C);
void fit_normalize_constraints(const fit_problem *pb0, fit_problem *pbs);

#endif
