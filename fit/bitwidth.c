/* Two-pass bit-width analysis (see bitwidth.h for the rules and why). */
#include "bitwidth.h"

#include <math.h>
#include <stdlib.h>

static pf_bw_node *node(pf_bw_op op, pf_bw_node *a, pf_bw_node *b)
{
    pf_bw_node *n = NULL;
    if (a && b)
        n = calloc(1, sizeof *n);
    if (!n) {
        pf_bw_free(a);
        pf_bw_free(b);
        return NULL;
    }
    n->op = op;
    n->a = a;
    n->b = b;
    return n;
}

pf_bw_node *pf_bw_leaf(pf_type t)
{
    if (t.is_float)
        return NULL;
    pf_bw_node *n = calloc(1, sizeof *n);
    if (!n)
        return NULL;
    n->op = PF_BW_LEAF;
    n->full = n->type = t;
    return n;
}

pf_bw_node *pf_bw_add(pf_bw_node *a, pf_bw_node *b) { return node(PF_BW_ADD, a, b); }
pf_bw_node *pf_bw_sub(pf_bw_node *a, pf_bw_node *b) { return node(PF_BW_SUB, a, b); }
pf_bw_node *pf_bw_mul(pf_bw_node *a, pf_bw_node *b) { return node(PF_BW_MUL, a, b); }

void pf_bw_free(pf_bw_node *n)
{
    if (!n)
        return;
    pf_bw_free(n->a);
    pf_bw_free(n->b);
    free(n);
}

static void bottom_up(pf_bw_node *n)
{
    if (n->op == PF_BW_LEAF) {
        n->type = n->full;
        return;
    }
    bottom_up(n->a);
    bottom_up(n->b);
    pf_fmt fa = pf_type_to_fmt(&n->a->full), fb = pf_type_to_fmt(&n->b->full), f;
    if (n->op == PF_BW_MUL)
        f = pf_fmt_mul(fa, fb);
    else if (n->op == PF_BW_ADD)
        f = pf_fmt_add(fa, fb);
    else
        f = pf_fmt_sub(fa, fb);
    n->full = n->type = pf_type_from_fmt(f);
}

int pf_bw_bottom_up(pf_bw_node *n)
{
    if (!n)
        return -1;
    bottom_up(n);
    return 0;
}

static int int_bits(const pf_type *t) { return t->size - t->exp; }

/* integer bits ib and lsb exponent e; at least one bit in all (more integer
 * bits rather than a coarser lsb, which would add a rounding) */
static pf_type shaped(int is_signed, int ib, int e)
{
    if (ib + e < 1)
        ib = 1 - e;
    return pf_type_fixed(is_signed, ib + e, e);
}

static void trim(pf_bw_node *n, int cap);

static void trim_operands(pf_bw_node *n)
{
    if (n->op == PF_BW_MUL) {
        trim(n->a, n->type.exp + int_bits(&n->b->full));
        trim(n->b, n->type.exp + int_bits(&n->a->full));
    } else {
        trim(n->a, n->type.exp);
        trim(n->b, n->type.exp);
    }
}

/* n's lsb may be no finer than 2^-cap */
static void trim(pf_bw_node *n, int cap)
{
    if (n->op == PF_BW_LEAF)
        return;
    int e = n->full.exp < cap ? n->full.exp : cap;
    n->type = shaped(n->full.is_signed, int_bits(&n->full), e);
    trim_operands(n);
}

int pf_bw_top_down(pf_bw_node *n, pf_type dest)
{
    if (!n || dest.is_float)
        return -1;
    bottom_up(n);
    if (n->op == PF_BW_LEAF)
        return 0;
    int ib = int_bits(&n->full), id = int_bits(&dest);
    int e = n->full.exp < dest.exp ? n->full.exp : dest.exp;
    n->type = shaped(n->full.is_signed && dest.is_signed, ib < id ? ib : id, e);
    trim_operands(n);
    return 0;
}

int pf_bw_horner(const pf_type *coef, int n, pf_type x, pf_type out, pf_bw_step *steps)
{
    if (n < 0 || x.is_float || out.is_float)
        return -1;
    for (int k = 0; k <= n; k++)
        if (coef[k].is_float)
            return -1;
    /* build (...(c_n*x + c_{n-1})*x ...)*x + c_0, remembering p_k nodes */
    pf_bw_node **p = malloc((size_t)(n + 1) * sizeof *p);
    if (!p)
        return -1;
    p[n] = pf_bw_leaf(coef[n]);
    for (int k = n - 1; k >= 0; k--) {
        p[k] = pf_bw_add(pf_bw_mul(p[k + 1], pf_bw_leaf(x)), pf_bw_leaf(coef[k]));
        if (!p[k]) { /* the failed constructor freed p[k+1]'s tree */
            free(p);
            return -1;
        }
    }
    pf_bw_top_down(p[0], out);
    for (int k = 0; k <= n; k++) {
        steps[k].p = p[k]->type;
        if (k < n) {
            steps[k].m = p[k]->a->type;
            steps[k].shift = p[k + 1]->type.exp + x.exp - p[k]->type.exp;
        } else {
            steps[k].m = p[k]->type;
            steps[k].shift = 0;
        }
    }
    pf_bw_free(p[0]);
    free(p);
    return 0;
}

/* finest exponent e <= cap with v 2^e <= 2^(W-1) - 1, or cap - 400 if none */
static int fit_exp(double v, int W, int cap)
{
    double lim = ldexp(1.0, W - 1) - 1;
    for (int e = cap; e > cap - 400; e--)
        if (v * ldexp(1.0, e) <= lim)
            return e;
    return cap - 400;
}

int pf_bw_horner_word(const double *pmax, int n, int W, int emax, pf_bw_wstep *st, double *err)
{
    if (n < 0 || W < 8 || W > 32)
        return -1;
    double q = ldexp(1.0, -(W - 1));
    st[n].exp = fit_exp(pmax[n], W, emax);
    st[n].xdrop = 0;
    st[n].kind = PF_BW_MULHRS;
    st[n].err = 0;
    if (st[n].exp < -W)
        return -1;
    for (int k = n - 1; k >= 0; k--) {
        int prev = st[k + 1].exp, e = prev;
        double ek;
        /* coarsen until p_k and its error fit; the error grows as e drops */
        for (;; e--) {
            int d = prev - e;
            if (d > W - 2 || e < -W)
                return -1;
            ek = st[k + 1].err + (d ? pmax[k + 1] * ldexp(q, d - 1) : 0) + ldexp(0.5, -e);
            if ((pmax[k] + ek) * ldexp(1.0, e) <= ldexp(1.0, W - 1) - 1)
                break;
        }
        st[k].exp = e;
        st[k].xdrop = prev - e;
        st[k].kind = PF_BW_MULHRS;
        st[k].err = ek;
    }
    *err = st[0].err;
    return 0;
}
