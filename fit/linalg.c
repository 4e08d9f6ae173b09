/* Householder QR in binary128, column-major, for the small dense systems of
 * the fitter (at most a few thousand rows, at most FIT_MAX_ORDER+1 columns).
 * QR rather than normal equations: the normal equations square the
 * condition number, which is what makes monomial fits hopeless past order 8. */
#include "linalg.h"

#include <stdlib.h>
#include <string.h>

static fit_real fabsq(fit_real x) { return x < 0 ? -x : x; }

static fit_real sqrtq_(fit_real x)
{
    /* Newton from the double square root: two steps reach 113 bits. */
    if (x <= 0)
        return 0;
    fit_real r = (fit_real)__builtin_sqrt((double)x);
    if (r == 0)
        return 0;
    r = (fit_real)0.5 * (r + x / r);
    r = (fit_real)0.5 * (r + x / r);
    r = (fit_real)0.5 * (r + x / r);
    return r;
}

fit_real la_sqrt(fit_real x) { return sqrtq_(x); }
fit_real la_fabs(fit_real x) { return fabsq(x); }

/* In-place Householder QR of A (m x n, m >= n, column-major, lda = m).
 * On return the upper triangle holds R; v[] holds the reflectors (m x n),
 * beta[] their scales.  Returns the smallest |R_jj| / max |R_jj|. */
fit_real la_qr(fit_real *A, int m, int n, fit_real *V, fit_real *beta)
{
    fit_real rmax = 0, rmin = -1;
    for (int j = 0; j < n; j++) {
        fit_real *a = A + (size_t)j * m;
        fit_real *v = V + (size_t)j * m;
        fit_real norm = 0, scale = 0;
        for (int i = j; i < m; i++)
            if (fabsq(a[i]) > scale)
                scale = fabsq(a[i]);
        if (scale > 0)
            for (int i = j; i < m; i++) {
                fit_real s = a[i] / scale;
                norm += s * s;
            }
        norm = scale * sqrtq_(norm);
        memset(v, 0, sizeof(fit_real) * (size_t)m);
        if (norm == 0) {
            beta[j] = 0;
        } else {
            fit_real alpha = a[j] > 0 ? -norm : norm;
            for (int i = j; i < m; i++)
                v[i] = a[i];
            v[j] -= alpha;
            fit_real vv = 0;
            for (int i = j; i < m; i++)
                vv += v[i] * v[i];
            beta[j] = vv > 0 ? 2 / vv : 0;
            /* apply H = I - beta v v^T to columns j..n-1 */
            for (int k = j; k < n; k++) {
                fit_real *c = A + (size_t)k * m;
                fit_real s = 0;
                for (int i = j; i < m; i++)
                    s += v[i] * c[i];
                s *= beta[j];
                for (int i = j; i < m; i++)
                    c[i] -= s * v[i];
            }
        }
        fit_real d = fabsq(A[(size_t)j * m + j]);
        if (d > rmax)
            rmax = d;
        if (rmin < 0 || d < rmin)
            rmin = d;
    }
    return rmax > 0 ? rmin / rmax : 0;
}

/* y <- Q^T y using the reflectors of la_qr. */
void la_apply_qt(const fit_real *V, const fit_real *beta, int m, int n, fit_real *y)
{
    for (int j = 0; j < n; j++) {
        const fit_real *v = V + (size_t)j * m;
        fit_real s = 0;
        for (int i = j; i < m; i++)
            s += v[i] * y[i];
        s *= beta[j];
        for (int i = j; i < m; i++)
            y[i] -= s * v[i];
    }
}

/* y <- Q y. */
void la_apply_q(const fit_real *V, const fit_real *beta, int m, int n, fit_real *y)
{
    for (int j = n - 1; j >= 0; j--) {
        const fit_real *v = V + (size_t)j * m;
        fit_real s = 0;
        for (int i = j; i < m; i++)
            s += v[i] * y[i];
        s *= beta[j];
        for (int i = j; i < m; i++)
            y[i] -= s * v[i];
    }
}

/* Solve R x = y (R upper triangular n x n inside A with lda = m). */
void la_back_subst(const fit_real *A, int m, int n, const fit_real *y, fit_real *x)
{
    for (int i = n - 1; i >= 0; i--) {
        fit_real s = y[i];
        for (int k = i + 1; k < n; k++)
            s -= A[(size_t)k * m + i] * x[k];
        x[i] = s / A[(size_t)i * m + i];
    }
}

/* Solve R^T x = y (forward substitution). */
void la_forward_subst_t(const fit_real *A, int m, int n, const fit_real *y, fit_real *x)
{
    for (int i = 0; i < n; i++) {
        fit_real s = y[i];
        for (int k = 0; k < i; k++)
            s -= A[(size_t)i * m + k] * x[k];
        x[i] = s / A[(size_t)i * m + i];
    }
}

/* Equality-constrained least squares by the null-space method:
 *   minimize ||A x - b||  subject to  C x = d
 * A: m x n, C: p x n (both column-major), p <= n, m >= n - p.
 * Returns 0, -1 when C is rank deficient, -2 when A restricted to the null
 * space of C is rank deficient. */
int la_lse(const fit_real *A, int m, int n, const fit_real *b,
           const fit_real *C, int p, const fit_real *d, fit_real *x)
{
    int rc = 0;
    /* QR of C^T (n x p): C^T = Q [R; 0]. */
    fit_real *CT = calloc((size_t)n * (p ? p : 1), sizeof *CT);
    fit_real *VC = calloc((size_t)n * (p ? p : 1), sizeof *VC);
    fit_real *bc = calloc((size_t)(p ? p : 1), sizeof *bc);
    fit_real *Q = calloc((size_t)n * n, sizeof *Q);
    fit_real *y1 = calloc((size_t)n, sizeof *y1);
    int r = n - p;
    fit_real *AZ = calloc((size_t)m * (r ? r : 1), sizeof *AZ);
    fit_real *VA = calloc((size_t)m * (r ? r : 1), sizeof *VA);
    fit_real *ba = calloc((size_t)(r ? r : 1), sizeof *ba);
    fit_real *rhs = calloc((size_t)m, sizeof *rhs);
    fit_real *z = calloc((size_t)n, sizeof *z);
    if (!CT || !VC || !bc || !Q || !y1 || !AZ || !VA || !ba || !rhs || !z) {
        rc = -3;
        goto out;
    }
    for (int i = 0; i < p; i++)
        for (int j = 0; j < n; j++)
            CT[(size_t)i * n + j] = C[(size_t)j * p + i];
    if (p > 0) {
        fit_real cond = la_qr(CT, n, p, VC, bc);
        if (cond < (fit_real)1e-28) {
            rc = -1;
            goto out;
        }
    }
    /* Q explicitly: columns Q e_k. */
    for (int k = 0; k < n; k++) {
        fit_real *q = Q + (size_t)k * n;
        q[k] = 1;
        if (p > 0)
            la_apply_q(VC, bc, n, p, q);
    }
    /* R^T y1 = d; x0 = Q1 y1. */
    if (p > 0)
        la_forward_subst_t(CT, n, p, d, y1);
    /* AZ = A Q2, rhs = b - A x0 with x0 = Q1 y1 */
    for (int j = 0; j < n; j++) {
        fit_real x0j = 0;
        for (int k = 0; k < p; k++)
            x0j += Q[(size_t)k * n + j] * y1[k];
        x[j] = x0j;
    }
    for (int i = 0; i < m; i++) {
        fit_real s = b[i];
        for (int j = 0; j < n; j++)
            s -= A[(size_t)j * m + i] * x[j];
        rhs[i] = s;
    }
    for (int c = 0; c < r; c++)
        for (int i = 0; i < m; i++) {
            fit_real s = 0;
            for (int j = 0; j < n; j++)
                s += A[(size_t)j * m + i] * Q[(size_t)(p + c) * n + j];
            AZ[(size_t)c * m + i] = s;
        }
    if (r > 0) {
        fit_real cond = la_qr(AZ, m, r, VA, ba);
        if (cond < (fit_real)1e-30) {
            rc = -2;
            goto out;
        }
        la_apply_qt(VA, ba, m, r, rhs);
        la_back_subst(AZ, m, r, rhs, z);
    }
    for (int j = 0; j < n; j++) {
        fit_real s = 0;
        for (int k = 0; k < p; k++)
            s += Q[(size_t)k * n + j] * y1[k];
        for (int c = 0; c < r; c++)
            s += Q[(size_t)(p + c) * n + j] * z[c];
        x[j] = s;
    }
out:
    free(CT); free(VC); free(bc); free(Q); free(y1);
    free(AZ); free(VA); free(ba); free(rhs); free(z);
    return rc;
}

/* Is e (length n) in the row space of C (p x n)?  Distance of e from
 * span(C^T), relative to |e|, computed via QR of C^T. */
fit_real la_rowspace_dist(const fit_real *C, int p, int n, const fit_real *e)
{
    if (p == 0)
        return 1;
    fit_real *CT = calloc((size_t)n * p, sizeof *CT);
    fit_real *VC = calloc((size_t)n * p, sizeof *VC);
    fit_real *bc = calloc((size_t)p, sizeof *bc);
    fit_real *y = calloc((size_t)n, sizeof *y);
    fit_real res = 1;
    if (CT && VC && bc && y) {
        for (int i = 0; i < p; i++)
            for (int j = 0; j < n; j++)
                CT[(size_t)i * n + j] = C[(size_t)j * p + i];
        la_qr(CT, n, p, VC, bc);
        memcpy(y, e, sizeof(fit_real) * (size_t)n);
        la_apply_qt(VC, bc, n, p, y);
        fit_real num = 0, den = 0;
        for (int j = 0; j < n; j++)
            den += e[j] * e[j];
        for (int j = p; j < n; j++)
            num += y[j] * y[j];
        res = den > 0 ? sqrtq_(num / den) : 0;
    }
    free(CT); free(VC); free(bc); free(y);
    return res;
}
