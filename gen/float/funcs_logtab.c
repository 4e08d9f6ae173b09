/* The table-driven reduction of log and log2 (gen/templates/log_tab.c.in):
 * the table, computed with MPFR when generating, and the scheme's error
 * model.  The rows are in gen/float/funcs_log.c.
 *
 * x = 2^k z, z's bits in [OFF, OFF + 2^23), subinterval i of 16 by the next
 * four bits; r = z INVC[i] - 1 and log(x) = k ln2 + LOGC[i] + log(1+r). */
#include "funcs_logtab.h"

#include <math.h>
#include <mpfr.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define NT 16

static float asf(uint32_t u)
{
    float f;
    memcpy(&f, &u, 4);
    return f;
}

/* subinterval i of offset off: z in [zl, zh], the floats it holds (the
   float rows, funcs_logtabf.c, share the subintervals) */
void pf_logtab_sub_range(uint32_t off, int i, double *zl, double *zh)
{
    *zl = asf(off + ((uint32_t)i << 19));
    *zh = asf(off + ((uint32_t)(i + 1) << 19) - 1);
}

/* INVC: 2/(zl + zh) rounded to double (one IEEE division of exact
   operands), so r is symmetric about 0 on the subinterval; exactly 1 on
   the subinterval holding z = 1, so that x near 1 gets r = z - 1 exactly
   and x = 1 gets 0 */
static double invc_of(uint32_t off, int i)
{
    double zl, zh;
    pf_logtab_sub_range(off, i, &zl, &zh);
    return zl <= 1 && 1 <= zh ? 1.0 : 2 / (zl + zh);
}

/* the subinterval's r range, r = z INVC - 1 (at its two ends; exact in
   long double for these operands' 24 + 53 bits is not needed: the double
   fma is within 2^-53 |r|, far below the margin of PF_LOGT_R) */
static void r_range(uint32_t off, int i, double *ra, double *rb)
{
    double zl, zh, c = invc_of(off, i);
    pf_logtab_sub_range(off, i, &zl, &zh);
    *ra = fma(zl, c, -1.0);
    *rb = fma(zh, c, -1.0);
}

static double max_r(uint32_t off)
{
    double m = 0;
    for (int i = 0; i < NT; i++) {
        double a, b;
        r_range(off, i, &a, &b);
        m = fmax(m, fmax(fabs(a), fabs(b)));
    }
    return m;
}

/* OFF: among the multiples of 2^16 from 0x3f300000 to 0x3f3f0000 (z's low
   edge from 0.6875 to 0.746), the one with the smallest max |r|, the lowest
   on a tie (deterministic) */
uint32_t pf_logtab_off(void)
{
    uint32_t best = 0;
    double bm = INFINITY;
    for (uint32_t off = 0x3f300000u; off <= 0x3f3f0000u; off += 0x10000u) {
        double m = max_r(off);
        if (m < bm)
            bm = m, best = off;
    }
    return best;
}

/* LOGC[i] = -log(INVC[i]) (log) or -log2(INVC[i]) (log2), rounded to double */
static double logc_of(double invc, int is_log2)
{
    mpfr_t v;
    mpfr_init2(v, 256);
    mpfr_set_d(v, invc, MPFR_RNDN);
    if (is_log2)
        mpfr_log2(v, v, MPFR_RNDN);
    else
        mpfr_log(v, v, MPFR_RNDN);
    mpfr_neg(v, v, MPFR_RNDN);
    double d = mpfr_get_d(v, MPFR_RNDN);
    mpfr_clear(v);
    return d;
}

static int extra_common(char *buf, size_t n, int is_log2)
{
    uint32_t off = pf_logtab_off();
    double R = max_r(off);
    if (!(R <= PF_LOGTAB_R)) {
        return snprintf(buf, n, "#error \"pfmathgen: the table's max |r| %a exceeds the fit domain %a\"\n", R,
                        PF_LOGTAB_R);
    }
    mpfr_t l2, v;
    mpfr_inits2(256, l2, v, (mpfr_ptr)0);
    mpfr_const_log2(l2, MPFR_RNDN);
    mpfr_ui_div(v, 1, l2, MPFR_RNDN);
    double ks = is_log2 ? 1.0 : mpfr_get_d(l2, MPFR_RNDN), ps = is_log2 ? mpfr_get_d(v, MPFR_RNDN) : 1.0;
    mpfr_clears(l2, v, (mpfr_ptr)0);
    size_t len = 0;
#define PUT(...) len += (size_t)snprintf(buf + (len < n ? len : n), len < n ? n - len : 0, __VA_ARGS__)
    PUT("/* The reduction's table, computed by pfmathgen (gen/float/funcs_logtab.c):\n"
        "   OFF = 0x%08x (z in [%a, %a]) is the multiple of 2^16 from 0x3f300000 to\n"
        "   0x3f3f0000 with the smallest max |r|, %a (the fit's domain is |r| <= %a);\n"
        "   subinterval i holds the z whose bits are in [OFF + i 2^19, OFF + (i+1) 2^19).\n"
        "   INVC[i] = 2/(zl + zh) rounded to double, zl and zh the subinterval's first and last\n"
        "   float (r symmetric about 0), but exactly 1 on the subinterval that holds 1;\n"
        "   LOGC[i] = %s(INVC[i]) computed with MPFR and rounded to nearest double.\n"
        "   y = p(r) PS + (k KS + LOGC[i]): %s, rounded to double. */\n",
        off, (double)asf(off), (double)asf(off + 0x7fffffu), R, PF_LOGTAB_R, is_log2 ? "-log2" : "-log",
        is_log2 ? "KS = 1, PS = 1/ln2" : "KS = ln2, PS = 1");
    PUT("#define PF_LOGT_OFF 0x%08xu\n", off);
    PUT("static const double PF_LOGT_KS PF_UNUSED = %a;\nstatic const double PF_LOGT_PS PF_UNUSED = %a;\n", ks, ps);
    PUT("#if defined(__GNUC__)\n#define PF_LOGT_ALIGN __attribute__((aligned(64)))\n#else\n#define PF_LOGT_ALIGN\n#endif\n");
    double c[NT];
    PUT("static const double PF_LOGT_INVC[16] PF_LOGT_ALIGN = {\n");
    for (int i = 0; i < NT; i++) {
        double zl, zh, ra, rb;
        pf_logtab_sub_range(off, i, &zl, &zh);
        r_range(off, i, &ra, &rb);
        c[i] = invc_of(off, i);
        char h[40];
        snprintf(h, sizeof h, "%a,", c[i]);
        PUT("    %-24s /* %2d: z in [%.9f, %.9f], r in [%+.6f, %+.6f] */\n", h, i, zl, zh, ra, rb);
    }
    PUT("};\nstatic const double PF_LOGT_LOGC[16] PF_LOGT_ALIGN = {\n");
    for (int i = 0; i < NT; i++) {
        double l = logc_of(c[i], is_log2) + 0.0; /* +0, not -0, at INVC = 1 */
        char h[40];
        snprintf(h, sizeof h, "%a,", l);
        PUT("    %-24s /* %2d: %s(INVC) = %.17g */\n", h, i, is_log2 ? "-log2" : "-log", l);
    }
    PUT("};\n\n");
#undef PUT
    return (int)len;
}

int pf_extra_logtab(char *buf, size_t n) { return extra_common(buf, n, 0); }
int pf_extra_log2tab(char *buf, size_t n) { return extra_common(buf, n, 1); }

/* ---- the error model, in ULP of the float result ----
 * f = k KS + L_i + log_b(1+r), L_i = -log_b(INVC[i]) (exact), r on a grid of
 * each subinterval's range, k from -149 to 128; the template computes
 * y = fma(r^2, q(r), fma(r, PS, fma(k, KS, LOGC))) in double (u = 2^-53):
 *   r = fma(z, INVC, -1) within u |r|, which moves log_b(1+r) by at most
 *   u |r| PS / (1 - |r|);
 *   q by pairs and Horner in r^2: each fma's rounding is below half an ulp
 *   of sum |c_m| (every partial value is below it, |r| < 1), and reaches the
 *   result multiplied by at most r^2;
 *   r^2's rounding times |q|; the fit's relative error times |target(r)|;
 *   PS, KS and LOGC rounded to double (u relative each), and half an ulp of
 *   each of the three fmas' results;
 * then the rounding to float, half an ULP. */
static double ulp_d(double v)
{
    v = fabs(v);
    return v < 0x1p-1022 ? 0x1p-1074 : ldexp(1.0, ilogb(v) - 52);
}
static double ulp_f(double v)
{
    v = fabs(v);
    return v < 0x1p-126 ? 0x1p-149 : ldexp(1.0, ilogb(v) - 23);
}
#define HD(v) (0.5 * ulp_d(v))

static int model_common(const fit_poly *p, int order, pf_scheme *sc, int is_log2)
{
    if (order < 2 || p->c[0] != 0 || p->c[1] != (is_log2 ? 0 : 1)) {
        snprintf(sc->text, sizeof sc->text, "error model: needs p(0) = 0, p'(0) = %d and order >= 2",
                 is_log2 ? 0 : 1);
        return -1;
    }
    uint32_t off = pf_logtab_off();
    const double KS = is_log2 ? 1 : M_LN2, PS = is_log2 ? 1 / M_LN2 : 1;
    double csum = 0;
    for (int m = 2; m <= order; m++)
        csum += fabs((double)p->c[m]);
    const double eq = (order - 1) * HD(csum); /* at most order - 1 fmas in q */
    double worst = 0, worst_r = 0;
    int worst_k = 0, worst_i = 0;
    const int ng = 512;
    for (int i = 0; i < NT; i++) {
        double ra, rb, c = invc_of(off, i);
        r_range(off, i, &ra, &rb);
        double L = -log(c) * PS; /* a double approximation: the model needs magnitudes */
        for (int j = 0; j <= ng; j++) {
            double r = ra + (rb - ra) * j / ng;
            double q = 0;
            for (int m = order; m >= 2; m--)
                q = q * r + (double)p->c[m];
            double r2 = r * r, g = log1p(r) * PS, tg = is_log2 ? g - r * PS : g;
            double ep = r2 * eq + fabs(q) * HD(r2) + 0x1p-53 * fabs(r) * PS / (1 - fabs(r)) +
                        p->max_err * fabs(tg) + fabs(r) * PS * 0x1p-53;
            for (int k = -149; k <= 128; k++) {
                double f = k * KS + L + g;
                if (f == 0)
                    continue; /* x = 1: r = 0, k = 0, LOGC = 0, every term is exactly 0 */
                double t = k * KS + L, s1 = r * PS + t;
                double e = ep + (L != 0 ? HD(L) : 0) + abs(k) * KS * 0x1p-53 + HD(t) + HD(s1) + HD(f);
                double bnd = 0.5 + e / ulp_f(f);
                if (bnd > worst)
                    worst = bnd, worst_r = r, worst_k = k, worst_i = i;
            }
        }
    }
    sc->ncomp = 0;
    sc->bound_ulp = worst;
    snprintf(sc->text, sizeof sc->text,
             "table of 16 (INVC, LOGC) in double, r = z INVC - 1 by one fma in double; q(r) in double by "
             "pairs fma(c_{2j+3}, r, c_{2j+2}) and Horner in r^2, y = r^2 q(r) + (r PS + (k KS + LOGC)) by "
             "three fmas in double, one rounding to float (the model's worst point is k = %d, subinterval %d, "
             "r = %.4f)",
             worst_k, worst_i, worst_r);
    return 0;
}

int pf_model_logtab(const fit_poly *p, int order, pf_scheme *sc) { return model_common(p, order, sc, 0); }
int pf_model_log2tab(const fit_poly *p, int order, pf_scheme *sc) { return model_common(p, order, sc, 1); }
