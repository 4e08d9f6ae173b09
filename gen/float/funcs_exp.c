/* Function table rows for exp and exp2 (see gen/float/funcs.h).
 *
 * exp(x)  = 2^k e^r,  k = round(x / ln2), r = x - k ln2 in [-ln2/2, ln2/2]
 * exp2(x) = 2^k 2^r,  k = round(x),       r = x - k    in [-1/2, 1/2]
 * One polynomial approximates e^r (2^r) on the reduced interval; 2^k is put
 * into the exponent bits by the templates (gen/templates/exp*_*.c.in). */
#include "funcs.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define HALF_LN2 (0.5 * M_LN2)

/* ---- fit targets, in the fit variable t ---- */
static void g_exp(mpfr_t y, const mpfr_t t, const void *c)
{
    (void)c;
    mpfr_exp(y, t, MPFR_RNDN);
}

static void g_exp2(mpfr_t y, const mpfr_t t, const void *c)
{
    (void)c;
    mpfr_exp2(y, t, MPFR_RNDN);
}

/* ---- constants of the reduction, computed with MPFR when generating ---- */
/* With fmaf, LN2HI is ln2 rounded to float: fmaf(-k, LN2HI, x) is exact
   for every k (gen/templates/exp_fma.c.in says why), so no bits are given
   up; LN2LO is the rest, and LN2HI + LN2LO is ln2 within 2^-49.  The
   exact variant takes both steps; the fast one only the first, whose error
   |k (ln2 - LN2HI)| < 160 * 2^-28.9 < 2^-21.6 (|k| <= 160 before the
   template's selects) moves e^r by that much relative, far below the fast
   bound (2^-10).  The reduction is emitted
   here, with its constants, as pf_exp_reduce(x, k). */
static int extra_exp_common(char *buf, size_t n, int steps)
{
    mpfr_t ln2, hi, lo, inv;
    mpfr_inits2(256, ln2, hi, lo, inv, (mpfr_ptr)0);
    mpfr_const_log2(ln2, MPFR_RNDN);
    mpfr_set_prec(hi, 24);
    mpfr_set(hi, ln2, MPFR_RNDN);
    mpfr_sub(lo, ln2, hi, MPFR_RNDN); /* exact at 256 bits */
    mpfr_prec_round(lo, 24, MPFR_RNDN);
    mpfr_set_prec(inv, 24);
    mpfr_ui_div(inv, 1, ln2, MPFR_RNDN);
    int len;
    if (steps == 2)
        len = snprintf(buf, n,
                       "/* Reduction constants, computed with MPFR by pfmathgen: 1/ln2 rounded to float,\n"
                       "   and ln2 = LN2HI + LN2LO with LN2HI ln2 rounded to float (fmaf(-k, LN2HI, x)\n"
                       "   is exact) and LN2LO the rest rounded to float. */\n"
                       "static const float PF_EXP_INVLN2 = %af;\n"
                       "static const float PF_EXP_LN2HI = %af;\n"
                       "static const float PF_EXP_LN2LO = %af;\n\n"
                       "/* r = x - k ln2 in two steps (Cody-Waite): the first exact, the second\n"
                       "   rounding once, so r is within half an ulp of x - k ln2, plus\n"
                       "   |k| 2^-49 for ln2's own split (the error model counts both) */\n"
                       "static inline float pf_exp_reduce(float x, float k)\n"
                       "{\n"
                       "    return fmaf(-k, PF_EXP_LN2LO, fmaf(-k, PF_EXP_LN2HI, x));\n"
                       "}\n\n",
                       mpfr_get_d(inv, MPFR_RNDN), mpfr_get_d(hi, MPFR_RNDN), mpfr_get_d(lo, MPFR_RNDN));
    else
        len = snprintf(buf, n,
                       "/* Reduction constants, computed with MPFR by pfmathgen: 1/ln2 and ln2\n"
                       "   (LN2HI) rounded to float. */\n"
                       "static const float PF_EXP_INVLN2 = %af;\n"
                       "static const float PF_EXP_LN2HI = %af;\n\n"
                       "/* r = x - k ln2 in one step, exact: r is off x - k ln2 by\n"
                       "   |k (ln2 - LN2HI)| < 2^-21.6 for |k| <= 160, which moves e^r by that\n"
                       "   much relative, far below this variant's bound; the second\n"
                       "   Cody-Waite step would cost an fmaf a lane */\n"
                       "static inline float pf_exp_reduce(float x, float k)\n"
                       "{\n"
                       "    return fmaf(-k, PF_EXP_LN2HI, x);\n"
                       "}\n\n",
                       mpfr_get_d(inv, MPFR_RNDN), mpfr_get_d(hi, MPFR_RNDN));
    mpfr_clears(ln2, hi, lo, inv, (mpfr_ptr)0);
    return len;
}

static int extra_exp_fma(char *buf, size_t n) { return extra_exp_common(buf, n, 2); }
static int extra_exp_fast(char *buf, size_t n) { return extra_exp_common(buf, n, 1); }

/* ---- the error model of the exact variants (gen/float/funcs.h: pf_spec.model) ----
 * y = p(r) by fmaf Horner, then y 2^k.  At each r of the domain a bound on
 * |y - e^r| (resp. 2^r), in ULP of the float e^r, is carried through the
 * Horner steps: s_j = fmaf(s_{j+1}, r, c_j) adds half an ulp of the float
 * s_j (a float rounding is at most that; this is tighter than float_model's
 * 2^-24 |s| and matters here, where the budget is spent).  r's own error dr
 * (half an ulp of r from its rounding, plus RABS) moves p by |p'(r)| dr; the
 * fit's relative error is added at the end.  Normal results are y 2^k
 * exactly, so that is the bound; subnormal ones round y 2^k once more, to at
 * least one bit less: 0.5 + (E + 0.5)/2 with E the bound before y's own
 * rounding. */
static double ulp_of(double v)
{
    return v == 0 ? 0x1p-149 : ldexp(1.0, ilogb(v) - 23);
}

static int model_exp_common(const fit_poly *p, int order, pf_scheme *sc, double a, double b, int r_rounded,
                            double rabs, double ln_base, const char *what)
{
    double worst = 0, worst_at = 0;
    const int n = 16384;
    for (int i = 0; i <= n; i++) {
        double r = a + (b - a) * i / n;
        double dr = (r_rounded ? 0.5 * ulp_of(fabs(r)) : 0) + rabs;
        double s = (double)p->c[order], e = 0, d = 0;
        for (int j = order - 1; j >= 0; j--) {
            double sn = s * r + (double)p->c[j];
            d = d * r + s; /* p'(r), by the same recurrence */
            e = e * fabs(r) + (j ? 0.5 * ulp_of(fabs(sn) + e) : 0);
            s = sn;
        }
        /* r's error moves p by p'(r) dr to first order; the second order
           (the rounded steps seeing r + dr) is bounded by e dr */
        double f = exp(r * ln_base), u = ulp_of(f);
        double pre = (e * (1 + dr) + fabs(d) * dr + p->max_err * f) / u;
        double bnd = fmax(0.5 + pre, 0.75 + pre / 2);
        if (bnd > worst)
            worst = bnd, worst_at = r;
    }
    sc->ncomp = 0;
    sc->bound_ulp = worst;
    snprintf(sc->text, sizeof sc->text,
             "%s; p(r) by Horner in float with fmaf, no compensated step (the model's worst "
             "point is r = %.4f)",
             what, worst_at);
    /* A bound above 1 ULP is stated, not refused: --order or --target may ask
       for less than the library's exact variant (whose default order the
       tests check is within 1 ULP by this model). */
    if (worst > 1.0) {
        size_t len = strlen(sc->text);
        snprintf(sc->text + len, sizeof sc->text - len, "; above 1 ULP at this order");
    }
    return 0;
}

static int model_exp(const fit_poly *p, int order, pf_scheme *sc)
{
    /* a little past +-ln2/2: k from x/ln2 rounded once may be off by the
       rounding of x * (1/ln2); RABS: k (ln2 - LN2HI - LN2LO) for |k| <= 152 */
    return model_exp_common(p, order, sc, -HALF_LN2 - 0x1p-20, HALF_LN2 + 0x1p-20, 1, 152 * 0x1p-49, 1.0,
                            "r = fmaf(-k, LN2HI, x) exact, then fmaf(-k, LN2LO, r): one rounding");
}

static int model_exp2(const fit_poly *p, int order, pf_scheme *sc)
{
    return model_exp_common(p, order, sc, -0.5, 0.5, 0, 0, M_LN2, "r = x - k exact");
}

#define EXP_RED "x = k ln2 + r, k = round(x/ln2), r in [-ln2/2, ln2/2] (Cody-Waite ln2 = hi + lo); exp(x) = 2^k e^r"
#define EXP_RED_FAST "x = k ln2 + r, k = round(x/ln2), r in [-ln2/2, ln2/2] (one step, ln2 rounded to float); exp(x) = 2^k e^r"
#define EXP2_RED "x = k + r, k = round(x), r = x - k in [-1/2, 1/2] (exact); exp2(x) = 2^k 2^r"

#define CON_ONE {FIT_CON_VALUE, 0, "p(0) = 1"}

const pf_spec pf_specs_exp[] = {
    {
        .func = "exp", .reduction = "ln2", .variant = "exact", .tmpl = "exp_fma", .tail = "exp_log_twopath.c", .arity = 1,
        .reduction_text = EXP_RED, .target_text = "e^t", .g = g_exp,
        .a = -HALF_LN2, .b = HALF_LN2, .parity = FIT_PARITY_NONE, .errkind = FIT_REL,
        .ncon = 2, .con = {CON_ONE, {FIT_CON_DERIV, 0, "p'(0) = 1"}},
        .default_order = 6, .real = "fma", .ulp_bound = 1.0, .extra = extra_exp_fma, .model = model_exp,
    },
    {
        .func = "exp", .reduction = "ln2", .variant = "fast", .tmpl = "exp_fma", .tail = "exp_log_twopath.c", .arity = 1,
        .reduction_text = EXP_RED_FAST, .target_text = "e^t", .g = g_exp,
        .a = -HALF_LN2, .b = HALF_LN2, .parity = FIT_PARITY_NONE, .errkind = FIT_REL,
        .ncon = 5,
        .con = {CON_ONE,
                {FIT_CON_VALUE, -HALF_LN2, "p(-ln2/2) = e^(-ln2/2)"},
                {FIT_CON_DERIV, -HALF_LN2, "p'(-ln2/2) = e^(-ln2/2)"},
                {FIT_CON_VALUE, HALF_LN2, "p(ln2/2) = e^(ln2/2)"},
                {FIT_CON_DERIV, HALF_LN2, "p'(ln2/2) = e^(ln2/2)"}},
        .default_order = 0, .fast_target = 0x1p-10, .real = "fma", .extra = extra_exp_fast,
    },
    {
        .func = "exp2", .reduction = "int", .variant = "exact", .tmpl = "exp2_fma", .tail = "exp_log_twopath.c", .arity = 1,
        .reduction_text = EXP2_RED, .target_text = "2^t", .g = g_exp2,
        .a = -0.5, .b = 0.5, .parity = FIT_PARITY_NONE, .errkind = FIT_REL,
        .ncon = 1, .con = {CON_ONE},
        .default_order = 6, .real = "fma", .ulp_bound = 1.0, .model = model_exp2,
    },
    {
        .func = "exp2", .reduction = "int", .variant = "fast", .tmpl = "exp2_fma", .tail = "exp_log_twopath.c", .arity = 1,
        .reduction_text = EXP2_RED, .target_text = "2^t", .g = g_exp2,
        .a = -0.5, .b = 0.5, .parity = FIT_PARITY_NONE, .errkind = FIT_REL,
        .ncon = 5,
        .con = {CON_ONE,
                {FIT_CON_VALUE, -0.5, "p(-1/2) = 2^(-1/2)"},
                {FIT_CON_DERIV, -0.5, "p'(-1/2) = ln2 2^(-1/2)"},
                {FIT_CON_VALUE, 0.5, "p(1/2) = 2^(1/2)"},
                {FIT_CON_DERIV, 0.5, "p'(1/2) = ln2 2^(1/2)"}},
        .default_order = 0, .fast_target = 0x1p-10, .real = "fma",
    },
    {0},
};
