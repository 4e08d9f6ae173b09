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
#include <stdlib.h>

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

/* The error of a candidate is judged on a fixed set: Chebyshev extrema of D
 * (dense at the ends, where near-minimax error curves peak), target values
 * from MPFR computed once, the polynomial in binary128.  Good enough to rank
 * candidates; the caller measures the winner with fit_measure. */
typedef struct {
    int m;
    fit_real *x, *g, *w; /* point, target, 1/g (REL) or 1 (ABS) */
} rgrid;

static int rgrid_init(rgrid *G, const fit_problem *pb)
{
    int n = 40 * (pb->order + 1) + 200;
    G->m = 0;
    G->x = malloc(sizeof(fit_real) * (size_t)n);
    G->g = malloc(sizeof(fit_real) * (size_t)n);
    G->w = malloc(sizeof(fit_real) * (size_t)n);
    if (!G->x || !G->g || !G->w)
        return -1;
    for (int i = 0; i < n; i++) {
        fit_real x = i == 0 ? pb->a : i == n - 1 ? pb->b
                   : (pb->a + pb->b) / 2 - (pb->b - pb->a) / 2 * (fit_real)cos(M_PI * i / (n - 1));
        fit_real g = fit_eval_target(pb, x);
        if (pb->errkind == FIT_REL && g == 0)
            continue; /* the constraints keep p(x) = 0 there (log at 1) */
        G->x[G->m] = x;
        G->g[G->m] = g;
        G->w[G->m] = pb->errkind == FIT_REL ? 1 / g : 1;
        G->m++;
    }
    return 0;
}

static void rgrid_free(rgrid *G)
{
    free(G->x);
    free(G->g);
    free(G->w);
}

static fit_real rgrid_err(const rgrid *G, const fit_poly *p)
{
    fit_real e = 0;
    for (int i = 0; i < G->m; i++) {
        fit_real v = la_fabs((fit_eval_poly(p, G->x[i]) - G->g[i]) * G->w[i]);
        if (!(v <= e))
            e = v; /* NaN propagates as "worst" */
    }
    return e;
}

static void round_all(fit_poly *p, fit_coeffmt fmt)
{
    for (int k = 0; k <= p->order; k++)
        p->c[k] = fit_round_coef(p->c[k], fmt, NULL);
}

/* One pin-and-refit chain from start; *last gets its end (every coefficient
 * pinned), *best the best of its prefixes: pin c_0..c_k and refit, then
 * round the rest as they are.  Why prefixes: at high order each refit
 * absorbs the last rounding error into the free coefficients, which grow
 * (log at order 30 reaches |c_29| ~ 1e10) until their own rounding costs
 * more than all the refits gained; the best prefix stops before that. */
static int round_chain(const fit_problem *pb, fit_coeffmt fmt, fit_refit_fn refit, const rgrid *G,
                       const fit_poly *start, fit_poly *last, fit_real *last_err, fit_poly *best,
                       fit_real *best_err, char *err, size_t errlen)
{
    fit_problem q = *pb;
    fit_poly cur = *start, cand;
    cand = cur;
    round_all(&cand, fmt);
    *best = cand;
    *best_err = rgrid_err(G, &cand);
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
        c->value = fit_round_coef(cur.c[k], fmt, NULL);
        if (refit(&q, &cur, err, errlen) != 0) {
            char tmp[200];
            snprintf(tmp, sizeof tmp, "%s", err);
            snprintf(err, errlen, "re-fit after rounding c%d: %s", k, tmp);
            return -1;
        }
        cand = cur;
        round_all(&cand, fmt);
        fit_real e = rgrid_err(G, &cand);
        if (e < *best_err) {
            *best = cand;
            *best_err = e;
        }
    }
    *last = cand;
    *last_err = rgrid_err(G, &cand);
    return 0;
}

static void challenge(fit_poly *best, fit_real *best_err, const fit_poly *p, fit_real e)
{
    if (e < *best_err) {
        *best = *p;
        *best_err = e;
    }
}

static _Thread_local fit_real pen_u;
static int lsq_pen_refit(const fit_problem *pb, fit_poly *out, char *err, size_t errlen)
{
    return fit_lsq_pen(pb, pen_u, out, err, errlen);
}

int fit_round(const fit_problem *pb, fit_coeffmt fmt, fit_refit_fn refit,
              fit_poly *inout, int *fixed_exp, char *err, size_t errlen)
{
    if (fmt.fmt == FIT_COEF_REAL)
        return 0;
    fit_target_cache_begin();
    const fit_poly start = *inout;
    rgrid G;
    if (rgrid_init(&G, pb) != 0) {
        rgrid_free(&G);
        fit_target_cache_end();
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    /* The plain chain's end (the classic result) stands unless another
     * candidate beats it on the grid by more than 0.1%: equal fits keep
     * the plain chain's coefficients. */
    fit_poly plain, best, last, pre;
    fit_real plain_err, best_err = 0, last_err, pre_err;
    int rc = round_chain(pb, fmt, refit, &G, &start, &plain, &plain_err, &best, &best_err, err, errlen);
    /* A minimax chain is judged against the least-squares chain from the
     * least-squares start: the minimax refits optimise the real
     * coefficients, not the rounded ones, and can end behind it. */
    if (rc == 0 && refit != fit_lsq) {
        fit_poly ls;
        if (fit_lsq(pb, &ls, err, errlen) == 0 &&
            round_chain(pb, fmt, fit_lsq, &G, &ls, &last, &last_err, &pre, &pre_err, err, errlen) == 0) {
            challenge(&best, &best_err, &last, last_err);
            challenge(&best, &best_err, &pre, pre_err);
        }
        err[0] = 0;
    }
    /* and against the chain whose refits price in the rounding still to
     * come (fit_lsq_pen): at high order it keeps the coefficients small */
    pen_u = fmt.fmt == FIT_COEF_FLOAT ? (fit_real)0x1p-24 : fmt.fmt == FIT_COEF_DOUBLE ? (fit_real)0x1p-53 : 0;
    if (rc == 0 && pen_u > 0) {
        fit_poly ls;
        if (fit_lsq_pen(pb, pen_u, &ls, err, errlen) == 0 &&
            round_chain(pb, fmt, lsq_pen_refit, &G, &ls, &last, &last_err, &pre, &pre_err, err, errlen) == 0) {
            challenge(&best, &best_err, &last, last_err);
            challenge(&best, &best_err, &pre, pre_err);
        }
        err[0] = 0;
    }
    if (rc == 0 && !(best_err < plain_err * (fit_real)0.999))
        best = plain;
    rgrid_free(&G);
    fit_target_cache_end();
    if (rc != 0)
        return rc;
    *inout = best;
    if (fixed_exp)
        for (int k = 0; k <= pb->order; k++)
            fit_round_coef(inout->c[k], fmt, &fixed_exp[k]);
    return 0;
}
