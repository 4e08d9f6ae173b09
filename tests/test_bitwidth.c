/* fit/bitwidth.c: the seed's Figure 4.8, and properties of both passes on
 * random trees checked with exact rational arithmetic (GMP): bottom-up types
 * hold every exact result; top-down types, evaluated with pffixed.h, stay
 * within the rounding-error bound their lsbs imply; Horner formats lose no
 * more than one lsb of the destination per step. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h> /* before gmp.h, for gmp_fprintf */
#include <gmp.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bitwidth.h"

static int quick;
static uint64_t rng_state = 0x2545f4914f6cdd1du;
static uint64_t rnd(void) /* splitmix64 */
{
    uint64_t z = (rng_state += 0x9e3779b97f4a7c15u);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
    return z ^ (z >> 31);
}
static int rnd_int(int lo, int hi) { return lo + (int)(rnd() % (uint64_t)(hi - lo + 1)); }

static pf_type T(const char *s)
{
    pf_type t;
    char err[200];
    if (pf_type_parse(s, &t, err, sizeof err) != 0) {
        print_error("%s\n", err);
        fail();
    }
    return t;
}

static void expect_type(const pf_type *got, const char *want, const char *what)
{
    char buf[64];
    pf_type_format(got, buf, sizeof buf);
    if (strcmp(buf, want) != 0) {
        print_error("%s: got %s, want %s\n", what, buf, want);
        fail();
    }
}

/* fixed<10,10> x,y; fixed<15,12> z,r; r = x*y + z */
static void test_figure_4_8(void **state)
{
    (void)state;
    pf_type x = T("fixed<10,10>"), z = T("fixed<15,12>"), r = T("fixed<15,12>");
    pf_bw_node *t1 = pf_bw_mul(pf_bw_leaf(x), pf_bw_leaf(x));
    pf_bw_node *t2 = pf_bw_add(t1, pf_bw_leaf(z));
    assert_non_null(t2);
    assert_int_equal(pf_bw_bottom_up(t2), 0);
    expect_type(&t1->type, "fixed<20,20>", "bottom-up t1 = x*y");
    expect_type(&t2->type, "fixed<24,20>", "bottom-up t2 = t1+z");
    assert_int_equal(pf_bw_top_down(t2, r), 0);
    expect_type(&t1->type, "fixed<12,12>", "top-down t1");
    expect_type(&t2->type, "fixed<15,12>", "top-down t2");
    expect_type(&t1->full, "fixed<20,20>", "t1 full");
    expect_type(&t2->full, "fixed<24,20>", "t2 full");
    expect_type(&t1->a->type, "fixed<10,10>", "x unchanged");
    expect_type(&t2->b->type, "fixed<15,12>", "z unchanged");
    pf_bw_free(t2);

    /* the same through the Horner convenience: r = y*x + z is degree 1 */
    pf_type coef[2] = { z, x };
    pf_bw_step st[2];
    assert_int_equal(pf_bw_horner(coef, 1, x, r, st), 0);
    expect_type(&st[1].p, "fixed<10,10>", "horner p_1 = c_1");
    expect_type(&st[0].m, "fixed<12,12>", "horner m_0");
    expect_type(&st[0].p, "fixed<15,12>", "horner p_0");
    assert_int_equal(st[0].shift, 10 + 10 - 12);
}

static void test_api_edges(void **state)
{
    (void)state;
    pf_type f = pf_type_float(), x = T("fixed<7,7>");
    assert_null(pf_bw_leaf(f));
    assert_null(pf_bw_add(NULL, pf_bw_leaf(x))); /* frees the other operand */
    assert_null(pf_bw_mul(pf_bw_leaf(x), NULL));
    assert_null(pf_bw_sub(NULL, NULL));
    assert_int_equal(pf_bw_bottom_up(NULL), -1);
    assert_int_equal(pf_bw_top_down(NULL, x), -1);
    pf_bw_node *n = pf_bw_leaf(x);
    assert_int_equal(pf_bw_top_down(n, f), -1);
    assert_int_equal(pf_bw_top_down(n, T("fixed<3,1>")), 0);
    expect_type(&n->type, "fixed<7,7>", "a leaf root keeps its type");
    pf_bw_free(n);
    pf_bw_step st[3];
    pf_type c[3] = { x, x, x };
    assert_int_equal(pf_bw_horner(c, -1, x, x, st), -1);
    assert_int_equal(pf_bw_horner(c, 2, f, x, st), -1);
    c[1] = f;
    assert_int_equal(pf_bw_horner(c, 2, x, x, st), -1);
    /* unsigned - unsigned is signed; unsigned + unsigned is not */
    pf_type u = T("ufixed<8,4>");
    n = pf_bw_sub(pf_bw_leaf(u), pf_bw_leaf(u));
    pf_bw_bottom_up(n);
    expect_type(&n->full, "fixed<9,4>", "u - u");
    pf_bw_free(n);
    n = pf_bw_add(pf_bw_leaf(u), pf_bw_leaf(u));
    pf_bw_bottom_up(n);
    expect_type(&n->full, "unsigned fixed<9,4>", "u + u");
    /* into a signed destination it stays unsigned; into unsigned too */
    pf_bw_top_down(n, T("fixed<15,2>"));
    expect_type(&n->type, "unsigned fixed<7,2>", "u + u into fixed<15,2>");
    pf_bw_free(n);
}

/* ---- random trees ------------------------------------------------------- */

static pf_type rnd_leaf_type(int maxsize)
{
    return pf_type_fixed((int)(rnd() % 2), rnd_int(1, maxsize), rnd_int(-4, 12));
}

static pf_bw_node *rnd_tree(int depth, int maxsize, pf_bw_node **leaves, int *nleaves)
{
    if (depth == 0 || rnd() % 4 == 0) {
        pf_bw_node *l = pf_bw_leaf(rnd_leaf_type(maxsize));
        leaves[(*nleaves)++] = l;
        return l;
    }
    pf_bw_node *a = rnd_tree(depth - 1, maxsize, leaves, nleaves);
    pf_bw_node *b = rnd_tree(depth - 1, maxsize, leaves, nleaves);
    switch (rnd() % 3) {
    case 0: return pf_bw_add(a, b);
    case 1: return pf_bw_sub(a, b);
    default: return pf_bw_mul(a, b);
    }
}

/* leaf values: stored integers in leaf->type, kept in a side table */
typedef struct { pf_bw_node *leaf; int64_t v; } leafval;
static leafval lv[64];
static int nlv;

static int64_t leaf_value(const pf_bw_node *n)
{
    for (int i = 0; i < nlv; i++)
        if (lv[i].leaf == n)
            return lv[i].v;
    fail();
    return 0;
}

static void q_of(mpq_t q, int64_t v, int exp)
{
    mpq_set_si(q, v, 1);
    if (exp >= 0)
        mpq_div_2exp(q, q, (unsigned long)exp);
    else
        mpq_mul_2exp(q, q, (unsigned long)-exp);
}

/* exact value of the expression */
static void exact(mpq_t q, const pf_bw_node *n)
{
    if (n->op == PF_BW_LEAF) {
        q_of(q, leaf_value(n), n->type.exp);
        return;
    }
    mpq_t b;
    mpq_init(b);
    exact(q, n->a);
    exact(b, n->b);
    if (n->op == PF_BW_ADD)
        mpq_add(q, q, b);
    else if (n->op == PF_BW_SUB)
        mpq_sub(q, q, b);
    else
        mpq_mul(q, q, b);
    mpq_clear(b);
}

/* x is a stored value of t: integral at its lsb and within its range */
static int fits(const mpq_t x, const pf_type *t)
{
    mpq_t s;
    mpq_init(s);
    if (t->exp >= 0)
        mpq_mul_2exp(s, x, (unsigned long)t->exp);
    else
        mpq_div_2exp(s, x, (unsigned long)-t->exp);
    int ok = mpz_cmp_ui(mpq_denref(s), 1) == 0;
    if (ok) {
        mpz_t lim;
        mpz_init_set_ui(lim, 1);
        mpz_mul_2exp(lim, lim, (unsigned long)t->size);
        ok = mpz_cmp(mpq_numref(s), lim) < 0;
        if (t->is_signed)
            mpz_neg(lim, lim);
        else
            mpz_set_ui(lim, 0);
        ok = ok && mpz_cmp(mpq_numref(s), lim) >= 0;
        mpz_clear(lim);
    }
    mpq_clear(s);
    return ok;
}

static int is_min(const mpq_t x, const pf_type *t) /* x == -2^size lsb */
{
    if (!t->is_signed)
        return 0;
    mpq_t m;
    mpq_init(m);
    q_of(m, pf_type_min_stored(t), t->exp);
    int r = mpq_equal(m, x);
    mpq_clear(m);
    return r;
}

/* every internal node's exact value fits its bottom-up type, except a
 * product of two operands both at their types' minimum (documented) */
static int check_bottom_up(const pf_bw_node *n, mpq_t q)
{
    if (n->op == PF_BW_LEAF) {
        exact(q, n);
        return 1;
    }
    mpq_t a, b;
    mpq_init(a);
    mpq_init(b);
    int ok = check_bottom_up(n->a, a) & check_bottom_up(n->b, b);
    if (n->op == PF_BW_ADD)
        mpq_add(q, a, b);
    else if (n->op == PF_BW_SUB)
        mpq_sub(q, a, b);
    else
        mpq_mul(q, a, b);
    int corner = n->op == PF_BW_MUL && is_min(a, &n->a->full) && is_min(b, &n->b->full);
    if (!corner && !fits(q, &n->full)) {
        char buf[64];
        pf_type_format(&n->full, buf, sizeof buf);
        gmp_fprintf(stderr, "value %Qd does not fit bottom-up %s\n", q, buf);
        ok = 0;
    }
    mpq_clear(a);
    mpq_clear(b);
    return ok;
}

static void rnd_leaf_values(void)
{
    for (int i = 0; i < nlv; i++) {
        const pf_type *t = &lv[i].leaf->type;
        int64_t lo = pf_type_min_stored(t), hi = pf_type_max_stored(t);
        lv[i].v = rnd() % 4 == 0 ? (rnd() % 2 ? lo : hi) : lo + (int64_t)(rnd() % (uint64_t)(hi - lo + 1));
    }
}

static void test_bottom_up_holds_exact(void **state)
{
    (void)state;
    int ntrees = quick ? 300 : 3000, bad = 0;
    for (int i = 0; i < ntrees; i++) {
        pf_bw_node *leaves[64];
        nlv = 0;
        int nl = 0;
        pf_bw_node *root = rnd_tree(3, 6, leaves, &nl);
        assert_non_null(root);
        assert_int_equal(pf_bw_bottom_up(root), 0);
        for (int k = 0; k < nl; k++)
            lv[nlv++].leaf = leaves[k];
        for (int trial = 0; trial < 30; trial++) {
            rnd_leaf_values();
            mpq_t q;
            mpq_init(q);
            if (!check_bottom_up(root, q))
                bad++;
            mpq_clear(q);
        }
        pf_bw_free(root);
    }
    assert_int_equal(bad, 0);
}

/* ---- top-down: structural rules and an error bound ---------------------- */

static int ib(const pf_type *t) { return t->size - t->exp; }

static void dump(const pf_bw_node *n, int depth)
{
    char b1[64], b2[64];
    pf_type_format(&n->full, b1, sizeof b1);
    pf_type_format(&n->type, b2, sizeof b2);
    fprintf(stderr, "%*s%s  full %s  type %s\n", 2 * depth, "", n->op == PF_BW_LEAF ? "leaf" : n->op == PF_BW_ADD ? "+" : n->op == PF_BW_SUB ? "-" : "*", b1, b2);
    if (n->op != PF_BW_LEAF) {
        dump(n->a, depth + 1);
        dump(n->b, depth + 1);
    }
}

static int check_rules(const pf_bw_node *n, int is_root, const pf_type *dest)
{
    if (n->op == PF_BW_LEAF)
        return memcmp(&n->type, &n->full, sizeof n->type) == 0;
    const pf_type *t = &n->type, *f = &n->full;
    int ok = t->exp <= f->exp && t->size >= 1 && t->size <= 63;
    if (is_root)
        ok = ok && t->exp <= dest->exp && (t->size == 1 || (ib(t) <= ib(dest) && ib(t) <= ib(f))) &&
             t->is_signed == (f->is_signed && dest->is_signed);
    else
        ok = ok && (ib(t) == ib(f) || (t->size == 1 && ib(t) > ib(f))) && t->is_signed == f->is_signed;
    /* operands carry no lsb the parent cannot see */
    const pf_bw_node *a = n->a, *b = n->b;
    if (n->op == PF_BW_MUL) {
        ok = ok && (a->op == PF_BW_LEAF || a->type.exp <= t->exp + ib(&b->full));
        ok = ok && (b->op == PF_BW_LEAF || b->type.exp <= t->exp + ib(&a->full));
    } else {
        ok = ok && (a->op == PF_BW_LEAF || a->type.exp <= t->exp);
        ok = ok && (b->op == PF_BW_LEAF || b->type.exp <= t->exp);
    }
    /* and lose none it can: trimming stops at the cap or the full lsb */
    if (n->op == PF_BW_MUL) {
        ok = ok && (a->op == PF_BW_LEAF || a->type.exp == t->exp + ib(&b->full) || a->type.exp == a->full.exp);
        ok = ok && (b->op == PF_BW_LEAF || b->type.exp == t->exp + ib(&a->full) || b->type.exp == b->full.exp);
    } else {
        ok = ok && (a->op == PF_BW_LEAF || a->type.exp == t->exp || a->type.exp == a->full.exp);
        ok = ok && (b->op == PF_BW_LEAF || b->type.exp == t->exp || b->type.exp == b->full.exp);
    }
    return ok && check_rules(a, 0, dest) && check_rules(b, 0, dest);
}

/* evaluate with the trimmed types through pffixed.h; stored in n->type */
static int64_t eval(const pf_bw_node *n)
{
    if (n->op == PF_BW_LEAF)
        return leaf_value(n);
    int64_t a = eval(n->a), b = eval(n->b);
    pf_fmt fa = pf_type_to_fmt(&n->a->type), fb = pf_type_to_fmt(&n->b->type), o = pf_type_to_fmt(&n->type);
    if (n->op == PF_BW_ADD)
        return pf_fx_add(a, fa, b, fb, o);
    if (n->op == PF_BW_SUB)
        return pf_fx_sub(a, fa, b, fb, o);
    return pf_fx_mul(a, fa, b, fb, o);
}

/* error bound of eval against exact, from the trimmed lsbs: each rounding
 * (saturation at a range end included) is off by under one lsb; errors of
 * operands propagate as in (a+da)(b+db) - ab.  mag: bound on |exact|. */
static double err_bound(const pf_bw_node *n, double *mag)
{
    if (n->op == PF_BW_LEAF) {
        *mag = fmax(fabs(pf_type_max(&n->type)), fabs(pf_type_min(&n->type)));
        return 0;
    }
    double ma, mb;
    double ea = err_bound(n->a, &ma), eb = err_bound(n->b, &mb);
    double own = pf_type_lsb(&n->type), e;
    if (n->op == PF_BW_MUL) {
        e = ea * mb + eb * ma + ea * eb + own;
        *mag = ma * mb;
    } else {
        e = ea + eb + own;
        *mag = ma + mb;
    }
    return e;
}

static void test_top_down(void **state)
{
    (void)state;
    int ntrees = quick ? 300 : 3000, bad = 0, checked = 0;
    for (int i = 0; i < ntrees; i++) {
        pf_bw_node *leaves[64];
        nlv = 0;
        int nl = 0;
        pf_bw_node *root = rnd_tree(3, 10, leaves, &nl);
        pf_type dest = pf_type_fixed((int)(rnd() % 4 != 0), rnd_int(1, 24), rnd_int(-4, 16));
        assert_int_equal(pf_bw_top_down(root, dest), 0);
        if (!check_rules(root, 1, &dest)) {
            if (bad++ < 3) {
                char b[64];
                pf_type_format(&dest, b, sizeof b);
                print_error("tree %d: trimming rules violated; dest %s\n", i, b);
                dump(root, 1);
            }
        }
        for (int k = 0; k < nl; k++)
            lv[nlv++].leaf = leaves[k];
        double mag, bound = err_bound(root, &mag);
        for (int trial = 0; trial < 20; trial++) {
            rnd_leaf_values();
            mpq_t q, g, d;
            mpq_init(q), mpq_init(g), mpq_init(d);
            exact(q, root);
            int64_t v = eval(root);
            q_of(g, v, root->type.exp);
            mpq_sub(d, g, q);
            double err = fabs(mpq_get_d(d));
            /* away from the root's range ends, where saturation is intended */
            double x = mpq_get_d(q);
            if (x <= pf_type_max(&root->type) - bound && x >= pf_type_min(&root->type) + bound) {
                checked++;
                if (err > bound) {
                    print_error("tree %d: error %g > bound %g\n", i, err, bound);
                    bad++;
                }
            }
            mpq_clear(q), mpq_clear(g), mpq_clear(d);
        }
        pf_bw_free(root);
    }
    assert_int_equal(bad, 0);
    assert_true(checked > ntrees); /* most cases are in range */
}

/* ---- Horner ------------------------------------------------------------- */

/* p(x) exactly */
static void poly_exact(mpq_t q, const int64_t *c, const pf_type *ct, int n, int64_t x, const pf_type *xt)
{
    mpq_t xv, cv;
    mpq_init(xv), mpq_init(cv);
    q_of(xv, x, xt->exp);
    q_of(q, c[n], ct[n].exp);
    for (int k = n - 1; k >= 0; k--) {
        mpq_mul(q, q, xv);
        q_of(cv, c[k], ct[k].exp);
        mpq_add(q, q, cv);
    }
    mpq_clear(xv), mpq_clear(cv);
}

static int same_type(const pf_type *a, const pf_type *b) { return memcmp(a, b, sizeof *a) == 0; }

static int64_t rnd_in(int64_t lo, int64_t hi) { return lo + (int64_t)(rnd() % (uint64_t)(hi - lo + 1)); }

/* x in [-1, 1), coefficients in [-2, 1).  A code generator rounds each
 * coefficient c_k (k < n) once to p_k's lsb; analysing again with those
 * coefficient types must give the same formats (a fixpoint).  Then
 * pf_fx_horner with the steps' shifts equals the tree evaluated op by op
 * with pf_fx_mul / pf_fx_add, and the result is within n lsb of the
 * destination from the exact p(x) with the unrounded coefficients (per step
 * one rounding of c_k and one of the product, each <= 1/2 lsb, scaled by
 * |x|^k <= 1). */
static void test_horner(void **state)
{
    (void)state;
    int nt = quick ? 200 : 2000, bad = 0, nsat = 0;
    for (int i = 0; i < nt; i++) {
        int n = rnd_int(1, 8);
        pf_type ct[9], cr[9], xt = pf_type_fixed(1, rnd_int(4, 20), 0), out = pf_type_fixed(1, rnd_int(8, 28), 0);
        xt.exp = xt.size;                           /* [-1, 1) */
        out.exp = out.size - rnd_int(n + 2, n + 4); /* room for |p| <= 2(n+1) */
        for (int k = 0; k <= n; k++) {
            int s = rnd_int(3, 24);
            ct[k] = pf_type_fixed(1, s, s - 1); /* [-2, 2) */
        }
        pf_bw_step st[9], st2[9];
        assert_int_equal(pf_bw_horner(ct, n, xt, out, st), 0);
        for (int k = 0; k <= n; k++) {
            cr[k] = ct[k];
            if (k < n && ct[k].exp > st[k].p.exp) {
                int size = ct[k].size - (ct[k].exp - st[k].p.exp);
                cr[k] = pf_type_fixed(1, size < 1 ? 1 : size, st[k].p.exp);
            }
        }
        assert_int_equal(pf_bw_horner(cr, n, xt, out, st2), 0);
        /* same lsbs (a rounded coefficient of size 1 may carry an extra
         * integer bit, which can widen the sums, never move an lsb) */
        int clamped = 0;
        for (int k = 0; k < n; k++)
            clamped |= cr[k].size - cr[k].exp != ct[k].size - ct[k].exp;
        for (int k = 0; k <= n; k++)
            if (st[k].p.exp != st2[k].p.exp || (k < n && (st[k].m.exp != st2[k].m.exp || st[k].shift != st2[k].shift)) ||
                (!clamped && (!same_type(&st[k].p, &st2[k].p) || (k < n && !same_type(&st[k].m, &st2[k].m))))) {
                if (bad++ < 5)
                    print_error("horner %d: step %d changes when coefficients are rounded to it\n", i, k);
            }
        pf_fmt fx = pf_type_to_fmt(&xt), step[9];
        int8_t shift[9];
        for (int k = 0; k <= n; k++) {
            step[k] = pf_type_to_fmt(&st2[k].p);
            if (k < n) {
                assert_int_equal(st2[k].shift, st2[k + 1].p.exp + xt.exp - st2[k].p.exp);
                shift[k] = (int8_t)st2[k].shift;
            }
        }
        for (int trial = 0; trial < 20; trial++) {
            int64_t c[9], cs[9], x = rnd_in(pf_type_min_stored(&xt) + 1, pf_type_max_stored(&xt));
            for (int k = 0; k <= n; k++) {
                c[k] = rnd_in(pf_type_min_stored(&ct[k]) + 1, pf_type_max_stored(&ct[k]) / 2);
                cs[k] = pf_fx_convert(c[k], pf_type_to_fmt(&ct[k]), pf_type_to_fmt(&cr[k]));
            }
            int64_t ch[9]; /* pf_fx_horner wants c_k at p_k's lsb */
            for (int k = 0; k <= n; k++)
                ch[k] = k == n ? cs[k] : pf_fx_convert(cs[k], pf_type_to_fmt(&cr[k]), pf_fmt_make(1, 63, step[k].exp));
            int64_t h = pf_fx_horner(x, ch, shift, step, n);
            /* the tree, op by op; sat: some node saturated (the top of a
             * trimmed type rounded up, see bitwidth.h) */
            int64_t p = cs[n];
            int sat = 0;
            for (int k = n - 1; k >= 0; k--) {
                pf_fmt fm = pf_type_to_fmt(&st2[k].m), wm = pf_fmt_make(1, 63, fm.exp), wp = pf_fmt_make(1, 63, step[k].exp);
                int64_t m = pf_fx_mul(p, step[k + 1], x, fx, fm);
                sat |= m != pf_fx_mul(p, step[k + 1], x, fx, wm);
                int64_t pk = pf_fx_add(m, fm, cs[k], pf_type_to_fmt(&cr[k]), step[k]);
                sat |= pk != pf_fx_add(m, fm, cs[k], pf_type_to_fmt(&cr[k]), wp);
                p = pk;
            }
            nsat += sat;
            if (p != h && !sat && bad++ < 5)
                print_error("horner %d: helper %lld, tree %lld\n", i, (long long)h, (long long)p);
            mpq_t q, g, d;
            mpq_init(q), mpq_init(g), mpq_init(d);
            poly_exact(q, c, ct, n, x, &xt);
            q_of(g, pf_fx_convert(h, step[0], pf_type_to_fmt(&out)), out.exp);
            mpq_sub(d, g, q);
            double err = fabs(mpq_get_d(d)) / pf_type_lsb(&out);
            if (err > (sat ? 2 * n : n) && bad++ < 5)
                gmp_fprintf(stderr, "horner %d (n=%d): exact %Qd, error %g lsb\n", i, n, q, err);
            mpq_clear(q), mpq_clear(g), mpq_clear(d);
        }
    }
    print_message("horner: %d of %d evaluations saturated a node\n", nsat, 20 * nt);
    assert_int_equal(bad, 0);
    assert_true(nsat < nt); /* a corner, not the rule */
}

/* ---- Horner in 16-bit words (pf_bw_horner_word) ----------------------- */

static int64_t floor_div(int64_t a, int64_t b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }
/* round(a b / 2^15), ties up: what pmulhrsw computes */
static int64_t mulhrs(int64_t a, int64_t b) { return floor_div(a * b + 16384, 32768); }

/* Random polynomials on [0, 1] with pmax[k] = sum_{j >= k} |a_j| (a bound
 * for x in [0, 1] that owes nothing to the code under test).  Coefficients
 * rounded to their steps' lsbs, the kernel evaluated exactly as the
 * generator emits it, p = mulhrs(p, x_d) + c_k with x_d = mulhrs(x, 2^(15-d)):
 * every value stays within +-32767 (no wrap, never -32768) and the result is
 * within the analysis's err of the exact polynomial with the rounded
 * coefficients, for all 32768 x of some polynomials and random x of the
 * rest.  The formats must be non-increasing, with d_k the drop. */
static void test_horner_word(void **state)
{
    (void)state;
    int nt = quick ? 100 : 600, bad = 0, tight = 0;
    for (int i = 0; i < nt; i++) {
        int n = rnd_int(0, 7);
        double a[8], pm[8];
        for (int k = 0; k <= n; k++) {
            double mag = ldexp(1.0, -rnd_int(0, 2 * k + 1));
            a[k] = mag * ((double)(rnd() >> 11) * 0x1p-53 * 4 - 2);
        }
        for (int k = n; k >= 0; k--)
            pm[k] = fabs(a[k]) + (k < n ? pm[k + 1] : 0);
        pf_bw_wstep st[8];
        double err;
        int emax = rnd_int(10, 15);
        assert_int_equal(pf_bw_horner_word(pm, n, 16, emax, st, &err), 0);
        int64_t c[8];
        for (int k = 0; k <= n; k++) {
            assert_true(st[k].exp <= emax);
            if (k < n) {
                assert_true(st[k].exp <= st[k + 1].exp);
                assert_int_equal(st[k].xdrop, st[k + 1].exp - st[k].exp);
                assert_int_equal(st[k].kind, PF_BW_MULHRS);
            }
            c[k] = llround(ldexp(a[k], st[k].exp));
            assert_true(c[k] >= -32767 && c[k] <= 32767);
        }
        int all = i % 20 == 0, ntrial = all ? 32768 : 200;
        double worst = 0;
        mpq_t q, xv, cv, d;
        mpq_init(q), mpq_init(xv), mpq_init(cv), mpq_init(d);
        for (int t = 0; t < ntrial; t++) {
            int64_t x = all ? t : rnd_in(0, 32767), p = c[n];
            for (int k = n - 1; k >= 0; k--) {
                int64_t xd = st[k].xdrop ? mulhrs(x, (int64_t)1 << (15 - st[k].xdrop)) : x;
                p = mulhrs(p, xd) + c[k];
                if (p < -32767 || p > 32767) {
                    if (bad++ < 5)
                        print_error("word %d: p_%d = %lld leaves the word at x = %lld\n", i, k, (long long)p, (long long)x);
                    p = 0;
                }
            }
            /* exact p(x) with the rounded coefficients */
            q_of(xv, x, 15);
            q_of(q, c[n], st[n].exp);
            for (int k = n - 1; k >= 0; k--) {
                mpq_mul(q, q, xv);
                q_of(cv, c[k], st[k].exp);
                mpq_add(q, q, cv);
            }
            q_of(d, p, st[0].exp);
            mpq_sub(d, d, q);
            double e = fabs(mpq_get_d(d));
            worst = e > worst ? e : worst;
            if (e > err * (1 + 1e-12) && bad++ < 5)
                print_error("word %d (n=%d): error %g above the bound %g at x = %lld\n", i, n, e, err, (long long)x);
        }
        tight += n > 1 && worst > err / 4;
        mpq_clear(q), mpq_clear(xv), mpq_clear(cv), mpq_clear(d);
    }
    print_message("horner_word: %d of %d polynomials reach a quarter of their bound\n", tight, nt);
    assert_int_equal(bad, 0);
    assert_true(tight > 0); /* the bound is not vacuous */
    /* edges: n < 0, a bad word size */
    double pm[1] = {1};
    pf_bw_wstep st[1];
    double e;
    assert_int_equal(pf_bw_horner_word(pm, -1, 16, 15, st, &e), -1);
    assert_int_equal(pf_bw_horner_word(pm, 0, 4, 15, st, &e), -1);
    /* a constant 1 in 16 bits: lsb 2^-14 (2^15 would overflow) */
    assert_int_equal(pf_bw_horner_word(pm, 0, 16, 15, st, &e), 0);
    assert_int_equal(st[0].exp, 14);
}

int main(void)
{
    quick = getenv("PF_QUICK") != NULL;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_figure_4_8),
        cmocka_unit_test(test_api_edges),
        cmocka_unit_test(test_bottom_up_holds_exact),
        cmocka_unit_test(test_top_down),
        cmocka_unit_test(test_horner),
        cmocka_unit_test(test_horner_word),
    };
    return cmocka_run_group_tests_name("bitwidth", tests, NULL, NULL);
}
