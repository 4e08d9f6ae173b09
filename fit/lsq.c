/* Least-squares relative-error fit with equality constraints (the seed's
 * method, eq. 4.1/4.2): minimize  int_D ((p - g)/g)^2 dt  by Gauss-Legendre
 * quadrature, subject to p(t_i) = g(t_i), p'(t_i) = g'(t_i), c_k = v.
 *
 * Basis: Chebyshev polynomials T_j(s) with s the affine map of D onto
 * [-1, 1]; for odd/even targets on D = [0, b], s = t/b and only T_j of the
 * matching parity (so the polynomial keeps the parity exactly). */
#include "basis.h"
#include "fit.h"
#include "linalg.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void fit_set_mpfr(mpfr_t y, fit_real v)
{
    /* three doubles hold all 113 bits of a normal binary128 exactly */
    double h = (double)v;
    fit_real r = v - h;
    double m = (double)r;
    double l = (double)(r - m);
    mpfr_t t;
    mpfr_init2(t, 64);
    mpfr_set_d(y, h, MPFR_RNDN);
    mpfr_set_d(t, m, MPFR_RNDN);
    mpfr_add(y, y, t, MPFR_RNDN);
    mpfr_set_d(t, l, MPFR_RNDN);
    mpfr_add(y, y, t, MPFR_RNDN);
    mpfr_clear(t);
}

fit_real fit_get_mpfr(const mpfr_t v)
{
    mpfr_t r;
    mpfr_init2(r, mpfr_get_prec(v) + 8);
    mpfr_set(r, v, MPFR_RNDN);
    double h = mpfr_get_d(r, MPFR_RNDN);
    mpfr_sub_d(r, r, h, MPFR_RNDN);
    double m = mpfr_get_d(r, MPFR_RNDN);
    mpfr_sub_d(r, r, m, MPFR_RNDN);
    double l = mpfr_get_d(r, MPFR_RNDN);
    mpfr_clear(r);
    return (fit_real)h + ((fit_real)m + (fit_real)l);
}

/* While a cache scope is open, fits evaluate g at many of the same t:
 * fit_round's refits at the same nodes (the problem only gains coefficient
 * pins), fit_measure's grid of 4097 points at every order the generator
 * tries and for each polynomial it measures, and the ladder search's
 * candidates, which fit the same targets again.  g(t) depends on the target
 * function, its context and t only (not on the problem's domain, order or
 * constraints), so it is remembered by those three; a target's context must
 * not change within a scope.  Scopes nest: an inner begin only counts, the
 * outermost end frees.  Open addressing; when full, values are simply not
 * stored.  The values are MPFR's either way, so a fit is the same with or
 * without the cache. */
#define TCACHE_SIZE 131072
typedef struct {
    fit_target_fn g;
    const void *ctx;
    fit_real t, v;
    unsigned char used;
} tentry;
static _Thread_local tentry *tc_cur;
static _Thread_local int tc_depth;
static _Thread_local size_t tc_count; /* values stored in the open scope */
static _Thread_local size_t tc_size;  /* its slots */

void fit_target_cache_begin_n(size_t slots)
{
    if (tc_depth++ > 0)
        return;
    tc_size = slots ? slots : 1;
    tc_cur = calloc(tc_size, sizeof *tc_cur); /* NULL: no cache, every g from MPFR */
    tc_count = 0;
}

void fit_target_cache_begin(void) { fit_target_cache_begin_n(TCACHE_SIZE); }

size_t fit_target_cache_count(void) { return tc_cur ? tc_count : 0; }

void fit_target_cache_end(void)
{
    if (tc_depth <= 0 || --tc_depth > 0)
        return;
    free(tc_cur);
    tc_cur = NULL;
}

static size_t tc_slot(const fit_problem *pb, fit_real t)
{
    unsigned char b[sizeof t + sizeof pb->g + sizeof pb->ctx];
    memcpy(b, &t, sizeof t);
    memcpy(b + sizeof t, &pb->g, sizeof pb->g);
    memcpy(b + sizeof t + sizeof pb->g, &pb->ctx, sizeof pb->ctx);
    uint64_t h = 1469598103934665603ull;
    for (size_t i = 0; i < sizeof b; i++)
        h = (h ^ b[i]) * 1099511628211ull;
    return (size_t)(h % tc_size);
}

static fit_real eval_target_mpfr(const fit_problem *pb, fit_real t);

fit_real fit_eval_target(const fit_problem *pb, fit_real t)
{
    if (!tc_cur)
        return eval_target_mpfr(pb, t);
    size_t i = tc_slot(pb, t);
    for (size_t probe = 0; probe < 64 && probe < tc_size; probe++, i = (i + 1) % tc_size) {
        tentry *e = &tc_cur[i];
        if (!e->used) {
            e->g = pb->g;
            e->ctx = pb->ctx;
            e->t = t;
            e->v = eval_target_mpfr(pb, t);
            e->used = 1;
            tc_count++;
            return e->v;
        }
        if (e->g == pb->g && e->ctx == pb->ctx && memcmp(&e->t, &t, sizeof t) == 0)
            return e->v;
    }
    return eval_target_mpfr(pb, t);
}

static fit_real eval_target_mpfr(const fit_problem *pb, fit_real t)
{
    mpfr_t x, y;
    mpfr_inits2(256, x, y, (mpfr_ptr)0);
    fit_set_mpfr(x, t);
    pb->g(y, x, pb->ctx);
    fit_real r = fit_get_mpfr(y);
    mpfr_clears(x, y, (mpfr_ptr)0);
    return r;
}

fit_real fit_eval_target_deriv(const fit_problem *pb, fit_real t)
{
    /* central difference at 640 bits, h = 2^-150: truncation ~h^2 g''',
     * cancellation ~2^-640/h; both far below binary128. */
    mpfr_t x, y1, y2;
    mpfr_inits2(640, x, y1, y2, (mpfr_ptr)0);
    fit_set_mpfr(x, t);
    mpfr_add_d(x, x, 0x1p-150, MPFR_RNDN);
    pb->g(y1, x, pb->ctx);
    fit_set_mpfr(x, t);
    mpfr_sub_d(x, x, 0x1p-150, MPFR_RNDN);
    pb->g(y2, x, pb->ctx);
    mpfr_sub(y1, y1, y2, MPFR_RNDN);
    mpfr_mul_2si(y1, y1, 149, MPFR_RNDN);
    fit_real r = fit_get_mpfr(y1);
    mpfr_clears(x, y1, y2, (mpfr_ptr)0);
    return r;
}

fit_real fit_eval_poly(const fit_poly *p, fit_real t)
{
    fit_real s = 0;
    for (int k = p->order; k >= 0; k--)
        s = s * t + p->c[k];
    return s;
}

fit_real fit_eval_poly_deriv(const fit_poly *p, fit_real t)
{
    fit_real s = 0;
    for (int k = p->order; k >= 1; k--)
        s = s * t + k * p->c[k];
    return s;
}

void fit_gauss_legendre(int n, fit_real *x, fit_real *w)
{
    /* Newton on P_n from the classical cosine guess, in binary128. */
    for (int i = 0; i < (n + 1) / 2; i++) {
        fit_real z = (fit_real)cos(M_PI * (i + 0.75) / (n + 0.5));
        fit_real dp = 1;
        for (int it = 0; it < 100; it++) {
            fit_real p0 = 1, p1 = z;
            for (int k = 2; k <= n; k++) {
                fit_real p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            dp = n * (z * p1 - p0) / (z * z - 1);
            fit_real dz = p1 / dp;
            z -= dz;
            if (la_fabs(dz) < (fit_real)1e-33)
                break;
        }
        /* recompute derivative at the converged root */
        fit_real p0 = 1, p1 = z;
        for (int k = 2; k <= n; k++) {
            fit_real p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
            p0 = p1;
            p1 = p2;
        }
        dp = n * (z * p1 - p0) / (z * z - 1);
        x[i] = -z;
        x[n - 1 - i] = z;
        w[i] = w[n - 1 - i] = 2 / ((1 - z * z) * dp * dp);
    }
}

/* Newton for every root costs more than the rest of a refit: the last node
 * set is kept (the same bits as computing it afresh). */
static void gl_nodes(int n, fit_real *x, fit_real *w)
{
    static _Thread_local int last_n;
    static _Thread_local fit_real *last_x, *last_w;
    if (n != last_n || !last_x) {
        free(last_x);
        free(last_w);
        last_x = malloc(sizeof(fit_real) * (size_t)n);
        last_w = malloc(sizeof(fit_real) * (size_t)n);
        if (!last_x || !last_w) {
            free(last_x);
            free(last_w);
            last_x = last_w = NULL;
            last_n = 0;
            fit_gauss_legendre(n, x, w);
            return;
        }
        fit_gauss_legendre(n, last_x, last_w);
        last_n = n;
    }
    memcpy(x, last_x, sizeof(fit_real) * (size_t)n);
    memcpy(w, last_w, sizeof(fit_real) * (size_t)n);
}

/* ---- Chebyshev basis on D ---- */

int basis_count(const fit_problem *pb)
{
    switch (pb->parity) {
    case FIT_PARITY_ODD: return (pb->order + 1) / 2;
    case FIT_PARITY_EVEN: return pb->order / 2 + 1;
    default: return pb->order + 1;
    }
}

static int basis_degree(const fit_problem *pb, int j)
{
    switch (pb->parity) {
    case FIT_PARITY_ODD: return 2 * j + 1;
    case FIT_PARITY_EVEN: return 2 * j;
    default: return j;
    }
}

/* s = alpha t + beta */
static void basis_map(const fit_problem *pb, fit_real *alpha, fit_real *beta)
{
    if (pb->parity != FIT_PARITY_NONE) {
        *alpha = 1 / pb->b;
        *beta = 0;
    } else {
        *alpha = 2 / (pb->b - pb->a);
        *beta = -(pb->a + pb->b) / (pb->b - pb->a);
    }
}

/* phi[j] = basis j at t; dphi[j] its derivative in t (dphi may be NULL). */
void basis_eval(const fit_problem *pb, fit_real t, fit_real *phi, fit_real *dphi)
{
    fit_real alpha, beta;
    basis_map(pb, &alpha, &beta);
    fit_real s = alpha * t + beta;
    fit_real T[2 * FIT_MAX_ORDER + 4], dT[2 * FIT_MAX_ORDER + 4];
    int maxd = basis_degree(pb, basis_count(pb) - 1);
    T[0] = 1;
    dT[0] = 0;
    T[1] = s;
    dT[1] = 1;
    for (int d = 1; d < maxd; d++) {
        T[d + 1] = 2 * s * T[d] - T[d - 1];
        dT[d + 1] = 2 * T[d] + 2 * s * dT[d] - dT[d - 1];
    }
    for (int j = 0; j < basis_count(pb); j++) {
        phi[j] = T[basis_degree(pb, j)];
        if (dphi)
            dphi[j] = dT[basis_degree(pb, j)] * alpha;
    }
}

/* M[k][j]: monomial coefficient of t^k in basis function j. */
void basis_to_monomial(const fit_problem *pb, fit_real M[FIT_MAX_ORDER + 1][FIT_MAX_ORDER + 1])
{
    fit_real alpha, beta;
    basis_map(pb, &alpha, &beta);
    static _Thread_local fit_real P[FIT_MAX_ORDER + 2][FIT_MAX_ORDER + 2];
    int maxd = pb->order;
    memset(P, 0, sizeof P);
    P[0][0] = 1;
    if (maxd >= 1) {
        P[1][0] = beta;
        P[1][1] = alpha;
    }
    for (int d = 1; d < maxd; d++)
        for (int k = 0; k <= d + 1; k++) {
            fit_real v = -P[d - 1][k] + 2 * beta * P[d][k];
            if (k > 0)
                v += 2 * alpha * P[d][k - 1];
            P[d + 1][k] = v;
        }
    for (int k = 0; k <= FIT_MAX_ORDER; k++)
        for (int j = 0; j <= FIT_MAX_ORDER; j++)
            M[k][j] = 0;
    for (int j = 0; j < basis_count(pb); j++)
        for (int k = 0; k <= pb->order; k++)
            M[k][j] = P[basis_degree(pb, j)][k];
}

int fit_default_nodes(const fit_problem *pb)
{
    if (pb->nodes > 0)
        return pb->nodes;
    /* Enough that doubling changes nothing at binary128 level for smooth
     * targets (checked in tests/test_fit.c). */
    return 16 * (pb->order + 1) + 64;
}

/* Constraint matrix rows in the basis (C is ncon x n, column-major). */
void constraint_rows(const fit_problem *pb, int n,
                            fit_real M[FIT_MAX_ORDER + 1][FIT_MAX_ORDER + 1], fit_real *C)
{
    fit_real phi[FIT_MAX_ORDER + 1], dphi[FIT_MAX_ORDER + 1];
    for (int c = 0; c < pb->ncon; c++) {
        const fit_constraint *k = &pb->con[c];
        if (k->kind == FIT_CON_COEF) {
            for (int j = 0; j < n; j++)
                C[(size_t)j * pb->ncon + c] = M[k->index][j];
        } else {
            basis_eval(pb, k->t, phi, dphi);
            for (int j = 0; j < n; j++)
                C[(size_t)j * pb->ncon + c] = k->kind == FIT_CON_VALUE ? phi[j] : dphi[j];
        }
    }
}

int fit_coef_determined(const fit_problem *pb, int k)
{
    int n = basis_count(pb);
    static _Thread_local fit_real M[FIT_MAX_ORDER + 1][FIT_MAX_ORDER + 1];
    fit_real C[FIT_MAX_CON * (FIT_MAX_ORDER + 1)], e[FIT_MAX_ORDER + 1];
    basis_to_monomial(pb, M);
    constraint_rows(pb, n, M, C);
    for (int j = 0; j < n; j++)
        e[j] = M[k][j];
    return la_rowspace_dist(C, pb->ncon, n, e) < (fit_real)1e-25;
}

/* p(0) and p'(0) are c0 and c1: pose them as coefficient constraints so
 * that they can hold exactly (log's p(0) = 0 keeps relative error finite). */
void fit_normalize_constraints(const fit_problem *pb0, fit_problem *pbs)
{
    *pbs = *pb0;
    for (int c = 0; c < pbs->ncon; c++)
        if (pbs->con[c].kind != FIT_CON_COEF && pbs->con[c].t == 0) {
            pbs->con[c].value = pbs->con[c].kind == FIT_CON_VALUE ? fit_eval_target(pb0, 0)
                                                                  : fit_eval_target_deriv(pb0, 0);
            pbs->con[c].index = pbs->con[c].kind == FIT_CON_VALUE ? 0 : 1;
            pbs->con[c].kind = FIT_CON_COEF;
        }
}

int fit_lsq(const fit_problem *pb0, fit_poly *out, char *err, size_t errlen)
{
    return fit_lsq_pen(pb0, 0, out, err, errlen);
}

/* With coef_u > 0, the sum of squares also counts the expected cost of
 * rounding each free coefficient later: c_k moves by up to coef_u |c_k|
 * (uniform, variance coef_u^2 c_k^2 / 3), which adds
 * coef_u^2 / 3 * c_k^2 * int_D (t^k / g)^2 dt  to the objective (ridge rows).
 * At high order the plain refit buys tiny gains with huge cancelling
 * coefficients (|c_k| ~ 1e10 for log at order 30) whose rounding then costs
 * far more; the penalty prices that in. */
int fit_lsq_pen(const fit_problem *pb0, fit_real coef_u, fit_poly *out, char *err, size_t errlen)
{
    fit_problem pbs;
    fit_normalize_constraints(pb0, &pbs);
    const fit_problem *pb = &pbs;
    int n = basis_count(pb);
    if (pb->order < 1 || pb->order > FIT_MAX_ORDER) {
        snprintf(err, errlen, "order %d out of range 1..%d", pb->order, FIT_MAX_ORDER);
        return -1;
    }
    if (pb->ncon > n) {
        snprintf(err, errlen, "order %d has %d free coefficients, fewer than the %d constraints",
                 pb->order, n, pb->ncon);
        return -1;
    }
    if (pb->parity != FIT_PARITY_NONE && pb->a != 0) {
        snprintf(err, errlen, "odd/even fits need a domain [0, b]");
        return -1;
    }
    int nq = fit_default_nodes(pb), m = nq + (coef_u > 0 ? pb->order + 1 : 0);
    fit_real *gx = malloc(sizeof(fit_real) * (size_t)nq);
    fit_real *gw = malloc(sizeof(fit_real) * (size_t)nq);
    fit_real *A = calloc((size_t)m * (size_t)n, sizeof(fit_real));
    fit_real *bv = calloc((size_t)m, sizeof(fit_real));
    fit_real pen[FIT_MAX_ORDER + 1] = {0}; /* int_D (t^k / g)^2 dt by the same quadrature */
    fit_real C[FIT_MAX_CON * (FIT_MAX_ORDER + 1)], d[FIT_MAX_CON], x[FIT_MAX_ORDER + 1];
    fit_real phi[FIT_MAX_ORDER + 1];
    static _Thread_local fit_real M[FIT_MAX_ORDER + 1][FIT_MAX_ORDER + 1];
    int rc = 0;
    if (!gx || !gw || !A || !bv) {
        snprintf(err, errlen, "out of memory");
        rc = -1;
        goto out;
    }
    gl_nodes(nq, gx, gw);
    fit_real half = (pb->b - pb->a) / 2, mid = (pb->a + pb->b) / 2;
    for (int i = 0; i < nq; i++) {
        fit_real t = mid + half * gx[i];
        fit_real g = fit_eval_target(pb, t);
        fit_real sw = la_sqrt(gw[i] * half);
        fit_real wt = pb->errkind == FIT_REL ? sw / g : sw;
        basis_eval(pb, t, phi, NULL);
        for (int j = 0; j < n; j++)
            A[(size_t)j * m + i] = phi[j] * wt;
        bv[i] = g * wt;
        if (coef_u > 0) {
            fit_real tk = wt;
            for (int k = 0; k <= pb->order; k++, tk *= t)
                pen[k] += tk * tk;
        }
    }
    basis_to_monomial(pb, M);
    if (coef_u > 0)
        for (int k = 0; k <= pb->order; k++) {
            int pinned = 0;
            for (int c = 0; c < pb->ncon; c++)
                pinned |= pb->con[c].kind == FIT_CON_COEF && pb->con[c].index == k;
            fit_real sc = pinned ? 0 : coef_u * la_sqrt(pen[k] / 3);
            for (int j = 0; j < n; j++)
                A[(size_t)j * m + nq + k] = sc * M[k][j];
        }
    constraint_rows(pb, n, M, C);
    for (int c = 0; c < pb->ncon; c++) {
        const fit_constraint *k = &pb->con[c];
        d[c] = k->kind == FIT_CON_COEF    ? k->value
               : k->kind == FIT_CON_VALUE ? fit_eval_target(pb, k->t)
                                          : fit_eval_target_deriv(pb, k->t);
    }
    int r = la_lse(A, m, n, bv, C, pb->ncon, d, x);
    if (r == -1) {
        snprintf(err, errlen, "constraints are dependent or inconsistent at order %d", pb->order);
        rc = -1;
        goto out;
    } else if (r != 0) {
        snprintf(err, errlen, "least-squares system is singular at order %d", pb->order);
        rc = -1;
        goto out;
    }
    memset(out, 0, sizeof *out);
    out->order = pb->order;
    for (int k = 0; k <= pb->order; k++) {
        fit_real s = 0;
        for (int j = 0; j < n; j++)
            s += M[k][j] * x[j];
        out->c[k] = s;
    }
    /* coefficient constraints hold exactly, not to binary128 rounding */
    for (int c = 0; c < pb->ncon; c++)
        if (pb->con[c].kind == FIT_CON_COEF)
            out->c[pb->con[c].index] = pb->con[c].value;
    /* parity zeros are structural: make them exact */
    for (int k = 0; k <= pb->order; k++)
        if ((pb->parity == FIT_PARITY_ODD && k % 2 == 0) || (pb->parity == FIT_PARITY_EVEN && k % 2 == 1))
            out->c[k] = 0;
out:
    free(gx);
    free(gw);
    free(A);
    free(bv);
    return rc;
}
