/* exp and exp2 in fixed point (see gen/templates/fx_exp.c.in).
 *
 * Inputs are first clamped to [XLO, XSAT - 1]: from XSAT up f(x) is at least
 * the output's max (saturate), below XLO it is under 1/4 lsb (the result
 * rounds to 0, and XLO's does too).  t = x (exp2) or x log2(e) (exp) in
 * 64 bits with Ft fraction bits; k = floor(t), f = t - k are taken with a
 * bias that makes t non-negative, so only unsigned shifts occur.  exp's
 * constant C = round(log2(e) 2^(Ft+Ei)) errs by at most 1/2 in its last
 * place: |error of t| <= |X|max 2^-(Ft+1), a relative error of
 * ln2 |error of t| in the result. */
#include "fixed_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void g_exp2(mpfr_t y, const mpfr_t t, const void *ctx)
{
    (void)ctx;
    mpfr_exp2(y, t, MPFR_RNDN);
}


/* ceil / floor of v 2^e for an MPFR value v, as int64 (clamped to +-2^62) */
static int64_t scaled_int(const mpfr_t v, int e, mpfr_rnd_t rnd)
{
    mpfr_t a;
    mpfr_init2(a, mpfr_get_prec(v) + 16);
    mpfr_mul_2si(a, v, e, MPFR_RNDN); /* exact */
    mpfr_rint(a, a, rnd);
    double d = mpfr_get_d(a, MPFR_RNDN);
    mpfr_clear(a);
    if (d > 0x1p62)
        return (int64_t)1 << 62;
    if (d < -0x1p62)
        return -((int64_t)1 << 62);
    return (int64_t)d;
}

/* 16-bit lanes: T = t 2^Ei as computed, for a stored (clamped) input */
static int64_t t16(const fx_gen *G, int64_t xc, int base2)
{
    if (base2)
        return xc;
    int64_t pr = xc * G->exp.b16; /* round(pr 2^-15), ties up: floor((pr + 2^14) / 2^15) */
    int64_t q = pr + 16384;
    q = q >= 0 ? q / 32768 : -((-q + 32767) / 32768);
    return xc + q;
}

/* 16-bit lanes (see fx_exp16.c.in): int16_t inputs with 1..15 fraction
   bits, and (t + K0) 2^Ei inside a uint16_t */
static int prepare16(fx_gen *G, char *err, size_t errlen, int base2)
{
    int Ei = G->in.exp;
    if (Ei < 1 || Ei > 15 || pf_type_max_stored(&G->in) > 32767) {
        snprintf(err, errlen, "16-bit lanes: input not an int16_t with 1..15 fraction bits");
        return -2;
    }
    double dt = 0;
    if (!base2) {
        mpfr_t l;
        mpfr_init2(l, 256);
        mpfr_set_ui(l, 1, MPFR_RNDN);
        mpfr_exp(l, l, MPFR_RNDN);
        mpfr_log2(l, l, MPFR_RNDN);
        mpfr_sub_ui(l, l, 1, MPFR_RNDN);
        G->exp.b16 = scaled_int(l, 15, MPFR_RNDN);
        mpfr_mul_2si(l, l, 15, MPFR_RNDN);
        mpfr_sub_si(l, l, (long)G->exp.b16, MPFR_RNDN);
        double cerr = fabs(mpfr_get_d(l, MPFR_RNDN)); /* |B - (log2 e - 1) 2^15| */
        mpfr_clear(l);
        double xm = fmax(fabs((double)G->exp.xlo), fabs((double)G->exp.xhi));
        dt = ldexp(0.5 + xm * cerr * 0x1p-15, -Ei);
    }
    G->exp.dt16 = dt;
    int64_t tlo = t16(G, G->exp.xlo, base2), thi = t16(G, G->exp.xhi, base2);
    int64_t one = (int64_t)1 << Ei;
    G->exp.klo = tlo >= 0 ? tlo / one : -((-tlo + one - 1) / one);
    G->exp.khi = thi >= 0 ? thi / one : -((-thi + one - 1) / one);
    G->exp.k0 = G->exp.klo < 0 ? -G->exp.klo : 0;
    if (thi + G->exp.k0 * one > 65535) {
        snprintf(err, errlen, "16-bit lanes: t does not fit a uint16_t");
        return -2;
    }
    G->exp.ft = Ei;
    G->dred = dt;
    if (base2)
        snprintf(G->red_text, sizeof G->red_text,
                 "t = x; k = floor(t), f = t - k (exact, the low bits of the stored integer, in a uint16_t biased "
                 "by %lld); inputs clamped to [%lld, %lld] (stored)%s",
                 (long long)G->exp.k0, (long long)G->exp.xlo, (long long)G->exp.xhi, G->exp.sat ? ", saturating from there" : "");
    else
        snprintf(G->red_text, sizeof G->red_text,
                 "t = x log2(e) = x + round(x B 2^-15), B = round((log2(e) - 1) 2^15) = %lld (MPFR), at the "
                 "input's lsb 2^-%d in a uint16_t biased by %lld; k = floor(t), f = t - k; inputs clamped to "
                 "[%lld, %lld] (stored)%s; error of t <= %.3e",
                 (long long)G->exp.b16, Ei, (long long)G->exp.k0, (long long)G->exp.xlo, (long long)G->exp.xhi,
                 G->exp.sat ? ", saturating from there" : "", dt);
    return 0;
}

static int prepare(fx_gen *G, char *err, size_t errlen, int base2)
{
    const char *fn = base2 ? "exp2" : "exp";
    int Ei = G->in.exp, Eo = G->out.exp;
    if (Ei > 62 || Ei < -62 || Eo > 62 || Eo < -62) {
        snprintf(err, errlen, "%s: exponents beyond +-62 are not supported", fn);
        return -1;
    }
    int64_t imin = pf_type_min_stored(&G->in), imax = pf_type_max_stored(&G->in);
    int64_t omax = pf_type_max_stored(&G->out);
    mpfr_t a;
    mpfr_init2(a, 256);
    /* XSAT: the smallest x with f(x) >= max value: x >= log(max) */
    mpfr_set_si(a, (long)omax, MPFR_RNDN);
    mpfr_mul_2si(a, a, -Eo, MPFR_RNDN);
    if (base2)
        mpfr_log2(a, a, MPFR_RNDU);
    else
        mpfr_log(a, a, MPFR_RNDU);
    int64_t xsat = scaled_int(a, Ei, MPFR_RNDU);
    /* XLO: the largest x with f(x) < lsb/4: x < log(2^-(Eo+2)), rounded down
       and one below when that lands on the bound */
    mpfr_set_si(a, -(Eo + 2), MPFR_RNDN);
    if (!base2) {
        mpfr_t l2;
        mpfr_init2(l2, 256);
        mpfr_const_log2(l2, MPFR_RNDU);
        mpfr_mul(a, a, l2, MPFR_RNDD);
        mpfr_clear(l2);
    }
    int64_t xlo = scaled_int(a, Ei, MPFR_RNDD) - 1;
    mpfr_clear(a);
    G->exp.sat = xsat <= imax;
    G->exp.loclamp = xlo > imin;
    G->exp.xsat = xsat;
    G->exp.xlo = xlo > imin ? xlo : imin;
    G->exp.xhi = xsat - 1 < imax ? xsat - 1 : imax;
    if (G->exp.xhi < G->exp.xlo + 1) {
        snprintf(err, errlen, "%s: output type %s has no room between 1/4 lsb and its max for %s inputs", fn,
                 G->out_text, G->in_text);
        return -1;
    }
    double xl = ldexp((double)G->exp.xlo, -Ei), xh = ldexp((double)G->exp.xhi, -Ei);
    double c = base2 ? 1 : M_LOG2E;
    G->exp.klo = (int64_t)floor(xl * c) - 1; /* one of margin each side: computed t errs */
    G->exp.khi = (int64_t)floor(xh * c) + 1;
    G->exp.k0 = G->exp.klo < 0 ? -G->exp.klo : 0;
    double xmaxabs = fmax(fabs((double)G->exp.xlo), fabs((double)G->exp.xhi));
    G->fmax = fx_out_max(G);
    if (G->exp.sat)
        snprintf(G->sat_text, sizeof G->sat_text, "x >= %lld (stored; %.9g) overflows: %lld (the max)",
                 (long long)G->exp.xsat, ldexp((double)G->exp.xsat, -Ei), (long long)omax);
    else
        snprintf(G->sat_text, sizeof G->sat_text, "no input overflows");
    if (G->W == 16)
        return prepare16(G, err, errlen, base2);
    if (base2) {
        G->exp.ft = Ei > 0 ? Ei : 0;
        G->dred = 0;
        snprintf(G->red_text, sizeof G->red_text,
                 "t = x; k = floor(t), f = t - k (exact%s); inputs clamped to [%lld, %lld] (stored)%s",
                 Ei > 0 ? ", the low bits of the stored integer" : ": x is an integer", (long long)G->exp.xlo,
                 (long long)G->exp.xhi, G->exp.sat ? ", saturating from there" : "");
    } else {
        /* (t + K0) 2^Ft and x C both stay below 2^61 */
        int64_t B = (G->exp.khi > -G->exp.klo ? G->exp.khi : -G->exp.klo) + G->exp.k0 + 2;
        G->exp.ft = 61 - fx_bitlen((uint64_t)B);
        int cc = (int)G->exp.ft - Ei;
        if (G->exp.ft < 1 || cc < 1 || cc > 61) {
            snprintf(err, errlen, "%s: input exponent %d not supported", fn, Ei);
            return -1;
        }
        mpfr_t l;
        mpfr_init2(l, 256);
        mpfr_set_ui(l, 1, MPFR_RNDN);
        mpfr_exp(l, l, MPFR_RNDN);
        mpfr_log2(l, l, MPFR_RNDN);
        G->exp.cexp = scaled_int(l, cc, MPFR_RNDN);
        mpfr_clear(l);
        G->dred = xmaxabs * ldexp(0.5, -G->exp.ft);
        snprintf(G->red_text, sizeof G->red_text,
                 "t = x log2(e) = x C 2^-%d with C = round(log2(e) 2^%d) = %lld (MPFR); k = floor(t), f = t - k; "
                 "inputs clamped to [%lld, %lld] (stored)%s; error of t <= %.3e",
                 G->exp.ft, cc, (long long)G->exp.cexp, (long long)G->exp.xlo, (long long)G->exp.xhi,
                 G->exp.sat ? ", saturating from there" : "", G->dred);
    }
    return 0;
}

static int prep_exp(fx_gen *G, char *err, size_t n) { return prepare(G, err, n, 0); }
static int prep_exp2(fx_gen *G, char *err, size_t n) { return prepare(G, err, n, 1); }

/* rounding of f to the Horner variable's 2^-(W-1) (and its saturation) */
static double df_of(const fx_gen *G) { return G->exp.ft > G->W - 1 ? 1.5 * ldexp(1.0, -(G->W - 1)) : 0; }

static void budget16(fx_gen *G)
{
    /* P >= 1: its absolute Horner error is a relative one; t's error
       moves 2^t by ln2 dt relatively; the final rounding is the 1/2 lsb */
    G->A = 0;
    G->R = G->poly_err + G->arith + M_LN2 * G->exp.dt16 * (1 + 1e-6);
    /* fast: the final scaling truncates (emit16), |floor(z) - z| < 1 lsb:
       the 1/2 lsb of the model's final rounding plus 1/2 lsb here */
    if (!G->exact)
        G->A = 0.5 * fx_lsb(G);
    int smin = G->Ep - G->out.exp - (int)G->exp.khi;
    if (smin < -14)
        G->R = INFINITY;
}

static void budget(fx_gen *G)
{
    if (G->W == 16) {
        budget16(G);
        return;
    }
    G->A = 0;
    G->R = G->poly_err + G->arith + M_LN2 * (G->dred + df_of(G)) * (1 + 1e-6);
    int shmax = G->Ep - G->out.exp - (int)G->exp.klo, shmin = G->Ep - G->out.exp - (int)G->exp.khi;
    /* left shifts must stay inside 64 bits */
    if (shmin < -(62 - (G->Ep + 2)) || shmax > 4000)
        G->R = INFINITY;
}

static void emit16(fx_gen *G, pf_buf *b, int base2)
{
    pf_buf body = {0}, horner = {0};
    int Ei = G->in.exp, Ep = G->Ep;
    int64_t omax = pf_type_max_stored(&G->out);
    int full = G->in.storage_bits == 16 && G->in.is_signed;
    /* the clamp's bounds come from k[]: GCC cannot bound xc then, and keeps
       x B's rounding multiply-high in 16 bits (pmulhrsw, see the array
       form) without a product by 1 */
    pf_put(&body, "    int16_t xc = (int16_t)x;");
    if (G->exp.loclamp) {
        char w[64];
        snprintf(w, sizeof w, "%lld: lowest input computed (clamp)", (long long)G->exp.xlo);
        const char *kl = fx_k16(G, G->exp.xlo, w);
        pf_printf(&body, "\n    xc = (int16_t)(xc < %s ? %s : xc); /* %lld */", kl, kl, (long long)G->exp.xlo);
    }
    if (G->exp.sat) {
        char w[64];
        snprintf(w, sizeof w, "%lld: highest input computed (clamp)", (long long)G->exp.xhi);
        const char *kh = fx_k16(G, G->exp.xhi, w);
        pf_printf(&body, "\n    xc = (int16_t)(xc > %s ? %s : xc); /* %lld */", kh, kh, (long long)G->exp.xhi);
    }
    pf_put(&body, "\n");
    long long bias = (long long)(G->exp.k0 << Ei);
    if (base2) {
        pf_printf(&body, "    uint16_t tb = (uint16_t)((uint16_t)xc + %lldu); /* (t + %lld) 2^%d */\n", bias,
                  (long long)G->exp.k0, Ei);
    } else {
        const char *kb = fx_k16(G, G->exp.b16, "B = round((log2(e) - 1) 2^15)");
        const char *xo = !G->exp.loclamp && !G->exp.sat && !full ? fx_opaque16(G, "xc") : "xc";
        pf_printf(&body, "    uint16_t tb = (uint16_t)((uint16_t)xc + (uint16_t)pf_fx_mulhrs(%s, %s) + %lldu); /* (t + %lld) 2^%d, t = x log2(e) */\n",
                  xo, kb, bias, (long long)G->exp.k0, Ei);
    }
    pf_printf(&body, "    uint16_t kb = (uint16_t)(tb >> %d); /* k + %lld */\n", Ei, (long long)G->exp.k0);
    {
        char e[64], w[64];
        snprintf(e, sizeof e, "tb & 0x%x", (1u << Ei) - 1);
        snprintf(w, sizeof w, "2^%d: f to 2^-15 units", 15 - Ei);
        const char *k2 = fx_k16(G, (int64_t)1 << (15 - Ei), w);
        pf_printf(&body, "    int16_t f = (int16_t)((%s) * %s); /* f in [0, 1), 2^-15 units (a product: see the array form) */\n",
                  e, k2);
    }
    pf_put(&body, "    /* P(f) ~ 2^f: Horner in 16-bit words, one rounding per step */\n");
    fx_emit_horner(G, &horner, "f", "    ");
    pf_put(&body, horner.s);
    /* P 2^k in output units: r = round(P 2^-s), s = Ep - Eo - k */
    int smin = Ep - G->out.exp - (int)G->exp.khi, smax = Ep - G->out.exp - (int)G->exp.klo;
    char sexpr[64];
    snprintf(sexpr, sizeof sexpr, "%lld - (int32_t)kb", (long long)(Ep - G->out.exp + G->exp.k0));
    if (!G->exact && smin >= -1 && smax + 1 <= 31) {
        /* fast: truncated, r = floor(P 2^-s) = floor(2a 2^-c), c = s + 1 >= 0
           (2a < 2^16 as p < 2^15); the bound (budget16) counts the floor as
           1 lsb.  Four vector instructions where rounding and the s = -1
           case took nine.  bw = 1: one 16-bit shift (vpsrlvw; c >= 16 gives
           0 there and in C); bw = 0: 32-bit lanes, the same values */
        long long K = (long long)(Ep - G->out.exp + 1 + G->exp.k0);
        pf_printf(&body, "    /* P 2^k truncated to the output: floor(2P 2^-c), c = s + 1 = %d - k in [%d, %d] */\n",
                  Ep - G->out.exp + 1, smin + 1, smax + 1);
        pf_printf(&body, "    uint16_t c = (uint16_t)(%lld - kb);\n    uint16_t r16;\n", K);
        pf_printf(&body, "    if (bw)\n        r16 = (uint16_t)((uint16_t)((uint16_t)p << 1) >> %s);\n",
                  smax + 1 > 16 ? "(c < 16 ? c : 16)" : "c");
        pf_put(&body, "    else\n        r16 = (uint16_t)(((uint32_t)(uint16_t)p << 1) >> c);\n");
        if (65534 > omax)
            pf_printf(&body, "    r16 = (uint16_t)(r16 < %lluu ? r16 : %lluu);\n", (unsigned long long)omax,
                      (unsigned long long)omax);
        G->bw16 = 1;
        snprintf(G->wide_text, sizeof G->wide_text,
                 "the scaling by 2^k is a per-element shift, truncating (floor: 1 lsb in the bound): in 16-bit "
                 "lanes where AVX-512BW has one (vpsrlvw), else in 32-bit lanes (AVX2 has no 16-bit per-element "
                 "shift); the same values, the error model does not need the wider lanes");
    } else {
        pf_printf(&body, "    /* P 2^k rounded once to the output, s = %d - k in [%d, %d] */\n", Ep - G->out.exp, smin, smax);
        fx_emit_vshift16(G, &body, "(uint16_t)p", 32767, sexpr, smin, smax, omax);
        snprintf(G->wide_text, sizeof G->wide_text,
                 G->bw16 ? "the scaling by 2^k is a per-element shift: in 16-bit lanes where AVX-512BW has one "
                           "(vpsrlvw), else in 32-bit lanes (AVX2 has no 16-bit per-element shift); the same values, "
                           "the error model does not need the wider lanes"
                         : "the scaling by 2^k is a per-element shift, done in 32-bit lanes (AVX2 has no 16-bit "
                           "per-element shift; the error model does not need them)");
    }
    /* overflow saturates through a mask: GCC 12 widens the whole loop to
       32-bit lanes for a select between a 16-bit comparison and r */
    if (G->exp.sat)
        pf_printf(&body, "    uint16_t m = (uint16_t)(0u - (uint16_t)(x >= %lld)); /* all ones from the first overflowing input */\n"
                         "    return (%s)((r16 & ~m) | (%lluu & m));", (long long)G->exp.xsat, G->ot, (unsigned long long)omax);
    else
        pf_printf(&body, "    return (%s)r16;", G->ot);
    char xsat[32], xlo[32];
    snprintf(xsat, sizeof xsat, "%lld", (long long)G->exp.xsat);
    snprintf(xlo, sizeof xlo, "%lld", (long long)G->exp.xlo);
    const char *kv[] = {"FUNC", base2 ? "exp2" : "exp", "TDEF", base2 ? "x" : "x log2(e)", "XSAT", xsat, "XLO", xlo,
                        "NAME", G->name, "IT", G->it, "OT", G->ot, "BODY", body.s, NULL};
    pf_subst(b, pf_template("fx_exp16.c"), kv);
    free(body.s);
    free(horner.s);
}

static void emit(fx_gen *G, pf_buf *b, int base2)
{
    if (G->W == 16) {
        emit16(G, b, base2);
        return;
    }
    pf_buf clamp = {0}, split = {0}, horner = {0}, out = {0};
    int W = G->W, Ei = G->in.exp, Ft = (int)G->exp.ft;
    /* clamp */
    pf_put(&clamp, "    int64_t xc = x;");
    if (G->exp.loclamp)
        pf_printf(&clamp, "\n    xc = xc < %lld ? %lld : xc;", (long long)G->exp.xlo, (long long)G->exp.xlo);
    if (G->exp.sat)
        pf_printf(&clamp, "\n    xc = xc > %lld ? %lld : xc;", (long long)G->exp.xhi, (long long)G->exp.xhi);
    /* t 2^Ft, biased by K0 2^Ft so that it is >= 0; kb = k + K0 */
    if (base2 && Ei <= 0) {
        pf_printf(&split, "    /* x is an integer: k = x, f = 0 */\n    uint64_t kb = (uint64_t)(xc * %lld + %lld);\n",
                  (long long)1 << -Ei, (long long)G->exp.k0);
        pf_printf(&split, "    %s f = 0;", G->wt);
    } else {
        if (base2)
            pf_printf(&split, "    uint64_t tb = (uint64_t)(xc + INT64_C(%lld)); /* (t + %lld) 2^%d */\n",
                      (long long)(G->exp.k0 << Ft), (long long)G->exp.k0, Ft);
        else if (G->exp.xlo < INT32_MIN || G->exp.xhi > INT32_MAX)
            pf_printf(&split,
                      "    uint64_t tb = (uint64_t)(xc * INT64_C(%lld) + INT64_C(%lld)); /* (t + %lld) 2^%d */\n",
                      (long long)G->exp.cexp, (long long)(G->exp.k0 << Ft), (long long)G->exp.k0, Ft);
        else if (G->exp.cexp <= INT32_MAX)
            pf_printf(&split,
                      "    uint64_t tb = (uint64_t)((int64_t)(int32_t)xc * %lld + INT64_C(%lld)); /* (t + %lld) 2^%d */\n",
                      (long long)G->exp.cexp, (long long)(G->exp.k0 << Ft), (long long)G->exp.k0, Ft);
        else
            /* x C from two 32x32-bit products (C = CH 2^31 + CL), which
               vectorize where a 64x64-bit product does not; the sum is
               in [0, 2^63), so its value mod 2^64 is the value */
            pf_printf(&split,
                      "    uint64_t tb = ((uint64_t)((int64_t)(int32_t)xc * %lld) << 31) + (uint64_t)((int64_t)(int32_t)xc * %lld)\n"
                      "                  + UINT64_C(%lld); /* (t + %lld) 2^%d, t = x %lld 2^-%d */\n",
                      (long long)(G->exp.cexp >> 31), (long long)(G->exp.cexp & 0x7fffffff), (long long)(G->exp.k0 << Ft),
                      (long long)G->exp.k0, Ft, (long long)G->exp.cexp, (int)G->exp.ft - G->in.exp);
        pf_printf(&split, "    uint64_t kb = tb >> %d; /* k + %lld */\n", Ft, (long long)G->exp.k0);
        pf_printf(&split, "    uint64_t fr = tb & UINT64_C(0x%llx); /* f 2^%d */\n",
                  (unsigned long long)(((uint64_t)1 << Ft) - 1), Ft);
        if (Ft <= W - 1)
            pf_printf(&split, "    %s f = (%s)(fr << %d); /* f in [0, 1), 2^-%d units */", G->wt, G->wt, W - 1 - Ft,
                      W - 1);
        else
            pf_printf(&split,
                      "    uint64_t f1 = pf_fx_rne_u(fr, %d);\n"
                      "    %s f = (%s)(f1 < UINT64_C(0x%llx) ? f1 : UINT64_C(0x%llx)); /* f in [0, 1), 2^-%d units */",
                      Ft - (W - 1), G->wt, G->wt, (unsigned long long)(((uint64_t)1 << (W - 1)) - 1),
                      (unsigned long long)(((uint64_t)1 << (W - 1)) - 1), W - 1);
    }
    fx_emit_horner(G, &horner, "f", "    ");
    pf_chomp(&horner);
    /* P 2^k in output units: shift right by sh = Ep - Eo - k */
    int base = G->Ep - G->out.exp;
    int shmin = base - (int)G->exp.khi, shmax = base - (int)G->exp.klo;
    int64_t omax = pf_type_max_stored(&G->out);
    long long bk = (long long)base + (long long)G->exp.k0; /* sh = bk - kb */
    const char *pcast = "(uint64_t)(p > 0 ? p : 0)";
    if (shmin >= 1) {
        pf_printf(&out, "    uint64_t sh = %lld - kb;\n", bk);
        pf_printf(&out, "    uint64_t r = pf_fx_rne_u(%s, %s);\n", pcast, shmax > 63 ? "sh < 63 ? sh : 63" : "sh");
    } else {
        pf_printf(&out, "    int64_t sh = %lld - (int64_t)kb;\n", bk);
        if (shmax <= 0)
            pf_printf(&out, "    uint64_t r = %s << -sh;\n", pcast);
        else
            pf_printf(&out,
                      "    uint64_t r = sh >= 1 ? pf_fx_rne_u(%s, (uint64_t)(sh < 63 ? sh : 63))\n"
                      "                         : %s << (sh > -62 ? -sh : 62);\n",
                      pcast, pcast);
    }
    pf_printf(&out, "    r = r < %lluu ? r : %lluu;\n", (unsigned long long)omax, (unsigned long long)omax);
    if (G->exp.sat)
        pf_printf(&out, "    return (%s)(x >= %lld ? %lluu : r);", G->ot, (long long)G->exp.xsat, (unsigned long long)omax);
    else
        pf_printf(&out, "    return (%s)r;", G->ot);
    char xsat[32], xlo[32], tdef[64];
    snprintf(xsat, sizeof xsat, "%lld", (long long)G->exp.xsat);
    snprintf(xlo, sizeof xlo, "%lld", (long long)G->exp.xlo);
    snprintf(tdef, sizeof tdef, "%s", base2 ? "x" : "x log2(e)");
    const char *kv[] = {"FUNC", base2 ? "exp2" : "exp", "TDEF", tdef, "XSAT", xsat, "XLO", xlo, "NAME", G->name,
                        "IT", G->it, "OT", G->ot, "CLAMP_CODE", clamp.s, "SPLIT_CODE", split.s, "HORNER", horner.s,
                        "OUT_TYPE", G->out_text, "OUT_CODE", out.s, NULL};
    pf_subst(b, pf_template("fx_exp.c"), kv);
    free(clamp.s);
    free(split.s);
    free(horner.s);
    free(out.s);
}

static void emit_exp(fx_gen *G, pf_buf *b) { emit(G, b, 0); }
static void emit_exp2(fx_gen *G, pf_buf *b) { emit(G, b, 1); }

const fx_func fx_func_exp = {
    .name = "exp", .ref = PF_EXP, .tmpl = "fx_exp", .target_text = "2^t", .g = g_exp2, .a = 0, .b = 1,
    .parity = FIT_PARITY_NONE, .errkind = FIT_REL, .errkind_fast = FIT_REL, .con_zero = 1, .con_text = "p(0) = 1 (exact powers of 2 at integer t)",
    .prepare = prep_exp, .budget = budget, .emit = emit_exp,
};

const fx_func fx_func_exp2 = {
    .name = "exp2", .ref = PF_EXP2, .tmpl = "fx_exp", .target_text = "2^t", .g = g_exp2, .a = 0, .b = 1,
    .parity = FIT_PARITY_NONE, .errkind = FIT_REL, .errkind_fast = FIT_REL, .con_zero = 1, .con_text = "p(0) = 1 (exact powers of 2 at integer t)",
    .prepare = prep_exp2, .budget = budget, .emit = emit_exp2,
};
