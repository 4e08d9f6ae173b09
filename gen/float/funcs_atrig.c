/* Function table rows for the atrig family: asin, acos, atan, atan2 (see
 * gen/float/funcs.h).
 *
 * Polynomials, all odd, p(t) = t + t z q(z) with z = t^2 and c1 = 1:
 *   asin(t) on [0, 1/2]: asin and acos, both variants.  Beyond |x| = 1/2
 *     asin(|x|) = pi/2 - 2 asin(s), s = sqrt((1 - |x|)/2) in [0, 1/2]
 *     acos(x) = 2 asin(s) (x > 1/2), pi - 2 asin(sqrt((1 + x)/2)) (x < -1/2),
 *   so one polynomial on [0, 1/2] is evaluated once, at a selected argument.
 *   Over that domain the Taylor ratio is t^2 <= 1/4: two bits per term.
 *   atan(t) on [0, 1/2] (exact): atan and atan2 reduce by atan a = pi/4 +
 *     atan((a - 1)/(a + 1)) on (1/2, 2] and pi/2 - atan(1/a) beyond, so
 *     |q| <= 1/2; atan's singularities at +-i then give a factor
 *     (2 + sqrt 5)^2 ~ 18 (4.2 bits) per odd term, and order 13 reaches
 *     2^-31.7.  The reduced argument is a quotient, carried as qh + ql.
 *   atan(t) on [0, 1] (fast): one reciprocal fold, atan(x) = pi/2 - atan(1/x).
 * The exact variants evaluate in float lanes with fmaf (gen/templates/
 * {asin,acos,atan,atan2}_ff.c.in): the correction t z q(z) is at most 5.4%
 * of the result, so its roundings weigh 1/20 of an ULP, and everything
 * else (the fold's constant, the square root, the quotient) is kept exact
 * as hi + lo floats up to one final rounding.  gen/float/funcs_atrig_model.c
 * bounds each scheme (the provenance's "Error model:" line), the fast asin
 * and acos too (as a fraction of the fast bound).
 * The fast rows match value and slope at both ends of the reduced domain:
 * at t = 0 the slope 1 (c1 = 1), at the outer end the value and slope of the
 * target.  The identities map p's value and slope at the outer end onto both
 * sides of the fold (asin at 1/2: d/dx [pi/2 - 2 p(s)] = p'(1/2)), so the
 * value constraint makes the folded function continuous at |x| = 1/2 (asin,
 * acos) and |x| = 1 (atan, atan2 at |y| = |x|), and the slope constraint
 * makes its slope there the true one.
 *
 * The constants pi/4, pi/2, pi the templates need are computed here with
 * MPFR (the `extra` callbacks): float hi + lo pairs for the exact variants
 * (so K + p loses nothing before the last rounding), the nearest floats
 * with lo = 0 for the fast variants. */
#include "funcs.h"

#include <stdio.h>

/* the exact schemes' error models (gen/float/funcs_atrig_model.c) */
int pf_model_asin(const fit_poly *p, int order, pf_scheme *sc);
int pf_model_acos(const fit_poly *p, int order, pf_scheme *sc);
int pf_model_atan(const fit_poly *p, int order, pf_scheme *sc);
int pf_model_atan2(const fit_poly *p, int order, pf_scheme *sc);
int pf_model_asin_fast(const fit_poly *p, int order, pf_scheme *sc);
int pf_model_acos_fast(const fit_poly *p, int order, pf_scheme *sc);
int pf_model_asin_mid(const fit_poly *p, int order, pf_scheme *sc);
int pf_model_acos_mid(const fit_poly *p, int order, pf_scheme *sc);
int pf_model_atan_mid(const fit_poly *p, int order, pf_scheme *sc);
int pf_model_atan2_mid(const fit_poly *p, int order, pf_scheme *sc);
int pf_model_atan_lean(const fit_poly *p, int order, pf_scheme *sc);
int pf_model_asin_lite(const fit_poly *p, int order, pf_scheme *sc);
int pf_model_atan_lite(const fit_poly *p, int order, pf_scheme *sc);
int pf_model_atan2_lite(const fit_poly *p, int order, pf_scheme *sc);
int pf_model_atan2_lean(const fit_poly *p, int order, pf_scheme *sc);

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

static float nearest_f(long num, long den)
{
    mpfr_t v;
    mpfr_init2(v, 256);
    pi_times(v, num, den);
    float f = mpfr_get_flt(v, MPFR_RNDN);
    mpfr_clear(v);
    return f;
}

/* hi = v rounded to float, lo = (v - hi) rounded to float */
static void split_f(long num, long den, float *hi, float *lo)
{
    mpfr_t v;
    mpfr_init2(v, 256);
    pi_times(v, num, den);
    *hi = mpfr_get_flt(v, MPFR_RNDN);
    mpfr_sub_d(v, v, (double)*hi, MPFR_RNDN);
    *lo = mpfr_get_flt(v, MPFR_RNDN);
    mpfr_clear(v);
}

static int extra_pi_ff(char *buf, size_t n)
{
    float h4, l4, h2, l2, h1, l1;
    split_f(1, 4, &h4, &l4);
    split_f(1, 2, &h2, &l2);
    split_f(1, 1, &h1, &l1);
    return snprintf(buf, n,
                    "/* pi/4, pi/2 and pi as hi + lo floats (hi the nearest float, lo the\n"
                    "   nearest float to the rest: 2^-48 relative; MPFR at 256 bits) */\n"
                    "#define PF_PIO4_HI %af\n#define PF_PIO4_LO %af\n"
                    "#define PF_PIO2_HI %af\n#define PF_PIO2_LO %af\n"
                    "#define PF_PI_HI %af\n#define PF_PI_LO %af\n\n",
                    (double)h4, (double)l4, (double)h2, (double)l2, (double)h1, (double)l1);
}

/* pi/4 = A + B + O(2^-45): A with 21 significant bits, so that m A is exact
   for m = 0..4, B the nearest float to the rest */
static int extra_pi_m4(char *buf, size_t n)
{
    mpfr_t v, a;
    mpfr_init2(v, 256);
    mpfr_init2(a, 21);
    pi_times(v, 1, 4);
    mpfr_set(a, v, MPFR_RNDN);
    float fa = mpfr_get_flt(a, MPFR_RNDN);
    mpfr_sub(v, v, a, MPFR_RNDN);
    float fb = mpfr_get_flt(v, MPFR_RNDN);
    mpfr_clear(v);
    mpfr_clear(a);
    return snprintf(buf, n,
                    "/* pi/4 = A + B to 2^-45: A rounded to 21 bits (m A exact for m <= 4), B the\n"
                    "   nearest float to the rest (MPFR at 256 bits) */\n"
                    "#define PF_PIO4_A %af\n#define PF_PIO4_B %af\n\n",
                    (double)fa, (double)fb);
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
#define ATAN_RED                                                                                  \
    "|x| <= 1/2: t = |x|; 1/2 < |x| <= 2: atan|x| = pi/4 + atan(t), t = (|x| - 1)/(|x| + 1); "   \
    "|x| > 2: pi/2 + atan(t), t = -1/|x|"
#define ATAN_RED_FAST "|x| <= 1: t = |x|; |x| > 1: atan|x| = pi/2 - atan(t), t = 1/|x|"
#define ATAN2_RED                                                                                 \
    "n = min(|y|,|x|), d = max; n/d <= 1/2: t = n/d; else pi/4 + atan(t), t = (n - d)/(n + d); "  \
    "atan2 from it by pi/2 - (|y| > |x|), pi - (x < 0 or x = -0), sign of y (C99 F.9.1.4)"
#define ATAN2_RED_FAST                                                                            \
    "t = min(|y|,|x|) / max(|y|,|x|); atan2 from atan(t) by pi/2 - (|y| > |x|), pi - (x < 0 or " \
    "x = -0), sign of y (C99 F.9.1.4)"

#define CON_SLOPE1 {FIT_CON_DERIV, 0, "p'(0) = 1"}
#define ASIN_FAST_CON                                                                             \
    {CON_SLOPE1, {FIT_CON_VALUE, 0.5, "p(1/2) = pi/6"}, {FIT_CON_DERIV, 0.5, "p'(1/2) = 2/sqrt(3)"}}
#define ATAN_FAST_CON {CON_SLOPE1, {FIT_CON_VALUE, 1, "p(1) = pi/4"}, {FIT_CON_DERIV, 1, "p'(1) = 1/2"}}

/* exact orders: the smallest odd orders whose float-coefficient polynomial is
   within 2^-29 relative whether it is fitted minimax (the exact default) or by
   least squares (asin 13 on [0, 1/2]: 2^-31.7 / 2^-30.1, atan 13 on [0, 1/2]:
   2^-31.7 / 2^-30.2).  The models then bound the float schemes at 0.80
   (asin), 0.68 (acos), 0.75 (atan), 0.95 (atan2) ULP.  One order less falls
   to 2^-27.5 (atan 11: 0.74 ULP on pfmathgen's sample): the one FMA saved
   is 2% of the loop, not worth the margin. */
#define ASIN_EXACT_ORDER 13
#define ATAN_EXACT_ORDER 13

#define ROW_ASIN_EXACT(fn, tm, red, mo)                                                            \
    {.func = fn, .reduction = "sqrthalf", .variant = "exact", .tmpl = tm, .arity = 1,             \
     .reduction_text = red, .target_text = "asin(t)", .g = g_asin, .a = 0, .b = 0.5,              \
     .parity = FIT_PARITY_ODD, .errkind = FIT_REL, .ncon = 1, .con = {CON_SLOPE1},                \
     .default_order = ASIN_EXACT_ORDER, .real = "fma", .ulp_bound = 1.0,                          \
     .extra = extra_pi_ff, .model = mo}
#define ROW_ASIN_FAST(fn, tm, red, mo)                                                            \
    {.func = fn, .reduction = "sqrthalf", .variant = "fast", .tmpl = tm, .arity = 1,              \
     .reduction_text = red, .target_text = "asin(t)", .g = g_asin, .a = 0, .b = 0.5,              \
     .parity = FIT_PARITY_ODD, .errkind = FIT_REL, .ncon = 3, .con = ASIN_FAST_CON,               \
     .default_order = 0, .fast_target = 0x1p-10, .real = "fma", .extra = extra_pi_float,          \
     .model = mo, .tail = "asin_acos_tail.c"}
/* The exact atan/atan2 template's ladder cost: its three-way reduction, the
   quotient's residual and the hi + lo steps.  The default rule (8 over the
   fast template) made order 9 of it look as cheap as the fast template's
   order 17, at 2.2x its time.  From one pfbench run (AVX-512, ns per
   element, ladder points): fast order 13 (cost 14) 0.244, mid order 17
   (cost 22) 0.342, exact order 11 0.545: a line through the first two puts
   the exact one at cost 39, 27 over its Horner terms (AVX2: 22). */
#define ATAN_EXACT_LADDER_COST 26
#define ROW_ATAN_EXACT(fn, tm, ar, red)                                                           \
    {.func = fn, .reduction = "recip", .variant = "exact", .tmpl = tm, .arity = ar,               \
     .reduction_text = red, .target_text = "atan(t)", .g = g_atan, .a = 0, .b = 0.5,              \
     .parity = FIT_PARITY_ODD, .errkind = FIT_REL, .ncon = 1, .con = {CON_SLOPE1},                \
     .default_order = ATAN_EXACT_ORDER, .real = "fma", .ulp_bound = 1.0,                          \
     .extra = ar == 2 ? extra_pi_m4 : extra_pi_ff, .model = ar == 2 ? pf_model_atan2 : pf_model_atan, \
     .ladder_cost = ATAN_EXACT_LADDER_COST}
#define ROW_ATAN_FAST(fn, tm, ar, red)                                                            \
    {.func = fn, .reduction = "recip", .variant = "fast", .tmpl = tm, .arity = ar,                \
     .reduction_text = red, .target_text = "atan(t)", .g = g_atan, .a = 0, .b = 1,                \
     .parity = FIT_PARITY_ODD, .errkind = FIT_REL, .ncon = 3, .con = ATAN_FAST_CON,               \
     .default_order = 0, .fast_target = 0x1p-10, .real = "fma", .extra = extra_pi_float}

/* The mid rows (variant "mid": ladder only, pfmathgen --max-ulp; the library
   does not ship them): the exact rows' fits (asin on [0, 1/2]) or the fast
   reduction's domain (atan on [0, 1], one division) with only the slope at 0
   constrained, evaluated as K + m v + c with K + m v exact and one final
   rounding, but the reduced argument (sqrtf, the quotient) rounded once and
   not carried as hi + lo (gen/templates/{asin,acos,atan,atan2}_mid.c.in).  Their cost over the
   fast template: the low part of K and a Fast2Sum, about two fmaf (4); the
   default order is what pfmathgen --variant would take, were it asked. */
#define MID_LADDER_COST 4
#define ROW_ASIN_MID(fn, tm, red, mo)                                                             \
    {.func = fn, .reduction = "sqrthalf", .variant = "mid", .tmpl = tm, .arity = 1,               \
     .reduction_text = red, .target_text = "asin(t)", .g = g_asin, .a = 0, .b = 0.5,              \
     .parity = FIT_PARITY_ODD, .errkind = FIT_REL, .ncon = 1, .con = {CON_SLOPE1},                \
     .default_order = 11, .real = "fma", .extra = extra_pi_ff, .model = mo,                       \
     .tail = "asin_acos_tail.c", .ladder_cost = MID_LADDER_COST}
#define ROW_ATAN_MID(fn, tm, ar, red, mo)                                                         \
    {.func = fn, .reduction = "recip", .variant = "mid", .tmpl = tm, .arity = ar,                 \
     .reduction_text = red, .target_text = "atan(t)", .g = g_atan, .a = 0, .b = 1,                \
     .parity = FIT_PARITY_ODD, .errkind = FIT_REL, .ncon = 1, .con = {CON_SLOPE1},                \
     .default_order = 19, .real = "fma", .extra = extra_pi_ff, .model = mo,                       \
     .ladder_cost = MID_LADDER_COST}

/* The lean rows (variant "lean": ladder only): the mid rows' fits, but the
   result is one fmaf mt P(z) + k with P = 1 + c3 z + ... rounded and k the
   nearest float of pi/2 (or pi): libmvec's shape.  Against the mid
   template: no Fast2Sum, no low part of K, no product t z (z P's variable
   carries c1 = 1), so no cost over the fast template's Horner terms
   (ladder_cost 1: after it at the same order).  Their floor is about 2 ULP
   (P's rounding near 1 and pi/2's 4.4e-8, 0.73 ULP of a result just above
   pi/4): atan2 at order 17 measures 2.1 ULP against libmvec's 3.2. */
#define ROW_ATAN_LEAN(fn, tm, ar, red, mo)                                                        \
    {.func = fn, .reduction = "recip", .variant = "lean", .tmpl = tm, .arity = ar,                \
     .reduction_text = red, .target_text = "atan(t)", .g = g_atan, .a = 0, .b = 1,                \
     .parity = FIT_PARITY_ODD, .errkind = FIT_REL, .ncon = 1, .con = {CON_SLOPE1},                \
     .default_order = 17, .real = "fma", .extra = extra_pi_float, .model = mo,                    \
     .ladder_cost = 1}

/* asin's lite row (gen/templates/asin_lite.c.in): the mid template without
   its Fast2Sum, (khi + u) + fmaf(u z, q, klo), and with the square root of
   the polynomial's variable itself (q runs on v = 4z, so sqrtf(v) = 2 sqrtf(w)
   to the bit; no separate 2 - 2a, no product by -2): about the fast
   template's operations (ladder_cost 1: after it at the same order). */
#define ROW_ASIN_LITE(fn, tm, red, mo)                                                            \
    {.func = fn, .reduction = "sqrthalf", .variant = "lite", .tmpl = tm, .arity = 1,              \
     .reduction_text = red, .target_text = "asin(t)", .g = g_asin, .a = 0, .b = 0.5,              \
     .parity = FIT_PARITY_ODD, .errkind = FIT_REL, .ncon = 1, .con = {CON_SLOPE1},                \
     .default_order = 11, .real = "fma", .extra = extra_pi_ff, .model = mo,                       \
     .tail = "asin_acos_tail.c", .ladder_cost = 1}

/* The lite rows (variant "lite": ladder only): the mid template without its
   Fast2Sum, (khi + m t) + fmaf(m t z, q, klo): two additions less than mid
   (cost 2), three operations more than lean, without pi/2's own error;
   khi + m t rounds exactly by Sterbenz where the result is smallest
   (t >= khi/2).  Order 17: 1.37 ULP over every float (atan), against the
   mid template's 1.3 at two operations more. */
#define ROW_ATAN_LITE(fn, tm, ar, red, mo)                                                        \
    {.func = fn, .reduction = "recip", .variant = "lite", .tmpl = tm, .arity = ar,                \
     .reduction_text = red, .target_text = "atan(t)", .g = g_atan, .a = 0, .b = 1,                \
     .parity = FIT_PARITY_ODD, .errkind = FIT_REL, .ncon = 1, .con = {CON_SLOPE1},                \
     .default_order = 17, .real = "fma", .extra = extra_pi_ff, .model = mo,                       \
     .ladder_cost = 2}

const pf_spec pf_specs_atrig[] = {
    ROW_ASIN_EXACT("asin", "asin_ff", ASIN_RED, pf_model_asin),
    ROW_ASIN_FAST("asin", "asin_fast", ASIN_RED, pf_model_asin_fast),
    ROW_ASIN_EXACT("acos", "acos_ff", ACOS_RED, pf_model_acos),
    ROW_ASIN_FAST("acos", "acos_fast", ACOS_RED, pf_model_acos_fast),
    ROW_ATAN_EXACT("atan", "atan_ff", 1, ATAN_RED),
    ROW_ATAN_FAST("atan", "atan_fast", 1, ATAN_RED_FAST),
    ROW_ATAN_EXACT("atan2", "atan2_ff", 2, ATAN2_RED),
    ROW_ATAN_FAST("atan2", "atan2_fast", 2, ATAN2_RED_FAST),
    ROW_ASIN_MID("asin", "asin_mid", ASIN_RED, pf_model_asin_mid),
    ROW_ASIN_MID("acos", "acos_mid", ACOS_RED, pf_model_acos_mid),
    ROW_ATAN_MID("atan", "atan_mid", 1, ATAN_RED_FAST, pf_model_atan_mid),
    ROW_ATAN_MID("atan2", "atan2_mid", 2, ATAN2_RED_FAST, pf_model_atan2_mid),
    ROW_ASIN_LITE("asin", "asin_lite", ASIN_RED, pf_model_asin_lite),
    ROW_ATAN_LEAN("atan", "atan_lean", 1, ATAN_RED_FAST, pf_model_atan_lean),
    ROW_ATAN_LITE("atan", "atan_lite", 1, ATAN_RED_FAST, pf_model_atan_lite),
    ROW_ATAN_LEAN("atan2", "atan2_lean", 2, ATAN2_RED_FAST, pf_model_atan2_lean),
    ROW_ATAN_LITE("atan2", "atan2_lite", 2, ATAN2_RED_FAST, pf_model_atan2_lite),
    {0},
};
