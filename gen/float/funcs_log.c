/* Function table rows for log and log2 (see gen/float/funcs.h).
 *
 * log(x)  = k ln2 + log(m),      x = 2^k m, m in [sqrt(2)/2, sqrt(2))
 * log2(x) = k + log(m) / ln2
 * One polynomial p(t) ~ log(1+t), t = m - 1, serves both; the templates
 * (gen/templates/log_fma.c.in, log2_fma.c.in) do the reconstruction. */
#include "funcs.h"
#include "funcs_logtab.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include <stdlib.h>

/* ---- fit targets, in the fit variable t ---- */
static void g_log1p(mpfr_t y, const mpfr_t t, const void *c)
{
    (void)c;
    mpfr_log1p(y, t, MPFR_RNDN);
}

/* log2(1+t): the float table rows' target (p(r) = r q(r), C[1] ~ 1/ln2) */
static void g_log2_1p(mpfr_t y, const mpfr_t t, const void *c)
{
    (void)c;
    mpfr_t l;
    mpfr_init2(l, mpfr_get_prec(y) + 64);
    mpfr_log1p(y, t, MPFR_RNDN);
    mpfr_const_log2(l, MPFR_RNDN);
    mpfr_div(y, y, l, MPFR_RNDN);
    mpfr_clear(l);
}

/* log2(1+t) - t/ln2: the remainder log2's split scheme fits (r^2 q(r)) */
static void g_log2rem(mpfr_t y, const mpfr_t t, const void *c)
{
    (void)c;
    mpfr_t a, l;
    mpfr_inits2(mpfr_get_prec(y) + 64, a, l, (mpfr_ptr)0);
    mpfr_log1p(a, t, MPFR_RNDN);
    mpfr_sub(a, a, t, MPFR_RNDN);
    mpfr_const_log2(l, MPFR_RNDN);
    mpfr_div(y, a, l, MPFR_RNDN);
    mpfr_clears(a, l, (mpfr_ptr)0);
}

/* m ranges of the reductions, as the templates compute them */
#define BAL_LO (0x1.6a09e6p-1 - 1) /* float just below sqrt(2)/2, minus 1 */
#define BAL_HI (0x1.6a09e6p+0 - 1)

/* ---- constants of the reconstruction, computed with MPFR when generating ---- */
static double mp_round(mpfr_t v, int bits)
{
    mpfr_t w;
    mpfr_init2(w, bits);
    mpfr_set(w, v, MPFR_RNDN);
    double d = mpfr_get_d(w, MPFR_RNDN);
    mpfr_clear(w);
    return d;
}

/* ln2 = LN2HI + LN2LO, LN2HI of 16 bits so k LN2HI is exact for |k| < 2^8;
   LN2 is ln2 rounded to float (the fast variant's one fmaf) */
static int extra_log(char *buf, size_t n)
{
    mpfr_t ln2, lo;
    mpfr_inits2(256, ln2, lo, (mpfr_ptr)0);
    mpfr_const_log2(ln2, MPFR_RNDN);
    double hi = mp_round(ln2, 16);
    mpfr_sub_d(lo, ln2, hi, MPFR_RNDN); /* exact at 256 bits */
    int len = snprintf(buf, n,
                       "/* Reconstruction constants, computed with MPFR by pfmathgen: ln2 = LN2HI + LN2LO\n"
                       "   with LN2HI of 16 significant bits, so k * LN2HI is exact for |k| < 2^8, and\n"
                       "   LN2LO the rest rounded to float; LN2 is ln2 rounded to float. */\n"
                       "static const float PF_LOG_LN2HI PF_UNUSED = %af;\n"
                       "static const float PF_LOG_LN2LO PF_UNUSED = %af;\n"
                       "static const float PF_LOG_LN2 PF_UNUSED = %af;\n\n",
                       hi, mp_round(lo, 24), mp_round(ln2, 24));
    mpfr_clears(ln2, lo, (mpfr_ptr)0);
    return len;
}

/* 1/ln2 = LH + LL, LH 1/ln2 rounded to float */
static int extra_log2(char *buf, size_t n)
{
    mpfr_t inv, lo;
    mpfr_inits2(256, inv, lo, (mpfr_ptr)0);
    mpfr_const_log2(inv, MPFR_RNDN);
    mpfr_ui_div(inv, 1, inv, MPFR_RNDN);
    double hi = mp_round(inv, 24);
    mpfr_sub_d(lo, inv, hi, MPFR_RNDN);
    int len = snprintf(buf, n,
                       "/* Reconstruction constants, computed with MPFR by pfmathgen: 1/ln2 = LH + LL,\n"
                       "   LH 1/ln2 rounded to float and LL the rest rounded to float. */\n"
                       "static const float PF_LOG2_LH PF_UNUSED = %af;\n"
                       "static const float PF_LOG2_LL PF_UNUSED = %af;\n\n",
                       hi, mp_round(lo, 24));
    mpfr_clears(inv, lo, (mpfr_ptr)0);
    return len;
}

/* ---- the error model of the exact variants (gen/float/funcs.h: pf_spec.model) ----
 * For every k the input can give (-149 .. 128) and r on a grid of the
 * domain, a bound on the emitted function's error in ULP of the float
 * result f = k ln2 + log(1+r) (log) or k + log2(1+r) (log2):
 *   q(r) by fmaf Horner: half an ulp of each step's float, carried through;
 *   every other float operation of the template's compensated branch: half
 *   an ulp of its result; the two-sums are exact;
 *   the fit's relative error times |log(1+r)|, and the constants' splits;
 *   plus the last addition's own rounding, half an ULP. */
static double ulp_of(double v)
{
    v = fabs(v);
    return v < 0x1p-126 ? 0x1p-149 : ldexp(1.0, ilogb(v) - 23);
}
#define H(v) (0.5 * ulp_of(v))

/* q(r) = c2 + c3 r + ... and a bound on its evaluation error, following
   the steps of the template's evaluation: plain fmaf Horner (estrin = 0,
   log), or exp_log_poly.h.in's split (log2): Horner for c2, c3, c4 and Estrin's
   scheme for the rest on r and r2 = r*r rounded.  Each fmaf(a, b, c) with
   errors ea, eb, ec adds |a| eb + |b| ea + ea eb + ec and half an ulp of its
   result; r is exact. */
static void model_q(const fit_poly *p, int order, double r, int estrin, double *qv, double *qe)
{
    int n = order - 1; /* coefficients c2 .. c_order */
    const fit_real *c = p->c + 2;
    if (!estrin || n <= 4 || n > 35) {
        double q = (double)c[n - 1], eq = 0;
        for (int j = n - 2; j >= 0; j--) {
            q = q * r + (double)c[j];
            eq = eq * fabs(r) + H(fabs(q) + eq);
        }
        *qv = q, *qe = eq;
        return;
    }
    double pv[16], pe[16];
    int m = n - 3;
    for (int i = 0; 2 * i < m; i++) {
        if (2 * i + 1 < m) {
            pv[i] = (double)c[3 + 2 * i + 1] * r + (double)c[3 + 2 * i];
            pe[i] = H(pv[i]);
        } else {
            pv[i] = (double)c[3 + 2 * i], pe[i] = 0;
        }
    }
    double w = r * r, ew = H(w);
    int cnt = (m + 1) / 2;
    while (cnt > 1) {
        for (int i = 0; 2 * i < cnt; i++) {
            if (2 * i + 1 < cnt) {
                double a = pv[2 * i + 1], ea = pe[2 * i + 1];
                double v = a * w + pv[2 * i];
                pe[i] = fabs(a) * ew + fabs(w) * ea + ea * ew + pe[2 * i] + H(fabs(v) + fabs(a) * ew + fabs(w) * ea);
                pv[i] = v;
            } else {
                pv[i] = pv[2 * i], pe[i] = pe[2 * i];
            }
        }
        cnt = (cnt + 1) / 2;
        double w2 = w * w;
        ew = 2 * fabs(w) * ew + ew * ew + H(w2);
        w = w2;
    }
    double q = pv[0], eq = pe[0];
    for (int j = 2; j >= 0; j--) {
        q = q * r + (double)c[j];
        eq = eq * fabs(r) + H(fabs(q) + eq);
    }
    *qv = q, *qe = eq;
}

static int model_log_common(const fit_poly *p, int order, pf_scheme *sc, int is_log2)
{
    if (order < 3 || p->c[0] != 0 || p->c[1] != 1) {
        snprintf(sc->text, sizeof sc->text, "error model: needs p(0) = 0, p'(0) = 1 and order >= 3");
        return -1;
    }
    const double L = 1 / M_LN2;
    double worst = 0, worst_r = 0;
    int worst_k = 0;
    const int n = 4096;
    for (int i = 0; i <= n; i++) {
        double r = BAL_LO + (BAL_HI - BAL_LO) * i / n;
        double q, eq;
        model_q(p, order, r, is_log2, &q, &eq);
        double r2 = r * r, g = log1p(r);
        double et = r2 * eq + fabs(q) * H(r2); /* r^2 q(r), before its own rounding */
        for (int k = -149; k <= 128; k++) {
            double f, e;
            /* at k = 0 the two-sum gives lo = 0, and the addition of lo is exact */
            if (!is_log2) {
                double w = k * (M_LN2 - 0x1.62e4p-1); /* k LN2LO (LN2HI: ln2 to 16 bits) */
                double lo = H(k * M_LN2 + r); /* |lo| <= half an ulp of hi */
                double u = r2 * q + w;
                /* fmaf(k, LN2LO, lo) rounds once; LN2LO is rounded to float: |k| 2^-41 */
                e = et + (k ? H(fabs(w) + lo) : 0) + abs(k) * 0x1p-41 + H(u) + p->max_err * fabs(g);
                f = k * M_LN2 + g;
            } else {
                /* |a_lo| <= half an ulp of r LH, |lo| half an ulp of hi, |r LL| < 2^-25 |r|;
                   v + v_lo0 = r2 LH exactly, then r2_lo LH is added (|r2_lo| <= 2^-24 r^2)
                   and v_lo rounded; i = fmaf(q, v_lo, w1), s = fmaf(q, v, i) */
                double alo = H(r * L), lo = k ? H(k + r * L) : 0, v = r2 * L;
                double vlo = H(v) + 0x1p-24 * r2 * L, w0 = alo + lo;
                double w1 = fabs(r) * 0x1p-25 + w0, i = w1 + fabs(q) * vlo, s = v * fabs(q) + i;
                e = r2 * eq * L + fabs(q) * H(vlo) + H(w0) + H(w1) + H(i) + H(s) + fabs(r) * 0x1p-48 +
                    r2 * fabs(q) * 0x1p-25 + p->max_err * fabs(g) * L;
                f = k + g * L;
            }
            if (f == 0)
                continue; /* x = 1: r = 0, k = 0, every term is exactly 0 */
            double bnd = 0.5 + e / ulp_of(f);
            if (bnd > worst)
                worst = bnd, worst_r = r, worst_k = k;
        }
    }
    sc->ncomp = 1;
    sc->bound_ulp = worst;
    snprintf(sc->text, sizeof sc->text,
             "q(r) = (p(r) - r)/r^2 in float with fmaf; %s, "
             "the small rest summed in float, one rounding into the result (the model's worst "
             "point is k = %d, r = %.4f)",
             is_log2 ? "k + r LH exact (two-sum), r^2 LH = v + v_lo exact but for v_lo's rounding "
                       "(two products, independent of q), q(r) by Horner for c2..c4 and Estrin's "
                       "scheme above"
                     : "q(r) by Horner; k LN2HI + r exact (two-sum)",
             worst_k, worst_r);
    /* A bound above 1 ULP is stated, not refused: --order or --target may ask
       for less than the library's exact variant (whose default order the
       tests check is within 1 ULP by this model). */
    if (worst > 1.0) {
        size_t len = strlen(sc->text);
        snprintf(sc->text + len, sizeof sc->text - len, "; above 1 ULP at this order");
    }
    return 0;
}

static int model_log(const fit_poly *p, int order, pf_scheme *sc) { return model_log_common(p, order, sc, 0); }
static int model_log2(const fit_poly *p, int order, pf_scheme *sc) { return model_log_common(p, order, sc, 1); }

/* ---- the double-evaluation scheme (gen/templates/log_dbl.c.in) ----
 * y = p(r) PS + k KS in double, one rounding to float.  PS and KS are
 * 1/ln2 and 1 (log2) or 1 and ln2 (log), rounded to double by MPFR. */
static int extra_logd_common(char *buf, size_t n, int is_log2)
{
    mpfr_t ln2, v;
    mpfr_inits2(256, ln2, v, (mpfr_ptr)0);
    mpfr_const_log2(ln2, MPFR_RNDN);
    mpfr_ui_div(v, 1, ln2, MPFR_RNDN);
    double ks = is_log2 ? 1.0 : mpfr_get_d(ln2, MPFR_RNDN), ps = is_log2 ? mpfr_get_d(v, MPFR_RNDN) : 1.0;
    int len = snprintf(buf, n,
                       "/* Reconstruction constants, computed with MPFR by pfmathgen: y = p(r) PS + k KS,\n"
                       "   %s rounded to double. */\n"
                       "static const double PF_LOGD_KS PF_UNUSED = %a;\n"
                       "static const double PF_LOGD_PS PF_UNUSED = %a;\n\n",
                       is_log2 ? "PS = 1/ln2" : "KS = ln2", ks, ps);
    mpfr_clears(ln2, v, (mpfr_ptr)0);
    return len;
}
static int extra_logd(char *buf, size_t n) { return extra_logd_common(buf, n, 0); }
static int extra_log2d(char *buf, size_t n) { return extra_logd_common(buf, n, 1); }

/* Its error model, in ULP of the float result f (log: k ln2 + log(1+r);
 * log2: k + log2(1+r)): Horner in double with fma, each step half an ulp
 * (double) of its result carried through; kd KS and the last fma half an
 * ulp (double) each, KS and PS's own rounding 2^-53 relative; the fit's
 * relative error times |log(1+r)| PS; then the rounding to float, half an
 * ULP.  The double roundings sum to below 2^-50 |f|; the fit's error is
 * what the order buys. */
static double ulp_d(double v)
{
    v = fabs(v);
    return v < 0x1p-1022 ? 0x1p-1074 : ldexp(1.0, ilogb(v) - 52);
}

static int model_logd_common(const fit_poly *p, int order, pf_scheme *sc, int is_log2)
{
    if (order < 2 || p->c[0] != 0) {
        snprintf(sc->text, sizeof sc->text, "error model: needs p(0) = 0 and order >= 2");
        return -1;
    }
    const double KS = is_log2 ? 1 : M_LN2, PS = is_log2 ? 1 / M_LN2 : 1;
    double worst = 0, worst_r = 0;
    int worst_k = 0;
    const int n = 4096;
    for (int i = 0; i <= n; i++) {
        double r = BAL_LO + (BAL_HI - BAL_LO) * i / n;
        double q = (double)p->c[order], eq = 0;
        for (int j = order - 1; j >= 0; j--) {
            q = q * r + (double)p->c[j];
            eq = eq * fabs(r) + 0.5 * ulp_d(fabs(q) + eq);
        }
        double g = log1p(r);
        for (int k = -149; k <= 128; k++) {
            double f = k * KS + g * PS;
            if (f == 0)
                continue; /* x = 1: r = 0, k = 0, every term is exactly 0 */
            double e = (eq + p->max_err * fabs(g)) * PS + fabs(q) * PS * 0x1p-53 + abs(k) * KS * 0x1p-52 +
                       0.5 * ulp_d(fabs(f)) * 2;
            double bnd = 0.5 + e / ulp_of(f);
            if (bnd > worst)
                worst = bnd, worst_r = r, worst_k = k;
        }
    }
    sc->ncomp = 0;
    sc->bound_ulp = worst;
    snprintf(sc->text, sizeof sc->text,
             "r = m - 1 exact in float; p(r) by Horner in double with fma, y = %s by one fma in "
             "double, one rounding to float (the model's worst point is k = %d, r = %.4f)",
             is_log2 ? "p(r)/ln2 + k" : "p(r) + k ln2", worst_k, worst_r);
    return 0;
}
static int model_logd(const fit_poly *p, int order, pf_scheme *sc) { return model_logd_common(p, order, sc, 0); }
static int model_log2d(const fit_poly *p, int order, pf_scheme *sc) { return model_logd_common(p, order, sc, 1); }

/* ---- the split scheme of log2 (gen/templates/log2_split.c.in) ----
 * (ncomp = 0, the ladder's mid row: see model_log2m.)
 * p(r) = r^2 q(r) fits log2(1+r) - r/ln2; the result is
 * hi + fmaf(r2, q, w), w = fmaf(r, LL, a_lo + lo) (+ fmaf(r2_lo, q, .) when
 * compensated), hi + lo = k + a and a + a_lo = r LH exactly.  Per k and r on
 * a grid: q by Horner (half an ulp a step, carried through); r2's rounding
 * (or none: r2 + r2_lo = r^2, then r2_lo q's fmaf rounds); a_lo + lo, the two
 * fmaf and LH + LL's distance to 1/ln2 (below 2^-49 r); the fit's relative
 * error times |log2(1+r) - r/ln2|; the last addition half an ULP.  ncomp = 1
 * without r2_lo, 2 with it: the cheaper one within 1 ULP. */
static double model_log2s_at(const fit_poly *p, int order, int ncomp, double *wr, int *wk)
{
    const double L = 1 / M_LN2;
    double worst = 0;
    const int n = 4096;
    for (int i = 0; i <= n; i++) {
        double r = BAL_LO + (BAL_HI - BAL_LO) * i / n;
        double q = (double)p->c[order], eq = 0;
        for (int j = order - 1; j >= 2; j--) {
            q = q * r + (double)p->c[j];
            eq = eq * fabs(r) + H(fabs(q) + eq);
        }
        double r2 = r * r, er2 = ncomp > 1 ? 0 : H(r2), rem = (log1p(r) - r) * L;
        for (int k = -149; k <= 128; k++) {
            double f = k + log1p(r) * L;
            if (f == 0)
                continue; /* x = 1: r = 0, k = 0, every term is exactly 0 */
            if (ncomp == 0) {
                /* u = fmaf(r2, q, r LL), t = fmaf(r, LH, u) (at k = 0 the result's own
                   rounding), then k + t */
                double v = fabs(r) * 0x1p-25, uv = r2 * fabs(q) + v, tv = fabs(log1p(r) * L);
                double e = H(v) + fabs(r) * 0x1p-49 + r2 * eq + fabs(q) * er2 + eq * er2 + H(uv) +
                           (k ? H(tv + H(uv)) : 0) + p->max_err * fabs(rem) + fabs((double)p->c[1] * r);
                double bnd = 0.5 + e / ulp_of(f);
                if (bnd > worst)
                    worst = bnd, *wr = r, *wk = k;
                continue;
            }
            double alo = H(r * L), lo = k ? H(k + r * L) : 0, w0 = alo + lo;
            double w = fabs(r) * 0x1p-25 + w0, ew = H(w0) + H(w) + fabs(r) * 0x1p-49;
            if (ncomp > 1) {
                w += H(r2) * fabs(q);
                ew += H(w);
            }
            double sv = r2 * fabs(q) + w;
            double e = ew + r2 * eq + fabs(q) * er2 + eq * er2 + H(sv) + p->max_err * fabs(rem) +
                       fabs((double)p->c[1] * r);
            double bnd = 0.5 + e / ulp_of(f);
            if (bnd > worst)
                worst = bnd, *wr = r, *wk = k;
        }
    }
    return worst;
}

/* the ladder's mid row: nothing compensated (ncomp = 0) */
static int model_log2m(const fit_poly *p, int order, pf_scheme *sc)
{
    if (order < 3 || p->c[0] != 0) {
        snprintf(sc->text, sizeof sc->text, "error model: needs p(0) = 0 and order >= 3");
        return -1;
    }
    double wr = 0;
    int wk = 0;
    sc->ncomp = 0;
    sc->bound_ulp = model_log2s_at(p, order, 0, &wr, &wk);
    snprintf(sc->text, sizeof sc->text,
             "r^2 q(r) fits log2(1+r) - r/ln2, q(r) by Horner in float with fmaf; t = fmaf(r, LH, fmaf(r^2, q, "
             "r LL)) with r^2 rounded, then k + t, nothing compensated (the model's worst point is k = %d, "
             "r = %.4f)",
             wk, wr);
    return 0;
}

#define LOG_CON_ZERO {FIT_CON_VALUE, 0, "p(0) = 0"}
#define LOG_CON_SLOPE(s) {FIT_CON_DERIV, 0, s}
#define BAL_TEXT "x = 2^k m, m in [0x1.6a09e6p-1, 0x1.6a09e6p+0) (balanced about 1), t = m - 1"
/* the table-driven rows (gen/float/funcs_logtab.c, gen/templates/log_tab.c.in).
   Their ladder cost is measured, not the double rule's 4 a term + 12: in one
   run (pfbench, AVX-512, 21:39 UTC) the arrays at order 5 took 0.67 ns an
   element against 0.57-0.60 for the mid-double rows at order 10-11 (cost
   56-60): double lanes plus the conversions and vpermt2pd; so 2 a term + 53
   (65 at order 5) keeps the ladder on the rows that are faster in the
   arrays.  The scalar form is where they gain (latency 11.8 ns against
   16.1-16.4 for the exact rows, the same run). */
#define TAB_COST 53
/* the float-lane table rows (gen/float/funcs_logtabf.c, log_tabf.c.in):
   nothing compensated, three table lookups.  Measured (pfbench with a
   sampled ladder, 22:07 UTC, one run) at order 4 against the fast rows the
   ladder picks for log2's L3 and L4 (order 10 and 9): AVX-512 0.21 ns an
   element against 0.23 and 0.22 (vpermps, one a table), but AVX2 0.40
   against 0.30 and 0.28 (two vpermps and a blend a table), and log's L4
   0.20 against 0.215 (AVX-512) but 0.40 against 0.275 (AVX2).  The ladder's
   cost is one figure for every ISA, so 2 a term + 14 (24 at order 4) keeps
   the fast rows there; the rows stay for --max-ulp between them. */
#define TABF_COST 14
/* the compensated float-lane table rows (variant "tabc", the same template
   with @NCOMP@ = 1; the model's compensated step adds COMP_COST 8).
   Measured (pfbench --ladder with sampled levels, one run, 2026-11-26) at
   order 5 (log model 0.564, log2 0.548 ULP): log AVX-512 0.30 ns an element
   against 0.273 for the exact row (cost 30) and 0.61 for mid-double at
   order 11 (cost 60); AVX2 0.551 against 0.352 and 0.831.  2 a term + 20
   (40 at order 5) sits between them, as the timings do: the exact row keeps
   the 1-ULP level, tabc takes the levels below the exact row's 0.76 ULP
   down to its own floor. */
#define TABC_COST 20
/* the lean log2 row (variant "tabl", gen/templates/log_tabl.c.in): two
   tables, no low parts, one rounding into the result; 14 vector operations
   a step on AVX-512 against tabf's 18.  Measured (pfbench --ladder with
   sampled levels, 2026-11-26, two runs) at order 4 (model 1.68 ULP,
   measured 1.36): AVX-512 0.178 ns an element against 0.252 (mid, order
   10: L2), 0.234 and 0.214 (fast, order 10 and 9: L3, L4) and 0.185 for
   fast at order 7 (L128, 58 ULP); libmvec 0.19, SLEEF u35 0.21.  AVX2
   0.267 against 0.335, 0.316 and 0.273, but 0.225 for fast order 7 (three
   interleaved runs against a ladder without tabl: AVX-512 0.176-0.196
   against 0.252-0.262, 0.235-0.238 and 0.216-0.217; AVX2 0.267-0.303
   against 0.337-0.344, 0.307-0.326 and 0.277-0.278).  So
   2 a term + 8 (18 at order 4): below fast order 9 (20), above fast order 7
   (16), where AVX2 would lose. */
#define TABL_COST 8
/* log's (k on its own and one more fmaf for ln2's low part: 16 operations
   a step on AVX-512; model 2.634 ULP at order 4, 2.167 at 5): measured
   (pfbench, three interleaved runs, 2026-11-26) at order 4 against the fast
   row at order 9 that log's L4 takes: AVX-512 0.192 against 0.216, but AVX2
   0.286 against 0.279.  2 a term + 10 (20 at order 4) ties it with fast
   order 9, and ties go to the fast row: L4 keeps it; tabl is left for the
   levels between its bound and fast order 9's (about 2.7-3.9 ULP). */
#define TABL_LOG_COST 10
#define TAB_TEXT                                                                                   \
    "x = 2^k z, z in [0x1.66p-1, 0x1.66p+0) by its bits from OFF, 16 subintervals by the next 4 bits, " \
    "t = r = z INVC[i] - 1 (the table below)"
#define FAST_CON                                                                                   \
    {LOG_CON_ZERO, LOG_CON_SLOPE("p'(0) = 1"), {FIT_CON_VALUE, BAL_LO, "p(a) = log(1+a)"},         \
     {FIT_CON_DERIV, BAL_LO, "p'(a) = 1/(1+a)"}, {FIT_CON_VALUE, BAL_HI, "p(b) = log(1+b)"},      \
     {FIT_CON_DERIV, BAL_HI, "p'(b) = 1/(1+b)"}}

/* log2's fast row fits log2(1+t) itself (C[1] ~ 1/ln2, gen/templates/log2_fast.c.in:
   y = fmaf(r, q(r), k), one fmaf a lane fewer than p(r)/ln2 with p ~ log(1+t)) */
#define FAST2_CON                                                                                  \
    {LOG_CON_ZERO, LOG_CON_SLOPE("p'(0) = 1/ln2"), {FIT_CON_VALUE, BAL_LO, "p(a) = log2(1+a)"},    \
     {FIT_CON_DERIV, BAL_LO, "p'(a) = 1/((1+a) ln2)"}, {FIT_CON_VALUE, BAL_HI, "p(b) = log2(1+b)"}, \
     {FIT_CON_DERIV, BAL_HI, "p'(b) = 1/((1+b) ln2)"}}

const pf_spec pf_specs_log[] = {
    {"log", "balanced", "tab", "log_tab", 1, TAB_TEXT, "log(1+t)", g_log1p, -PF_LOGTAB_R, PF_LOGTAB_R,
     FIT_PARITY_NONE, FIT_REL, 2, {LOG_CON_ZERO, LOG_CON_SLOPE("p'(0) = 1")}, 5, 0, "double",
     NULL, 1.0, NULL, pf_extra_logtab, pf_model_logtab, NULL, "log_tab_tail.c", TAB_COST},
    {"log", "balanced", "exact", "log_fma", 1, BAL_TEXT, "log(1+t)", g_log1p, BAL_LO, BAL_HI,
     FIT_PARITY_NONE, FIT_REL, 2, {LOG_CON_ZERO, LOG_CON_SLOPE("p'(0) = 1")}, 10, 0, "fma",
     NULL, 1.0, NULL, extra_log, model_log, NULL, "exp_log_twopath.c", 0},
    {"log", "balanced", "mid-double", "log_dbl", 1, BAL_TEXT, "log(1+t)", g_log1p, BAL_LO, BAL_HI,
     FIT_PARITY_NONE, FIT_REL, 2, {LOG_CON_ZERO, LOG_CON_SLOPE("p'(0) = 1")}, 10, 0, "double",
     NULL, 1.0, NULL, extra_logd, model_logd, NULL, "exp_log_twopath.c", 0},
    {"log", "balanced", "tabf", "log_tabf", 1, TAB_TEXT, "log(1+t)", g_log1p, -PF_LOGTAB_R, PF_LOGTAB_R,
     FIT_PARITY_NONE, FIT_REL, 2, {LOG_CON_ZERO, LOG_CON_SLOPE("p'(0) = 1")}, 4, 0, "fma",
     NULL, 0, NULL, pf_extra_logtabf, pf_model_logtabf, NULL, "log_tabf_tail.c", TABF_COST},
    {"log", "balanced", "tabc", "log_tabf", 1, TAB_TEXT, "log(1+t)", g_log1p, -PF_LOGTAB_R, PF_LOGTAB_R,
     FIT_PARITY_NONE, FIT_REL, 2, {LOG_CON_ZERO, LOG_CON_SLOPE("p'(0) = 1")}, 5, 0, "fma",
     NULL, 0, NULL, pf_extra_logtabf, pf_model_logtabc, NULL, "log_tabf_tail.c", TABC_COST},
    {"log", "balanced", "tabl", "log_tabl", 1, TAB_TEXT, "log(1+t)", g_log1p, -PF_LOGTL_R, PF_LOGTL_R,
     FIT_PARITY_NONE, FIT_REL, 1, {LOG_CON_ZERO}, 4, 0, "fma",
     NULL, 0, NULL, pf_extra_logtabl, pf_model_logtabl, NULL, "log_tabl_tail.c", TABL_LOG_COST},
    {"log", "balanced", "fast", "log_fma", 1, BAL_TEXT, "log(1+t)", g_log1p, BAL_LO, BAL_HI,
     FIT_PARITY_NONE, FIT_REL, 6, FAST_CON, 0, 0x1p-10, "fma", NULL, 0, NULL, extra_log, NULL, NULL, "exp_log_twopath.c", 0},
    {"log", "seed", "exact", "log_seed", 1,
     "x = 2^k m, m in [1, 2) (the seed's reduction), t = m - 1",
     "log(1+t)", g_log1p, 0, 1, FIT_PARITY_NONE, FIT_REL, 2,
     {LOG_CON_ZERO, LOG_CON_SLOPE("p'(0) = 1")}, 10, 0, "double",
     "0x1.62e42fefa39efp-1", 0, NULL, NULL, NULL, NULL, NULL, 0},
    {"log", "seed", "fast", "log_seed", 1,
     "x = 2^k m, m in [1, 2) (the seed's reduction), t = m - 1",
     "log(1+t)", g_log1p, 0, 1, FIT_PARITY_NONE, FIT_REL, 4,
     {LOG_CON_ZERO, LOG_CON_SLOPE("p'(0) = 1"),
      {FIT_CON_VALUE, 1, "p(1) = log 2"}, {FIT_CON_DERIV, 1, "p'(1) = 1/2"}},
     0, 0x1p-10, "float", "0x1.62e42fefa39efp-1", 0, NULL, NULL, NULL, NULL, NULL, 0},
    {"log2", "balanced", "tab", "log_tab", 1, TAB_TEXT, "log2(1+t) - t/ln2", g_log2rem, -PF_LOGTAB_R, PF_LOGTAB_R,
     FIT_PARITY_NONE, FIT_REL, 2, {LOG_CON_ZERO, LOG_CON_SLOPE("p'(0) = 0")}, 5, 0, "double",
     NULL, 1.0, NULL, pf_extra_log2tab, pf_model_log2tab, NULL, "log_tab_tail.c", TAB_COST},
    {"log2", "balanced", "exact", "log2_fma", 1, BAL_TEXT, "log(1+t)", g_log1p, BAL_LO, BAL_HI,
     FIT_PARITY_NONE, FIT_REL, 2, {LOG_CON_ZERO, LOG_CON_SLOPE("p'(0) = 1")}, 10, 0, "fma",
     NULL, 1.0, NULL, extra_log2, model_log2, "exp_log_poly.h", "exp_log_twopath.c", 0},
    {"log2", "balanced", "mid", "log2_split", 1, BAL_TEXT, "log2(1+t) - t/ln2", g_log2rem, BAL_LO, BAL_HI,
     FIT_PARITY_NONE, FIT_REL, 2, {LOG_CON_ZERO, LOG_CON_SLOPE("p'(0) = 0")}, 10, 0, "fma",
     NULL, 0, NULL, extra_log2, model_log2m, NULL, "exp_log_twopath.c", 4},
    {"log2", "balanced", "mid-double", "log_dbl", 1, BAL_TEXT, "log(1+t)", g_log1p, BAL_LO, BAL_HI,
     FIT_PARITY_NONE, FIT_REL, 2, {LOG_CON_ZERO, LOG_CON_SLOPE("p'(0) = 1")}, 10, 0, "double",
     NULL, 1.0, NULL, extra_log2d, model_log2d, NULL, "exp_log_twopath.c", 0},
    {"log2", "balanced", "tabf", "log_tabf", 1, TAB_TEXT, "log2(1+t)", g_log2_1p, -PF_LOGTAB_R, PF_LOGTAB_R,
     FIT_PARITY_NONE, FIT_REL, 1, {LOG_CON_ZERO}, 4, 0, "fma",
     NULL, 0, NULL, pf_extra_log2tabf, pf_model_log2tabf, NULL, "log_tabf_tail.c", TABF_COST},
    {"log2", "balanced", "tabc", "log_tabf", 1, TAB_TEXT, "log2(1+t) - t/ln2", g_log2rem, -PF_LOGTAB_R, PF_LOGTAB_R,
     FIT_PARITY_NONE, FIT_REL, 2, {LOG_CON_ZERO, LOG_CON_SLOPE("p'(0) = 0")}, 5, 0, "fma",
     NULL, 0, NULL, pf_extra_log2tabf, pf_model_log2tabc, NULL, "log_tabf_tail.c", TABC_COST},
    {"log2", "balanced", "tabl", "log_tabl", 1, TAB_TEXT, "log2(1+t)", g_log2_1p, -PF_LOGTL_R, PF_LOGTL_R,
     FIT_PARITY_NONE, FIT_REL, 1, {LOG_CON_ZERO}, 4, 0, "fma",
     NULL, 0, NULL, pf_extra_log2tabl, pf_model_log2tabl, NULL, "log_tabl_tail.c", TABL_COST},
    {"log2", "balanced", "fast", "log2_fast", 1, BAL_TEXT, "log2(1+t)", g_log2_1p, BAL_LO, BAL_HI,
     FIT_PARITY_NONE, FIT_REL, 6, FAST2_CON, 0, 0x1p-10, "fma", NULL, 0, NULL, NULL, NULL, NULL, "exp_log_twopath.c", 0},
    {0},
};
