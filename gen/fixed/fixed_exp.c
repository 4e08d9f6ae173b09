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
#include "fixed_exp16f.h"
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

/* ---- exact, 16-bit lanes: the table kernel (kind 1) ----
 *
 * T = (t + K0) 2^F, F = 16 + J, is held as two 16-bit words hi:lo: j = hi
 * mod 2^J and k + K0 = hi >> J pick 2^(j/2^J) and the power of two, r = lo
 * is the rest, in [0, 2^-J) at 2^-F.  2^t = 2^k 2^(j/2^J) 2^r: E = (2^r -
 * 1) 2^F from a degree-2 polynomial (two unsigned multiply-highs), then
 * N = 2^f 2^16 = 2^16 + M with M = A[j] + round(2^(j/2^J) E 2^-(F-16) +
 * residual of A[j]): one rounding, as D[j] carries A[j]'s own rounding
 * error (and the 1/2 of the floor).  The result is round(N 2^-s) with
 * s = 16 - Eo - k >= 1: the 2^(16 - s) part is exact, so it is
 * avg(M >> (s - 1), 0) + 2^(16 - s).
 * J = 4 (16-entry tables) first: one vpermw per table on AVX-512BW, two
 * vpshufb on AVX2; 2^(j/16) E is avg(E, pmulhuw(A[j], E)) (A = (2^(j/16) -
 * 1) 2^16, so no table of 2^(j/16) itself).  exp2: J = 5 (32 entries:
 * one vpermw; four vpshufb and three vpblendvb on AVX2; with r of 6 bits
 * the AVX-512 loop reads E from a 64-entry table, vpermi2w) where J = 4
 * misses the bound, and J = 6 (64-entry tables, vpermi2w, a table U[j] =
 * 2^(j/64) 2^15 and pmulhuw(U[j], E)) where 5 does too (it has no AVX2
 * loop); exp: J = 4 only (see prep_tab_noclamp).  exp2 with J = 4: no
 * clamp at the top where the inputs above XSAT fit (prep_tab), and the
 * loops take hi and lo from x itself (no bias add; emit_tab).  The vector
 * loops are software pipelined (fx_pipe_loop; the AVX2 loop in three
 * stages, pipe3_loop).
 * Every step is a 16-bit word; exp's x log2(e) to 2^-F (the error model
 * needs t to ~2^-19) is a 16x16 -> 32-bit product from a low/high pair,
 * plus the fraction's high half and one carry.  The error bound is taken
 * over every clamped input: the kernel is modelled here exactly as
 * emitted (tab_eval), against 2^t in long double. */

/* the emitted integer pipeline for one clamped input: hi, lo, M, c, y */
typedef struct {
    unsigned hi, lo, m, c, y;
} tab_val;

static void tab_eval(const fx_gen *G, int base2, int64_t xc, tab_val *v)
{
    const fx_exp_red *X = &G->exp;
    int Ei = G->in.exp, J = X->tj, F = 16 + J;
    uint16_t hi, lo;
    if (base2) {
        uint16_t tb = (uint16_t)((uint16_t)xc + (uint16_t)(X->tk0 << Ei));
        hi = (uint16_t)(tb >> (Ei - J));
        lo = (uint16_t)((uint32_t)tb << (16 - Ei + J));
    } else {
        uint16_t u = (uint16_t)((uint16_t)xc + (uint16_t)X->toff);
        uint32_t pr = (uint32_t)u * (uint32_t)X->tl1;
        uint16_t q = (uint16_t)(((uint32_t)u * (uint32_t)X->tl2 >> 16) + (uint32_t)X->tcl);
        lo = (uint16_t)(pr + q);
        hi = (uint16_t)((pr >> 16) + (lo < q));
    }
    uint16_t g = (uint16_t)(X->tc1 + ((uint32_t)lo * (uint32_t)X->tc2 >> 16));
    uint16_t e = (uint16_t)((uint32_t)lo * g >> 16);
    unsigned j = hi & ((1u << J) - 1);
    uint16_t w;
    if (J != 6) /* avg(E, pmulhuw(A, E)) + D */
        w = (uint16_t)((((uint32_t)e + ((uint32_t)X->ta[j] * e >> 16) + 1u) >> 1) + X->td[j]);
    else
        w = (uint16_t)(((uint32_t)X->tu[j] * e >> 16) + X->td[j]);
    uint32_t ms = (uint32_t)X->ta[j] + (w >> (F - 17));
    uint16_t m = (uint16_t)(ms < 65535u ? ms : 65535u);
    uint16_t kb = (uint16_t)(hi >> J);
    uint16_t c = (uint16_t)(X->tcc - kb);
    uint16_t y0 = (uint16_t)(((uint32_t)(c < 16 ? m >> c : 0) + 1u) >> 1);
    uint32_t ys = (uint32_t)y0 + X->tp[kb & 31u];
    v->hi = hi;
    v->lo = lo;
    v->m = m;
    v->c = c;
    v->y = ys < 65535u ? ys : 65535u;
}

static long double pow2l(long double t) { return exp2l(t); }

/* 0: the kernel with 2^J-entry tables is set up and bounded below 1 lsb
   (G->exp.t*); -2: not this type pair, or not within the bound */
static int prep_tab(fx_gen *G, int base2, int J, char *err, size_t errlen)
{
    fx_exp_red *X = &G->exp;
    int Ei = G->in.exp, Eo = G->out.exp, F = 16 + J, NJ = 1 << J;
    if (!G->exact || G->in.storage_bits != 16 || !G->in.is_signed || G->out.storage_bits != 16 || G->out.is_signed ||
        Ei < (base2 ? J : J + 1) || Ei > 15)
        return -2;
    X->tj = J;
    long double l2e = 1.4426950408889634073599246810018921L;
    /* tables: 2^(j/2^J) from MPFR */
    mpfr_t a, b;
    mpfr_init2(a, 256);
    mpfr_init2(b, 256);
    memset(X->tu, 0, sizeof X->tu);
    for (int j = 0; j < NJ; j++) {
        mpfr_set_si(a, j, MPFR_RNDN);
        mpfr_div_2ui(a, a, (unsigned long)J, MPFR_RNDN);
        mpfr_exp2(a, a, MPFR_RNDN);                  /* T1 */
        if (J == 6)
            X->tu[j] = (uint16_t)scaled_int(a, 15, MPFR_RNDN);
        mpfr_sub_ui(b, a, 1, MPFR_RNDN);
        mpfr_mul_2ui(b, b, 16, MPFR_RNDN);           /* (T1 - 1) 2^16 */
        int64_t A = scaled_int(b, 0, MPFR_RNDN);
        X->ta[j] = (uint16_t)A;
        mpfr_sub_si(b, b, (long)A, MPFR_RNDN);       /* residual in [-1/2, 1/2] */
        mpfr_add_d(b, b, 0.5, MPFR_RNDN);
        X->td[j] = (uint16_t)scaled_int(b, F - 17, MPFR_RNDN);
    }
    mpfr_clear(b);
    if (X->ta[0] != 0) { /* 2^0 - 1: the AVX2 loop's lookups rely on it */
        mpfr_clear(a);
        return -2;
    }
    /* 2^r - 1 on [0, 2^-J]: minimax (absolute), p(0) = 1 */
    fit_problem pb;
    memset(&pb, 0, sizeof pb);
    pb.g = g_exp2;
    pb.a = 0;
    pb.b = (fit_real)1 / NJ;
    pb.order = 2;
    pb.errkind = FIT_ABS;
    pb.ncon = 1;
    pb.con[0].kind = FIT_CON_VALUE;
    pb.con[0].t = 0;
    fit_poly fp;
    if (fit_minimax(&pb, &fp, err, errlen) != 0) {
        mpfr_clear(a);
        return -2;
    }
    X->tc1 = (int64_t)llroundl(ldexpl((long double)fp.c[1], 16));
    X->tc2 = (int64_t)llroundl(ldexpl((long double)fp.c[2], 32 - F));
    if (X->tc1 + X->tc2 > 65535) {
        mpfr_clear(a);
        return -2;
    }
    /* exp2 whose r = lo 2^-F has at most 5 bits (r = m 2^-Ei, m < 2^(Ei - J)),
       or 6 with J < 6: the AVX-512 loop reads E from a 32- or 64-entry table
       of the polynomial's own values (one vpermw or vpermi2w on tb's low
       bits instead of a shift, two multiply-highs and an add): the same bits
       as the plain-C steps and the AVX2 loop, which keep the polynomial */
    X->tet = base2 && (Ei - J <= 5 || (J != 6 && Ei - J == 6));
    if (X->tet) {
        int mb = Ei - J;
        for (uint32_t i = 0; i < 64; i++) {
            uint32_t lo = (uint16_t)((i & ((1u << mb) - 1)) << (16 - mb));
            uint16_t g = (uint16_t)(X->tc1 + (lo * (uint32_t)X->tc2 >> 16));
            X->te[i] = (uint16_t)(lo * g >> 16);
        }
    }
    /* the reduction */
    /* inputs clamp to [xlo, xtop]: from xsat up the result saturates, as
       it does at xsat itself (see below), so no separate select */
    int64_t xlo = X->xlo, xhi = X->xhi, xtop = X->sat ? X->xsat : xhi;
    if (base2) {
        X->tk0 = X->k0; /* prepare16's: x + K0 2^Ei in a uint16_t */
    } else {
        mpfr_set_ui(a, 1, MPFR_RNDN);
        mpfr_exp(a, a, MPFR_RNDN);
        mpfr_log2(a, a, MPFR_RNDN);
        mpfr_mul_2si(a, a, F - Ei, MPFR_RNDN); /* L */
        int64_t Lf = scaled_int(a, 16, MPFR_RNDN);
        X->tl1 = Lf >> 16;
        X->tl2 = Lf & 0xffff;
        if (X->tl1 > 65535) {
            mpfr_clear(a);
            return -2;
        }
        /* u = x + off in [0, 65535]; off such that off Lq - 1/2 is just
           below a multiple of 2^F: the low word's constant Cl then keeps
           q + Cl in 16 bits and the middle bits of the constant are 0 */
        int found = 0;
        long double P2 = ldexpl(1, F);
        for (int64_t off = -xlo; off <= 65535 - xtop && !found; off++) {
            long double c = (long double)off * (long double)Lf / 65536.0L - 0.5L; /* off Lq - 1/2 */
            int64_t K0 = (int64_t)ceill(c / P2);
            long double cl = (long double)K0 * P2 - c;
            int64_t Cl = (int64_t)llroundl(cl);
            if (Cl >= 0 && Cl <= 65536 - X->tl2) {
                X->toff = off;
                X->tk0 = K0;
                X->tcl = Cl;
                found = 1;
            }
        }
        if (!found) {
            mpfr_clear(a);
            return -2;
        }
    }
    mpfr_clear(a);
    /* k + K0 over the clamped inputs: the power-of-two table and s.
       exp2, J = 4: no clamp at the top where every input from xsat up keeps
       (t + K0) 2^Ei in the uint16_t and k + K0 within the 32 entries of P
       beside the others' (checked below): those inputs' own steps then give
       the max, as P = 65535 for every k + K0 > tcc (the shift count wraps:
       0), and one vpminsw fewer per vector */
    X->tcc = 15 - Eo + X->tk0;
    int nohi = base2 && X->sat && J == 4 && pf_type_max_stored(&G->in) + (X->tk0 << Ei) <= 65535;
    int64_t xtopc = xtop;
    tab_val v;
retry:
    memset(X->tp, 0, sizeof X->tp);
    int64_t kbmin = INT64_MAX, kbmax = INT64_MIN;
    X->tcarry0 = 0;
    X->tnohi = nohi;
    xtop = nohi ? pf_type_max_stored(&G->in) : xtopc;
    for (int64_t x = xlo; x <= xtop; x++) {
        tab_eval(G, base2, x, &v);
        int64_t kb = v.hi >> J;
        kbmin = kb < kbmin ? kb : kbmin;
        kbmax = kb > kbmax ? kb : kbmax;
        if (!base2 && ((uint32_t)(uint16_t)((uint16_t)x + (uint16_t)X->toff) * (uint32_t)X->tl1 & 0xffffu) == 0)
            X->tcarry0 = 1; /* lo = q happens: the AVX2 carry needs its general form */
    }
    /* s >= 1 up to xhi; s = 0 (k + K0 = tcc + 1) only where the result
       saturates: P = 65535 there, and the saturating add gives 65535
       whatever avg(M >> c, 0) is (c wraps: its shift gives 0) */
    int64_t kbhi = INT64_MIN;
    for (int64_t x = xlo; x <= xhi; x++) {
        tab_eval(G, base2, x, &v);
        kbhi = (int64_t)(v.hi >> J) > kbhi ? (int64_t)(v.hi >> J) : kbhi;
    }
    if (nohi && (kbmax - kbmin >= 32 || kbhi > X->tcc || X->tcc - kbmin > 31)) {
        nohi = 0;
        goto retry;
    }
    if (kbmax - kbmin >= 32 || kbhi > X->tcc || (kbmax > X->tcc + 1 && !X->tnohi) || X->tcc - kbmin > 31)
        return -2;
    for (int64_t kb = kbmin; kb <= kbmax; kb++) {
        int64_t s = X->tcc - kb + 1;
        X->tp[kb & 31] = (uint16_t)(s < 1 ? 65535 : s <= 16 ? 1 << (16 - s) : s == 17 ? 1 : 0);
    }
    X->klo = kbmin - X->tk0;
    X->khi = kbhi - X->tk0;
    if (X->sat) { /* from xsat: f(x) >= the max, and so must the result be */
        for (int64_t x = X->xsat; x <= xtop; x++) {
            tab_eval(G, base2, x, &v);
            if (v.y != 65535 && nohi) {
                nohi = 0;
                goto retry;
            }
            if (v.y != 65535)
                return -2;
        }
    }
    /* the bound: every clamped input, the pre-rounding value (2^16 + M) 2^-s
       against f(x) 2^Eo; with the kernel's and the reduction's parts */
    double worst = 0, kern = 0, red = 0, poly = 0;
    long double PF = ldexpl(1, F);
    for (int64_t x = xlo; x <= xhi; x++) {
        tab_eval(G, base2, x, &v);
        long double t = base2 ? ldexpl((long double)x, -Ei) : (long double)x * l2e * ldexpl(1, -Ei);
        long double yt = pow2l(t + Eo);
        long double yp = ldexpl(65536.0L + v.m, -(int)(v.c + 1));
        double e = (double)fabsl(yp - yt);
        worst = e > worst ? e : worst;
        long double T = (t + X->tk0) * PF, Tc = (long double)v.hi * 65536 + v.lo;
        double dr = (double)fabsl(Tc - T);
        red = dr > red ? dr : red;
        long double mt =
            (pow2l(ldexpl((long double)((v.hi & (unsigned)(NJ - 1)) * 65536u + v.lo), -F)) - 1) * 65536;
        double dk = (double)fabsl((long double)v.m - mt);
        kern = dk > kern ? dk : kern;
    }
    for (uint32_t r = 0; r < 65536; r++) {
        uint16_t g = (uint16_t)(X->tc1 + (r * (uint32_t)X->tc2 >> 16));
        uint16_t e = (uint16_t)(r * g >> 16);
        double d = (double)fabsl((long double)e - (pow2l(ldexpl((long double)r, -F)) - 1) * PF);
        poly = d > poly ? d : poly;
    }
    X->terr = worst * (1 + 1e-9) + 1e-9; /* long double's own error: far below */
    X->tkern = kern;
    X->tred = red;
    X->tpoly = poly;
    G->dred = ldexp(red, -F);
    /* exact: the pre-rounding error and the final rounding's 1/2 below 1 lsb */
    if (!(X->terr + 0.5 < 1 - 1e-6))
        return -2;
    return 0;
}

/* exp's AVX2 loop without the top clamp: u = x + off by a signed saturating
   add (vpaddsw) where every input up to the clamp keeps x + off <= 32767, so
   that no computed input changes, and where every input above it, with u
   saturated at 32767, reaches the s <= 0 select with e = 17 - s in [17, 23]
   (the H table's 0xff bytes), through the AVX2 loop's own carry: the max, as
   the clamp gave.  One vpminsw fewer per 16 lanes (fixed<15,11> ->
   ufixed<16,8>, Zen 3: 8.88 -> 8.63 TSC ticks per 16 lanes) */
static int avx2_sat_add(const fx_gen *G, int base2)
{
    const fx_exp_red *X = &G->exp;
    int J = X->tj;
    if (base2 || !X->sat || X->tnohi || J != 4 || X->xsat - 1 + X->toff > 32767)
        return 0;
    for (int64_t x = X->xsat; x <= 32767; x++) {
        int64_t us = x + X->toff;
        uint16_t u = (uint16_t)(us > 32767 ? 32767 : us);
        uint32_t pr = (uint32_t)u * (uint32_t)X->tl1;
        uint16_t q = (uint16_t)(((uint32_t)u * (uint32_t)X->tl2 >> 16) + (uint32_t)X->tcl);
        uint16_t lo = (uint16_t)(pr + q);
        unsigned cy = X->tcarry0 ? lo < q : lo <= q; /* as the AVX2 loop computes it */
        int64_t kb = (uint16_t)((pr >> 16) + cy) >> J;
        if (kb < X->tcc + 1 || kb > X->tcc + 7)
            return 0;
    }
    return 1;
}

static void tab_texts(fx_gen *G, int base2)
{
    const fx_exp_red *X = &G->exp;
    int Ei = G->in.exp, Eo = G->out.exp, J = X->tj, F = 16 + J, NJ = 1 << J;
    int smin = (int)(X->tcc - (X->khi + X->tk0)) + 1, smax = (int)(X->tcc - (X->klo + X->tk0)) + 1;
    long long xtop = (long long)(X->sat ? X->xsat : X->xhi);
    char nohi[160] = "";
    if (X->tnohi)
        snprintf(nohi, sizeof nohi,
                 "; no clamp at the top: from %lld (stored) up, k + %lld > %lld reads P = 65535 (the shift count "
                 "wraps: 0) and the saturating add gives the max",
                 (long long)X->xsat, (long long)X->tk0, (long long)X->tcc);
    if (base2)
        snprintf(G->red_text, sizeof G->red_text,
                 "t = x; T = (t + %lld) 2^%d = hi 2^16 + lo from the stored integer biased by %lld 2^%d (exact): "
                 "j = hi & %d, k + %lld = hi >> %d, r = lo 2^-%d in [0, 2^-%d), t = k + j/%d + r; inputs %s "
                 "[%lld, %lld] (stored)%s",
                 (long long)X->tk0, F, (long long)X->tk0, Ei, NJ - 1, (long long)X->tk0, J, F, J, NJ,
                 X->tnohi ? (X->loclamp ? "clamped below, computed in" : "computed in") : "clamped to",
                 (long long)X->xlo, X->tnohi ? (long long)X->xhi : xtop,
                 X->tnohi ? nohi : X->sat ? ", the last one saturating" : "");
    else
        snprintf(G->red_text, sizeof G->red_text,
                 "t = x log2(e); T = (t + %lld) 2^%d = hi 2^16 + lo in two 16-bit words: u = x + %lld (a uint16_t), "
                 "T = u L1 + floor(u L2 2^-16) + %lld with L = log2(e) 2^%d = L1 + L2 2^-16, L1 = %lld, L2 = %lld "
                 "(MPFR, rounded to 2^-16), u L1 from a low/high product pair and the low word's carry into hi by an "
                 "unsigned compare; j = hi & %d, k + %lld = hi >> %d, r = lo 2^-%d in [0, 2^-%d); inputs clamped to "
                 "[%lld, %lld] (stored)%s; |error of T| <= %.3f 2^-%d (every clamped input)",
                 (long long)X->tk0, F, (long long)X->toff, (long long)X->tcl, F - Ei, (long long)X->tl1,
                 (long long)X->tl2, NJ - 1, (long long)X->tk0, J, F, J, (long long)X->xlo, xtop,
                 X->sat ? ", the last one saturating" : "", X->tred, F);
    snprintf(G->alt_domain, sizeof G->alt_domain,
             "2^r - 1 on r in [0, 2^-%d]; 2^(j/%d) for j in [0, %d] from tables (2^t = 2^k 2^(j/%d) 2^r)", J, NJ,
             NJ - 1, NJ);
    snprintf(G->alt_order, sizeof G->alt_order,
             "2 (2^r - 1 = r (c1 + c2 r): 2 fixed-point coefficients), and %s %d-entry tables of 2^(j/%d); "
             "uint16_t words: 16-bit lanes",
             J != 6 ? "two" : "three", NJ, NJ);
    snprintf(G->alt_method, sizeof G->alt_method,
             "minimax absolute error of 2^r on [0, 2^-%d] (nlopt SLSQP, epigraph form), c1 and c2 rounded to nearest "
             "at 2^-16 and 2^-%d (their multiply-highs' lsbs); tables rounded to nearest from MPFR (256 bits): "
             "A[j] = (2^(j/%d) - 1) 2^16, %sD[j] = (A[j]'s residual + 1/2) 2^%d",
             J, 32 - F, NJ, J != 6 ? "" : "U[j] = 2^(j/64) 2^15, ", F - 17);
    snprintf(G->alt_con, sizeof G->alt_con, "p(0) = 1 (2^r - 1 has no constant term; exact at r = 0)");
    char avgt[64];
    snprintf(avgt, sizeof avgt, "avg(E, pmulhuw(A[j], E)) (= 2^(j/%d) E 2^-1, pavgw)", NJ);
    snprintf(G->alt_formats, sizeof G->alt_formats,
             "r uint16_t at 2^-%d; E = pmulhuw(r, c1 + pmulhuw(r, c2)) = (2^r - 1) 2^%d (floors; c1 = %lld, c2 = %lld); "
             "M = A[j] + ((%s + D[j]) >> %d), saturated at 65535 (2^f 2^16 = 2^16 + M: one rounding of "
             "the sum, D carrying A's); result round((2^16 + M) 2^-s), s = %d - k in [%d, %d], as avg(M >> (s - 1), 0) "
             "(pavgw) + P[k] (P = 2^(16 - s), 1 at s = 17, 0 beyond, 65535 at s %s 0: the saturating add gives the max "
             "there, %s)%s",
             F, F, (long long)X->tc1, (long long)X->tc2,
             J != 6 ? avgt : "pmulhuw(U[j], E)", F - 17, 16 - Eo,
             smin, smax, X->tnohi ? "<=" : "=", X->tnohi ? "at every saturating input" : "at the clamped top input",
             J != 6 ? "; AVX2: round(M 2^-s) + P as avg(Q, pmulhuw(M, Q)) with Q = 2^(17 - s) for s >= 2 (vpshufb "
                      "table, 0 from s = 18), and 2^15 + avg(M, 0) (saturating) at s = 1: the same values"
                    : "");
    snprintf(G->alt_poly, sizeof G->alt_poly,
             "E within %.3f of (2^r - 1) 2^%d for every r (polynomial and floors, all 2^16 r); M within %.4f of "
             "(2^f - 1) 2^16 for every input's (j, r)",
             X->tpoly, F, X->tkern);
    if (J != 6)
        snprintf(G->wide_text, sizeof G->wide_text,
                 "16-bit words throughout%s; AVX-512BW (x86-64-v4): lookups vpermw, the shift vpsrlvw; AVX2 "
                 "(x86-64-v3): a lookup two vpshufb and a vpblendvb, the shift a pmulhuw by 2^(17 - s)%s, three "
                 "blocks in flight; the default clone, scalar form: the same steps in plain C",
                 base2 ? "" : ", x log2(e) to 2^-20 a 16x16 -> 32-bit product (pmullw, pmulhuw) plus a carry",
                 avx2_sat_add(G, base2) ? ", the top clamp a saturating add (vpaddsw)" : "");
    else
        snprintf(G->wide_text, sizeof G->wide_text,
                 "16-bit words throughout%s; lookups (vpermi2w, vpermw) and the per-element shift (vpsrlvw) in "
                 "16-bit lanes by AVX-512BW intrinsics (x86-64-v4); other clones, scalar form: the same steps in "
                 "plain C",
                 base2 ? "" : ", x log2(e) to 2^-22 (the bound needs ~2^-19) a 16x16 -> 32-bit product (pmullw, "
                              "pmulhuw) plus a carry");
    if (X->tet) { /* exp2, r of <= 5 bits: the AVX-512 loop reads E from a table */
        size_t o = strlen(G->alt_formats);
        snprintf(G->alt_formats + o, sizeof G->alt_formats - o,
                 "; r has %d bits (r = m 2^-%d): the AVX-512 loop reads E from a %d-entry table of these same "
                 "values (%s on the biased input's low bits)",
                 Ei - J, Ei, Ei - J == 6 ? 64 : 32, Ei - J == 6 ? "vpermi2w" : "vpermw");
    }
    snprintf(G->alt_arith, sizeof G->alt_arith,
             "integers only (no floating point, no <math.h>); the steps before the result floor (unsigned "
             "multiply-highs, shifts: in the bound), the result is rounded once to nearest, ties up (pavgw); "
             "bit-identical under any compiler flags");
    snprintf(G->bound_note, sizeof G->bound_note,
             "taken over every clamped input from the emitted integer steps (the table kernel)");
}

/* 32-bit entries: GCC vectorizes the plain-C lookups then (AVX2: 2.5 times
   the speed of 16-bit entries); the AVX-512 loop narrows them once */
static void tab_table(pf_buf *b, const char *name, const char *suf, const uint16_t *v, int n, const char *what)
{
    pf_printf(b, "/* %s */\nstatic const uint32_t %s_%s[%d] = {", what, name, suf, n);
    for (int i = 0; i < n; i++)
        pf_printf(b, "%s%u,", i % 8 ? " " : "\n    ", v[i]);
    pf_put(b, "\n};\n");
}

/* signed 16-bit literal of the same bits, for _mm512_set1_epi16 */
static long long s16(int64_t v) { return (long long)(int16_t)(uint16_t)v; }

/* the AVX-512 exact loops' clamp constants where the kernel clamps */
static void bw_clamp_consts(pf_buf *kern, const fx_exp_red *X)
{
    if (X->loclamp)
        pf_printf(kern, "    const __m512i xlo = _mm512_set1_epi16(%lld);\n", (long long)X->xlo);
    if (X->sat && !X->tnohi)
        pf_printf(kern, "    const __m512i xhi = _mm512_set1_epi16(%lld);\n", (long long)X->xsat);
}

/* x loaded and clamped as xc (the first steps of a loop's stage 1) */
static void bw_clamp_load(pf_buf *s1, const fx_exp_red *X)
{
    pf_put(s1, "        __m512i xc = _mm512_loadu_si512(x + i);\n");
    if (X->loclamp)
        pf_put(s1, "        xc = _mm512_max_epi16(xc, xlo);\n");
    if (X->sat && !X->tnohi)
        pf_put(s1, "        xc = _mm512_min_epi16(xc, xhi);\n");
}

/* s, each non-empty line indented by 4 n more spaces */
static void put_in(pf_buf *b, const char *s, size_t len, int n)
{
    const char *end = s + len;
    while (s < end) {
        const char *e = memchr(s, '\n', (size_t)(end - s));
        size_t k = e ? (size_t)(e - s) + 1 : (size_t)(end - s);
        for (int i = 0; i < n && k > 1; i++)
            pf_put(b, "    ");
        pf_putn(b, s, k);
        s += k;
    }
}

/* The AVX2 table-kernel loop, software pipelined in three stages: a pass
   runs stage 1 (s1: x + i loaded, up to lo and hi) of block i, stage 2
   (s2, its first n2 bytes: E, the lookups, M) of block i - 16 and stage 3
   (s3: from k on, r) of block i - 32, three blocks in flight.  One block's
   steps are two chains of some 25 dependent instructions (the reduction
   and E into M, M into r) that the scheduler does not overlap enough with
   two stages (fx_pipe_loop); fixed<15,11> -> ufixed<16,8> on Zen 3, the
   loop alone, TSC ticks per 16 lanes: exp 8.63 -> 8.28, exp2 6.50 -> 6.30
   (the same code placed at several alignments; the two-stage loop moves
   between 6.3 and 6.7 with its alignment); bench_fixed 40, ns/element: exp
   0.234 -> 0.212, exp2 0.171 -> 0.162.  Tried and slower or no better
   (exp2): four stages, the three unrolled by two (no register moves), k and
   Q in stage 2, E in stage 1.  n in [16, 32): one unpipelined block;
   fewer than 16 left over: the scalar form */
static void pipe3_loop(pf_buf *kern, const char *s1, const char *s2, size_t n2, const char *s3, const char *scalar)
{
    size_t n1 = strlen(s1), n3 = strlen(s3);
    pf_put(kern, "    size_t i = 0;\n    if (n >= 32) {\n"
                 "        /* software pipelined in three stages: a pass runs the reduction of block i,\n"
                 "           E, the lookups and M of block i - 16, and the scaling of block i - 32\n"
                 "           (three blocks in flight: one block's chain is longer than the CPU overlaps;\n"
                 "           Zen 3, fixed<15,11> -> ufixed<16,8>, bench_fixed 40 against two stages:\n"
                 "           exp 0.234 -> 0.212, exp2 0.171 -> 0.162 ns/element) */\n"
                 "        __m256i p_lo, p_hi, q_m, q_hi;\n        {\n");
    put_in(kern, s1, n1, 1);
    pf_put(kern, "            p_lo = lo, p_hi = hi;\n        }\n        {\n"
                 "            __m256i lo = p_lo, hi = p_hi;\n");
    put_in(kern, s2, n2, 1);
    pf_put(kern, "            q_m = m, q_hi = hi;\n        }\n        i = 16;\n        {\n");
    put_in(kern, s1, n1, 1);
    pf_put(kern, "            p_lo = lo, p_hi = hi;\n        }\n"
                 "        for (i = 32; i + 16 <= n; i += 16) {\n            __m256i n_lo, n_hi, n_m;\n            {\n");
    put_in(kern, s1, n1, 2);
    pf_put(kern, "                n_lo = lo, n_hi = hi;\n            }\n            {\n"
                 "                __m256i lo = p_lo, hi = p_hi;\n");
    put_in(kern, s2, n2, 2);
    pf_put(kern, "                n_m = m;\n            }\n            {\n                __m256i m = q_m, hi = q_hi;\n");
    put_in(kern, s3, n3, 2);
    pf_put(kern, "                _mm256_storeu_si256((__m256i *)(y + i - 32), r);\n            }\n"
                 "            q_m = n_m, q_hi = p_hi, p_lo = n_lo, p_hi = n_hi;\n        }\n"
                 "        {\n            __m256i m = q_m, hi = q_hi;\n");
    put_in(kern, s3, n3, 1);
    pf_put(kern, "            _mm256_storeu_si256((__m256i *)(y + i - 32), r);\n        }\n"
                 "        {\n            __m256i lo = p_lo, hi = p_hi;\n");
    put_in(kern, s2, n2, 1);
    put_in(kern, s3, n3, 1);
    /* 16 to 31 elements: one block, unpipelined, so short arrays keep the
       vector loop (before this the scalar form took them all) */
    pf_put(kern, "            _mm256_storeu_si256((__m256i *)(y + i - 16), r);\n        }\n    }\n"
                 "    for (; i + 16 <= n; i += 16) {\n");
    put_in(kern, s1, n1, 0);
    put_in(kern, s2, n2, 0);
    put_in(kern, s3, n3, 0);
    pf_printf(kern, "        _mm256_storeu_si256((__m256i *)(y + i), r);\n    }\n"
                    "    for (; i < n; i++)\n        y[i] = %s(x[i]);\n}\n#endif",
              scalar);
}

static void emit_tab(fx_gen *G, pf_buf *body, pf_buf *tabs, pf_buf *kern, int base2)
{
    const fx_exp_red *X = &G->exp;
    int Ei = G->in.exp, J = X->tj, F = 16 + J, NJ = 1 << J;
    const char *N = G->name;
    char w[64], what[160];
    const char *kl = NULL, *kh = NULL;
    if (X->loclamp) {
        snprintf(w, sizeof w, "%lld: lowest input computed (clamp)", (long long)X->xlo);
        kl = fx_k16(G, X->xlo, w);
    }
    if (X->sat && !X->tnohi) {
        snprintf(w, sizeof w, "%lld: highest input computed (clamp: saturates)", (long long)X->xsat);
        kh = fx_k16(G, X->xsat, w);
    }
    if (!kl && !kh)
        fx_k16(G, 0, "0 (unused: no clamp)");
    snprintf(what, sizeof what, "A[j] = round((2^(j/%d) - 1) 2^16) (MPFR)", NJ);
    tab_table(tabs, N, "ta", X->ta, NJ, what);
    if (J == 6)
        tab_table(tabs, N, "tu", X->tu, NJ, "U[j] = round(2^(j/64) 2^15) (MPFR)");
    snprintf(what, sizeof what, "D[j] = round(((2^(j/%d) - 1) 2^16 - A[j] + 1/2) 2^%d), in [0, %d] (MPFR)", NJ, F - 17,
             1 << (F - 17));
    tab_table(tabs, N, "td", X->td, NJ, what);
    tab_table(tabs, N, "tp", X->tp, 32, "P[(k + K0) & 31] = round(2^(16 - s)), s = 16 - Eo - k (0 off the range)");
    pf_put(body, "    int16_t xc = (int16_t)x;\n");
    if (kl)
        pf_printf(body, "    xc = (int16_t)(xc < %s ? %s : xc); /* %lld */\n", kl, kl, (long long)X->xlo);
    if (kh)
        pf_printf(body, "    xc = (int16_t)(xc > %s ? %s : xc); /* %lld */\n", kh, kh, (long long)X->xsat);
    else
        pf_put(body, "    (void)k;\n");
    pf_printf(body, "    /* T = (t + %lld) 2^%d = hi 2^16 + lo: j = hi & %d, k + %lld = hi >> %d, r = lo 2^-%d */\n",
              (long long)X->tk0, F, NJ - 1, (long long)X->tk0, J, F);
    if (base2) {
        pf_printf(body, "    uint16_t tb = (uint16_t)((uint16_t)xc + %lluu); /* (t + %lld) 2^%d */\n",
                  (unsigned long long)(uint16_t)(X->tk0 << Ei), (long long)X->tk0, Ei);
        pf_printf(body, "    uint16_t hi = (uint16_t)(tb >> %d);\n", Ei - J);
        pf_printf(body, "    uint16_t lo = (uint16_t)((uint32_t)tb << %d);\n", 16 - Ei + J);
    } else {
        pf_printf(body, "    uint16_t u = (uint16_t)((uint16_t)xc + %lluu);\n", (unsigned long long)(uint16_t)X->toff);
        pf_printf(body, "    uint32_t pr = (uint32_t)u * %lldu; /* u L1: pmullw, pmulhuw */\n", (long long)X->tl1);
        pf_printf(body, "    uint16_t q = (uint16_t)(((uint32_t)u * %lldu >> 16) + %lldu); /* floor(u L2 2^-16) + Cl */\n",
                  (long long)X->tl2, (long long)X->tcl);
        pf_put(body, "    uint16_t lo = (uint16_t)(pr + q);\n");
        pf_put(body, "    uint16_t hi = (uint16_t)((pr >> 16) + (lo < q)); /* the carry */\n");
    }
    pf_printf(body, "    /* E = (2^r - 1) 2^%d = r (c1 + c2 r), floors */\n"
                    "    uint16_t g = (uint16_t)(%lldu + ((uint32_t)lo * %lldu >> 16));\n"
                    "    uint16_t e = (uint16_t)((uint32_t)lo * g >> 16);\n",
              F, (long long)X->tc1, (long long)X->tc2);
    if (J != 6)
        pf_printf(body, "    /* M = (2^(j/%d + r) - 1) 2^16, one rounding: A[j] + round(2^(j/%d) E 2^-%d + A[j]'s residual),\n"
                        "       2^(j/%d) E 2^-1 = avg(E, pmulhuw(A[j], E)) (pavgw) */\n"
                        "    unsigned j = hi & %du;\n"
                        "    uint16_t v = (uint16_t)((((uint32_t)e + ((uint32_t)%s_ta[j] * e >> 16) + 1u) >> 1) + %s_td[j]);\n"
                        "    uint32_t ms = (uint32_t)%s_ta[j] + (uint32_t)(v >> %d);\n"
                        "    uint16_t m = (uint16_t)(ms < 65535u ? ms : 65535u);\n",
                  NJ, NJ, F - 16, NJ, NJ - 1, N, N, N, F - 17);
    else
        pf_printf(body, "    /* M = (2^(j/64 + r) - 1) 2^16, one rounding: A[j] + round(U[j] E 2^-21 + A[j]'s residual) */\n"
                        "    unsigned j = hi & 63u;\n"
                        "    uint16_t v = (uint16_t)(((uint32_t)%s_tu[j] * e >> 16) + %s_td[j]);\n"
                        "    uint32_t ms = (uint32_t)%s_ta[j] + (uint32_t)(v >> 5);\n"
                        "    uint16_t m = (uint16_t)(ms < 65535u ? ms : 65535u);\n",
                  N, N, N);
    pf_printf(body, "    /* round((2^16 + M) 2^-s), s = c + 1 >= 1: avg(M >> c, 0) + 2^(16 - s) */\n"
                    "    uint16_t kb = (uint16_t)(hi >> %d);\n"
                    "    uint16_t c = (uint16_t)(%lld - kb); /* in [0, %lld]; wraps at s = 0 (saturated by P) */\n"
                    "    uint16_t y0 = (uint16_t)(((uint32_t)(c < 16 ? m >> c : 0) + 1u) >> 1); /* pavgw; vpsrlvw's 0 */\n"
                    "    uint32_t ys = (uint32_t)y0 + %s_tp[kb & 31u];\n"
                    "    uint16_t r16 = (uint16_t)(ys < 65535u ? ys : 65535u);\n",
              J, (long long)X->tcc, (long long)(X->tcc - (X->klo + X->tk0)), N);
    pf_printf(body, "    return (%s)r16;", G->ot);
    /* the AVX-512BW loop: the same steps on 32 lanes */
    const char *cond = "#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(__AVX2__)\n";
    pf_printf(kern,
              "\n\n/* AVX-512BW: the same steps on 32 lanes, with intrinsics, as GCC does not turn\n"
              "   the table lookups into %s (nor the carry into a mask): the\n"
              "   array form runs this loop on a CPU with x86-64-v4 (see its dispatch), the\n"
              "   rest of the array and the other clones use the scalar steps above.  The\n"
              "   same values (pfmathgen sweeps the array form on its machine against the\n"
              "   scalar one). */\n%s#include <immintrin.h>\n"
              "extern %s %s(%s x); /* the scalar form, for the last n %% 32 */\n"
              "/* 32 table entries as 16-bit words, for vpermw%s */\n"
              "__attribute__((target(\"arch=x86-64-v4\"))) static inline __m512i %s_w16(const uint32_t *t)\n{\n"
              "    return _mm512_inserti64x4(_mm512_castsi256_si512(_mm512_cvtepi32_epi16(_mm512_loadu_si512(t))),\n"
              "                              _mm512_cvtepi32_epi16(_mm512_loadu_si512(t + 16)), 1);\n}\n",
              J != 6 && !(X->tet && Ei - J == 6) ? "vpermw" : "vpermi2w/vpermw", cond, G->ot, N, G->it,
              J != 6 && !(X->tet && Ei - J == 6) ? "" : "/vpermi2w", N);
    if (J == 4)
        pf_printf(kern, "/* 16 entries as 16-bit words, twice (vpermw reads 5 index bits: hi's low 4 are j) */\n"
                        "__attribute__((target(\"arch=x86-64-v4\"))) static inline __m512i %s_w16b(const uint32_t *t)\n{\n"
                        "    return _mm512_broadcast_i64x4(_mm512_cvtepi32_epi16(_mm512_loadu_si512(t)));\n}\n",
                  N);
    pf_printf(kern, "__attribute__((target(\"arch=x86-64-v4\"), noinline))\n"
                    "static void %s_array_bw(const %s *x, %s *y, size_t n)\n{\n",
              N, G->it, G->ot);
    /* exp2 with J = 5 and E from a 64-entry table: the loop runs on
       tbn = CB - x = (c + 1) 2^Ei - 1 - (tb mod 2^Ei), whose top bits are
       c = s - 1 itself (no vpsubw for the shift count) and whose low bits
       index the tables reversed; the clamped top input (s = 0) wraps to
       c = 31 mod 32, the max.  Where every c of the other inputs is at
       most 30 */
    int cmpl = base2 && X->tet && J == 5 && Ei - J == 6;
    int64_t CB = (X->tcc + 1 - X->tk0) * ((int64_t)1 << Ei) - 1;
    if (cmpl) {
        int64_t xtop = X->sat ? X->xsat : X->xhi;
        for (int64_t x = X->xlo; x <= xtop && cmpl; x++) {
            int64_t tn = CB - x;
            if (x <= X->xhi ? tn < 0 || tn > 65535 || (tn >> Ei) > 30 : ((uint16_t)tn >> Ei) % 32 != 31)
                cmpl = 0;
        }
    }
    if (cmpl) {
        uint16_t rv[64];
        pf_buf t = {0};
        for (int i = 0; i < 64; i++)
            rv[i] = X->te[63 - i];
        tab_table(&t, N, "ter", rv, 64, "E[63 - i] (tbn's low 6 bits are 63 - r's)");
        for (int i = 0; i < 32; i++)
            rv[i] = X->ta[31 - i];
        tab_table(&t, N, "tar", rv, 32, "A[31 - i] (j = 31 - (tbn >> 6) mod 32)");
        for (int i = 0; i < 32; i++)
            rv[i] = X->td[31 - i];
        tab_table(&t, N, "tdr", rv, 32, "D[31 - i]");
        for (int i = 0; i < 32; i++) {
            int64_t kb = X->tcc - i;
            rv[i] = (uint16_t)(i == 31 ? (X->sat ? 65535 : 0) : kb >= X->klo + X->tk0 ? X->tp[kb & 31] : 0);
        }
        tab_table(&t, N, "tpr", rv, 32, "P at c = s - 1 = i (P[(k + K0) & 31] above, k + K0 = tcc - c); 31: s = 0");
        pf_put(kern, t.s);
        free(t.s);
        pf_printf(kern, "    const __m512i ta = %s_w16(%s_tar), td = %s_w16(%s_tdr), tp = %s_w16(%s_tpr);\n"
                        "    const __m512i te0 = %s_w16(%s_ter), te1 = %s_w16(%s_ter + 32);\n"
                        "    const __m512i cb = _mm512_set1_epi16(%lld); /* CB = (tcc + 1 - K0) 2^%d - 1 */\n",
                  N, N, N, N, N, N, N, N, N, N, s16(CB), Ei);
        bw_clamp_consts(kern, X);
        pf_buf s1 = {0}, s2 = {0};
        bw_clamp_load(&s1, X);
        pf_printf(&s1, "        __m512i tn = _mm512_sub_epi16(cb, xc); /* (c + 1) 2^%d - 1 - (tb mod 2^%d) */\n"
                       "        __m512i hn = _mm512_srli_epi16(tn, %d), e = _mm512_permutex2var_epi16(te0, tn, te1);\n",
                  Ei, Ei, Ei - J);
        pf_printf(&s2, "        __m512i a = _mm512_permutexvar_epi16(hn, ta);\n"
                       "        __m512i v = _mm512_avg_epu16(e, _mm512_mulhi_epu16(a, e));\n"
                       "        v = _mm512_add_epi16(v, _mm512_permutexvar_epi16(hn, td));\n"
                       "        __m512i m = _mm512_adds_epu16(a, _mm512_srli_epi16(v, %d));\n"
                       "        __m512i c = _mm512_srli_epi16(tn, %d);\n"
                       "        __m512i r = _mm512_avg_epu16(_mm512_srlv_epi16(m, c), _mm512_setzero_si512());\n"
                       "        r = _mm512_adds_epu16(r, _mm512_permutexvar_epi16(c, tp));\n",
                  F - 17, Ei);
        static const char *const cv[] = {"tn", "hn", "e"};
        fx_pipe_loop(kern, "__m512i", 32, s1.s, s2.s, cv, 3, "_mm512_storeu_si512(y + i - 32, r);", N);
        free(s1.s);
        free(s2.s);
    }
    if (X->tet && !cmpl) {
        pf_buf te = {0};
        snprintf(what, sizeof what, "E[i] = the polynomial's E at r = (i mod 2^(Ei - %d)) 2^-Ei (the plain-C steps' values)",
                 J);
        tab_table(&te, N, "te", X->te, Ei - J == 6 ? 64 : 32, what);
        pf_put(kern, te.s);
        free(te.s);
    }
    if (!cmpl) {
        if (base2) {
            uint16_t rv[32];
            pf_buf t = {0};
            for (int i = 0; i < 32; i++)
                rv[i] = X->tp[(i + X->tk0) & 31];
            tab_table(&t, N, "tpk", rv, 32, "P[(k + K0) & 31] at k & 31 = i (P above rotated by K0)");
            pf_put(kern, t.s);
            free(t.s);
        }
        if (J == 5)
            pf_printf(kern, "    const __m512i ta = %s_w16(%s_ta), td = %s_w16(%s_td);\n", N, N, N, N);
        else if (J == 4)
            pf_printf(kern, "    const __m512i ta = %s_w16b(%s_ta), td = %s_w16b(%s_td);\n", N, N, N, N);
        else
            pf_printf(kern, "    const __m512i ta0 = %s_w16(%s_ta), ta1 = %s_w16(%s_ta + 32);\n"
                            "    const __m512i tu0 = %s_w16(%s_tu), tu1 = %s_w16(%s_tu + 32);\n"
                            "    const __m512i td0 = %s_w16(%s_td), td1 = %s_w16(%s_td + 32);\n",
                      N, N, N, N, N, N, N, N, N, N, N, N);
        if (!base2)
            pf_printf(kern, "    const __m512i tp = %s_w16(%s_tp);\n", N, N);
        if (X->tet && Ei - J == 6)
            pf_printf(kern, "    const __m512i te0 = %s_w16(%s_te), te1 = %s_w16(%s_te + 32);\n", N, N, N, N);
        else if (X->tet)
            pf_printf(kern, "    const __m512i te = %s_w16(%s_te);\n", N, N);
        /* exp2: no bias (one vpaddw fewer): hi - K0 2^J = x >> (Ei - J)
           (arithmetic; the lookups read hi mod 2^J, or mod 32 of tables
           repeated or of 32 entries, the same), lo = x << (16 - Ei + J), and
           k = (hi - K0 2^J) >> J reads P rotated by K0 */
        int64_t cc = base2 ? X->tcc - X->tk0 : X->tcc;
        if (X->tet)
            pf_printf(kern, "    const __m512i cc = _mm512_set1_epi16(%lld);\n", s16(cc));
        else
        pf_printf(kern, "    const __m512i c1 = _mm512_set1_epi16(%lld), c2 = _mm512_set1_epi16(%lld), cc = _mm512_set1_epi16(%lld);\n",
                  s16(X->tc1), s16(X->tc2), s16(cc));
        if (base2)
            pf_printf(kern, "    const __m512i tpk = %s_w16(%s_tpk); /* P at k = (hi - K0 2^J) >> J */\n", N, N);
        else
            pf_printf(kern, "    const __m512i off = _mm512_set1_epi16(%lld), l1 = _mm512_set1_epi16(%lld), l2 = _mm512_set1_epi16(%lld),\n"
                            "                  cl = _mm512_set1_epi16(%lld), one = _mm512_set1_epi16(1);\n",
                      s16(X->toff), s16(X->tl1), s16(X->tl2), s16(X->tcl));
        bw_clamp_consts(kern, X);
        pf_buf s1 = {0}, s2 = {0};
        bw_clamp_load(&s1, X);
        if (base2 && X->tet && Ei - J == 6)
            pf_printf(&s1, "        __m512i hi = _mm512_srai_epi16(xc, %d), e = _mm512_permutex2var_epi16(te0, xc, te1);\n",
                      Ei - J);
        else if (base2 && X->tet)
            pf_printf(&s1, "        __m512i hi = _mm512_srai_epi16(xc, %d), e = _mm512_permutexvar_epi16(xc, te);\n",
                      Ei - J);
        else if (base2)
            pf_printf(&s1, "        __m512i hi = _mm512_srai_epi16(xc, %d), lo = _mm512_slli_epi16(xc, %d);\n",
                      Ei - J, 16 - Ei + J);
        else
            pf_put(&s1, "        __m512i u = _mm512_add_epi16(xc, off);\n"
                         "        __m512i q = _mm512_add_epi16(_mm512_mulhi_epu16(u, l2), cl);\n"
                         "        __m512i lo = _mm512_add_epi16(_mm512_mullo_epi16(u, l1), q);\n"
                         "        __m512i hi = _mm512_mulhi_epu16(u, l1);\n"
                         "        hi = _mm512_mask_add_epi16(hi, _mm512_cmplt_epu16_mask(lo, q), hi, one);\n");
        if (!X->tet)
            pf_put(&s1, "        __m512i e = _mm512_mulhi_epu16(lo, _mm512_add_epi16(c1, _mm512_mulhi_epu16(lo, c2)));\n");
        if (J != 6)
            pf_printf(&s2, "        __m512i a = _mm512_permutexvar_epi16(hi, ta);\n"
                            "        __m512i v = _mm512_avg_epu16(e, _mm512_mulhi_epu16(a, e));\n"
                            "        v = _mm512_add_epi16(v, _mm512_permutexvar_epi16(hi, td));\n"
                            "        __m512i m = _mm512_adds_epu16(a, _mm512_srli_epi16(v, %d));\n"
                            "        __m512i kb = _mm512_sr%si_epi16(hi, %d);\n",
                      F - 17, base2 ? "a" : "l", J);
        else
            pf_put(&s2, "        __m512i v = _mm512_mulhi_epu16(_mm512_permutex2var_epi16(tu0, hi, tu1), e);\n"
                         "        v = _mm512_add_epi16(v, _mm512_permutex2var_epi16(td0, hi, td1));\n"
                         "        __m512i m = _mm512_adds_epu16(_mm512_permutex2var_epi16(ta0, hi, ta1), _mm512_srli_epi16(v, 5));\n"
                         "        __m512i kb = _mm512_srli_epi16(hi, 6);\n");
        if (base2 && J == 6)
            memcpy(strstr(s2.s, "kb = _mm512_srli_epi16(hi, 6)") + 12, "srai", 4);
        pf_printf(&s2, "        __m512i r = _mm512_avg_epu16(_mm512_srlv_epi16(m, _mm512_sub_epi16(cc, kb)), _mm512_setzero_si512());\n"
                       "        r = _mm512_adds_epu16(r, _mm512_permutexvar_epi16(kb, %s));\n",
                  base2 ? "tpk" : "tp");
        static const char *const cv[] = {"hi", "e"};
        fx_pipe_loop(kern, "__m512i", 32, s1.s, s2.s, cv, 2, "_mm512_storeu_si512(y + i - 32, r);", N);
        free(s1.s);
        free(s2.s);
    }
    G->bw16 = 2;
    if (J == 6)
        return;
    /* AVX2: no vpermw, no 16-bit per-element shift, no unsigned compare
       into a mask.  A 16-entry table of words is two vpshufb (its low and
       high bytes) merged by vpblendvb; D (< 256) one vpshufb.  The scaling
       round((2^16 + M) 2^-s) is avg(Q, pmulhuw(M, Q)) with Q = 2^(17 - s)
       for s in [2, 17] (a vpshufb table on s - 2; from s = 18 the index
       passes 0x7f and vpshufb gives 0, as the scalar's P does), and
       2^15 + avg(M, 0) (saturating) at s = 1: both equal avg(M >> (s - 1),
       0) + P[k] of the scalar form */
    pf_buf tb5 = {0};
    int sadd = avx2_sat_add(G, base2);
    if (J == 4)
        pf_printf(&tb5, "    uint8_t b[4][16]; /* A's low, high bytes, D, the bytes of Q = 2^e (b[3][i] = 2^i, 0 from i = 8) */\n"
                        "    for (int k = 0; k < 16; k++) {\n"
                        "        b[0][k] = (uint8_t)%s_ta[k];\n"
                        "        b[1][k] = (uint8_t)(%s_ta[k] >> 8);\n"
                        "        b[2][k] = (uint8_t)%s_td[k];\n"
                        "        b[3][k] = (uint8_t)(k < 8 ? 1u << k : 0u);\n"
                        "    }\n",
                  N, N, N);
    else
        pf_printf(&tb5, "    uint8_t b[7][16]; /* A's low, high bytes, D (entries 0-15), the bytes of Q = 2^e (b[3][i] =\n"
                        "                         2^i, 0 from i = 8); A's low, high bytes, D (entries 16-31) */\n"
                        "    for (int k = 0; k < 16; k++) {\n"
                        "        b[0][k] = (uint8_t)%s_ta[k];\n"
                        "        b[1][k] = (uint8_t)(%s_ta[k] >> 8);\n"
                        "        b[2][k] = (uint8_t)%s_td[k];\n"
                        "        b[3][k] = (uint8_t)(k < 8 ? 1u << k : 0u);\n"
                        "        b[4][k] = (uint8_t)%s_ta[k + 16];\n"
                        "        b[5][k] = (uint8_t)(%s_ta[k + 16] >> 8);\n"
                        "        b[6][k] = (uint8_t)%s_td[k + 16];\n"
                        "    }\n",
                  N, N, N, N, N, N);
    /* j in both bytes of its word: hi & (2^J - 1), its low byte copied up by a
       vpshufb (a shuffle, where a pmulhuw would load the multipliers, of
       which the loop has eight more) */
    const char *k18 = J == 4 ? "    kc[17] = _mm256_set1_epi16(15); /* j = hi & 15 */\n"
                             : "    kc[17] = _mm256_set1_epi16(31); /* j = hi & 31 */\n"
                               "    for (int k = 18; k < 21; k++)\n"
                               "        kc[k] = _mm256_broadcastsi128_si256(_mm_loadu_si128((const __m128i *)b[k - 14]));\n";
    pf_printf(kern,
              "\n\n/* AVX2 (x86-64-v3): the same steps on 16 lanes.  No vpermw: a table of 16\n"
              "   words is two vpshufb (its low and its high bytes) merged by vpblendvb;\n"
              "   no 16-bit per-element shift: round((2^16 + M) 2^-s) = avg(Q, pmulhuw(M, Q))\n"
              "   with Q = 2^(17 - s) for s >= 2 (one vpshufb of a table of 2^i, 0 from s = 18), and\n"
              "   2^15 + avg(M, 0) at s = 1.  The same values. */\n%s"
              "__attribute__((target(\"arch=x86-64-v3\"), noinline))\n"
              "static void %s_array_avx2(const %s *x, %s *y, size_t n)\n{\n"
              "%s"
              "    /* the constants in memory GCC cannot see through: with 16 ymm registers it\n"
              "       would otherwise rebuild some of them (mov, vmovd, vpbroadcastw) inside\n"
              "       the loop, where a memory operand costs nothing */\n"
              "    __m256i kc[%d];\n"
              "    for (int k = 0; k < 4; k++)\n"
              "        kc[k] = _mm256_broadcastsi128_si256(_mm_loadu_si128((const __m128i *)b[k]));\n"
              "    kc[4] = _mm256_set1_epi16(-256); /* the high bytes, for vpblendvb */\n"
              "    kc[5] = _mm256_set1_epi16(0x101);\n"
              "%s"
              "    kc[7] = _mm256_set1_epi16(%lld); /* c1 */\n"
              "    kc[8] = _mm256_set1_epi16(%lld); /* c2 */\n"
              "    kc[9] = _mm256_set1_epi16(%lld); /* cq: (kb + cq) 0x101 = e 0x101 - 0x800, e = 17 - s */\n"
              "    kc[10] = _mm256_set1_epi16(%lld); /* kb at s = %d */\n"
              "    kc[11] = _mm256_set1_epi16(%lld); /* off (exp2: none, unused) */\n"
              "    kc[12] = _mm256_set1_epi16(%lld); /* L1 */\n"
              "    kc[13] = _mm256_set1_epi16(%lld); /* L2 */\n"
              "    kc[14] = _mm256_set1_epi16(%lld); /* Cl */\n"
              "    kc[15] = _mm256_set1_epi16(%lld); /* the low clamp */\n"
              "    kc[16] = _mm256_set1_epi16(%lld); /* the high clamp */\n"
              "%s"
              "    __asm__(\"\" : : \"r\"(kc) : \"memory\");\n"
              "    const __m256i al = kc[0], ah = kc[1], dt = kc[2], pw = kc[3], hib = kc[4], dup = kc[5];\n"
              "    const __m256i h15 = kc[6], c1 = kc[7], c2 = kc[8], cq = kc[9], k1 = kc[10];\n"
              "    const __m256i %s = kc[11], l1 = kc[12], l2 = kc[13], cl = kc[14], xlo = kc[15], xhi = kc[16];\n"
              "    const __m256i jmask = kc[17];\n%s"
              "    const __m256i jdup = _mm256_setr_epi8(0, 0, 2, 2, 4, 4, 6, 6, 8, 8, 10, 10, 12, 12, 14, 14,\n"
              "                                          0, 0, 2, 2, 4, 4, 6, 6, 8, 8, 10, 10, 12, 12, 14, 14);\n"
              "    (void)l1, (void)l2, (void)cl, (void)xlo, (void)xhi%s;\n",
              cond, N, G->it, G->ot, tb5.s, J == 4 ? 18 : 21,
              sadd ? "    kc[6] = _mm256_setr_epi8(0, -1, -1, -1, -1, -1, -1, -1, -128, -1, -1, -1, -1, -1, -1, -1,\n"
                     "                             0, -1, -1, -1, -1, -1, -1, -1, -128, -1, -1, -1, -1, -1, -1, -1); /* H's bytes */\n"
              : X->sat && !X->tnohi ? "    kc[6] = _mm256_setr_epi8(0, -1, 0, 0, 0, 0, 0, 0, -128, -1, 0, 0, 0, 0, 0, 0,\n"
                                    "                             0, -1, 0, 0, 0, 0, 0, 0, -128, -1, 0, 0, 0, 0, 0, 0); /* H's bytes */\n"
                                  : "    kc[6] = _mm256_set1_epi16(-32768);\n",
              s16(X->tc1), s16(X->tc2),
              s16(16 - X->tcc - 2048 + (base2 ? X->tk0 : 0)),
              s16((base2 ? X->tcc - X->tk0 : X->tcc) - (X->sat && !X->tnohi)), X->sat && !X->tnohi ? 2 : 1,
              base2 ? 0 : s16(X->toff), s16(X->tl1), s16(X->tl2), s16(X->tcl),
              X->loclamp ? s16(X->xlo) : 0, X->sat && !X->tnohi ? s16(X->xsat) : 0, k18, base2 ? "bias" : "off",
              J == 4 ? "" : "    const __m256i al1 = kc[18], ah1 = kc[19], dt1 = kc[20];\n",
              base2 ? (J == 4 ? ", (void)bias, (void)jdup, (void)hib" : ", (void)bias")
                    : (J == 4 ? ", (void)jdup, (void)hib" : ""));
    free(tb5.s);
    pf_buf s1 = {0}, s2 = {0};
    pf_put(&s1, "        __m256i xc = _mm256_loadu_si256((const __m256i *)(x + i));\n");
    if (X->loclamp)
        pf_put(&s1, "        xc = _mm256_max_epi16(xc, xlo);\n");
    if (X->sat && !X->tnohi && !sadd)
        pf_put(&s1, "        xc = _mm256_min_epi16(xc, xhi);\n");
    if (base2) /* no bias: hi - K0 2^J, k and its constants as in the AVX-512 loop */
        pf_printf(&s1, "        __m256i hi = _mm256_srai_epi16(xc, %d), lo = _mm256_slli_epi16(xc, %d);\n",
                  Ei - J, 16 - Ei + J);
    else {
        pf_put(&s1, sadd ? "        __m256i u = _mm256_adds_epi16(xc, off); /* saturating: the top clamp (see kc[6]) */\n"
                          : "        __m256i u = _mm256_add_epi16(xc, off);\n");
        pf_put(&s1, "        __m256i q = _mm256_add_epi16(_mm256_mulhi_epu16(u, l2), cl);\n"
                     "        __m256i lo = _mm256_add_epi16(_mm256_mullo_epi16(u, l1), q);\n");
        if (X->tcarry0)
            pf_put(&s1, "        /* the carry, lo < q: lo <= q and lo != q */\n"
                         "        __m256i cy = _mm256_andnot_si256(_mm256_cmpeq_epi16(lo, q), _mm256_cmpeq_epi16(_mm256_max_epu16(lo, q), q));\n");
        else
            pf_put(&s1, "        /* the carry, lo < q: lo <= q (lo = q occurs for no input) */\n"
                         "        __m256i cy = _mm256_cmpeq_epi16(_mm256_max_epu16(lo, q), q);\n");
        pf_put(&s1, "        __m256i hi = _mm256_sub_epi16(_mm256_mulhi_epu16(u, l1), cy);\n");
    }
    /* stage 2 (pipe3_loop): E, the lookups, M */
    pf_put(&s2, "        __m256i e = _mm256_mulhi_epu16(lo, _mm256_add_epi16(c1, _mm256_mulhi_epu16(lo, c2)));\n");
    /* J = 4: A's low byte by j in the low byte of its index word, its high
       byte by j in the high byte (j << 8), merged by vpor: the other byte of
       each reads entry 0, and A[0] = 0; D by the second index, its byte
       shifted down (a vpsllw and a vpor where a vpshufb and a vpblendvb
       were: AVX2 exp2 0.153 -> 0.145 ns/element) */
    if (J == 4)
        pf_put(&s2, "        __m256i jl = _mm256_and_si256(hi, jmask), jh = _mm256_slli_epi16(jl, 8); /* j, j << 8 */\n"
                     "        __m256i a = _mm256_or_si256(_mm256_shuffle_epi8(al, jl), _mm256_shuffle_epi8(ah, jh));\n"
                     "        __m256i v = _mm256_avg_epu16(e, _mm256_mulhi_epu16(a, e));\n"
                     "        v = _mm256_add_epi16(v, _mm256_srli_epi16(_mm256_shuffle_epi8(dt, jh), 8));\n"
                     "        __m256i m = _mm256_adds_epu16(a, _mm256_srli_epi16(v, 3));\n"
                     "        __m256i kb = _mm256_srli_epi16(hi, 4);\n");
    else
        pf_put(&s2, "        __m256i jd = _mm256_shuffle_epi8(_mm256_and_si256(hi, jmask), jdup); /* j in both bytes */\n"
                     "        __m256i jm = _mm256_slli_epi16(jd, 3); /* j's bit 4 as each byte's bit 7 (vpblendvb) */\n"
                     "        __m256i a = _mm256_blendv_epi8(_mm256_blendv_epi8(_mm256_shuffle_epi8(al, jd), _mm256_shuffle_epi8(al1, jd), jm),\n"
                     "                                       _mm256_blendv_epi8(_mm256_shuffle_epi8(ah, jd), _mm256_shuffle_epi8(ah1, jd), jm), hib);\n"
                     "        __m256i v = _mm256_avg_epu16(e, _mm256_mulhi_epu16(a, e));\n"
                     "        v = _mm256_add_epi16(v, _mm256_srli_epi16(_mm256_blendv_epi8(_mm256_shuffle_epi8(dt, jd), _mm256_shuffle_epi8(dt1, jd), jm), 8));\n"
                     "        __m256i m = _mm256_adds_epu16(a, _mm256_srli_epi16(v, 4));\n"
                     "        __m256i kb = _mm256_srli_epi16(hi, 5);\n");
    if (base2) /* k, not k + K0 */
        memcpy(strstr(s2.s, "kb = _mm256_srli_epi16(hi, ") + 12, "srai", 4);
    pf_put(&s2, "        /* Q = 2^e, e = 17 - s: its low byte 2^e at byte index e, its high byte 2^(e - 8) at\n"
                 "           e - 8 (vpshufb's 0 where an index is negative: e < 8, e < 0 from s = 18, or in\n"
                 "           [8, 15] for the low byte, where the table holds 0) */\n"
                 "        __m256i qi = _mm256_mullo_epi16(_mm256_add_epi16(kb, cq), dup);\n"
                 "        __m256i qq = _mm256_shuffle_epi8(pw, qi);\n"
                 "        __m256i r = _mm256_avg_epu16(qq, _mm256_mulhi_epu16(m, qq));\n");
    /* clamped at the top: s = 1 and s = 0 (the clamped top input) in one
       select, 2^15 + avg(M, 0) and 65535 as avg(M, 0) + H (saturating), H =
       2^15 or 65535 by a vpshufb of a byte table on the same index (e = 16:
       bytes 0 and 8, e = 17: bytes 1 and 9; without the top clamp, sadd,
       e = 17..23: bytes 1-7 and 9-15); one vpor fewer */
    int s01 = X->sat && !X->tnohi;
    if (s01)
        pf_printf(&s2, "        r = _mm256_blendv_epi8(r, _mm256_adds_epu16(_mm256_avg_epu16(m, _mm256_setzero_si256()), _mm256_shuffle_epi8(h15, qi)),\n"
                       "                               _mm256_cmpgt_epi16(kb, k1)); /* s = 1: 2^15 + avg(M, 0); s %s 0: the max */\n",
                  sadd ? "<=" : "=");
    else
        pf_put(&s2, "        r = _mm256_blendv_epi8(r, _mm256_adds_epu16(_mm256_avg_epu16(m, _mm256_setzero_si256()), h15),\n"
                     "                               _mm256_cmpeq_epi16(kb, k1)); /* s = 1 */\n");
    if (X->sat && !s01)
        pf_printf(&s2, "        r = _mm256_or_si256(r, _mm256_cmpgt_epi16(kb, k1)); /* s %s 0: %s, the max */\n",
                  X->tnohi ? "<=" : "=", X->tnohi ? "the saturating inputs" : "the clamped top input");
    /* stage 3: from kb (k and s) on */
    char *k3 = strstr(s2.s, "        __m256i kb = ");
    pipe3_loop(kern, s1.s, s2.s, (size_t)(k3 - s2.s), k3, N);
    free(s1.s);
    free(s2.s);
    G->bw16 = 3;
}

/* exp2's table kernel without the low clamp (one vpmaxsw fewer per 32
   lanes): with K0 = -floor(min t), (t + K0) 2^Ei of every input up to XSAT
   fits the uint16_t, and below XLO the kernel's own steps give 0 (its
   shift count passes 16; the bound is then taken over every input).  The
   clamped kernel where that does not hold */
static int prep_tab_noclamp(fx_gen *G, int base2, char *err, size_t errlen)
{
    fx_exp_red *X = &G->exp, save = *X;
    int64_t imin = pf_type_min_stored(&G->in), one = (int64_t)1 << G->in.exp;
    int64_t k0 = imin >= 0 ? 0 : (-imin + one - 1) / one, xtop = X->sat ? X->xsat : X->xhi;
    /* 16-entry tables first, then 32, then 64.  Also for exp2 whose r has
       7 bits with 16 entries (fixed<15,11>), where 32 entries would leave
       6 and let the AVX-512 loop read E from a 64-entry table: the AVX2
       loop's 32-entry lookups (four vpshufb and three vpblendvb a table)
       cost more than that saves (fixed<15,11> -> ufixed<16,8>, ns/element
       AVX2 0.220 -> 0.165, AVX-512 0.078 -> 0.096).  exp: 16 entries only;
       where they miss the bound, so did 32 and 64 for every type pair
       tried (fixed<15,5..15> -> ufixed<16,-5..17>), and a path no type
       takes is a path no test runs */
    int order[3] = {4, 5, 6}, norder = base2 ? 3 : 1;
    for (int oi = 0; oi < norder; oi++) {
        int J = order[oi];
        if (base2 && X->loclamp && xtop + k0 * one <= 65535) {
            X->loclamp = 0;
            X->xlo = imin;
            X->k0 = k0;
            if (prep_tab(G, base2, J, err, errlen) == 0)
                return 0;
        }
        *X = save;
        if (prep_tab(G, base2, J, err, errlen) == 0)
            return 0;
        *X = save;
    }
    return -2;
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
    /* exact: the table kernel where the type pair allows it (else the
       Horner form, which the exact bound sends to 32-bit words) */
    if (G->exact && prep_tab_noclamp(G, base2, err, errlen) == 0) {
        G->kind = 1;
        tab_texts(G, base2);
        return 0;
    }
    /* fast: the segment-table kernel where it meets the bound (fixed_exp16f.c) */
    if (!G->exact && fx_exp16f_prep(G, base2) == 0) {
        G->kind = 2;
        fx_exp16f_texts(G, base2);
        return 0;
    }
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
    G->kind = 0;
    G->alt_domain[0] = G->alt_order[0] = G->alt_method[0] = G->alt_con[0] = G->alt_formats[0] = G->alt_poly[0] = 0;
    G->alt_arith[0] = 0;
    G->bound_note[0] = 0;
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
    if (G->kind == 2) {
        fx_exp16f_budget(G);
        return;
    }
    if (G->kind == 1) {
        /* the table kernel: no Horner polynomial on [0, 1] (the fit the
           pipeline makes is not used); the pre-rounding error over every
           clamped input, of which the polynomial's share is E's error
           (2^-F units, F = 16 + J) moved to the result: at most
           2^(16 - s) 2 2^-F E lsb, s >= 1 */
        G->R = 0;
        G->A = G->exp.terr * fx_lsb(G);
        G->poly_err = G->exp.tpoly * ldexp(1, -G->exp.tj) * fx_lsb(G);
        return;
    }
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
    pf_buf body = {0}, horner = {0}, tabs = {0}, kern = {0};
    if (G->kind == 1 || G->kind == 2) {
        if (G->kind == 1)
            emit_tab(G, &body, &tabs, &kern, base2);
        else
            fx_exp16f_emit(G, &body, &tabs, &kern, base2);
        char xsat[32], xlo[32];
        snprintf(xsat, sizeof xsat, "%lld", (long long)G->exp.xsat);
        snprintf(xlo, sizeof xlo, "%lld", (long long)G->exp.xlo);
        const char *kv[] = {"FUNC", base2 ? "exp2" : "exp", "TDEF", base2 ? "x" : "x log2(e)", "XSAT", xsat, "XLO", xlo,
                            "NAME", G->name, "IT", G->it, "OT", G->ot, "BODY", body.s, "TABLES", tabs.s,
                            "KERNEL", kern.s, NULL};
        pf_subst(b, pf_template("fx_exp16.c"), kv);
        free(body.s);
        free(tabs.s);
        free(kern.s);
        return;
    }
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
                        "NAME", G->name, "IT", G->it, "OT", G->ot, "BODY", body.s, "TABLES", "", "KERNEL", "", NULL};
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
