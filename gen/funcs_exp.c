/* Function table rows for exp and exp2 (see gen/funcs.h).
 *
 * exp(x)  = 2^k e^r,  k = round(x / ln2), r = x - k ln2 in [-ln2/2, ln2/2]
 * exp2(x) = 2^k 2^r,  k = round(x),       r = x - k    in [-1/2, 1/2]
 * One polynomial approximates e^r (2^r) on the reduced interval; 2^k is put
 * into the exponent bits by the templates (gen/templates/exp*_*.c.in). */
#include "funcs.h"

#include <math.h>
#include <stdio.h>

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

/* ---- constants of the reduction, computed with MPFR when generating ----
 * ln2 = LN2HI + LN2LO (Cody-Waite): LN2HI keeps few enough significant bits
 * that k * LN2HI is exact for every k the clamped input can give (|k| < 2^8),
 * so r = (x - k LN2HI) - k LN2LO loses nothing to the cancellation. */
static int ln2_split(char *buf, size_t n, int prec, int hibits, const char *type, const char *sfx)
{
    mpfr_t ln2, hi, lo, inv;
    mpfr_inits2(256, ln2, hi, lo, inv, (mpfr_ptr)0);
    mpfr_const_log2(ln2, MPFR_RNDN);
    mpfr_set_prec(hi, hibits);
    mpfr_set(hi, ln2, MPFR_RNDN);
    mpfr_sub(lo, ln2, hi, MPFR_RNDN); /* exact at 256 bits */
    mpfr_prec_round(lo, prec, MPFR_RNDN);
    mpfr_set_prec(inv, prec);
    mpfr_ui_div(inv, 1, ln2, MPFR_RNDN);
    int len = snprintf(buf, n,
                       "/* Reduction constants, computed with MPFR by pfmathgen: 1/ln2 rounded to %s,\n"
                       "   and ln2 = LN2HI + LN2LO with LN2HI of %d significant bits, so k * LN2HI is\n"
                       "   exact for |k| < 2^%d (Cody-Waite); LN2LO is the rest rounded to %s. */\n"
                       "static const %s PF_EXP_INVLN2 = %a%s;\n"
                       "static const %s PF_EXP_LN2HI = %a%s;\n"
                       "static const %s PF_EXP_LN2LO = %a%s;\n\n",
                       type, hibits, prec - hibits, type, type, mpfr_get_d(inv, MPFR_RNDN), sfx, type,
                       mpfr_get_d(hi, MPFR_RNDN), sfx, type, mpfr_get_d(lo, MPFR_RNDN), sfx);
    mpfr_clears(ln2, hi, lo, inv, (mpfr_ptr)0);
    return len;
}

static int extra_exp_double(char *buf, size_t n) { return ln2_split(buf, n, 53, 32, "double", ""); }
static int extra_exp_float(char *buf, size_t n) { return ln2_split(buf, n, 24, 16, "float", "f"); }

#define HALF_LN2 (0.5 * M_LN2)

#define EXP_RED "x = k ln2 + r, k = round(x/ln2), r in [-ln2/2, ln2/2] (Cody-Waite ln2 = hi + lo); exp(x) = 2^k e^r"
#define EXP2_RED "x = k + r, k = round(x), r = x - k in [-1/2, 1/2] (exact); exp2(x) = 2^k 2^r"

#define CON_ONE {FIT_CON_VALUE, 0, "p(0) = 1"}

const pf_spec pf_specs_exp[] = {
    {
        .func = "exp", .reduction = "ln2", .variant = "exact", .tmpl = "exp_exact", .arity = 1,
        .reduction_text = EXP_RED, .target_text = "e^t", .g = g_exp,
        .a = -HALF_LN2, .b = HALF_LN2, .parity = FIT_PARITY_NONE, .errkind = FIT_REL,
        .ncon = 2, .con = {CON_ONE, {FIT_CON_DERIV, 0, "p'(0) = 1"}},
        .default_order = 6, .real = "double", .ulp_bound = 1.0, .extra = extra_exp_double,
    },
    {
        .func = "exp", .reduction = "ln2", .variant = "fast", .tmpl = "exp_fast", .arity = 1,
        .reduction_text = EXP_RED, .target_text = "e^t", .g = g_exp,
        .a = -HALF_LN2, .b = HALF_LN2, .parity = FIT_PARITY_NONE, .errkind = FIT_REL,
        .ncon = 5,
        .con = {CON_ONE,
                {FIT_CON_VALUE, -HALF_LN2, "p(-ln2/2) = e^(-ln2/2)"},
                {FIT_CON_DERIV, -HALF_LN2, "p'(-ln2/2) = e^(-ln2/2)"},
                {FIT_CON_VALUE, HALF_LN2, "p(ln2/2) = e^(ln2/2)"},
                {FIT_CON_DERIV, HALF_LN2, "p'(ln2/2) = e^(ln2/2)"}},
        .default_order = 0, .fast_target = 0x1p-10, .real = "float", .extra = extra_exp_float,
    },
    {
        .func = "exp2", .reduction = "int", .variant = "exact", .tmpl = "exp2_exact", .arity = 1,
        .reduction_text = EXP2_RED, .target_text = "2^t", .g = g_exp2,
        .a = -0.5, .b = 0.5, .parity = FIT_PARITY_NONE, .errkind = FIT_REL,
        .ncon = 1, .con = {CON_ONE},
        .default_order = 6, .real = "double", .ulp_bound = 1.0,
    },
    {
        .func = "exp2", .reduction = "int", .variant = "fast", .tmpl = "exp2_fast", .arity = 1,
        .reduction_text = EXP2_RED, .target_text = "2^t", .g = g_exp2,
        .a = -0.5, .b = 0.5, .parity = FIT_PARITY_NONE, .errkind = FIT_REL,
        .ncon = 5,
        .con = {CON_ONE,
                {FIT_CON_VALUE, -0.5, "p(-1/2) = 2^(-1/2)"},
                {FIT_CON_DERIV, -0.5, "p'(-1/2) = ln2 2^(-1/2)"},
                {FIT_CON_VALUE, 0.5, "p(1/2) = 2^(1/2)"},
                {FIT_CON_DERIV, 0.5, "p'(1/2) = ln2 2^(1/2)"}},
        .default_order = 0, .fast_target = 0x1p-10, .real = "float",
    },
    {0},
};
