/* Error models of the atrig family's exact float schemes (the specs' model
 * hooks, gen/float/funcs.h).  Each template computes
 *     result = K + sg (v + c),   c = fmaf(fl(T z), q(z), lo)
 * with v a float (the reduced argument, or 2 sqrt(w) as s + lo), q(z) the
 * polynomial p(t) = t + t z q(z) after its c1 = 1 (fmaf Horner in float),
 * K + sg v exact as h + l (Fast2Sum), K = khi + klo.  The bound at a point
 * is 0.5 ULP (the last add) plus, over the ULP of the true result:
 *   the fit's relative error times |v + c|,
 *   q's running Horner bound times |T z| (gen/float/float_model.h's recurrence,
 *   with z's own error dz),
 *   |T z q| (u + T's relative error) for fl(T z), u |c| for the fmaf,
 *   2u (|c| + |klo| + |l|) for the two adds before the last (|l| <= u |K|;
 *   exact when K = 0),
 *   the reduction's error (sqrt: 2^-46 of S; quotient: 2^-44 of q) and K's
 *   representation (hi + lo floats: 2^-48 |K|; atan2's m A + m B: 2^-45).
 * The max over a grid of each branch's reduced argument is the model's
 * figure; the exhaustive sweep (pfsweep --all) is the proof. */
#include "funcs.h"

#include <math.h>
#include <stdio.h>

#define U 0x1p-24
#define NGRID 4096

typedef struct {
    const fit_poly *p;
    int order;
    double eps;      /* the emitted polynomial's max relative error */
    double worst;    /* max bound so far, ULP */
    double at;       /* the input where it is reached */
} model;

/* q(z) = c3 + c5 z + ... by fmaf Horner: value, *err the running bound */
static double q_horner(const model *m, double z, double dz, double *err)
{
    double s = (double)m->p->c[m->order], e = 0;
    for (int k = m->order - 2; k >= 3; k -= 2) {
        double sn = s * z + (double)m->p->c[k];
        e = e * fabs(z) + fabs(s) * dz + U * fabs(sn);
        s = sn;
    }
    *err = e;
    return s;
}

static double ulp_of(double r)
{
    int e;
    frexp(fabs(r), &e);
    return ldexp(1.0, (e - 1 > -126 ? e - 1 : -126) - 23);
}

/* one point: truth the true result; K, klo the constant and its low part;
   v the main term (|T| = |v|), z and dz, rel_t T's relative error, lo the
   low part added in c, red the reduction's absolute error in v + lo, kerr
   the constant's representation error; x the input, for the report */
static void point(model *m, double x, double truth, double K, double klo, double v, double z,
                  double dz, double rel_t, double lo, double red, double kerr)
{
    double eq, q = q_horner(m, z, dz, &eq);
    double tz = fabs(v * z), c = v * z * q + lo;
    /* with K = 0 (khi = klo = 0) h = v, l = 0 and the two adds are exact */
    double adds = K != 0 ? 2 * U * (fabs(c) + fabs(klo) + U * fabs(K)) : 0;
    double e = m->eps * fabs(v + c) + red + kerr + tz * eq + tz * fabs(q) * (U + rel_t) +
               U * fabs(c) + adds;
    double b = 0.5 + e / ulp_of(truth);
    if (b > m->worst) {
        m->worst = b;
        m->at = x;
    }
}

/* One scheme per function: its bound is reported, not used to refuse.  At
   the library's orders it is below 1 ULP; a lower order asked for with
   --order or --target (e.g. --target float: order 11) may not be, and then
   the text says so and the sweep decides. */
static int finish(const model *m, pf_scheme *sc, const char *text)
{
    sc->ncomp = 0;
    sc->bound_ulp = m->worst;
    if (m->worst > 1.0)
        snprintf(sc->text, sizeof sc->text,
                 "%s; the model does not prove 1 ULP at this order (%.3f at x = %a)", text,
                 m->worst, m->at);
    else
        snprintf(sc->text, sizeof sc->text, "%s", text);
    return 0;
}

/* ---- asin, acos: v = |x| (or x) for |x| <= 1/2, else S = 2 sqrt((1 - |x|)/2) ---- */
#define SQRT_TEXT                                                                                  \
    "q(z) by fmaf Horner in float; p = v + fmaf(T z, q, lo); 2 sqrt((1-|x|)/2) = s + lo to "     \
    "2^-46 (s = sqrtf, lo = fmaf residual times 0.5/s); K + sg v exact "                           \
    "(Fast2Sum), pi/2 and pi as float hi + lo; one final rounding"

static void sqrt_branch(model *m, double x, double truth, double K, double klo)
{
    double w = (1 - fabs(x)) / 2, S = 2 * sqrt(w);
    /* s = sqrtf(4w) correctly rounded, |lo| <= 2^-24 S, s + lo within 2^-46 S */
    point(m, x, truth, K, klo, S, w, 0, U, 0x1p-24 * S, 0x1p-46 * S, 0x1p-48 * K);
}

static int model_asin_acos(const fit_poly *p, int order, pf_scheme *sc, int acos_)
{
    model m = {p, order, p->max_err, 0, 0};
    double pio2 = acos(-1.0) / 2, klo2 = 4.37e-8, klo1 = 8.75e-8;
    for (int i = 1; i <= NGRID; i++) {
        double x = 0.5 * i / NGRID;               /* (0, 1/2] */
        double xb = 0.5 + 0.5 * i / NGRID;        /* (1/2, 1] */
        double xt = ldexp(0.5, -i * 40 / NGRID);  /* toward 0 */
        xb = xb < 1 ? xb : 1 - 0x1p-24;
        if (!acos_) {
            point(&m, x, asin(x), 0, 0, x, x * x, U * x * x, 0, 0, 0, 0);
            point(&m, xt, asin(xt), 0, 0, xt, xt * xt, U * xt * xt, 0, 0, 0, 0);
            sqrt_branch(&m, xb, asin(xb), pio2, klo2);
        } else {
            point(&m, x, acos(x), pio2, klo2, x, x * x, U * x * x, 0, 0, 0, 0x1p-48 * pio2);
            point(&m, -x, acos(-x), pio2, klo2, x, x * x, U * x * x, 0, 0, 0, 0x1p-48 * pio2);
            sqrt_branch(&m, xb, acos(xb), 0, 0);
            sqrt_branch(&m, -xb, acos(-xb), 2 * pio2, klo1);
        }
    }
    return finish(&m, sc, SQRT_TEXT);
}

int pf_model_asin(const fit_poly *p, int order, pf_scheme *sc)
{
    return model_asin_acos(p, order, sc, 0);
}

int pf_model_acos(const fit_poly *p, int order, pf_scheme *sc)
{
    return model_asin_acos(p, order, sc, 1);
}

/* ---- atan, atan2: q = qh + ql to 2^-44 (the quotient's fmaf residual) ---- */
#define QUOT_TEXT                                                                                  \
    "q(z) by fmaf Horner in float; p = qh + fmaf(qh z, q, ql); the reduced argument as qh + ql " \
    "(one division 1/den, fmaf residual, den = hi + lo); K + sg qh exact (Fast2Sum), K as float " \
    "hi + lo; one final rounding"

/* result K + sg atan(q); qh is off q by up to 2u |q| (ql), which moves z
   and T: dz = 5u z, rel_t = 2u; exact: q = |x| (atan, |x| <= 1/2), z = fl(q q) */
static void quot_point(model *m, double x, double truth, double K, double klo, double q,
                       double kerr, int exact)
{
    double z = q * q;
    if (exact)
        point(m, x, truth, K, klo, q, z, U * z, 0, 0, 0, kerr);
    else
        point(m, x, truth, K, klo, q, z, 5 * U * z, 2 * U, 2 * U * fabs(q), 0x1p-44 * fabs(q),
              kerr);
}

int pf_model_atan(const fit_poly *p, int order, pf_scheme *sc)
{
    model m = {p, order, p->max_err, 0, 0};
    double pio4 = atan(1.0), l4 = 3.4e-8;
    for (int i = 1; i <= NGRID; i++) {
        double a = 0.5 * i / NGRID;                            /* (0, 1/2] */
        double at = ldexp(0.5, -i * 40 / NGRID);
        double am = 0.5 + 1.5 * i / NGRID;                     /* (1/2, 2] */
        double ab = 2 * pow(2.0, 40.0 * i / NGRID);            /* (2, 2^41] */
        quot_point(&m, a, atan(a), 0, 0, a, 0, 1);
        quot_point(&m, at, atan(at), 0, 0, at, 0, 1);
        quot_point(&m, am, atan(am), pio4, l4, (am - 1) / (am + 1), 0x1p-48 * pio4, 0);
        quot_point(&m, ab, atan(ab), 2 * pio4, 2 * l4, -1 / ab, 0x1p-47 * pio4, 0);
    }
    return finish(&m, sc, QUOT_TEXT);
}

int pf_model_atan2(const fit_poly *p, int order, pf_scheme *sc)
{
    model m = {p, order, p->max_err, 0, 0};
    double pio4 = atan(1.0);
    for (int mid = 0; mid <= 1; mid++)
        for (int swap = 0; swap <= 1; swap++)
            for (int negx = 0; negx <= 1; negx++) {
                int k = mid;
                k = swap ? 2 - k : k;
                k = negx ? 4 - k : k;
                double sg = swap != negx ? -1 : 1, K = k * pio4;
                for (int i = 1; i <= NGRID; i++) {
                    /* the ratio n/d: (0, 1/2] or (1/2, 1], and toward 0 */
                    double t = mid ? 0.5 + 0.5 * i / NGRID : 0.5 * i / NGRID;
                    double q = mid ? (t - 1) / (t + 1) : t;
                    double truth = K + sg * (atan(t) - (mid ? pio4 : 0));
                    quot_point(&m, t, truth, K, k * 0x1p-22, q, 0x1p-45 * K, 0);
                    if (!mid) {
                        double tt = ldexp(0.5, -i * 40 / NGRID);
                        quot_point(&m, tt, K + sg * atan(tt), K, k * 0x1p-22, tt, 0x1p-45 * K, 0);
                    }
                }
            }
    return finish(&m, sc, QUOT_TEXT);
}

/* ---- fast asin, acos (gen/templates/{asin,acos}_fast.c.in) ----
 * r = fmaf(t, q(z), k), q(z) = 1 + c3 z + ... by fmaf Horner (c1 = 1 its
 * constant term): t = x, z = fl(x^2) for |x| <= 1/2 (asin: k = +-0; acos:
 * t = -x, k = pi/2), else t = -+S (asin, k = +-pi/2) or +-S (acos, k = 0 or
 * pi) with S = sqrtf(2 - 2|x|) correctly rounded and z = (1 - |x|)/2 exact.
 * The absolute error bound at a point: the fit's relative error times |t q|
 * (p(t) = t q(t^2) ~ asin t, and above 1/2 S q(w) = 2 p(sqrt w)), |t| times
 * q's running Horner bound, u |S q| for S's rounding, k's representation
 * (the nearest floats of pi/2, pi) and u |r| for the last rounding.  The
 * figure is its max over a grid as a fraction of the fast allowance
 * max(2^-10 |f|, 2^-11), and in ULPs of the result; fastsweep_atrig (every
 * float) is the proof. */
typedef struct {
    const fit_poly *p;
    int order;
    double frac, frac_at, ulps;
} fmodel;

/* q(z) = 1 + c3 z + c5 z^2 + ... by fmaf Horner, *err its running bound */
static double q_full(const fmodel *m, double z, double dz, double *err)
{
    double s = (double)m->p->c[m->order], e = 0;
    for (int k = m->order - 2; k >= 1; k -= 2) {
        double sn = s * z + (double)m->p->c[k];
        e = e * fabs(z) + fabs(s) * dz + U * fabs(sn);
        s = sn;
    }
    *err = e;
    return s;
}

/* t the main term (|t| = |x| or S, rel_t its relative rounding), z, dz,
   kerr the constant's representation error, truth the true result */
static void fpoint(fmodel *m, double x, double truth, double t, double rel_t, double z, double dz,
                   double kerr)
{
    double eq, q = q_full(m, z, dz, &eq);
    double tq = fabs(t * q);
    double b = m->p->max_err * tq + fabs(t) * eq + rel_t * tq + kerr + U * fabs(truth) * 1.001;
    double allow = fmax(0x1p-10 * fabs(truth), 0x1p-11);
    if (b / allow > m->frac) {
        m->frac = b / allow;
        m->frac_at = x;
    }
    m->ulps = fmax(m->ulps, b / ulp_of(truth));
}

static int model_asin_acos_fast(const fit_poly *p, int order, pf_scheme *sc, int acos_)
{
    fmodel m = {p, order, 0, 0, 0};
    double pio2 = acos(-1.0) / 2;
    double e2 = fabs((double)(float)pio2 - pio2), e1 = fabs((double)(float)(2 * pio2) - 2 * pio2);
    for (int i = 1; i <= NGRID; i++) {
        double x = 0.5 * i / NGRID;              /* (0, 1/2] */
        double xt = ldexp(0.5, -i * 40 / NGRID); /* toward 0 */
        double xb = 0.5 + 0.5 * i / NGRID;       /* (1/2, 1] */
        xb = xb < 1 ? xb : 1 - 0x1p-24;
        double w = (1 - xb) / 2, S = 2 * sqrt(w);
        if (!acos_) {
            fpoint(&m, x, asin(x), x, 0, x * x, U * x * x, 0);
            fpoint(&m, xt, asin(xt), xt, 0, xt * xt, U * xt * xt, 0);
            fpoint(&m, xb, asin(xb), S, U, w, 0, e2);
        } else {
            fpoint(&m, x, acos(x), x, 0, x * x, U * x * x, e2);
            fpoint(&m, -x, acos(-x), x, 0, x * x, U * x * x, e2);
            fpoint(&m, xb, acos(xb), S, U, w, 0, 0);
            fpoint(&m, -xb, acos(-xb), S, U, w, 0, e1);
        }
    }
    sc->ncomp = 0;
    sc->bound_ulp = m.ulps;
    snprintf(sc->text, sizeof sc->text,
             "q(z) = 1 + c3 z + ... by fmaf Horner in float (on v = 4z, c_k times 4^-k: the same "
             "bits); r = fmaf(t, q, k), t = x or S = "
             "sqrtf(2 - 2|x|) (correctly rounded) with a sign, z = x^2 or (1 - |x|)/2 (exact), k = 0, "
             "pi/2 or pi as the nearest float; at most %.3f of the fast bound max(2^-10 |f|, "
             "2^-11) (at x = %a)",
             m.frac, m.frac_at);
    if (m.frac > 1) /* a lower order asked for: said, not refused; the sweep decides */
        snprintf(sc->text, sizeof sc->text,
                 "q(z) by fmaf Horner, r = fmaf(t, q, k); the model does not prove the fast bound "
                 "at this order (%.3f of it at x = %a)",
                 m.frac, m.frac_at);
    return 0;
}

int pf_model_asin_fast(const fit_poly *p, int order, pf_scheme *sc)
{
    return model_asin_acos_fast(p, order, sc, 0);
}

int pf_model_acos_fast(const fit_poly *p, int order, pf_scheme *sc)
{
    return model_asin_acos_fast(p, order, sc, 1);
}

/* ---- the mid schemes (gen/templates/{asin,acos,atan,atan2}_mid.c.in) ----
 * result = K + m v + c, c = fmaf(m v z, q, klo), K + m v exact as h + l
 * (Fast2Sum), l + c rounded, then one final rounding.  What the exact
 * schemes keep as hi + lo and these round is the reduced argument:
 * v = sqrtf(2 - 2|x|) (asin, acos) or t = fl(1/|x|), fl(n/d) (atan,
 * atan2), within half an ULP of itself; the result moves by that times the
 * slope of the folded polynomial (2 asin(S/2): 1/sqrt(1 - S^2/4) <= 1.16;
 * atan: 1/(1 + t^2)).  atan's polynomial runs up to z = 1, where q's
 * roundings no longer shrink by z per step: each is bounded by half an ULP
 * of its own partial sum (not u times it, which is up to twice that), and
 * so is every other rounding here.  The figure is a bound for any level
 * (the ladder compares it with its U), reported as is. */
/* the rounding error of an operation whose exact result is r: half an ULP,
   of the binade below when r is a power of 2 (which rounds to itself; the
   grid's t = 1, z = 1 would otherwise count the larger ULP) */
static double half_ulp(double r)
{
    return r == 0 ? 0 : 0.5 * ulp_of(fabs(r) * (1 - 0x1p-40));
}

/* q(z) = c3 + c5 z + ... by fmaf Horner: value, *err the running bound of
   its roundings plus |q'(z)| dz (z's own error, through the derivative: at
   z near 1 the alternating partial sums would overcount it) */
static double q_horner_mid(const model *m, double z, double dz, double *err)
{
    double s = (double)m->p->c[m->order], e = 0, ds = 0;
    for (int k = m->order - 2; k >= 3; k -= 2) {
        double sn = s * z + (double)m->p->c[k];
        ds = ds * z + s;
        e = e * fabs(z) + half_ulp(sn);
        s = sn;
    }
    *err = e + fabs(ds) * dz;
    return s;
}

/* one point: v the reduced argument as computed (|v|), z and dz, red the
   error of v moved to the result, K, klo the constant, kerr its
   representation error */
static void point_mid(model *m, double x, double truth, double K, double klo, double v, double z,
                      double dz, double red, double kerr)
{
    double eq, q = q_horner_mid(m, z, dz, &eq);
    double vz = fabs(v * z), c = fabs(vz * q) + fabs(klo);
    /* fl(v z), the fmaf; with K = 0 h = v, l = 0 and l + c = c exactly */
    double e = m->eps * fabs(v + v * z * q) + red + kerr + vz * eq + half_ulp(vz) * fabs(q) +
               half_ulp(c) + (K != 0 ? half_ulp(c + half_ulp(K + v)) : 0);
    double b = 0.5 + e / ulp_of(truth);
    if (b > m->worst) {
        m->worst = b;
        m->at = x;
    }
}

#define MID_TEXT_SQRT                                                                              \
    "q(z) by fmaf Horner in float; K + m v + fmaf(m v z, q, klo), v = |x| or S = sqrtf(2 - 2|x|) " \
    "(rounded once, no residual), K + m v exact (Fast2Sum), K = pi/2, pi as float hi + lo; one "  \
    "final rounding"
#define MID_TEXT_QUOT                                                                              \
    "q(z) by fmaf Horner in float; K + m t + fmaf(m t z, q, klo), t = min/max (one division, "    \
    "rounded once), K + m t exact (Fast2Sum), K = pi/2, pi as float hi + lo; one final rounding"

static int finish_mid(const model *m, pf_scheme *sc, const char *text)
{
    sc->ncomp = 0;
    sc->bound_ulp = m->worst;
    snprintf(sc->text, sizeof sc->text, "%s; the model's bound %.3f ULP (at x = %a)", text, m->worst,
             m->at);
    return 0;
}

static void sqrt_branch_mid(model *m, double x, double truth, double K, double klo)
{
    double w = (1 - fabs(x)) / 2, S = 2 * sqrt(w);
    point_mid(m, x, truth, K, klo, S, w, 0, half_ulp(S) / sqrt(1 - S * S / 4), 0x1p-48 * K);
}

static int model_asin_acos_mid(const fit_poly *p, int order, pf_scheme *sc, int acos_)
{
    model m = {p, order, p->max_err, 0, 0};
    double pio2 = acos(-1.0) / 2;
    double klo2 = pio2 - (double)(float)pio2, klo1 = 2 * pio2 - (double)(float)(2 * pio2);
    for (int i = 1; i <= NGRID; i++) {
        double x = 0.5 * i / NGRID;               /* (0, 1/2] */
        double xb = 0.5 + 0.5 * i / NGRID;        /* (1/2, 1] */
        double xt = ldexp(0.5, -i * 40 / NGRID);  /* toward 0 */
        xb = xb < 1 ? xb : 1 - 0x1p-24;
        if (!acos_) {
            point_mid(&m, x, asin(x), 0, 0, x, x * x, half_ulp(x * x), 0, 0);
            point_mid(&m, xt, asin(xt), 0, 0, xt, xt * xt, half_ulp(xt * xt), 0, 0);
            sqrt_branch_mid(&m, xb, asin(xb), pio2, klo2);
        } else {
            point_mid(&m, x, acos(x), pio2, klo2, x, x * x, half_ulp(x * x), 0, 0x1p-48 * pio2);
            point_mid(&m, -x, acos(-x), pio2, klo2, x, x * x, half_ulp(x * x), 0, 0x1p-48 * pio2);
            sqrt_branch_mid(&m, xb, acos(xb), 0, 0);
            sqrt_branch_mid(&m, -xb, acos(-xb), 2 * pio2, klo1);
        }
    }
    return finish_mid(&m, sc, MID_TEXT_SQRT);
}

int pf_model_asin_mid(const fit_poly *p, int order, pf_scheme *sc)
{
    return model_asin_acos_mid(p, order, sc, 0);
}

int pf_model_acos_mid(const fit_poly *p, int order, pf_scheme *sc)
{
    return model_asin_acos_mid(p, order, sc, 1);
}

/* The atan and atan2 models visit the same points, whatever the scheme:
   point(m, x, truth, K, klo, sg, t, rnd) with t the reduced argument,
   K = 0, pi/2 or pi with klo = K - fl(K), sg the sign of t in K + sg atan(t),
   rnd = 0 where t is exact. */
typedef void (*atan_point_fn)(model *m, double x, double truth, double K, double klo, double sg, double t,
                              int rnd);

/* atan: t in (0, 1] and toward 0 (K = 0), and |x| > 1 through t = fl(1/|x|) */
static void walk_atan(model *m, atan_point_fn point)
{
    double pio2 = acos(-1.0) / 2, klo2 = pio2 - (double)(float)pio2;
    for (int i = 1; i <= NGRID; i++) {
        double t = (double)i / NGRID;               /* (0, 1] */
        double tt = ldexp(1.0, -i * 40 / NGRID);    /* toward 0 */
        point(m, t, atan(t), 0, 0, 1, t, 0);
        point(m, tt, atan(tt), 0, 0, 1, tt, 0);
        double tb = fmin(t, 1 - 0x1p-24);   /* fl(1/a) < 1 for a > 1 */
        point(m, 1 / tb, atan(1 / tb), pio2, klo2, -1, tb, 1);
        point(m, 1 / tt, atan(1 / tt), pio2, klo2, -1, tt, 1);
    }
}

/* atan2: t = min/max rounded once, in each of the four (swap, sign of x) cases */
static void walk_atan2(model *m, atan_point_fn point)
{
    double pio2 = acos(-1.0) / 2;
    double klo[3] = {0, pio2 - (double)(float)pio2, 2 * pio2 - (double)(float)(2 * pio2)};
    for (int swap = 0; swap <= 1; swap++)
        for (int negx = 0; negx <= 1; negx++) {
            int k = swap ? 1 : 2 * negx;   /* K = k pi/2 */
            double sg = swap != negx ? -1 : 1, K = k * pio2;
            for (int i = 1; i <= NGRID; i++) {
                double t = (double)i / NGRID, tt = ldexp(1.0, -i * 40 / NGRID);
                point(m, t, K + sg * atan(t), K, klo[k], sg, t, 1);
                point(m, tt, K + sg * atan(tt), K, klo[k], sg, tt, 1);
            }
        }
}

/* t = fl(n/d) in (0, 1]: K + sg atan(t); rnd = 0 when t is exact (atan's
   |x| <= 1, t = |x|) */
static void mid_quot(model *m, double x, double truth, double K, double klo, double sg, double t, int rnd)
{
    (void)sg;
    double red = rnd ? half_ulp(t) / (1 + t * t) : 0;
    point_mid(m, x, truth, K, klo, t, t * t, half_ulp(t * t), red, 0x1p-48 * K);
}

int pf_model_atan_mid(const fit_poly *p, int order, pf_scheme *sc)
{
    model m = {p, order, p->max_err, 0, 0};
    walk_atan(&m, mid_quot);
    return finish_mid(&m, sc, MID_TEXT_QUOT);
}

int pf_model_atan2_mid(const fit_poly *p, int order, pf_scheme *sc)
{
    model m = {p, order, p->max_err, 0, 0};
    walk_atan2(&m, mid_quot);
    return finish_mid(&m, sc, MID_TEXT_QUOT);
}

/* ---- the lean schemes (gen/templates/{atan,atan2}_lean.c.in) ----
 * r = fmaf(mt, P(z), k): P = 1 + c3 z + ... by fmaf Horner (c1 = 1 its
 * constant term), mt = +-t, k the nearest float of K = 0, pi/2 or pi, one
 * rounding for the fmaf.  The error at a point, over the ULP of the true
 * result, beside that last half ULP: the fit's relative error times |t P|,
 * |t| times P's running Horner bound (half an ULP of each partial sum, P
 * near 1 included, plus |P'(z)| dz), t's rounding through atan' (as the
 * mid schemes) and |k - K|, which the mid schemes carry as klo and this
 * one does not (fl(pi/2) - pi/2 = 4.4e-8: 0.73 ULP of a result just above
 * pi/4, the worst place for it). */
static double p_horner_lean(const model *m, double z, double dz, double *err)
{
    double s = (double)m->p->c[m->order], e = 0, ds = 0;
    for (int k = m->order - 2; k >= 1; k -= 2) {
        double sn = s * z + (double)m->p->c[k];
        ds = ds * z + s;
        e = e * fabs(z) + half_ulp(sn);
        s = sn;
    }
    *err = e + fabs(ds) * dz;
    return s;
}

/* t in (0, 1] the reduced argument as computed, rnd = 0 when exact; K the
   constant, kerr |fl(K) - K| */
static void point_lean(model *m, double x, double truth, double t, int rnd, double kerr)
{
    double z = t * t, eP, P = p_horner_lean(m, z, half_ulp(z), &eP);
    double red = rnd ? half_ulp(t) / (1 + z) : 0;
    double e = m->eps * fabs(t * P) + fabs(t) * eP + red + kerr;
    double b = 0.5 + e / ulp_of(truth);
    if (b > m->worst) {
        m->worst = b;
        m->at = x;
    }
}

/* the walkers' point: lean carries |fl(K) - K| = |klo| as an error */
static void lean_quot(model *m, double x, double truth, double K, double klo, double sg, double t, int rnd)
{
    (void)K;
    (void)sg;
    point_lean(m, x, truth, t, rnd, fabs(klo));
}

#define LEAN_TEXT                                                                                  \
    "P(z) = 1 + c3 z + ... by fmaf Horner in float; fmaf(m t, P, k), t = min/max (one division, " \
    "rounded once), k = 0, pi/2, pi as the nearest float; one final rounding"

int pf_model_atan_lean(const fit_poly *p, int order, pf_scheme *sc)
{
    model m = {p, order, p->max_err, 0, 0};
    walk_atan(&m, lean_quot);
    return finish_mid(&m, sc, LEAN_TEXT);
}

int pf_model_atan2_lean(const fit_poly *p, int order, pf_scheme *sc)
{
    model m = {p, order, p->max_err, 0, 0};
    walk_atan2(&m, lean_quot);
    return finish_mid(&m, sc, LEAN_TEXT);
}

/* ---- the lite schemes (gen/templates/{atan,atan2}_lite.c.in) ----
 * (khi + sg t) + fmaf(sg t z, q, klo): the mid schemes' terms, and h =
 * khi + sg t's own rounding, half an ULP of h, which the mid schemes carry
 * as l.  h is exact when K = 0, and when sg = -1 and t >= khi/2 (Sterbenz:
 * khi/2 <= t <= 1 < 2 khi): atan's |x| in (1, 1.27]. */
static void point_lite(model *m, double x, double truth, double K, double klo, double sg,
                       double t, int rnd)
{
    double z = t * t, eq, q = q_horner_mid(m, z, half_ulp(z), &eq);
    double tz = t * z, c = fabs(tz * q) + fabs(klo);
    double red = rnd ? half_ulp(t) / (1 + z) : 0;
    double e = m->eps * fabs(t + tz * q) + red + 0x1p-48 * K + tz * eq + half_ulp(tz) * fabs(q) +
               half_ulp(c) + (K != 0 && !(sg < 0 && t >= (double)(float)K / 2) ? half_ulp(K + sg * t) : 0);
    double b = 0.5 + e / ulp_of(truth);
    if (b > m->worst) {
        m->worst = b;
        m->at = x;
    }
}

#define LITE_TEXT                                                                                  \
    "q(z) by fmaf Horner in float; (khi + m t) + fmaf(m t z, q, klo), t = min/max (one division, " \
    "rounded once), khi + m t rounded once, K = pi/2, pi as float hi + lo; one final rounding"

int pf_model_atan_lite(const fit_poly *p, int order, pf_scheme *sc)
{
    model m = {p, order, p->max_err, 0, 0};
    walk_atan(&m, point_lite);
    return finish_mid(&m, sc, LITE_TEXT);
}

int pf_model_atan2_lite(const fit_poly *p, int order, pf_scheme *sc)
{
    model m = {p, order, p->max_err, 0, 0};
    walk_atan2(&m, point_lite);
    return finish_mid(&m, sc, LITE_TEXT);
}

/* ---- asin's lite scheme (gen/templates/asin_lite.c.in) ----
 * r = fl(khi + u) + fmaf(fl(u z), q(z), klo): u = a (z = fl(a^2), K = 0)
 * or -2s (s = sqrtf(w), z = w exact, K = pi/2 as hi + lo).  Beside the
 * last half ULP: the fit's relative error times |u + u z q|, |u z| times
 * q's running Horner bound (half an ULP of each partial sum, plus
 * |q'| dz), fl(u z)'s half ULP times |q|, c's half ULP, khi + u's half ULP
 * (none when K = 0 or 2s >= khi/2, Sterbenz), s's rounding through the
 * slope 2/sqrt(1 - s^2) of 2 asin(s), and K's representation (2^-48).
 * The template computes the same bits on v = 4z (2s = sqrtf(4w), the big
 * lanes negated): powers of two and signs change no rounding. */
/* u as |u|, k = |K|, klo = |klo|, red s's rounding moved to the result */
static void point_asin_lite(model *m, double x, double truth, double u, double k, double z,
                            double dz, double red, double klo)
{
    double eq, q = q_horner_mid(m, z, dz, &eq);
    double uz = fabs(u * z);
    double h = k != 0 && fabs(u) < (double)(float)k / 2 ? half_ulp(k - fabs(u)) : 0;
    double c = uz * fabs(q) + klo;   /* u z q and klo have one sign */
    double e = m->eps * fabs(fabs(u) + uz * q) + uz * eq + half_ulp(uz) * fabs(q) + half_ulp(c) + h +
               red + 0x1p-48 * k;
    double b = 0.5 + e / ulp_of(truth);
    if (b > m->worst) {
        m->worst = b;
        m->at = x;
    }
}

int pf_model_asin_lite(const fit_poly *p, int order, pf_scheme *sc)
{
    model m = {p, order, p->max_err, 0, 0};
    double pio2 = acos(-1.0) / 2, klo2 = fabs(pio2 - (double)(float)pio2);
    for (int i = 1; i <= NGRID; i++) {
        double x = 0.5 * i / NGRID;               /* (0, 1/2] */
        double xt = ldexp(0.5, -i * 40 / NGRID);  /* toward 0 */
        double xb = 0.5 + 0.5 * i / NGRID;        /* (1/2, 1] */
        xb = xb < 1 ? xb : 1 - 0x1p-24;
        double w = (1 - xb) / 2, s = sqrt(w);
        point_asin_lite(&m, x, asin(x), x, 0, x * x, half_ulp(x * x), 0, 0);
        point_asin_lite(&m, xt, asin(xt), xt, 0, xt * xt, half_ulp(xt * xt), 0, 0);
        point_asin_lite(&m, xb, asin(xb), 2 * s, pio2, w, 0, 2 * half_ulp(s) / sqrt(1 - w), klo2);
    }
    return finish_mid(&m, sc,
                      "q(z) by fmaf Horner in float (on v = 4z, c_k times powers of 4: the same "
                      "bits); fmaf(u z, q, k + u), u = |x| or -2 sqrtf(w) = -sqrtf(4w) "
                      "(z = x^2 or w = (1 - |x|)/2 exact), k = 0 or pi/2 as the nearest float, "
                      "k + u rounded once; one final rounding");
}
