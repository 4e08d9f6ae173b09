/* The table-driven reduction of log and log2 in float lanes
 * (gen/templates/log_tabf.c.in): the same subintervals as the double rows
 * (gen/float/funcs_logtab.c: OFF, 16 subintervals), tables of floats that
 * fit one AVX-512 register each, nothing compensated; a ladder row for the
 * levels above 1 ULP.  The rows are in gen/float/funcs_log.c.
 *
 * r = fmaf(z, INVC[i], -1) (one rounding), y = T + fmaf(r, q(r), LL) with
 * T = k KHI + LHI[i] exact (LHI on a grid of 2^-15 (log2) or 2^-16 (log),
 * KHI = 1 or ln2 to 16 bits) and LL = k KLO + LLO[i] the small rest. */
#include "funcs_logtab.h"

#include <math.h>
#include <mpfr.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define NT 16

/* INVC in float: 2/(zl + zh) rounded to float (MPFR), 1 on the subinterval
   holding 1 (r = z - 1 exact there, and x = 1 gives 0) */
static float invcf_of(uint32_t off, int i)
{
    double zl, zh;
    pf_logtab_sub_range(off, i, &zl, &zh);
    if (zl <= 1 && 1 <= zh)
        return 1.0f;
    mpfr_t v;
    mpfr_init2(v, 24);
    mpfr_set_d(v, zl + zh, MPFR_RNDN); /* exact: two floats of nearby binades */
    mpfr_ui_div(v, 2, v, MPFR_RNDN);
    float c = mpfr_get_flt(v, MPFR_RNDN);
    mpfr_clear(v);
    return c;
}

static void rf_range(uint32_t off, int i, double *ra, double *rb)
{
    double zl, zh, c = invcf_of(off, i);
    pf_logtab_sub_range(off, i, &zl, &zh);
    *ra = zl * c - 1;
    *rb = zh * c - 1;
}

/* -log_b(c) (exact c) split into LHI on the grid 2^-g and LLO rounded to float */
static void logc_split(float c, int is_log2, double *hi, float *lo, double *full)
{
    mpfr_t v, h;
    mpfr_inits2(256, v, h, (mpfr_ptr)0);
    mpfr_set_flt(v, c, MPFR_RNDN);
    if (is_log2)
        mpfr_log2(v, v, MPFR_RNDN);
    else
        mpfr_log(v, v, MPFR_RNDN);
    mpfr_neg(v, v, MPFR_RNDN);
    int g = is_log2 ? 15 : 16;
    mpfr_mul_2si(h, v, g, MPFR_RNDN);
    mpfr_rint(h, h, MPFR_RNDN);
    mpfr_mul_2si(h, h, -g, MPFR_RNDN);
    *hi = mpfr_get_d(h, MPFR_RNDN) + 0.0; /* exact: a multiple of 2^-g below 1/2; +0 at c = 1 */
    *full = mpfr_get_d(v, MPFR_RNDN);
    mpfr_sub(v, v, h, MPFR_RNDN);
    *lo = mpfr_get_flt(v, MPFR_RNDN) + 0.0f;
    mpfr_clears(v, h, (mpfr_ptr)0);
}

/* ln2 = KHI + KLO: KHI ln2 to 16 significant bits (k KHI exact for |k| < 2^8),
   KLO the rest rounded to float; log2: KHI = 1, KLO = 0 */
static void kconst(int is_log2, double *khi, float *klo)
{
    if (is_log2) {
        *khi = 1, *klo = 0;
        return;
    }
    mpfr_t l, h;
    mpfr_inits2(256, l, h, (mpfr_ptr)0);
    mpfr_const_log2(l, MPFR_RNDN);
    mpfr_set(h, l, MPFR_RNDN);
    mpfr_prec_round(h, 16, MPFR_RNDN);
    *khi = mpfr_get_d(h, MPFR_RNDN);
    mpfr_sub(l, l, h, MPFR_RNDN);
    *klo = mpfr_get_flt(l, MPFR_RNDN);
    mpfr_clears(l, h, (mpfr_ptr)0);
}

/* 1/ln2 = LH + LL: LH rounded to float, LL the rest rounded to float */
static void inv_ln2_split(float *lh, float *ll)
{
    mpfr_t v;
    mpfr_init2(v, 256);
    mpfr_const_log2(v, MPFR_RNDN);
    mpfr_ui_div(v, 1, v, MPFR_RNDN);
    *lh = mpfr_get_flt(v, MPFR_RNDN);
    mpfr_sub_d(v, v, (double)*lh, MPFR_RNDN);
    *ll = mpfr_get_flt(v, MPFR_RNDN);
    mpfr_clear(v);
}

static void hexf(char *b, size_t n, double v) { snprintf(b, n, "%af,", v); }

static int extra_common(char *buf, size_t n, int is_log2)
{
    uint32_t off = pf_logtab_off();
    double R = 0;
    for (int i = 0; i < NT; i++) {
        double a, b;
        rf_range(off, i, &a, &b);
        R = fmax(R, fmax(fabs(a), fabs(b)));
    }
    if (!(R <= PF_LOGTAB_R))
        return snprintf(buf, n, "#error \"pfmathgen: the table's max |r| %a exceeds the fit domain %a\"\n", R,
                        PF_LOGTAB_R);
    double khi;
    float klo;
    kconst(is_log2, &khi, &klo);
    size_t len = 0;
#define PUT(...) len += (size_t)snprintf(buf + (len < n ? len : n), len < n ? n - len : 0, __VA_ARGS__)
    PUT("/* The reduction's table, computed by pfmathgen (gen/float/funcs_logtabf.c) with MPFR:\n"
        "   OFF = 0x%08x as the double table's (gen/float/funcs_logtab.c: the multiple of 2^16\n"
        "   with the smallest max |r|); subinterval i holds the z whose bits are in\n"
        "   [OFF + i 2^19, OFF + (i+1) 2^19); max |r| = %a (the fit's domain is |r| <= %a).\n"
        "   INVC[i] = 2/(zl + zh) rounded to float (zl, zh the subinterval's first and last\n"
        "   float), but exactly 1 on the subinterval that holds 1;\n"
        "   %s(INVC[i]) = LHI[i] + LLO[i]: LHI rounded to a multiple of 2^-%d (so that\n"
        "   k KHI + LHI is exact in float), LLO the rest rounded to float;\n"
        "   %s. */\n",
        off, R, PF_LOGTAB_R, is_log2 ? "-log2" : "-log", is_log2 ? 15 : 16,
        is_log2 ? "KHI = 1, KLO = 0 (log2: k is added as it is)"
                : "ln2 = KHI + KLO, KHI ln2 to 16 significant bits (k KHI exact for |k| < 2^8), KLO the rest "
                  "rounded to float");
    PUT("#define PF_LOGTF_OFF 0x%08xu\n", off);
    PUT("static const float PF_LOGTF_KHI PF_UNUSED = %af;\nstatic const float PF_LOGTF_KLO PF_UNUSED = %af;\n",
        khi, (double)klo);
    float lh, ll;
    inv_ln2_split(&lh, &ll);
    PUT("/* 1/ln2 = LH + LL (LH rounded to float, LL the rest rounded to float; MPFR):\n"
        "   the compensated log2 rows' r/ln2 */\n");
    PUT("static const float PF_LOGTF_LH PF_UNUSED = %af;\nstatic const float PF_LOGTF_LL PF_UNUSED = %af;\n",
        (double)lh, (double)ll);
    PUT("#if defined(__GNUC__)\n#define PF_LOGTF_ALIGN __attribute__((aligned(64)))\n#else\n#define PF_LOGTF_ALIGN\n#endif\n");
    float c[NT], lo[NT];
    double hi[NT], full[NT];
    for (int i = 0; i < NT; i++) {
        c[i] = invcf_of(off, i);
        logc_split(c[i], is_log2, &hi[i], &lo[i], &full[i]);
    }
    char h[48];
    PUT("static const float PF_LOGTF_INVC[16] PF_LOGTF_ALIGN = {\n");
    for (int i = 0; i < NT; i++) {
        double a, b;
        rf_range(off, i, &a, &b);
        hexf(h, sizeof h, c[i]);
        PUT("    %-18s /* %2d: r in [%+.6f, %+.6f] */\n", h, i, a, b);
    }
    PUT("};\nstatic const float PF_LOGTF_LHI[16] PF_LOGTF_ALIGN = {\n");
    for (int i = 0; i < NT; i++) {
        hexf(h, sizeof h, hi[i]);
        PUT("    %-18s /* %2d: %s(INVC) = %.17g */\n", h, i, is_log2 ? "-log2" : "-log", full[i]);
    }
    PUT("};\nstatic const float PF_LOGTF_LLO[16] PF_LOGTF_ALIGN = {\n");
    for (int i = 0; i < NT; i++) {
        hexf(h, sizeof h, lo[i]);
        PUT("    %s\n", h);
    }
    PUT("};\n\n");
#undef PUT
    return (int)len;
}

int pf_extra_logtabf(char *buf, size_t n) { return extra_common(buf, n, 0); }
int pf_extra_log2tabf(char *buf, size_t n) { return extra_common(buf, n, 1); }

/* ---- the error model, in ULP of the float result ----
 * f = k ln_b(2)... : f = k KS + L_i + log_b(1+r), L_i = -log_b(INVC[i]) exact,
 * on a grid of r over each subinterval and k from -149 to 128:
 *   r = fmaf(z, INVC, -1): half an ulp of r, times |d log_b(1+r)/dr| <= PS/(1-|r|);
 *   q = C[1] + C[2] r + ... by fmaf Horner: half an ulp a step, carried through;
 *   LL = fmaf(k, KLO, LLO): LLO's and KLO's roundings (|k| 2^-41 for log) and its own;
 *   v = fmaf(r, q, LL): r times q's error and its own rounding;
 *   the fit's relative error times |log_b(1+r)|;
 *   T = k KHI + LHI exact; the last addition is the result's own rounding
 *   (and at k = 0 on the subinterval with INVC = 1, T = 0 and r is exact: v's
 *   rounding is then the result's). */
static double ulp_f(double v)
{
    v = fabs(v);
    return v < 0x1p-126 ? 0x1p-149 : ldexp(1.0, ilogb(v) - 23);
}
#define H(v) (0.5 * ulp_f(v))

/* subinterval i's table entries and r range, as the emitted tables hold them */
typedef struct {
    float c, lo;          /* INVC, LLO */
    double ra, rb;        /* r over the subinterval */
    double hi, full;      /* LHI, -log_b(INVC) */
} sub_entry;
static sub_entry sub_of(uint32_t off, int i, int is_log2)
{
    sub_entry e;
    e.c = invcf_of(off, i);
    rf_range(off, i, &e.ra, &e.rb);
    logc_split(e.c, is_log2, &e.hi, &e.lo, &e.full);
    return e;
}

/* q = c_order r^(order-lo) + ... + c_lo by fmaf Horner at r, and the bound
   on its rounding errors: half an ulp a step, carried through */
static void horner_err(const fit_poly *p, int order, int lo, double r, double *qv, double *qe)
{
    double q = (double)p->c[order], eq = 0;
    for (int m = order - 1; m >= lo; m--) {
        q = q * r + (double)p->c[m];
        eq = eq * fabs(r) + H(fabs(q) + eq);
    }
    *qv = q, *qe = eq;
}

static int model_common(const fit_poly *p, int order, pf_scheme *sc, int is_log2)
{
    if (order < 2 || p->c[0] != 0) {
        snprintf(sc->text, sizeof sc->text, "error model: needs p(0) = 0 and order >= 2");
        return -1;
    }
    uint32_t off = pf_logtab_off();
    const double KS = is_log2 ? 1 : M_LN2, PS = is_log2 ? 1 / M_LN2 : 1;
    double worst = 0, worst_r = 0;
    int worst_k = 0, worst_i = 0;
    const int ng = 512;
    for (int i = 0; i < NT; i++) {
        sub_entry se = sub_of(off, i, is_log2);
        double ra = se.ra, rb = se.rb, hi = se.hi, full = se.full;
        float lo = se.lo, c = se.c;
        for (int j = 0; j <= ng; j++) {
            double r = ra + (rb - ra) * j / ng, q, eq;
            horner_err(p, order, 1, r, &q, &eq);
            /* INVC = 1: r = z - 1 is exact (Sterbenz) */
            double g = log1p(r) * PS, er = c == 1.0f ? 0 : H(r) * PS / (1 - fabs(r));
            for (int k = -149; k <= 128; k++) {
                double f = k * KS + full + g;
                if (f == 0)
                    continue; /* x = 1: r = 0, k = 0, LHI = LLO = 0, every term is exactly 0 */
                double ll = k * (KS - (is_log2 ? 1 : 0x1.62e4p-1)) + lo; /* k KLO + LLO */
                double ell = (lo != 0 ? H(lo) : 0) + (is_log2 ? 0 : abs(k) * 0x1p-41 + (k ? H(ll) : 0));
                double v = r * q + ll;
                /* at k = 0 on INVC = 1, T = 0 and the addition is exact: v's
                   rounding is the result's own */
                double ev = k == 0 && hi == 0 ? 0 : H(v);
                double e = er + fabs(r) * eq + ell + ev + p->max_err * fabs(g);
                double bnd = 0.5 + e / ulp_f(f);
                if (bnd > worst)
                    worst = bnd, worst_r = r, worst_k = k, worst_i = i;
            }
        }
    }
    sc->ncomp = 0;
    sc->bound_ulp = worst;
    snprintf(sc->text, sizeof sc->text,
             "table of 16 (INVC, LHI, LLO) in float, r = fmaf(z, INVC, -1); q(r) = p(r)/r by Horner in float "
             "with fmaf, y = (k KHI + LHI) + fmaf(r, q, k KLO + LLO), the first part exact, nothing "
             "compensated (the model's worst point is k = %d, subinterval %d, r = %.4f)",
             worst_k, worst_i, worst_r);
    return 0;
}

int pf_model_logtabf(const fit_poly *p, int order, pf_scheme *sc) { return model_common(p, order, sc, 0); }
int pf_model_log2tabf(const fit_poly *p, int order, pf_scheme *sc) { return model_common(p, order, sc, 1); }

/* ---- the compensated rows' error model (@NCOMP@ = 1), in ULP of the float result ----
 * z INVC = p + plo exactly and r = p - 1 exactly, so the reduced argument
 * r + plo is exact; f = k KS + L_i + log_b(1 + r + plo).  On a grid of r
 * over each subinterval and k from -149 to 128:
 *   the fast two-sum T + a = hi + lo is exact: checked, |T| >= |a| on every
 *   subinterval for k = 0 (T = LHI), or T = 0 (then hi = a, lo = 0);
 *   plo (|plo| <= half an ulp of p; 0 where INVC = 1) enters as plo (1 - r)
 *   PS: the rest of log_b(1 + r + plo) - log_b(1+r) is below plo^2 +
 *   |plo| r^2 / (1 - |r|), times PS;
 *   log2: r LH = a + alo exactly, r LL within 2^-24 of itself and LH + LL
 *   within 2^-49 of 1/ln2;
 *   LLO's and KLO's roundings (|k| 2^-41 for log);
 *   the small sum s + lo (ll, pl, alo, r LL): half an ulp of each partial
 *   sum, bounded by the sum of the magnitudes;
 *   q(r) by fmaf Horner: half an ulp a step, carried through, times r^2;
 *   r^2 rounded: half an ulp times |q|; v = fmaf(r^2, q, s + lo): half an
 *   ulp of v; the fit's relative error times |target(r)|;
 *   the last addition hi + v is the result's own rounding (half an ULP). */
static int model_comp(const fit_poly *p, int order, pf_scheme *sc, int is_log2)
{
    if (order < 3 || p->c[0] != 0 || p->c[1] != (is_log2 ? 0 : 1)) {
        snprintf(sc->text, sizeof sc->text, "error model: needs p(0) = 0, p'(0) = %d and order >= 3",
                 is_log2 ? 0 : 1);
        return -1;
    }
    uint32_t off = pf_logtab_off();
    const double KS = is_log2 ? 1 : M_LN2, PS = is_log2 ? 1 / M_LN2 : 1;
    double worst = 0, worst_r = 0;
    int worst_k = 0, worst_i = 0;
    const int ng = 512;
    for (int i = 0; i < NT; i++) {
        sub_entry se = sub_of(off, i, is_log2);
        double ra = se.ra, rb = se.rb, hi = se.hi, full = se.full;
        float lo = se.lo, c = se.c;
        /* the fast two-sum at k = 0: |LHI| >= |a| (a = r, or r LH rounded) */
        double amax = fmax(fabs(ra), fabs(rb)) * PS * (1 + 0x1p-23);
        if (hi != 0 && fabs(hi) < amax) {
            snprintf(sc->text, sizeof sc->text,
                     "error model: subinterval %d has |LHI| = %a below max |r PS| = %a (the fast two-sum needs "
                     "it above)",
                     i, fabs(hi), amax);
            return -1;
        }
        /* |plo| <= half an ulp of p = z INVC rounded (p within |r| of 1) */
        double plo = c == 1.0f ? 0 : H(1 + fmax(fabs(ra), fabs(rb)));
        for (int j = 0; j <= ng; j++) {
            double r = ra + (rb - ra) * j / ng, q, eq;
            horner_err(p, order, 2, r, &q, &eq);
            double r2 = r * r, g = log1p(r) * PS, tg = is_log2 ? g - r * PS : g;
            double epl = (plo * plo + plo * r2 / (1 - fabs(r))) * PS + H(plo) * PS; /* pl: approximation, rounding */
            double ea = is_log2 ? fabs(r) * 0x1p-49 + H(fabs(r) * 0x1p-26) : 0; /* 1/ln2's split, r LL */
            double alo = is_log2 ? H(r * PS) : 0;
            double eq2 = r2 * eq + fabs(q) * H(r2);
            for (int k = -149; k <= 128; k++) {
                double f = k * KS + full + g;
                if (f == 0)
                    continue; /* x = 1: r = 0, k = 0, LHI = LLO = 0, every term is exactly 0 */
                double t = k * KS + hi;
                double ll = k * (KS - (is_log2 ? 1 : 0x1.62e4p-1)) + lo; /* k KLO + LLO */
                double ell = (lo != 0 ? H(lo) : 0) + (is_log2 ? 0 : abs(k) * 0x1p-41 + (k ? H(ll) : 0));
                double lov = t == 0 ? 0 : H(t + r * PS); /* |lo| <= half an ulp of hi */
                /* the partial sums of s + lo, each rounded: at most three of
                   magnitude <= the sum of the magnitudes */
                double smag = fabs(ll) + plo * PS + alo + fabs(r) * 0x1p-26 + lov;
                double es = 3 * H(smag);
                double v = r2 * fabs(q) + smag;
                double e = epl + ea + ell + es + eq2 + H(v) + p->max_err * fabs(tg);
                double bnd = 0.5 + e / ulp_f(f);
                if (bnd > worst)
                    worst = bnd, worst_r = r, worst_k = k, worst_i = i;
            }
        }
    }
    sc->ncomp = 1;
    sc->bound_ulp = worst;
    snprintf(sc->text, sizeof sc->text,
             "table of 16 (INVC, LHI, LLO) in float; z INVC = p + plo and r = p - 1 exact, %s, "
             "(k KHI + LHI) + %s = hi + lo exact (fast two-sum), q(r) by Horner in float with fmaf, "
             "y = hi + fmaf(r^2, q, small rest): one rounding into the result (the model's worst point is "
             "k = %d, subinterval %d, r = %.4f)",
             is_log2 ? "r^2 q(r) fits log2(1+r) - r/ln2, r LH = a + alo exact" : "p(r) = r + r^2 q(r)",
             is_log2 ? "a" : "r", worst_k, worst_i, worst_r);
    return 0;
}

int pf_model_logtabc(const fit_poly *p, int order, pf_scheme *sc) { return model_comp(p, order, sc, 0); }
int pf_model_log2tabc(const fit_poly *p, int order, pf_scheme *sc) { return model_comp(p, order, sc, 1); }

/* ---- the lean rows ("tabl", gen/templates/log_tabl.c.in) ----
 * Two tables of 16 floats (two vpermps a vector on AVX-512) and no low parts.
 * log2: w = (x's bits - OFF) >> 19 (arithmetic) = 16 k + i, the index in
 *   its low 4 bits; t = fmaf(w, 1/16, LHT[i]) = k + LHI[i] exactly, LHT[i] =
 *   LHI[i] - i/16 (LHI on the grid 2^-16 and |k + LHI| < 2^8, so the sum is
 *   a float); r = fmaf(z, INVC[i], -1); y = fmaf(r, q(r), t): one rounding.
 * log: k on its own; t = fmaf(k, KHI, LHT[i]) = k KHI + LHI[i] exactly (KHI
 *   ln2 to 16 bits, LHT = LHI on the grid 2^-16), s = fmaf(k, KLO, t) (one
 *   rounding, none at k = 0), y = fmaf(r, q(r), s).
 * -log_b(INVC[i]) is not rounded to the grid but chosen near it (Gal's
 * accurate tables): among the floats c near 2/(zl + zh) whose max |r| stays
 * within the fit domain (|r| <= PF_LOGTL_R), INVC[i] is the c whose
 * -log_b(c) is nearest a multiple of 2^-16 (ties: the nearer c), LHI[i] that
 * multiple; the rest (log2 2^-32.2, log 2^-31 here) is not stored but counted
 * by the model.
 * The subinterval holding 1 keeps INVC = 1, LHI = 0 (r = z - 1 exact there,
 * and x = 1 gives 0). */
#define TL_GRID 16        /* LHI on the grid 2^-16 */
#define TL_SEARCH 16384   /* floats tried on each side of 2/(zl + zh) */

typedef struct {
    float c[NT];          /* INVC */
    double hi[NT];        /* LHI: a multiple of 2^-16 */
    double res[NT];       /* -log_b(INVC) - LHI (MPFR, to double) */
    double ra[NT], rb[NT];
    double rmax;
} tl_table;

/* -log_b(c) - its nearest multiple of 2^-16, and that multiple, at precision prec */
static double tl_resid(float c, int is_log2, int prec, double *hi)
{
    mpfr_t v, h;
    mpfr_inits2(prec, v, h, (mpfr_ptr)0);
    mpfr_set_flt(v, c, MPFR_RNDN);
    if (is_log2)
        mpfr_log2(v, v, MPFR_RNDN);
    else
        mpfr_log(v, v, MPFR_RNDN);
    mpfr_neg(v, v, MPFR_RNDN);
    mpfr_mul_2si(h, v, TL_GRID, MPFR_RNDN);
    mpfr_rint(h, h, MPFR_RNDN);
    mpfr_mul_2si(h, h, -TL_GRID, MPFR_RNDN);
    *hi = mpfr_get_d(h, MPFR_RNDN) + 0.0;
    mpfr_sub(v, v, h, MPFR_RNDN);
    double res = mpfr_get_d(v, MPFR_RNDN);
    mpfr_clears(v, h, (mpfr_ptr)0);
    return res;
}

static const tl_table *tl_get(int is_log2)
{
    static tl_table T[2];
    static int done[2];
    tl_table *t = &T[is_log2];
    if (done[is_log2])
        return t;
    uint32_t off = pf_logtab_off();
    t->rmax = 0;
    for (int i = 0; i < NT; i++) {
        double zl, zh;
        pf_logtab_sub_range(off, i, &zl, &zh);
        float c0 = invcf_of(off, i), best = c0;
        if (c0 != 1.0f) {
            uint32_t b0;
            memcpy(&b0, &c0, 4);
            double bres = INFINITY, h;
            for (int d = 0; d <= 2 * TL_SEARCH; d++) {
                int dd = (d & 1) ? -((d + 1) / 2) : d / 2; /* 0, -1, 1, -2, 2, ...: ties to the nearer */
                uint32_t b = b0 + (uint32_t)dd;
                float c;
                memcpy(&c, &b, 4);
                if (fmax(fabs(zl * c - 1), fabs(zh * c - 1)) > PF_LOGTL_R)
                    continue;
                double res = fabs(tl_resid(c, is_log2, 96, &h));
                if (res < bres)
                    bres = res, best = c;
            }
        }
        t->c[i] = best;
        t->res[i] = tl_resid(best, is_log2, 256, &t->hi[i]);
        t->ra[i] = zl * best - 1, t->rb[i] = zh * best - 1;
        t->rmax = fmax(t->rmax, fmax(fabs(t->ra[i]), fabs(t->rb[i])));
    }
    done[is_log2] = 1;
    return t;
}

static int extra_tabl(char *buf, size_t n, int is_log2)
{
    const tl_table *T = tl_get(is_log2);
    uint32_t off = pf_logtab_off();
    if (!(T->rmax <= PF_LOGTL_R))
        return snprintf(buf, n, "#error \"pfmathgen: the table's max |r| %a exceeds the fit domain %a\"\n", T->rmax,
                        PF_LOGTL_R);
    double rmx = 0;
    for (int i = 0; i < NT; i++)
        rmx = fmax(rmx, fabs(T->res[i]));
    const char *lb = is_log2 ? "-log2" : "-log";
    size_t len = 0;
#define PUT(...) len += (size_t)snprintf(buf + (len < n ? len : n), len < n ? n - len : 0, __VA_ARGS__)
    PUT("/* The reduction's tables, computed by pfmathgen (gen/float/funcs_logtabf.c) with MPFR:\n"
        "   OFF = 0x%08x as the double table's (gen/float/funcs_logtab.c); subinterval i holds\n"
        "   the z whose bits are in [OFF + i 2^19, OFF + (i+1) 2^19).  INVC[i]: of the floats c\n"
        "   within %d of 2/(zl + zh) (zl, zh the subinterval's first and last float) whose\n"
        "   max |z c - 1| is within the fit domain %a, the one whose %s(c) is nearest a\n"
        "   multiple LHI[i] of 2^-%d (Gal's accurate tables); exactly 1, LHI = 0, on the\n"
        "   subinterval that holds 1.  max |r| = %a; max |%s(INVC) - LHI| = %a (not stored:\n"
        "   the error model counts it).  %s */\n",
        off, TL_SEARCH, PF_LOGTL_R, lb, TL_GRID, T->rmax, lb, rmx,
        is_log2 ? "LHT[i] = LHI[i] - i/16, so that\n"
                  "   fmaf(16 k + i, 1/16, LHT[i]) = k + LHI[i] exactly."
                : "LHT[i] = LHI[i]; ln2 = KHI + KLO, KHI ln2 to 16\n"
                  "   significant bits (k KHI + LHI exact), KLO the rest rounded to float.");
    PUT("#define PF_LOGTL_OFF 0x%08xu\n", off);
    PUT("#define PF_LOGTL_LOG2 %d\n", is_log2);
    double khi;
    float klo;
    kconst(is_log2, &khi, &klo);
    PUT("static const float PF_LOGTL_KHI PF_UNUSED = %af;\nstatic const float PF_LOGTL_KLO PF_UNUSED = %af;\n",
        khi, (double)klo);
    PUT("#if defined(__GNUC__)\n#define PF_LOGTL_ALIGN __attribute__((aligned(64)))\n#else\n#define PF_LOGTL_ALIGN\n#endif\n");
    char h[48];
    PUT("static const float PF_LOGTL_INVC[16] PF_LOGTL_ALIGN = {\n");
    for (int i = 0; i < NT; i++) {
        hexf(h, sizeof h, T->c[i]);
        PUT("    %-18s /* %2d: r in [%+.6f, %+.6f] */\n", h, i, T->ra[i], T->rb[i]);
    }
    PUT("};\nstatic const float PF_LOGTL_LHT[16] PF_LOGTL_ALIGN = {\n");
    for (int i = 0; i < NT; i++) {
        /* exact: multiples of 2^-16 below 2 */
        hexf(h, sizeof h, is_log2 ? T->hi[i] - i / 16.0 : T->hi[i]);
        PUT("    %-18s /* %2d: LHI = %a, %s(INVC) - LHI = %+.3e */\n", h, i, T->hi[i], lb, T->res[i]);
    }
    PUT("};\n\n");
#undef PUT
    return (int)len;
}

int pf_extra_log2tabl(char *buf, size_t n) { return extra_tabl(buf, n, 1); }
int pf_extra_logtabl(char *buf, size_t n) { return extra_tabl(buf, n, 0); }

/* Their error model, in ULP of the float result f = k KS + LHI + res +
 * log_b(1+r), on a grid of r over each subinterval and k from -149 to 128:
 *   r = fmaf(z, INVC, -1): half an ulp of r times PS/(1 - |r|), none
 *   where INVC = 1 (Sterbenz);
 *   q(r) = p(r)/r by fmaf Horner: half an ulp a step, carried through, times |r|;
 *   the table's rest |res|; the fit's relative error times |log_b(1+r)|;
 *   t = k KHI + LHI exact; log: s = fmaf(k, KLO, t), half an ulp of s and
 *   KLO's rounding (|k| 2^-41), none at k = 0;
 *   y = fmaf(r, q, s): one rounding, the result's own. */
static int model_tabl(const fit_poly *p, int order, pf_scheme *sc, int is_log2)
{
    if (order < 2 || p->c[0] != 0) {
        snprintf(sc->text, sizeof sc->text, "error model: needs p(0) = 0 and order >= 2");
        return -1;
    }
    const tl_table *T = tl_get(is_log2);
    const double KS = is_log2 ? 1 : M_LN2, PS = is_log2 ? 1 / M_LN2 : 1;
    double worst = 0, worst_r = 0, rmx = 0;
    int worst_k = 0, worst_i = 0;
    const int ng = 512;
    for (int i = 0; i < NT; i++) {
        double ra = T->ra[i], rb = T->rb[i];
        rmx = fmax(rmx, fabs(T->res[i]));
        for (int j = 0; j <= ng; j++) {
            double r = ra + (rb - ra) * j / ng, q, eq;
            horner_err(p, order, 1, r, &q, &eq);
            double g = log1p(r) * PS, er = T->c[i] == 1.0f ? 0 : H(r) * PS / (1 - fabs(r));
            double e0 = er + fabs(r) * eq + fabs(T->res[i]) + p->max_err * fabs(g);
            for (int k = -149; k <= 128; k++) {
                double f = k * KS + T->hi[i] + T->res[i] + g;
                if (f == 0)
                    continue; /* x = 1: r = 0, k = 0, LHI = 0, every term is exactly 0 */
                double es = is_log2 || k == 0 ? 0 : H(k * KS + T->hi[i]) + abs(k) * 0x1p-41;
                double bnd = 0.5 + (e0 + es) / ulp_f(f);
                if (bnd > worst)
                    worst = bnd, worst_r = r, worst_k = k, worst_i = i;
            }
        }
    }
    sc->ncomp = 0;
    sc->bound_ulp = worst;
    snprintf(sc->text, sizeof sc->text,
             "tables of 16 (INVC, LHT) in float, %s(INVC) within %.1e of LHI on the grid 2^-16 (Gal); "
             "r = fmaf(z, INVC, -1), %s, q(r) = p(r)/r by Horner "
             "in float with fmaf, y = fmaf(r, q, %s): %s (the model's worst point "
             "is k = %d, subinterval %d, r = %.4f)",
             is_log2 ? "-log2" : "-log", rmx,
             is_log2 ? "t = fmaf(16 k + i, 1/16, LHT) = k + LHI exact"
                     : "t = fmaf(k, KHI, LHI) exact, s = fmaf(k, KLO, t)",
             is_log2 ? "t" : "s", is_log2 ? "one rounding into the result" : "two roundings (one at k = 0)",
             worst_k, worst_i, worst_r);
    return 0;
}

int pf_model_log2tabl(const fit_poly *p, int order, pf_scheme *sc) { return model_tabl(p, order, sc, 1); }
int pf_model_logtabl(const fit_poly *p, int order, pf_scheme *sc) { return model_tabl(p, order, sc, 0); }
