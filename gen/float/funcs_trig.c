/* Function table rows for the trig family: sin, cos, tan (see gen/float/funcs.h).
 *
 * Exact sin and cos (issue 12): float lanes, x = m pi/2 + r with r in
 * [-pi/4, pi/4] carried as rh + rl, sin's odd polynomial (the row's fit)
 * and cos's even one (fitted by extra_trig_ff) on [0, pi/4 + 2^-7], the
 * lane's by m's parity; Cody-Waite in float below 2^16, Payne-Hanek beyond
 * (sin_pio2_ff.c.in, model_ff).  The rest of this comment is about the
 * fast variants, the mid rows and tan.
 *
 * Two polynomials serve the three functions:
 *   sin(t) on [0, pi/2], odd: sin and cos.  The argument is reduced by pi,
 *     x + s pi/2 = k pi + r, r in [-pi/2, pi/2], s = 0 (sin) or 1 (cos), so
 *     sin(x) = (-1)^k sin(r) and cos(x) = sin(x + pi/2) = (-1)^k sin(r).
 *     One odd polynomial on [-pi/2, pi/2] then covers both: no cos
 *     polynomial and no quadrant select between two polynomials.
 *     Exception, the fast cos: cos(t) on [0, pi/2], even, on sin's
 *     reduction (s = 0), cos(x) = (-1)^k cos(r); its zeros sit at the
 *     folds, where the fast bound is absolute, and it saves the two
 *     additions of the + pi/2 and sin's clamp (sin_pi_fast_even.c.in).
 *   tan(t) on [0, pi/4], odd: x = n pi/2 + r, r in [-pi/4, pi/4],
 *     tan(x) = tan(r) (n even) or -1/tan(r) = -cot(r) (n odd).
 * Why this is enough: near the ends of [-pi/2, pi/2] sin is flat (slope
 * cos r -> 0), so the error of the reduction does not matter there; near
 * r = 0 the relative error of r is that of the result, and r is exact to
 * far more bits than float needs (below).
 *
 * Two paths per input, chosen by the same test in the scalar and the array
 * form (the array form computes Payne-Hanek only in blocks holding such an
 * input; gen/templates/sin_pio2_ff.c.in, sin_pi_fast*.c.in, tan_pio2*.c.in):
 * Exact tan (double evaluation with fma, float coefficients):
 *   |x| < 2^28: Cody-Waite with FMA, pi/2 = P1 + P2 + O(2^-107), 53-bit
 *     parts: fma(-m, P1, x) is exact, the second fma rounds once; r is right
 *     to 2^-49 of the smallest |r| of any float (2^-29.86 in units of pi/2,
 *     found by an exhaustive search: docs/trig.md).
 *   |x| >= 2^28 (every float up to 3.4e38), inf, NaN: Payne-Hanek, |x| 2/pi
 *     mod 4 in 64-bit fixed point (62 fraction bits) from a 96-bit window of
 *     the bits of 2/pi selected by the exponent (3 words of a 40-word
 *     table); the error, under 2 units of 2^-62, is below 2^-31 of the
 *     smallest |r| of any float.
 *   The bits of 2/pi and the splits of pi/2 come from MPFR here (the
 *   `extra` callbacks), never typed by hand.
 * Fast variants (float evaluation with fmaf): Cody-Waite with FMA in float
 *   for |x| < 2^17 (two 24-bit parts of pi/2 for sin and cos, three for tan:
 *   see extra_trig_float), Payne-Hanek beyond as above; the bound
 *   max(2^-10 relative, 2^-11 absolute) holds for every finite float. */
#include "funcs.h"

#include <math.h>
#include <stdio.h>
#include <stdint.h>
#include <string.h>

/* ---- fit targets, in the fit variable t ---- */
static void g_sin(mpfr_t y, const mpfr_t t, const void *c)
{
    (void)c;
    mpfr_sin(y, t, MPFR_RNDN);
}

/* sin(t) (1 - 2^-21 sin(t)^2): odd, slope 1 at 0, peak 1 - 2^-21 with slope
   0 at pi/2, within 2^-21 relative of sin (the fast variant's target) */
static void g_sin_lowered(mpfr_t y, const mpfr_t t, const void *c)
{
    (void)c;
    mpfr_t s;
    mpfr_init2(s, mpfr_get_prec(y) + 64);
    mpfr_sin(s, t, MPFR_RNDN);
    mpfr_sqr(y, s, MPFR_RNDN);
    mpfr_mul_2si(y, y, -21, MPFR_RNDN);
    mpfr_ui_sub(y, 1, y, MPFR_RNDN);
    mpfr_mul(y, y, s, MPFR_RNDN);
    mpfr_clear(s);
}

static void g_cos(mpfr_t y, const mpfr_t t, const void *c)
{
    (void)c;
    mpfr_cos(y, t, MPFR_RNDN);
}

static void g_tan(mpfr_t y, const mpfr_t t, const void *c)
{
    (void)c;
    mpfr_tan(y, t, MPFR_RNDN);
}

/* ---- constants of the reductions, computed with MPFR ---- */
#define TRIG_PREC 1024

/* v = pi/2 */
static void pio2(mpfr_t v)
{
    mpfr_const_pi(v, MPFR_RNDN);
    mpfr_div_2ui(v, v, 1, MPFR_RNDN);
}

/* Cody-Waite split: part[i] = the next `bits[i]` significant bits of pi/2
   (truncated toward the remainder, so every part but the last is exactly a
   prefix of pi/2's binary expansion), the last part rounded to prec bits. */
static void pio2_split(int nparts, const int *bits, int prec, double *part)
{
    mpfr_t rest, p;
    mpfr_init2(rest, TRIG_PREC);
    mpfr_init2(p, TRIG_PREC);
    pio2(rest);
    for (int i = 0; i < nparts; i++) {
        int b = i < nparts - 1 ? bits[i] : prec;
        mpfr_set_prec(p, b);
        mpfr_set(p, rest, i < nparts - 1 ? MPFR_RNDZ : MPFR_RNDN);
        part[i] = mpfr_get_d(p, MPFR_RNDN); /* exact: b <= 53 */
        mpfr_sub(rest, rest, p, MPFR_RNDN); /* exact at TRIG_PREC bits */
    }
    mpfr_clears(rest, p, (mpfr_ptr)0);
}

/* 2/pi * 2^scale rounded to prec bits */
static double twoopi(int prec, int scale)
{
    mpfr_t v;
    mpfr_init2(v, TRIG_PREC);
    mpfr_const_pi(v, MPFR_RNDN);
    mpfr_ui_div(v, 2, v, MPFR_RNDN);
    mpfr_mul_2si(v, v, scale, MPFR_RNDN);
    mpfr_prec_round(v, prec, MPFR_RNDN);
    double d = mpfr_get_d(v, MPFR_RNDN);
    mpfr_clear(v);
    return d;
}

/* pi/2 * 2^scale rounded to double */
static double pio2_scaled(int scale)
{
    mpfr_t v;
    mpfr_init2(v, TRIG_PREC);
    pio2(v);
    mpfr_mul_2si(v, v, scale, MPFR_RNDN);
    double d = mpfr_get_d(v, MPFR_RNDN);
    mpfr_clear(v);
    return d;
}

/* Bit i >= 1 of the binary expansion 2/pi = sum b_i 2^-i (b_i = 0 for i <= 0). */
#define PH_WORDS 40
static void twoopi_words(uint32_t *w)
{
    enum { NB = 8 * PH_WORDS + 64 };
    static unsigned char b[NB + 1];
    mpfr_t v;
    mpfr_init2(v, TRIG_PREC);
    mpfr_const_pi(v, MPFR_RNDN);
    mpfr_ui_div(v, 2, v, MPFR_RNDN); /* 2/pi < 1: b_0 = 0 */
    for (int i = 1; i <= NB; i++) {
        mpfr_mul_2ui(v, v, 1, MPFR_RNDN); /* exact */
        b[i] = mpfr_cmp_ui(v, 1) >= 0;
        if (b[i])
            mpfr_sub_ui(v, v, 1, MPFR_RNDN); /* exact */
    }
    mpfr_clear(v);
    /* word j holds b_i for i = 8j - 151 .. 8j - 120, most significant first:
       for a float of biased exponent e the template takes words e>>3, +4, +8
       and shifts the significand left by e&7 (see trig_ph.h.in) */
    for (int j = 0; j < PH_WORDS; j++) {
        uint32_t x = 0;
        for (int k = 0; k < 32; k++) {
            int i = 8 * j - 151 + k;
            x = x << 1 | (uint32_t)(i >= 1 ? b[i] : 0);
        }
        w[j] = x;
    }
}

/* Payne-Hanek constants, shared by every variant (the exact ones use them
   for |x| >= 2^CW_LOG2, the fast ones for |x| >= 2^FAST_LOG2): the result
   r = f * PIO2_2M62 for f the signed 62-bit fraction of |x| * 2/pi, and the
   bits of 2/pi from MPFR. */
static int extra_ph(char *buf, size_t n)
{
    uint32_t w[PH_WORDS];
    twoopi_words(w);
    int len = snprintf(
        buf, n,
        "/* Payne-Hanek for the rare large |x|: r = f * PF_TRIG_PIO2_2M62, f the signed\n"
        "   62-bit fraction of |x| * 2/pi */\n"
        "static const double PF_TRIG_PIO2_2M62 = %a;     /* pi/2 * 2^-62 */\n"
        "/* Bits of 2/pi = sum b_i 2^-i: word j holds b_(8j-151) .. b_(8j-120), b_i = 0\n"
        "   for i < 1.  A float of biased exponent e takes words e>>3, +4, +8: a 96-bit\n"
        "   window starting 2 bits above the units of |x| * 2/pi. */\n"
        "static const uint32_t PF_TRIG_2OPI_BITS[%d] = {",
        pio2_scaled(-62), PH_WORDS);
    for (int j = 0; j < PH_WORDS && len >= 0 && (size_t)len < n; j++)
        len += snprintf(buf + len, n - (size_t)len, "%s0x%08xu,", j % 6 ? " " : "\n    ", w[j]);
    if (len >= 0 && (size_t)len < n)
        len += snprintf(buf + len, n - (size_t)len, "\n};\n\n");
    return len;
}

/* Cody-Waite bound of the exact variants: |x| < 2^CW_LOG2.  With FMA,
   fma(-m, PIO2_1, x) is exact for every m (a multiple of 2^-52 below 2 in
   magnitude); the second step rounds once (2^-53 relative) and pi/2 - PIO2_1
   - PIO2_2 = O(2^-107), so r's error is below 2^-53 |r| + 2^(CW_LOG2-107),
   2^-49 of the smallest |r| of any float (2^-29.86 of pi/2).  The limit
   keeps x 2/pi's own rounding (2^-54 |x| 2/pi, for m) below 2^-26, so r
   leaves the polynomial's domain by at most that. */
#define CW_LOG2 28

static int extra_trig_double(char *buf, size_t n)
{
    double part[2];
    int bits[1] = {53};
    pio2_split(2, bits, 53, part);
    int len = snprintf(
        buf, n,
        "/* Reduction constants, computed with MPFR by pfmathgen (gen/float/funcs_trig.c).\n"
        "   Cody-Waite with FMA for |x| < 2^%d: pi/2 = PIO2_1 + PIO2_2 + O(2^-107),\n"
        "   fma(-m, PIO2_1, x) exact, fma(-m, PIO2_2, .) rounded once. */\n"
        "static const double PF_TRIG_2OPI = %a;          /* 2/pi */\n"
        "static const double PF_TRIG_PIO2_1 = %a;\n"
        "static const double PF_TRIG_PIO2_2 = %a;\n"
        "static const uint32_t PF_TRIG_CW_LIMIT = 0x%08xu; /* bits of 2^%d */\n",
        CW_LOG2, twoopi(53, 0), part[0], part[1], (unsigned)((127 + CW_LOG2) << 23), CW_LOG2);
    if (len >= 0 && (size_t)len < n)
        len += extra_ph(buf + len, n - (size_t)len);
    return len;
}

/* Fast variants: pi/2 in float parts of 24 bits (the last rounded); with
   FMA, fma(-m, P1, x) is exact for |x| >= 1 (a multiple of 2^-23 below 2)
   and each later step rounds once.  For |x| < 2^17 (m < 2^17):
   - sin, cos: two parts, r within 2^-24 + m (pi/2 - P1 - P2) < 2^-23
     absolute, far inside the absolute allowance 2^-11 of the fast bound
     max(2^-10 relative, 2^-11 absolute), which is all the zeros of sin and
     cos need;
   - tan: three parts, r right to about 2^-23 relative even next to a
     multiple of pi/2 (the smallest |r| there, 2^-27.9, is far above
     m (pi/2 - P1 - P2 - P3) < 2^-55), which the poles need: there the bound
     is relative and tan = -1/r (1 + O(r^2)). */
#define FAST_LOG2 17
static int extra_trig_float(char *buf, size_t n, int nparts)
{
    double part[3];
    int bits[2] = {24, 24};
    pio2_split(nparts, bits, 24, part);
    int len = snprintf(buf, n,
                       "/* Reduction constants, computed with MPFR by pfmathgen (gen/float/funcs_trig.c):\n"
                       "   2/pi rounded to float; pi/2 = sum PF_TRIG_PIO2F[i] (Cody-Waite with\n"
                       "   FMA), 24-bit parts, the last rounded; for |x| < 2^%d. */\n"
                       "static const float PF_TRIG_2OPIF = %af;\n"
                       "#define PF_TRIG_NPARTS %d\n"
                       "static const float PF_TRIG_PIO2F[PF_TRIG_NPARTS] = {",
                       FAST_LOG2, twoopi(24, 0), nparts);
    for (int i = 0; i < nparts && len >= 0 && (size_t)len < n; i++)
        len += snprintf(buf + len, n - (size_t)len, "%s%af", i ? ", " : "", part[i]);
    if (len >= 0 && (size_t)len < n)
        len += snprintf(buf + len, n - (size_t)len,
                        "};\nstatic const uint32_t PF_TRIG_CW_LIMIT = 0x%08xu; /* bits of 2^%d */\n",
                        (unsigned)((127 + FAST_LOG2) << 23), FAST_LOG2);
    if (len >= 0 && (size_t)len < n)
        len += extra_ph(buf + len, n - (size_t)len);
    return len;
}
static int extra_sincos_float(char *buf, size_t n) { return extra_trig_float(buf, n, 2); }
static int extra_tan_float(char *buf, size_t n) { return extra_trig_float(buf, n, 3); }

/* Mid variants (ladder only; sin_cw_float.c.in, tan_cw_float.c.in): float
   lanes, Cody-Waite with FMA for |x| < 2^MID_LOG2 with three 24-bit parts of
   pi/2 (the first two truncated prefixes, the third rounded: pi/2 - P1 - P2
   - P3 < 2^-72), the third kept apart as c = -m P3 so that r carries a single
   rounding (the templates' comments).  2^16 keeps the bench's [-1e4, 1e4]
   on the Cody-Waite path and |c| <= 2^16 P3 < 2^-32. */
#define MID_LOG2 16
static int extra_trig_mid(char *buf, size_t n)
{
    double part[3];
    int bits[2] = {24, 24};
    pio2_split(3, bits, 24, part);
    int len = snprintf(buf, n,
                       "/* Reduction constants, computed with MPFR by pfmathgen (gen/float/funcs_trig.c):\n"
                       "   2/pi rounded to float; pi/2 = P1 + P2 + P3 + O(2^-72), P1 and P2 24-bit\n"
                       "   prefixes, P3 rounded; Cody-Waite with FMA for |x| < 2^%d. */\n"
                       "static const float PF_TRIG_2OPIF = %af;\n"
                       "static const float PF_TRIG_PIO2F[3] = {%af, %af, %af};\n"
                       "static const uint32_t PF_TRIG_CW_LIMIT = 0x%08xu; /* bits of 2^%d */\n",
                       MID_LOG2, twoopi(24, 0), part[0], part[1], part[2],
                       (unsigned)((127 + MID_LOG2) << 23), MID_LOG2);
    if (len >= 0 && (size_t)len < n)
        len += extra_ph(buf + len, n - (size_t)len);
    return len;
}

/* Error model of the mid variants, a first-order bound in ULP of the result,
   the maximum over a fine grid of r in [R_MIN, b].  Each rounding errs by
   at most half an ulp of its value, hu(v) (the value's binade taken
   MID_MARGIN above the grid point, so that the points between are
   covered); an absolute error E costs E / ulp(f(r)) ULP (the binade taken
   MID_MARGIN below):
     0.5                 the final subtraction r - v (sin, cos: 0 where it
                         is exact, mid_final) or addition
   + the roundings of w  z = r^2, Horner on z, r z (or r^3 once), and the
                         fmafs forming w (mid_bound's forms), propagated to
                         w to first order
   + the fit error       max_err |f(r)| (relative fit)
   + the reduction       r2's one rounding, hu(r), times |f'(r)|; cos
                         (s = 1): for |x| < 1, r1 = x - P1 (m = 1) rounds
                         too when |r1| >= 1 (x is finer than P1 there; below
                         1 it is a multiple of 2^-24 and exact), hu(r)
                         |f'(r)| more where |r| > 1 - 2^-20
   + the tail c          its rounding u |c| and the term dropped from
                         f(r2 + c) (sin: |c| r^2 / 2, tan: |c| tan^2 r),
                         |c| <= 2^MID_LOG2 2/pi P3
   + tan, n odd          -1/p rounds once more: 0.5.
   R_MIN = 2^-27.8: no float below 2^20 comes closer to a multiple of pi/2
   (2^-28.5 units of pi/2, docs/trig.md), so no r with m != 0 is smaller
   (m = 0 makes r = x exact and c = 0, and the error is the polynomial's). */
#define MID_RMIN 0x1.2p-28
/* 2^18 points: neighbours differ by under 2^-11 relative (the geometric
   part by 2^-12), so r^3 by under 2^-9.4: the margin MID_MARGIN of the
   binades below covers every value between two points (it was 2^-6 with
   2^14 points, which charged z = r^2 the binade of 2 from r = 1.39 on) */
#define MID_GRID (1 << 18)
#define MID_MARGIN 0x1p-9
static double mid_hu(double v) /* half an ulp of a float near |v| */
{
    int e;
    frexp(fabs(v) * (1 + MID_MARGIN), &e);
    return ldexp(1.0, e - 25);
}
static double mid_ulp(double f) /* an ulp of a float near |f|, from below */
{
    int e;
    frexp(fabs(f) * (1 - MID_MARGIN), &e);
    return ldexp(1.0, e - 24);
}
/* The final rounding of sin and cos's r - v (v = -(c3 t + inner), the last
   fmaf's value, 0 <= v <= r), in ULP of f: 0.5, except where v and the
   result share a binade [B, 2B): then r (a multiple of ulp(r) >= ulp(f),
   as r >= f) and the rounded v are multiples of ulp(v) = B 2^-23, and so is
   r - v, which lies in [B, 2B): the subtraction is exact (0).  Near the
   edge (v within the margin of B) either the rounded v is >= B (exact
   subtraction) or below B, where its rounding was half the one the caller
   charged (mid_hu(v) counts B's binade): 0.5 - that half, in ULP.  The
   binades are taken with the same margins as mid_hu and mid_ulp.
   This takes the bound of mid order 9 from 2.35 to below 2 (the term that
   set it, v >= 1/2 for r > 1.497, is where the subtraction is exact). */
static double mid_final(double r, double t, double c3, double in, double cmax, double f)
{
    (void)r;
    double v = fabs(c3 * t + in), af = fabs(f);
    int ef, eh;
    frexp(af * (1 - MID_MARGIN), &ef);
    frexp(af * (1 + MID_MARGIN), &eh);
    /* f straddles a binade: no claim, except at 1 (|f| <= 1): there r - v
       is a multiple of 2^-24 too, and one in [1, 1 + 2^-24] rounds to 1.0
       (a tie goes to even), no further from f than r - v itself; one
       beyond would already be 2 ULP away */
    if (ef != eh && ef != 0)
        return 0.5;
    double B = ldexp(1.0, ef - 1);
    double vlo = (v - cmax) * (1 - MID_MARGIN), vhi = (v + cmax) * (1 + MID_MARGIN);
    if (vlo >= B)
        return 0;
    if (vhi >= B) /* v rounded to below B: its rounding was hu(B) / 2 */
        return 0.5 - 0.5 * mid_hu(v + cmax) / mid_ulp(f);
    return 0.5;
}

/* form: 0 tan's w = fmaf(r z, q, c), q = c3 + c5 z + ...; 1 sin and cos's
   w = fmaf(t, c3, fmaf(t z, q5, c)), t = r z, q5 = c5 + c7 z + ...; 2 the
   same with t = r^3 rounded once (z + fmaf(r, r, -z) = r^2 exactly) */
static double mid_bound(const fit_poly *p, int tan_, int cos_, int form, double b, double *at)
{
    const double u = 0x1p-24;
    double part[3];
    int bits[2] = {24, 24};
    pio2_split(3, bits, 24, part);
    double cmax = ldexp(1.0, MID_LOG2) * 0.6366197723675814 * part[2] * 1.0001;
    int nq = 0, k0 = form ? 5 : 3;
    double a[FIT_MAX_ORDER + 1], c3 = p->order >= 3 ? (double)p->c[3] : 0;
    for (int k = k0; k <= p->order; k += 2)
        a[nq++] = (double)p->c[k];
    double worst = 0;
    *at = 0;
    for (int i = 0; i <= MID_GRID; i++) {
        /* geometric near 0 (where |f| is small), uniform above 2^-6 */
        double r = i < MID_GRID / 4 ? MID_RMIN * pow(0x1p-6 / MID_RMIN, (double)i / (MID_GRID / 4))
                                    : 0x1p-6 + (b - 0x1p-6) * (i - MID_GRID / 4) / (0.75 * MID_GRID);
        double z = r * r, ez = mid_hu(z);
        double s = nq ? a[nq - 1] : 0, es = 0; /* q or q5 and its error */
        for (int j = nq - 2; j >= 0; j--) {
            double v = s * z + a[j];
            es = fabs(z) * es + fabs(s) * ez + mid_hu(v);
            s = v;
        }
        double t = r * z, et = form == 2 ? mid_hu(t) + mid_hu(r * u * z) : r * ez + mid_hu(t), ew = 0;
        if (form == 0 && nq) {
            double w = t * s;
            ew = fabs(t) * es + fabs(s) * et + mid_hu(fabs(w) + cmax);
        } else if (form && p->order >= 3) {
            double tz = t * z, etz = fabs(z) * et + fabs(t) * ez + mid_hu(tz), in = tz * s;
            double ein = nq ? fabs(tz) * es + fabs(s) * etz + mid_hu(fabs(in) + cmax) : 0;
            ew = fabs(c3) * et + ein + mid_hu(fabs(c3 * t + in) + cmax);
        }
        double f = tan_ ? tan(r) : sin(r), df = tan_ ? 1 + f * f : cos(r);
        double err = ew + p->max_err * fabs(f) + mid_hu(r) * df;
        if (cos_ && r > 1 - 0x1p-20)
            err += mid_hu(r) * df;
        err += u * cmax + cmax * (tan_ ? f * f : z / 2);
        double fin = form ? mid_final(r, t, c3, nq ? t * z * s : 0, cmax, f) : 0.5;
        double ulp = fin + err / mid_ulp(f) + (tan_ ? 0.5 : 0);
        if (ulp > worst)
            worst = ulp, *at = r;
    }
    return worst;
}

static int model_mid(const fit_poly *p, pf_scheme *sc, int tan_, int cos_, int form, double b)
{
    double at;
    sc->ncomp = form == 2;
    sc->bound_ulp = mid_bound(p, tan_, cos_, form, b, &at);
    snprintf(sc->text, sizeof sc->text,
             "float lanes with fmaf: r carries one rounding (tail c = -m P3 kept apart), %s; "
             "first-order bound's worst r = %.4g",
             tan_ ? "r + (r z q(z) + c), -1/p for n odd"
             : form == 2 ? "r + (c3 r^3 + r^3 z q5(z) + c), r^3 rounded once (r^2 = z + fmaf(r, r, -z))"
                         : "r + (c3 r^3 + r^3 z q5(z) + c), r^3 = r z",
             at);
    return 0;
}

/* Error model of the exact variants (double evaluation): the reduction and
   Horner's rule in double add under 2^-48 relative (the reduction's 2^-49
   above, each fma 2^-53 on terms that do not cancel), -1/p (tan) one more
   2^-53; the result is then rounded to float once.  So the error is at most
   0.5 ULP + (fit error + 2^-48) 2^24 ULP (an ulp of y is >= |y| 2^-24). */
static int model_double(const fit_poly *p, int order, pf_scheme *sc)
{
    (void)order;
    sc->ncomp = 0;
    sc->bound_ulp = 0.5 + (p->max_err + 0x1p-48) * 0x1p24;
    snprintf(sc->text, sizeof sc->text,
             "reduction and Horner in double with fma (float coefficients), one rounding to float");
    if (sc->bound_ulp > 1.0) {
        snprintf(sc->text, sizeof sc->text, "fit error %.3g leaves %.3f ULP > 1", p->max_err, sc->bound_ulp);
        return -1;
    }
    return 0;
}

/* the mid rows' domains: past pi/2 (pi/4) by 2^-7, what the rounded x 2/pi
   (and cos's + 1) can move r for |x| < 2^MID_LOG2 (sin_cw_float.c.in) */
#define MID_PAST 0x1p-7
static int model_mid_sin(const fit_poly *p, int order, pf_scheme *sc)
{
    (void)order;
    return model_mid(p, sc, 0, 0, 1, 1.5707963267948966 + MID_PAST);
}
static int model_mid_cos(const fit_poly *p, int order, pf_scheme *sc)
{
    (void)order;
    return model_mid(p, sc, 0, 1, 1, 1.5707963267948966 + MID_PAST);
}
/* the same with r^3 rounded once: one compensated step (@NCOMP@ = 1) */
static int model_mid_sin_c(const fit_poly *p, int order, pf_scheme *sc)
{
    (void)order;
    return model_mid(p, sc, 0, 0, 2, 1.5707963267948966 + MID_PAST);
}
static int model_mid_cos_c(const fit_poly *p, int order, pf_scheme *sc)
{
    (void)order;
    return model_mid(p, sc, 0, 1, 2, 1.5707963267948966 + MID_PAST);
}
static int model_mid_tan(const fit_poly *p, int order, pf_scheme *sc)
{
    (void)order;
    return model_mid(p, sc, 1, 0, 0, 0.7853981633974483 + MID_PAST);
}

/* ---- exact sin and cos in float lanes (issue 12; sin_pio2_ff.c.in) ----
   x = m pi/2 + r, r in [-pi/4, pi/4] (FF_PAST beyond: x 2/pi rounds in float
   for |x| < 2^FF_LOG2), sin r from the row's odd polynomial, cos r from an
   even one fitted here (1 - t^2/2 + c4 t^4 + ..., relative error, p(0) = 1 and
   c2 = -1/2 exactly), the lane's polynomial chosen by m's parity.  Cody-Waite
   with FMA in float for |x| < 2^FF_LOG2 (three 24-bit parts of pi/2, r kept
   as a float pair rh + rl: TwoProd of m P2 and Fast2Sum, see the template),
   Payne-Hanek beyond.  2^16 keeps the bench's [-1e4, 1e4] on the vector
   path; m < 2^15.4 there, so m P2 < 2^-8.3 (r1 is a multiple of its ulp) and
   m (pi/2 - P1 - P2 - P3) < 2^-56. */
#define FF_LOG2 16
#define FF_PAST 0x1p-7
#define FF_COS_ORDER 8

static int cos_ff_fit_once(fit_poly *out, char *err, size_t errlen)
{
    fit_problem pb;
    memset(&pb, 0, sizeof pb);
    pb.g = g_cos;
    pb.a = 0;
    pb.b = 0.7853981633974483 + FF_PAST;
    pb.order = FF_COS_ORDER;
    pb.parity = FIT_PARITY_EVEN;
    pb.errkind = FIT_REL;
    pb.ncon = 2;
    pb.con[0].kind = FIT_CON_VALUE; /* p(0) = cos 0 = 1 */
    pb.con[0].t = 0;
    pb.con[1].kind = FIT_CON_COEF; /* c2 = -1/2 exactly: the template's rh^2/2 */
    pb.con[1].index = 2;
    pb.con[1].value = -0.5;
    if (fit_minimax(&pb, out, err, errlen) != 0)
        return -1;
    fit_coeffmt fmt = {FIT_COEF_FLOAT, 0};
    if (fit_round(&pb, fmt, fit_minimax, out, NULL, err, errlen) != 0)
        return -1;
    fit_measure(&pb, out);
    return 0;
}

/* cos's fit depends on nothing but the constants above; the row's extra
   (the emitted table) and its model (every order the ladder tries) both
   need it, so it is fitted once a process (generation is single-threaded) */
static int cos_ff_fit(fit_poly *out, char *err, size_t errlen)
{
    static fit_poly c;
    static int state; /* 0 not yet, 1 fitted, -1 failed */
    static char msg[256];
    if (!state) {
        state = cos_ff_fit_once(&c, msg, sizeof msg) == 0 ? 1 : -1;
    }
    if (state < 0) {
        snprintf(err, errlen, "%s", msg);
        return -1;
    }
    *out = c;
    return 0;
}

static int extra_trig_ff(char *buf, size_t n)
{
    double part[3];
    int bits[2] = {24, 24};
    pio2_split(3, bits, 24, part);
    fit_poly c;
    char err[256];
    if (cos_ff_fit(&c, err, sizeof err) != 0)
        return snprintf(buf, n, "#error cos fit failed: %s\n", err);
    int len = snprintf(buf, n,
                       "/* Reduction constants, computed with MPFR by pfmathgen (gen/float/funcs_trig.c):\n"
                       "   2/pi rounded to float; pi/2 = P1 + P2 + P3 + O(2^-72), P1 and P2 24-bit\n"
                       "   prefixes, P3 rounded; Cody-Waite with FMA in float for |x| < 2^%d. */\n"
                       "static const float PF_TRIG_2OPIF = %af;\n"
                       "static const float PF_TRIG_PIO2F[3] = {%af, %af, %af};\n"
                       "static const uint32_t PF_TRIG_CW_LIMIT = 0x%08xu; /* bits of 2^%d */\n"
                       "/* cos(t) ~ 1 - t^2/2 + sum PF_TRIG_COSC[k] t^(2k+4) on [0, pi/4 + 2^%d]: fitted\n"
                       "   by pfmathgen (minimax relative error, p(0) = 1 and c2 = -1/2 exact,\n"
                       "   coefficients rounded to float by pin-and-refit), order %d; max relative\n"
                       "   error %.3e (2^%.2f) at t = %a */\n"
                       "#define PF_TRIG_NCOSC %d\n"
                       "static const float PF_TRIG_COSC[PF_TRIG_NCOSC] = {",
                       FF_LOG2, twoopi(24, 0), part[0], part[1], part[2], (unsigned)((127 + FF_LOG2) << 23),
                       FF_LOG2, (int)log2(FF_PAST), FF_COS_ORDER, c.max_err, log2(c.max_err), c.max_err_at,
                       FF_COS_ORDER / 2 - 1);
    for (int k = 4; k <= FF_COS_ORDER && len >= 0 && (size_t)len < n; k += 2)
        len += snprintf(buf + len, n - (size_t)len, "%s%af", k > 4 ? ", " : "", (double)c.c[k]);
    if (len >= 0 && (size_t)len < n)
        len += snprintf(buf + len, n - (size_t)len, "};\n");
    if (len >= 0 && (size_t)len < n)
        len += extra_ph(buf + len, n - (size_t)len);
    return len;
}

/* Error model of the float-lane exact sin and cos (sin_pio2_ff.c.in), a
   first-order bound in ULP of the result, the maximum over a grid of r in
   [MID_RMIN, pi/4 + FF_PAST] for either kind of lane.  Each rounding errs
   by at most half an ulp of its value (mid_hu), an absolute error E costs
   E / ulp(f(r)) ULP (mid_ulp); rl, the low part of r, is at most half an
   ulp of r (Cody-Waite: the exact Fast2Sum error plus m P2's exact tail;
   Payne-Hanek: r's one split).
   sin lanes, f = rh - w, w = fmaf(A, -S(z), nrl), A = (rh + 3 rl) z:
     0.5 (the final subtraction) + w's rounding + A's (z = rh^2 rounded,
     rh + 3 rl rounded, the product rounded: each times |S|) + Horner's on
     -S (times |A|) + the fit error + what 3 rl z S(z) leaves of rl's
     factor cos r - 1 (|rl| |3 z S + 1 - cos r|) + the reduction's tail.
   cos lanes, f = 1 - w, w = fmaf(rh/2, rh, I), I = fmaf(z^2, -C(z), rh rl):
     0.5 + w's and I's roundings + z^2's (z and the square, times |C|) +
     Horner's on -C (times z^2) + rh rl's + the fit error + the terms the
     scheme drops (rl^2/2 and rl (rh - sin rh)) + the tail.
   R_MIN as for the mid rows: no float with m != 0 lands closer to a
   multiple of pi/2 than 2^-28.5 units of it below 2^20 (docs/trig.md). */
static double ff_horner(const double *a, int n, double z, double ez, double *es)
{
    double s = n ? a[n - 1] : 0;
    *es = 0;
    for (int j = n - 2; j >= 0; j--) {
        double v = s * z + a[j];
        *es = fabs(z) * *es + fabs(s) * ez + mid_hu(v);
        s = v;
    }
    return s;
}

static int model_ff(const fit_poly *p, int order, pf_scheme *sc)
{
    (void)order;
    fit_poly c;
    char err[256];
    if (cos_ff_fit(&c, err, sizeof err) != 0) {
        snprintf(sc->text, sizeof sc->text, "cos fit failed: %s", err);
        return -1;
    }
    double as[FIT_MAX_ORDER + 1], ac[FIT_MAX_ORDER + 1];
    int ns = 0, nc = 0;
    for (int k = 3; k <= p->order; k += 2)
        as[ns++] = (double)p->c[k];
    for (int k = 4; k <= c.order; k += 2)
        ac[nc++] = (double)c.c[k];
    double part[3];
    int bits[2] = {24, 24};
    pio2_split(3, bits, 24, part);
    /* m (pi/2 - P1 - P2 - P3): P3 is rounded to 24 bits, so the rest is below
       half its ulp */
    double tail = ldexp(1.0, FF_LOG2) * 0.6366197723675814 * 1.0001 * mid_hu(part[2]) * 2;
    const double b = 0.7853981633974483 + FF_PAST;
    double worst_s = 0, worst_c = 0, at_s = 0, at_c = 0;
    for (int i = 0; i <= MID_GRID; i++) {
        double r = i < MID_GRID / 4 ? MID_RMIN * pow(0x1p-6 / MID_RMIN, (double)i / (MID_GRID / 4))
                                    : 0x1p-6 + (b - 0x1p-6) * (i - MID_GRID / 4) / (0.75 * MID_GRID);
        double rl = mid_hu(r), z = r * r, ez = mid_hu(z);
        /* sin lane */
        double es, S = ff_horner(as, ns, z, ez, &es);
        double A = r * z, eA = z * mid_hu(r) + r * ez + mid_hu(A);
        double w = A * S, ew = fabs(S) * eA + fabs(A) * es + mid_hu(fabs(w) + rl);
        double f = sin(r);
        double e = ew + p->max_err * f + rl * fabs(3 * z * S + 1 - cos(r)) + mid_hu(rl) + tail;
        double u = 0.5 + e / mid_ulp(f);
        if (u > worst_s)
            worst_s = u, at_s = r;
        /* cos lane */
        double ec, C = ff_horner(ac, nc, z, ez, &ec);
        double z2 = z * z, ez2 = 2 * z * ez + mid_hu(z2);
        double I = -z2 * C + r * rl, eI = fabs(C) * ez2 + z2 * ec + mid_hu(r * rl) + mid_hu(fabs(I));
        double wc = z / 2 + I, ewc = eI + mid_hu(wc);
        double fc = cos(r);
        double e2 = ewc + c.max_err * fc + rl * rl / 2 + rl * (r - sin(r)) + tail;
        double u2 = 0.5 + e2 / mid_ulp(fc);
        if (u2 > worst_c)
            worst_c = u2, at_c = r;
    }
    sc->ncomp = 0;
    sc->bound_ulp = worst_s > worst_c ? worst_s : worst_c;
    int tl = snprintf(sc->text, sizeof sc->text,
             "float lanes with fmaf: pi/2 reduction to rh + rl (TwoProd, Fast2Sum), one Horner chain a lane "
             "with sin's or cos's coefficients by m's parity (sin: odd, the Order line's order; cos: "
             "even, order %d, fixed); sin lanes rh - fmaf((rh + 3 rl) z, -S, -rl), "
             "cos lanes 1 - fmaf(rh/2, rh, fmaf(z^2, -C, rh rl)); first-order bound: sin lanes %.3f "
             "(worst r = %.4g), cos lanes %.3f (r = %.4g; cos fit %.3e)",
             c.order, worst_s, at_s, worst_c, at_c, c.max_err);
    if (tl < 0 || (size_t)tl >= sizeof sc->text) /* a cut provenance line would hide the cos bound */
        return -1;
    if (sc->bound_ulp > 1.0)
        return -1;
    return 0;
}

/* ---- rows ---- */
#define PIO2 1.5707963267948966 /* the nearest double to pi/2 (below it) */
#define PIO4 0.7853981633974483

#define SIN_RED "x + s pi/2 = k pi + r, r in [-pi/2, pi/2] (s = 0); sin x = (-1)^k sin r"
#define COS_RED "x + s pi/2 = k pi + r, r in [-pi/2, pi/2] (s = 1); cos x = sin(x + pi/2) = (-1)^k sin r"
#define COS_RED_EVEN "x = k pi + r, r in [-pi/2, pi/2]; cos x = (-1)^k cos r"
#define TAN_RED "x = n pi/2 + r, r in [-pi/4, pi/4]; tan x = tan r (n even), -1/tan r (n odd)"
#define RED_EXACT ", Cody-Waite with FMA in double |x| < 2^28, Payne-Hanek beyond (array: only in blocks holding such an x)"
#define RED_FAST ", Cody-Waite with FMA in float |x| < 2^17, Payne-Hanek beyond (array: only in blocks holding such an x)"

#define CON_SLOPE1 {FIT_CON_DERIV, 0, "p'(0) = 1"}
#define SIN_FAST_CON {CON_SLOPE1, {FIT_CON_VALUE, PIO2, "p(pi/2) = 1 - 2^-21"}, {FIT_CON_DERIV, PIO2, "p'(pi/2) = 0"}}
/* cos, fast (even): q(0) = 1 exactly, so cos(0) = 1 and |f| <= 1 with no
   clamp; q(pi/2) = 0, so the folds at r = +-pi/2 are continuous (the slope
   is, by parity) */
#define COS_FAST_CON {{FIT_CON_VALUE, 0, "p(0) = 1"}, {FIT_CON_VALUE, PIO2, "p(pi/2) = 0"}}
#define TAN_FAST_CON {CON_SLOPE1, {FIT_CON_VALUE, PIO4, "p(pi/4) = 1"}, {FIT_CON_DERIV, PIO4, "p'(pi/4) = 2"}}

/* exact orders: the smallest odd orders whose float-coefficient polynomial
   keeps the model's bound (model_double: 0.5 + (fit error + 2^-48) 2^24 ULP)
   within 1 ULP with room for the sweep: sin 9 reaches 2^-27.3 (0.60 ULP;
   7: 2^-22.0, over 1 ULP), tan 13 reaches 2^-25.7 (0.81 ULP; 11: 2^-21.9).
   Exhaustive sweeps: docs/trig.md. */
#define SIN_EXACT_ORDER 9
#define TAN_EXACT_ORDER 13

/* sin and cos, exact (sin_pio2_ff.c.in): float lanes, reduction by pi/2
   with sin's and cos's polynomials (model_ff).  Sin order 7 on
   [0, pi/4 + 2^-7] reaches 2^-27.9 (the model's bound ~0.83 ULP with cos's
   order 8 beside it; sin 5 reaches only 2^-20).  ladder_cost 20: the
   reduction's ten operations, the per-lane selects, cos's and the sign's
   few, beside 2 a Horner term (above the mid rows' 10: the ladder's 2- and
   3-ULP levels keep those).  The row keeps the key .reduction = "pi" of
   sin's and cos's other rows although it reduces by pi/2: the ladder
   (gen/float/ladder.c) weighs the rows sharing the default row's key. */
#define SIN_FF_ORDER 7
#define RED_FF "x = m pi/2 + r, r in [-pi/4, pi/4], q = m + s (s = 0: sin, 1: cos); f = (-1)^(q>>1) (q even: sin r, q odd: cos r), Cody-Waite with FMA in float |x| < 2^16 (r = rh + rl: TwoProd, Fast2Sum), Payne-Hanek beyond (array: only in blocks holding such an x)"
#define ROW_SIN_EXACT(fn, phase)                                                                  \
    {.func = fn, .reduction = "pi", .variant = "exact", .tmpl = "sin_pio2_ff", .arity = 1,        \
     .head = "trig_ph.h", .tail = "tail_twopath.c", .reduction_text = RED_FF,                     \
     .target_text = "sin(t) (and cos(t), even, fitted beside it)", .g = g_sin, .a = 0,           \
     .b = PIO4 + FF_PAST, .parity = FIT_PARITY_ODD, .errkind = FIT_REL, .ncon = 1,               \
     .con = {CON_SLOPE1}, .default_order = SIN_FF_ORDER, .real = "fma", .kscale = phase,          \
     .ulp_bound = 1.0, .extra = extra_trig_ff, .model = model_ff, .ladder_cost = 20}
/* exact-double (ladder only, --max-ulp below the float-lane row's 0.83):
   the previous exact scheme (sin_pi.c.in), reduction by pi and Horner in
   double lanes with fma (model_double: 0.603 ULP at order 9, every float
   0.6031).  It keeps a pfmath point more accurate than SLEEF u10 (0.78-0.79
   ULP on the bench's domains) at the ladder's 0.75 level (mk/ladder.mk);
   the double rule's cost (4 a term + 12) puts it above the float-lane row,
   so the 1-ULP level keeps that one. */
#define ROW_SIN_DBL(fn, phase, red)                                                               \
    {.func = fn, .reduction = "pi", .variant = "exact-double", .tmpl = "sin_pi", .arity = 1,      \
     .head = "trig_ph.h", .tail = "tail_twopath.c",                                               \
     .reduction_text = red RED_EXACT, .target_text = "sin(t)", .g = g_sin, .a = 0, .b = PIO2,     \
     .parity = FIT_PARITY_ODD, .errkind = FIT_REL, .ncon = 1, .con = {CON_SLOPE1},                \
     .default_order = SIN_EXACT_ORDER, .real = "double", .kscale = phase, .ulp_bound = 1.0,      \
     .extra = extra_trig_double, .model = model_double}
/* sin, fast (sin_pi_fast.c.in): fitted to sin lowered by 2^-21 at its peak,
   so that Horner's rule in float (a few ulps of rounding) keeps |p| <= 1
   with no clamp; the value 1 - 2^-21 and slope 0 at pi/2 come from the
   target through the constraints, slope 1 at 0 as before */
#define SIN_FAST_ROW                                                                              \
    {.func = "sin", .reduction = "pi", .variant = "fast", .tmpl = "sin_pi_fast", .arity = 1,      \
     .head = "trig_ph.h", .tail = "tail_twopath.c",                                               \
     .reduction_text = SIN_RED RED_FAST, .target_text = "sin(t) (1 - 2^-21 sin(t)^2)",           \
     .g = g_sin_lowered, .a = 0, .b = PIO2, .parity = FIT_PARITY_ODD, .errkind = FIT_REL,        \
     .ncon = 3, .con = SIN_FAST_CON, .default_order = 0, .fast_target = 0x1p-10, .real = "fma",  \
     .extra = extra_sincos_float}

#define RED_MID ", Cody-Waite with FMA in float |x| < 2^16 (r2 + c, one rounding), Payne-Hanek beyond (array: only in blocks holding such an x)"
/* mid (ladder only, --max-ulp): float lanes, r + r^3 q(r^2) with c1 = 1
   exact; ladder_cost 10: the float reduction (three fmaf, a subtraction, the
   tail's product), the final subtraction and the split-off c3 term's two
   operations, beside 2 a Horner term.  Two rows: "mid", r^3 = r z, and
   "mid-r3", r^3 rounded once (model *_c: one compensated step, 8 more by
   the ladder's cost).  The variant names differ so that pf_generate finds
   each (it looks a row up by function, variant and reduction). */
#define ROW_SIN_MID(fn, var, phase, red, mdl)                                                       \
    {.func = fn, .reduction = "pi", .variant = var, .tmpl = "sin_cw_float", .arity = 1,           \
     .head = "trig_ph.h", .tail = "tail_twopath.c",                                               \
     .reduction_text = red RED_MID, .target_text = "sin(t)", .g = g_sin, .a = 0,                  \
     .b = PIO2 + MID_PAST, .parity = FIT_PARITY_ODD, .errkind = FIT_REL, .ncon = 1,               \
     .con = {CON_SLOPE1}, .default_order = SIN_EXACT_ORDER, .real = "fma", .kscale = phase,       \
     .extra = extra_trig_mid, .model = mdl, .ladder_cost = 10}

const pf_spec pf_specs_trig[] = {
    ROW_SIN_EXACT("sin", "0"),
    SIN_FAST_ROW,
    ROW_SIN_MID("sin", "mid", "0", SIN_RED, model_mid_sin),
    ROW_SIN_MID("sin", "mid-r3", "0", SIN_RED, model_mid_sin_c),
    ROW_SIN_DBL("sin", "0", SIN_RED),
    ROW_SIN_EXACT("cos", "1"),
    /* cos, fast: the even polynomial of cos on the reduction of sin (two
       fewer additions a vector than sin(x + pi/2), no |r| and no clamp:
       sin_pi_fast_even.c.in).  Fitted for absolute error 2^-11 (cos's zeros
       are at the folds, where the bound is absolute; elsewhere
       2^-10 |cos| >= 2^-11 |cos| as well) with room for the roundings. */
    {.func = "cos", .reduction = "pi", .variant = "fast", .tmpl = "sin_pi_fast_even", .arity = 1,
     .head = "trig_ph.h", .tail = "tail_twopath.c",
     .reduction_text = COS_RED_EVEN RED_FAST, .target_text = "cos(t)", .g = g_cos, .a = 0, .b = PIO2,
     .parity = FIT_PARITY_EVEN, .errkind = FIT_ABS, .ncon = 2, .con = COS_FAST_CON,
     .default_order = 0, .fast_target = 0x1.cp-12, .real = "fma", .extra = extra_sincos_float},
    ROW_SIN_MID("cos", "mid", "1", COS_RED, model_mid_cos),
    ROW_SIN_MID("cos", "mid-r3", "1", COS_RED, model_mid_cos_c),
    ROW_SIN_DBL("cos", "1", COS_RED),
    {.func = "tan", .reduction = "pio2", .variant = "exact", .tmpl = "tan_pio2", .arity = 1,
     .head = "trig_ph.h", .tail = "tail_twopath.c",
     .reduction_text = TAN_RED RED_EXACT, .target_text = "tan(t)", .g = g_tan, .a = 0, .b = PIO4,
     .parity = FIT_PARITY_ODD, .errkind = FIT_REL, .ncon = 1, .con = {CON_SLOPE1},
     .default_order = TAN_EXACT_ORDER, .real = "double", .ulp_bound = 1.0,
     .extra = extra_trig_double, .model = model_double},
    {.func = "tan", .reduction = "pio2", .variant = "mid", .tmpl = "tan_cw_float", .arity = 1,
     .head = "trig_ph.h", .tail = "tail_twopath.c",
     .reduction_text = TAN_RED RED_MID, .target_text = "tan(t)", .g = g_tan, .a = 0,
     .b = PIO4 + MID_PAST, .parity = FIT_PARITY_ODD, .errkind = FIT_REL, .ncon = 1,
     .con = {CON_SLOPE1}, .default_order = TAN_EXACT_ORDER, .real = "fma",
     .extra = extra_trig_mid, .model = model_mid_tan, .ladder_cost = 9},
    {.func = "tan", .reduction = "pio2", .variant = "fast", .tmpl = "tan_pio2_fast", .arity = 1,
     .head = "trig_ph.h", .tail = "tail_twopath.c",
     .reduction_text = TAN_RED RED_FAST, .target_text = "tan(t)", .g = g_tan, .a = 0, .b = PIO4,
     .parity = FIT_PARITY_ODD, .errkind = FIT_REL, .ncon = 3, .con = TAN_FAST_CON,
     .default_order = 0, .fast_target = 0x1p-10, .real = "fma", .extra = extra_tan_float},
    {0},
};
