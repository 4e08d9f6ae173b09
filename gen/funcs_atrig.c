/* Function table rows for the atrig family: asin, acos, atan, atan2 (see
 * gen/funcs.h).
 *
 * Two polynomials serve the four functions:
 *   asin(t) on [0, 1/2], odd: asin and acos.  Beyond |x| = 1/2 both use
 *     asin(|x|) = pi/2 - 2 asin(s), s = sqrt((1 - |x|)/2) in [0, 1/2]
 *     acos(x) = 2 asin(s) (x > 1/2), pi - 2 asin(sqrt((1 + x)/2)) (x < -1/2),
 *   so one polynomial on [0, 1/2] is evaluated once, at a selected argument.
 *   Over that domain the Taylor ratio is t^2 <= 1/4: two bits per term.
 *   atan(t) on [0, 1], odd: atan and atan2.  Beyond 1, atan(x) = pi/2 -
 *     atan(1/x).  atan's singularities at +-i limit the best polynomial on
 *     [-1, 1] to a factor (1 + sqrt 2)^2 ~ 5.8 (2.5 bits) per odd term; order
 *     21 (11 terms) reaches 2^-29, well inside order 30, so no second identity
 *     (atan(x) = pi/4 + atan((x-1)/(x+1))) is needed.
 * The fast rows match value and slope at both ends of the reduced domain:
 * at t = 0 the slope 1 (c1 = 1), at the outer end the value and slope of the
 * target.  The identities map p's value and slope at the outer end onto both
 * sides of the fold (asin at 1/2: d/dx [pi/2 - 2 p(s)] = p'(1/2)), so the
 * value constraint makes the folded function continuous at |x| = 1/2 (asin,
 * acos) and |x| = 1 (atan, atan2 at |y| = |x|), and the slope constraint
 * makes its slope there the true one.
 *
 * The constants pi/2, pi, pi/4 the templates need are computed here with
 * MPFR (the `extra` callbacks): double hi + lo pairs for the exact variants
 * (so the subtraction pi/2 - 2 asin(s) near |x| = 1 loses nothing), the
 * nearest floats with lo = 0 for the fast variants. */
#include "funcs.h"

#include <stdio.h>

/* ---- fit targets, in the fit variable t ---- */
static void g_asin(mpfr_t y, const mpfr_t t, const void *c)
{
    (void)c;
    mpfr_asin(y, t, MPFR_RNDN);
}

static void g_atan(mpfr_t y, const mpfr_t t, const void *c)
{
    (void)c;
    mpfr_atan(y, t, MPFR_RNDN);
}

/* ---- constants, computed at generation time ---- */

/* v = pi * num / den at 256 bits */
static void pi_times(mpfr_t v, long num, long den)
{
    mpfr_const_pi(v, MPFR_RNDN);
    mpfr_mul_si(v, v, num, MPFR_RNDN);
    mpfr_div_si(v, v, den, MPFR_RNDN);
}

/* hi = v rounded to double, lo = (v - hi) rounded to double */
static void split_d(long num, long den, double *hi, double *lo)
{
    mpfr_t v;
    mpfr_init2(v, 256);
    pi_times(v, num, den);
    *hi = mpfr_get_d(v, MPFR_RNDN);
    mpfr_sub_d(v, v, *hi, MPFR_RNDN);
    *lo = mpfr_get_d(v, MPFR_RNDN);
    mpfr_clear(v);
}

static float nearest_f(long num, long den)
{
    mpfr_t v;
    mpfr_init2(v, 256);
    pi_times(v, num, den);
    float f = mpfr_get_flt(v, MPFR_RNDN);
    mpfr_clear(v);
    return f;
}

static int extra_pi_double(char *buf, size_t n)
{
    double h2, l2, h1, l1, h4, l4;
    split_d(1, 2, &h2, &l2);
    split_d(1, 1, &h1, &l1);
    split_d(1, 4, &h4, &l4);
    return snprintf(buf, n,
                    "/* pi/2 and pi as hi + lo (hi the nearest double, lo the nearest double to\n"
                    "   the rest; computed with MPFR at 256 bits), pi/4 to the nearest double */\n"
                    "#define PF_PIO2_HI %a\n#define PF_PIO2_LO %a\n"
                    "#define PF_PI_HI %a\n#define PF_PI_LO %a\n"
                    "#define PF_PIO4 %a\n\n",
                    h2, l2, h1, l1, h4);
}

static int extra_pi_float(char *buf, size_t n)
{
    return snprintf(buf, n,
                    "/* pi/2, pi, pi/4 rounded to float (MPFR at 256 bits).  The fast variant\n"
                    "   keeps no low parts: their 2^-25 relative is far below its 2^-10 bound,\n"
                    "   and pi - pi/2, pi - pi/4 of these floats round to the nearest floats of\n"
                    "   pi/2 and 3pi/4, so atan2's exact special results stay exact. */\n"
                    "#define PF_PIO2_HI %af\n#define PF_PIO2_LO 0.0f\n"
                    "#define PF_PI_HI %af\n#define PF_PI_LO 0.0f\n"
                    "#define PF_PIO4 %af\n\n",
                    (double)nearest_f(1, 2), (double)nearest_f(1, 1), (double)nearest_f(1, 4));
}

/* ---- rows ---- */
#define ASIN_RED "|x| <= 1/2: t = |x|; |x| > 1/2: asin|x| = pi/2 - 2 asin(t), t = sqrt((1 - |x|)/2)"
#define ACOS_RED                                                                                  \
    "|x| <= 1/2: acos x = pi/2 - asin x; x > 1/2: 2 asin(t), t = sqrt((1 - x)/2); "              \
    "x < -1/2: pi - 2 asin(t), t = sqrt((1 + x)/2)"
#define ATAN_RED "|x| <= 1: t = |x|; |x| > 1: atan|x| = pi/2 - atan(t), t = 1/|x|"
#define ATAN2_RED                                                                                 \
    "t = min(|y|,|x|) / max(|y|,|x|); atan2 from atan(t) by pi/2 - (|y| > |x|), pi - (x < 0 or " \
    "x = -0), sign of y (C99 F.9.1.4)"

#define CON_SLOPE1 {FIT_CON_DERIV, 0, "p'(0) = 1"}
#define ASIN_FAST_CON                                                                             \
    {CON_SLOPE1, {FIT_CON_VALUE, 0.5, "p(1/2) = pi/6"}, {FIT_CON_DERIV, 0.5, "p'(1/2) = 2/sqrt(3)"}}
#define ATAN_FAST_CON {CON_SLOPE1, {FIT_CON_VALUE, 1, "p(1) = pi/4"}, {FIT_CON_DERIV, 1, "p'(1) = 1/2"}}

/* exact orders: the smallest odd orders whose float-coefficient polynomial is
   within 2^-29 relative whether it is fitted minimax (the exact default) or by
   least squares (asin 13: 2^-31.7 / 2^-30.1, atan 21: 2^-31.1 / 2^-29.2).
   After the final rounding that is <= 0.5 + 2 * 2^-29 * 2^24 = 0.57 ULP, the
   2 being asin's worst amplification just above |x| = 1/2.  One order less
   (asin 11, atan 19) falls to 2^-26..2^-27 by least squares: too close to 1 ULP. */
#define ASIN_EXACT_ORDER 13
#define ATAN_EXACT_ORDER 21

#define ROW_ASIN_EXACT(fn, tm, red)                                                               \
    {.func = fn, .reduction = "sqrthalf", .variant = "exact", .tmpl = tm, .arity = 1,             \
     .reduction_text = red, .target_text = "asin(t)", .g = g_asin, .a = 0, .b = 0.5,              \
     .parity = FIT_PARITY_ODD, .errkind = FIT_REL, .ncon = 1, .con = {CON_SLOPE1},                \
     .default_order = ASIN_EXACT_ORDER, .real = "double", .ulp_bound = 1.0,                       \
     .extra = extra_pi_double}
#define ROW_ASIN_FAST(fn, tm, red)                                                                \
    {.func = fn, .reduction = "sqrthalf", .variant = "fast", .tmpl = tm, .arity = 1,              \
     .reduction_text = red, .target_text = "asin(t)", .g = g_asin, .a = 0, .b = 0.5,              \
     .parity = FIT_PARITY_ODD, .errkind = FIT_REL, .ncon = 3, .con = ASIN_FAST_CON,               \
     .default_order = 0, .fast_target = 0x1p-10, .real = "float", .extra = extra_pi_float}
#define ROW_ATAN_EXACT(fn, tm, ar, red)                                                           \
    {.func = fn, .reduction = "recip", .variant = "exact", .tmpl = tm, .arity = ar,               \
     .reduction_text = red, .target_text = "atan(t)", .g = g_atan, .a = 0, .b = 1,                \
     .parity = FIT_PARITY_ODD, .errkind = FIT_REL, .ncon = 1, .con = {CON_SLOPE1},                \
     .default_order = ATAN_EXACT_ORDER, .real = "double", .ulp_bound = 1.0,                       \
     .extra = extra_pi_double}
#define ROW_ATAN_FAST(fn, tm, ar, red)                                                            \
    {.func = fn, .reduction = "recip", .variant = "fast", .tmpl = tm, .arity = ar,                \
     .reduction_text = red, .target_text = "atan(t)", .g = g_atan, .a = 0, .b = 1,                \
     .parity = FIT_PARITY_ODD, .errkind = FIT_REL, .ncon = 3, .con = ATAN_FAST_CON,               \
     .default_order = 0, .fast_target = 0x1p-10, .real = "float", .extra = extra_pi_float}

const pf_spec pf_specs_atrig[] = {
    ROW_ASIN_EXACT("asin", "asin_sqrthalf", ASIN_RED),
    ROW_ASIN_FAST("asin", "asin_sqrthalf", ASIN_RED),
    ROW_ASIN_EXACT("acos", "acos_sqrthalf", ACOS_RED),
    ROW_ASIN_FAST("acos", "acos_sqrthalf", ACOS_RED),
    ROW_ATAN_EXACT("atan", "atan_recip", 1, ATAN_RED),
    ROW_ATAN_FAST("atan", "atan_recip", 1, ATAN_RED),
    ROW_ATAN_EXACT("atan2", "atan2_recip", 2, ATAN2_RED),
    ROW_ATAN_FAST("atan2", "atan2_recip", 2, ATAN2_RED),
    {0},
};
