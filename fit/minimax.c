/* Minimax refinement of a constrained fit (see fit.h).
 *
 * The error at x_i is e_i(z) = e_ls(x_i) + a_i . z, where z are coordinates
 * in the null space of the constraints (so every z keeps them) and a_i the
 * null-space basis polynomials at x_i, divided by g(x_i) for relative error.
 * minimize s  s.t.  -s <= e_i(z) <= s  is a linear program; nlopt's SLSQP
 * solves it in a few dozen iterations.  Everything is scaled by the LSQ
 * error E so that s ~ 1 and SLSQP works in well-scaled double. */
#include "basis.h"
#include "fit.h"
#include "linalg.h"

#include <math.h>
#include <nlopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    int m, nz;
    double *a; /* m x nz, row-major, scaled by 1/E */
    double *e; /* m, LSQ error / E */
} mm_data;

static double objective(unsigned n, const double *x, double *grad, void *d)
{
    (void)d;
    if (grad) {
        memset(grad, 0, sizeof(double) * n);
        grad[n - 1] = 1;
    }
    return x[n - 1];
}

/* 2m constraints: e_i(z) - s <= 0 and -e_i(z) - s <= 0 */
static void constraints(unsigned mc, double *res, unsigned n, const double *x, double *grad, void *dd)
{
    const mm_data *d = dd;
    (void)mc;
    int nz = d->nz;
    for (int i = 0; i < d->m; i++) {
        const double *ai = d->a + (size_t)i * nz;
        double v = d->e[i];
        for (int j = 0; j < nz; j++)
            v += ai[j] * x[j];
        res[2 * i] = v - x[nz];
        res[2 * i + 1] = -v - x[nz];
        if (grad) {
            double *g0 = grad + (size_t)(2 * i) * n, *g1 = g0 + n;
            for (int j = 0; j < nz; j++) {
                g0[j] = ai[j];
                g1[j] = -ai[j];
            }
            g0[nz] = -1;
            g1[nz] = -1;
        }
    }
}

int fit_minimax(const fit_problem *pb0, fit_poly *out, char *err, size_t errlen)
{
    fit_problem pbs;
    fit_normalize_constraints(pb0, &pbs);
    const fit_problem *pb = &pbs;
    fit_poly ls;
    if (fit_lsq(pb0, &ls, err, errlen) != 0)
        return -1;
    int n = basis_count(pb), p = pb->ncon, nz = n - p;
    if (nz <= 0) { /* fully determined: nothing to refine */
        *out = ls;
        return 0;
    }
    static _Thread_local fit_real M[FIT_MAX_ORDER + 1][FIT_MAX_ORDER + 1];
    basis_to_monomial(pb, M);
    /* null space of C: last nz columns of Q in C^T = Q R */
    fit_real *C = calloc((size_t)(p ? p : 1) * n, sizeof *C);
    fit_real *CT = calloc((size_t)n * (p ? p : 1), sizeof *CT);
    fit_real *V = calloc((size_t)n * (p ? p : 1), sizeof *V);
    fit_real beta[FIT_MAX_CON + 1];
    fit_real Z[FIT_MAX_ORDER + 1][FIT_MAX_ORDER + 1]; /* Z[j][c]: basis coef j of null vector c */
    if (p > 0) {
        constraint_rows(pb, n, M, C);
        for (int i = 0; i < p; i++)
            for (int j = 0; j < n; j++)
                CT[(size_t)i * n + j] = C[(size_t)j * p + i];
        la_qr(CT, n, p, V, beta);
    }
    for (int c = 0; c < nz; c++) {
        fit_real q[FIT_MAX_ORDER + 1] = {0};
        q[p + c] = 1;
        if (p > 0)
            la_apply_q(V, beta, n, p, q);
        for (int j = 0; j < n; j++)
            Z[j][c] = q[j];
    }
    /* null-space polynomials in monomial form, for evaluation */
    fit_poly zp[FIT_MAX_ORDER + 1];
    for (int c = 0; c < nz; c++) {
        memset(&zp[c], 0, sizeof zp[c]);
        zp[c].order = pb->order;
        for (int k = 0; k <= pb->order; k++) {
            fit_real s = 0;
            for (int j = 0; j < n; j++)
                s += M[k][j] * Z[j][c];
            zp[c].c[k] = s;
        }
    }
    /* dense set: Chebyshev extrema on D (they crowd at the ends, where the
       error of a near-minimax polynomial oscillates fastest) */
    int m = 60 * (pb->order + 1) + 200;
    mm_data d = {0, nz, malloc(sizeof(double) * (size_t)m * nz), malloc(sizeof(double) * (size_t)m)};
    fit_real *ev = malloc(sizeof(fit_real) * (size_t)m);
    fit_real *gv = malloc(sizeof(fit_real) * (size_t)m);
    fit_real *xv = malloc(sizeof(fit_real) * (size_t)m);
    fit_real *tv = malloc(sizeof(fit_real) * (size_t)m);
    fit_real E = 0;
    for (int i = 0; i < m; i++) {
        fit_real x = (pb->a + pb->b) / 2 - (pb->b - pb->a) / 2 * (fit_real)cos(M_PI * i / (m - 1));
        if (i == 0)
            x = pb->a;
        if (i == m - 1)
            x = pb->b;
        fit_real g = fit_eval_target(pb, x);
        if (pb->errkind == FIT_REL && g == 0)
            continue;
        fit_real w = pb->errkind == FIT_REL ? 1 / g : 1;
        xv[d.m] = x;
        tv[d.m] = g;
        gv[d.m] = w;
        ev[d.m] = (fit_eval_poly(&ls, x) - g) * w;
        if (la_fabs(ev[d.m]) > E)
            E = la_fabs(ev[d.m]);
        d.m++;
    }
    int rc = 0;
    if (E == 0) {
        *out = ls;
        goto done;
    }
    /* columns scaled to max 1 so that every variable moves on the same scale */
    fit_real colscale[FIT_MAX_ORDER + 1] = {0};
    for (int i = 0; i < d.m; i++)
        for (int c = 0; c < nz; c++) {
            fit_real v = la_fabs(fit_eval_poly(&zp[c], xv[i]) * gv[i] / E);
            if (v > colscale[c])
                colscale[c] = v;
        }
    for (int c = 0; c < nz; c++)
        if (colscale[c] == 0)
            colscale[c] = 1;
    for (int i = 0; i < d.m; i++) {
        d.e[i] = (double)(ev[i] / E);
        for (int c = 0; c < nz; c++)
            d.a[(size_t)i * nz + c] = (double)(fit_eval_poly(&zp[c], xv[i]) * gv[i] / E / colscale[c]);
    }
    nlopt_opt opt = nlopt_create(NLOPT_LD_SLSQP, (unsigned)nz + 1);
    double *x = calloc((size_t)nz + 1, sizeof *x);
    double *tol = malloc(sizeof(double) * 2 * (size_t)d.m);
    for (int i = 0; i < 2 * d.m; i++)
        tol[i] = 1e-12;
    x[nz] = 1.0; /* z = 0 (the LSQ fit) is feasible with s = 1 */
    nlopt_set_min_objective(opt, objective, NULL);
    nlopt_add_inequality_mconstraint(opt, 2 * (unsigned)d.m, constraints, &d, tol);
    nlopt_set_xtol_rel(opt, 1e-10);
    nlopt_set_ftol_rel(opt, 1e-12);
    nlopt_set_maxeval(opt, 2000);
    double fmin = 0;
    nlopt_result r = nlopt_optimize(opt, x, &fmin);
    if (getenv("PF_DEBUG_MINIMAX"))
        fprintf(stderr, "minimax: nlopt %d, s = %g, m = %d, nz = %d\n", (int)r, fmin, d.m, nz);
    nlopt_destroy(opt);
    free(tol);
    if (r < 0 && r != NLOPT_ROUNDOFF_LIMITED) {
        snprintf(err, errlen, "minimax (nlopt SLSQP) failed with code %d", (int)r);
        rc = -1;
    } else if (!(fmin <= 1.0 + 1e-9)) {
        *out = ls; /* never worse than the start */
    } else {
        *out = ls;
        for (int k = 0; k <= pb->order; k++) {
            fit_real s = 0;
            for (int c = 0; c < nz; c++)
                s += zp[c].c[k] * ((fit_real)x[c] / colscale[c]);
            out->c[k] += s;
        }
        for (int c = 0; c < pb->ncon; c++)
            if (pb->con[c].kind == FIT_CON_COEF)
                out->c[pb->con[c].index] = pb->con[c].value;
        for (int k = 0; k <= pb->order; k++)
            if ((pb->parity == FIT_PARITY_ODD && k % 2 == 0) || (pb->parity == FIT_PARITY_EVEN && k % 2 == 1))
                out->c[k] = 0;
        /* SLSQP saw the problem in double and through the null-space
           polynomials' monomial form; judged again in binary128 on the same
           set, the result must beat its start, or the start is kept. */
        fit_real Em = 0;
        for (int i = 0; i < d.m; i++) {
            fit_real v = la_fabs((fit_eval_poly(out, xv[i]) - tv[i]) * gv[i]);
            if (!(v <= Em))
                Em = v;
        }
        if (!(Em < E))
            *out = ls;
    }
    free(x);
done:
    free(d.a); free(d.e); free(ev); free(gv); free(xv); free(tv);
    free(C); free(CT); free(V);
    return rc;
}
