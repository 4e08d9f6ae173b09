/* sin and cos in fixed point (see gen/templates/fx_sincos.c.in).
 *
 * Reduction: u = x 2/pi, kept modulo 4 as a phase.  Two ways, the cheaper
 * one whose error is within a sixteenth of the budget:
 *   kind 0 (16-bit inputs, 32-bit words): x * round(2/pi 2^31) in 64 bits,
 *          rounded to 30 fraction bits; the uint32_t cast is the mod 4.
 *          |error of u| <= |x|max |C 2^-31 - 2/pi| + 2^-31.
 *   kind 1: x * C mod 2^64 with C = round(2/pi 2^(62-Ei)) mod 2^64: the
 *          bits of 2/pi above the word only add multiples of 4 (as in
 *          Payne-Hanek), so the product is u mod 4 with 62 fraction bits.
 *          |error of u| <= |X|max 2^-63; 32-bit words round v to 30
 *          fraction bits, 2^-31 more.
 * The fold is exact; sin(pi/2 v) moves by at most pi/2 |error of v|. */
#include "fixed_internal.h"
#include "round_fixed.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define C31 1367130551 /* round(2/pi 2^31), checked against MPFR in prepare */

static void g_sinpi2(mpfr_t y, const mpfr_t t, const void *ctx)
{
    (void)ctx;
    mpfr_t a;
    mpfr_init2(a, mpfr_get_prec(y) + 64);
    mpfr_const_pi(a, MPFR_RNDN);
    mpfr_mul(a, a, t, MPFR_RNDN);
    mpfr_div_2ui(a, a, 1, MPFR_RNDN);
    mpfr_sin(y, a, MPFR_RNDN);
    mpfr_clear(a);
}

/* round(2/pi 2^e) mod 2^64 */
static uint64_t two_over_pi_bits(int e)
{
    mpfr_t a;
    mpz_t z;
    mpfr_init2(a, 1024);
    mpz_init(z);
    mpfr_const_pi(a, MPFR_RNDN);
    mpfr_ui_div(a, 2, a, MPFR_RNDN);
    mpfr_mul_2si(a, a, e, MPFR_RNDN);
    mpfr_get_z(z, a, MPFR_RNDN);
    mpz_fdiv_r_2exp(z, z, 64);
    uint64_t r = 0;
    for (int i = 1; i >= 0; i--) {
        mpz_t q;
        mpz_init(q);
        mpz_fdiv_q_2exp(q, z, 32 * (unsigned)i);
        mpz_fdiv_r_2exp(q, q, 32);
        r = (r << 32) | (uint64_t)mpz_get_ui(q);
        mpz_clear(q);
    }
    mpz_clear(z);
    mpfr_clear(a);
    return r;
}

static double two_over_pi_err31(void)
{
    mpfr_t a;
    mpfr_init2(a, 256);
    mpfr_const_pi(a, MPFR_RNDN);
    mpfr_ui_div(a, 2, a, MPFR_RNDN);
    mpfr_mul_2si(a, a, 31, MPFR_RNDN);
    mpfr_sub_si(a, a, C31, MPFR_RNDN);
    double d = fabs(mpfr_get_d(a, MPFR_RNDN));
    mpfr_clear(a);
    return d; /* in units of 2^-31 */
}


/* 16-bit lanes: w = round(x 2^(15-Ei) / pi), quarter turns in 2^-14 units,
 * modulo 4 (a uint16_t).  T = round(2^(30-Ei) / pi) from MPFR is split as
 * A 2^15 + B with |B| <= 2^14: w = x A mod 2^16 (exact, pmullw) +
 * round(x B 2^-15) (pmulhrsw), so |error of w| <= 1/2 + |x| |T - 2^(30-Ei)/pi| 2^-15.
 * Returns that bound, in units of w. */
static double phase16(int Ei, double Xmax, int64_t *A, int64_t *B)
{
    mpfr_t a, c;
    mpz_t z, q;
    mpfr_inits2(1024, a, c, (mpfr_ptr)0);
    mpz_inits(z, q, (mpz_ptr)0);
    mpfr_const_pi(a, MPFR_RNDN);
    mpfr_ui_div(a, 1, a, MPFR_RNDN);
    mpfr_mul_2si(a, a, 30 - Ei, MPFR_RNDN); /* 2^(30-Ei) / pi */
    mpfr_get_z(z, a, MPFR_RNDN);            /* T */
    mpfr_set_z(c, z, MPFR_RNDN);
    mpfr_sub(c, c, a, MPFR_RNDN);
    double terr = fabs(mpfr_get_d(c, MPFR_RNDN)); /* |T - 2^(30-Ei)/pi| */
    /* A = round(T / 2^15) mod 2^16, B = T - round(T / 2^15) 2^15 */
    mpz_set(q, z);
    mpz_add_ui(q, q, 1u << 14);
    mpz_fdiv_q_2exp(q, q, 15);
    mpz_mul_2exp(q, q, 15);
    mpz_sub(z, z, q);
    *B = mpz_get_si(z);
    mpz_fdiv_q_2exp(q, q, 15);
    mpz_fdiv_r_2exp(q, q, 16);
    *A = (int64_t)mpz_get_ui(q);
    mpfr_clears(a, c, (mpfr_ptr)0);
    mpz_clears(z, q, (mpz_ptr)0);
    return 0.5 + Xmax * terr * 0x1p-15;
}

/* Kind 3, exact variants with at most 16-bit storage: 32-bit lanes, every
 * product a 32x32 -> 32-bit low product (vpmulld) whose operands are
 * bounded so that it cannot wrap, and shifts; no 64-bit lane anywhere.
 * Why 32 bits: the phase needs about 20 fraction bits (16-bit lanes give
 * 14, a quarter lsb of error by itself at a 2^-14 output) and the product
 * v P about 33 significant bits, so neither fits 16-bit words.
 *   phase  z = x TH mod 2^32 (u in 2^-30 units; the bits of 2/pi above the
 *          word only add multiples of 4), or floor(x T48 / 2^16) mod 2^32 =
 *          x TH + floor(x TL / 2^16) with T48 = TH 2^16 + TL when one
 *          product's error (|x| |TH - 2/pi 2^(30-Ei)| 2^-30) exceeds L/16;
 *   fold   a = |v| 2^30 and the sign of v, exactly (so sin is exactly odd
 *          and cos exactly even);
 *   square a = vh 2^15 + vl: s = vh^2 + floor(vh vl / 2^14) in 2^-30 units
 *          (the vl^2 term and the floor: < 2^-29), s16 = round(s 2^16);
 *   P      = c1 + c3 s + s^2 T(s), c1 at 2^-31, c3 at 2^-15 (pinned by the
 *          fit: c3 s16 lands on 2^-31 with no shift), T = c5 + c7 s + ...
 *          by Horner in s16, each step floored to its own format, y = s T
 *          at 2^-ey, all summed in a uint32_t at 2^-31 (P > 0);
 *   v P    = vh P16 + floor(vl P16 / 2^15) at 2^-31 (uint32_t: |v| P <= 1
 *          + the error), P16 = round(P 2^16);
 *   output round(|v| P 2^Eo), then the sign of v. */
static int kind3_ok(const fx_gen *G)
{
    int Eo = G->out.exp, Ei = G->in.exp;
    int64_t one = (int64_t)1 << (Eo < 0 ? 0 : Eo > 40 ? 40 : Eo);
    return G->exact && G->out.is_signed && G->out.storage_bits <= 16 && G->in.storage_bits <= 16 && Eo >= 0 &&
           Eo <= 28 && pf_type_max_stored(&G->out) >= one + 1 && pf_type_min_stored(&G->out) <= -one - 1 &&
           Ei >= -16 && Ei <= 30;
}

/* |2/pi 2^e - round(2/pi 2^e)| */
static double two_over_pi_frac(int e)
{
    mpfr_t a, r;
    mpfr_inits2(1024, a, r, (mpfr_ptr)0);
    mpfr_const_pi(a, MPFR_RNDN);
    mpfr_ui_div(a, 2, a, MPFR_RNDN);
    mpfr_mul_2si(a, a, e, MPFR_RNDN);
    mpfr_rint(r, a, MPFR_RNDN);
    mpfr_sub(a, a, r, MPFR_RNDN);
    double d = fabs(mpfr_get_d(a, MPFR_RNDN));
    mpfr_clears(a, r, (mpfr_ptr)0);
    return d;
}

static int prepare3(fx_gen *G, double Xmax, int is_cos, double L)
{
    int Ei = G->in.exp;
    uint64_t t30 = two_over_pi_bits(30 - Ei) & 0xffffffffu;
    uint64_t t46 = two_over_pi_bits(46 - Ei) & UINT64_C(0xffffffffffff);
    double e1 = Xmax * two_over_pi_frac(30 - Ei) * 0x1p-30;              /* quarter turns */
    double e2 = Xmax * two_over_pi_frac(46 - Ei) * 0x1p-46 + 0x1p-30;    /* + the floor */
    G->kind = 3;
    G->wt = "int32_t";
    snprintf(G->order_text, sizeof G->order_text, "int32_t words: 32-bit lanes, 32x32 -> 32-bit products");
    snprintf(G->alt_arith, sizeof G->alt_arith,
             "integers only (no floating point, no <math.h>); roundings to nearest with ties up, and floors where "
             "the error bound counts a whole lsb; bit-identical under any compiler flags");
    G->trig.two = M_PI / 2 * e1 > L / 16;
    G->trig.th = (int64_t)(G->trig.two ? t46 >> 16 : t30);
    G->trig.tl = (int64_t)(G->trig.two ? t46 & 0xffffu : 0);
    G->dred = G->trig.two ? e2 : e1;
    if (G->trig.two)
        snprintf(G->red_text, sizeof G->red_text,
                 "u = x 2/pi mod 4 in 2^-30 units, a uint32_t: z = x %lld + floor(x %lld 2^-16) + %s = floor(x T "
                 "2^-16) + offset, T = %lld 2^16 + %lld = round(2/pi 2^%d) mod 2^48 (bits of 2/pi that only add "
                 "multiples of 4 dropped, MPFR; one product x round(2/pi 2^%d) would err by %.2e quarter turns, "
                 "above L/16); phase w = (u + %d) mod 4; fold to |v| in [0, 1] (v = w - 1 or 3 - w, 2^-30 "
                 "units) and the sign of v, exactly; error of v <= %.3e",
                 (long long)G->trig.th, (long long)G->trig.tl, is_cos ? "0" : "0xc0000000", (long long)G->trig.th,
                 (long long)G->trig.tl, 46 - Ei, 30 - Ei, e1, is_cos ? 2 : 1, G->dred);
    else
        snprintf(G->red_text, sizeof G->red_text,
                 "u = x 2/pi mod 4 in 2^-30 units, a uint32_t: z = x %lld + %s, %lld = round(2/pi 2^%d) mod 2^32 "
                 "(bits of 2/pi that only add multiples of 4 dropped, MPFR; one 32x32 -> 32-bit product); phase "
                 "w = (u + %d) mod 4; fold to |v| in [0, 1] (v = w - 1 or 3 - w, 2^-30 units) and the sign of v, "
                 "exactly; error of v <= %.3e",
                 (long long)G->trig.th, is_cos ? "0" : "0xc0000000", (long long)G->trig.th, 30 - Ei,
                 is_cos ? 2 : 1, G->dred);
    return 0;
}

static int prepare(fx_gen *G, char *err, size_t errlen, int is_cos)
{
    const char *fn = is_cos ? "cos" : "sin";
    if (G->out.is_float || G->in.is_float)
        return -1;
    if (!G->out.is_signed) {
        snprintf(err, errlen, "%s: output type %s is unsigned but %s takes negative values; use a signed type",
                 fn, G->out_text, fn);
        return -1;
    }
    int Ei = G->in.exp;
    if (Ei > 60 || Ei < -60) {
        snprintf(err, errlen, "%s: input exponent %d not supported (the reduction needs -60 <= exp <= 60)", fn, Ei);
        return -1;
    }
    double Xmax = fmax(fabs((double)pf_type_min_stored(&G->in)), (double)pf_type_max_stored(&G->in));
    double xmax = ldexp(Xmax, -Ei);
    double L = fx_lsb(G);
    double budget = (G->exact ? 0.5 : 3.5) * L / 16;
    double e31 = two_over_pi_err31();
    if (e31 > 0.5 || e31 < 0.1) { /* the constant above is wrong */
        snprintf(err, errlen, "%s: internal constant 2/pi 2^31 mismatch", fn);
        return -1;
    }
    double du0 = xmax * e31 * 0x1p-31 + (Ei + 1 >= 1 ? 0x1p-31 : 0);
    double du1 = Xmax * 0x1p-63 + (G->W == 32 ? 0x1p-31 : 0);
    G->fmax = 1;
    snprintf(G->sat_text, sizeof G->sat_text, "none needed unless the output cannot hold +-1");
    G->alt_formats[0] = G->order_text[0] = G->alt_arith[0] = 0;
    if (G->W == 16) {
        /* kind 2 (every step in 16-bit lanes) needs x in an int16_t; its
           phase w has 14 fraction bits, so its error alone is about a
           quarter of an lsb of a 2^-14 output: an exact variant whose lsb
           is that fine takes kind 3 (32-bit lanes, see kind3 above) */
        int k2 = pf_type_max_stored(&G->in) <= 32767;
        double e2 = INFINITY;
        if (k2)
            e2 = M_PI / 2 * phase16(Ei, Xmax, &G->trig.a16, &G->trig.b16) * 0x1p-14;
        if (G->exact && kind3_ok(G) && (!k2 || e2 > L / 4))
            return prepare3(G, Xmax, is_cos, L);
        if (!k2) {
            snprintf(err, errlen, "16-bit lanes: input above 32767");
            return -2;
        }
        double dw = phase16(Ei, Xmax, &G->trig.a16, &G->trig.b16);
        G->kind = 2;
        G->dred = dw * 0x1p-14;
        snprintf(G->red_text, sizeof G->red_text,
                 "on |x| (sin(-x) = -sin(x), cos(-x) = cos(x), exactly); u = |x| 2/pi in quarter turns, 2^-14 "
                 "units, modulo 4 in a uint16_t: w = |x| %lld + round(|x| %lld 2^-15) + %d 2^14 (2^(30-%d)/pi = %lld 2^15 + %lld, MPFR; the product by %lld taken mod 2^16, "
                 "the other by the rounding multiply-high); fold to v in [-1, 1] (v = w - 1 or 3 - w, 2^-14 "
                 "units), +-1 held as +-(1 - 2^-14) (sin is flat there: it moves the result by < 5e-9), doubled "
                 "to 2^-15 units; error of v <= %.3e",
                 (long long)G->trig.a16, (long long)G->trig.b16, is_cos ? 2 : 1, Ei, (long long)G->trig.a16,
                 (long long)G->trig.b16, (long long)G->trig.a16, G->dred);
        return 0;
    }
    if (G->W == 32 && G->in.storage_bits <= 16 && (du0 * M_PI / 2 <= budget || du0 <= du1)) {
        G->kind = 0;
        G->dred = du0;
        G->trig.sh = Ei + 1;
        snprintf(G->red_text, sizeof G->red_text,
                 "u = x 2/pi with 2/pi = %d 2^-31, the product rounded to 2^-30; phase w = (u + %d) mod 4 "
                 "(uint32_t, 30 fraction bits); fold to v in [-1, 1] (v = w - 1 or 3 - w); error of v <= %.3e",
                 C31, is_cos ? 2 : 1, du0);
    } else {
        G->kind = 1;
        G->dred = du1;
        G->trig.c64 = (int64_t)two_over_pi_bits(62 - Ei);
        snprintf(G->red_text, sizeof G->red_text,
                 "u = x 2/pi mod 4 = x C mod 2^64 in 2^-62 units, C = round(2/pi 2^%d) mod 2^64 (bits of 2/pi "
                 "that only add multiples of 4 dropped, from MPFR); phase w = (u + %d) mod 4; fold to v in "
                 "[-1, 1] (v = w - 1 or 3 - w)%s; error of v <= %.3e",
                 62 - Ei, is_cos ? 2 : 1, G->W == 32 ? ", rounded to 2^-30" : "", du1);
        if ((uint64_t)G->trig.c64 == 0) {
            snprintf(err, errlen, "%s: input exponent %d too large for the reduction", fn, Ei);
            return -1;
        }
    }
    return 0;
}

/* kind 3: the formats of P = c1 + c3 s + s y, y = s T(s) (see kind3 above),
 * the coefficients rounded to them by pin-and-refit, and the arithmetic's
 * error bound (G->arith, absolute, for |v| <= 1) */
static int fit16(fx_gen *G, char *err, size_t errlen)
{
    if (G->kind != 3)
        return 1;
    int m = G->m;
    fit_problem *pb = &G->pb;
    if (m < 1) {
        snprintf(err, errlen, "order %d: the 32-bit-lane kernel needs c1 and c3", G->order);
        return -1;
    }
    int E[FX_MAXC], ey = 0;
    double a[FX_MAXC], pm[FX_MAXC];
    for (int pass = 0; pass < 2; pass++) {
        /* pass 0: formats from the real fit; pass 1: the same bounds on the
           rounded coefficients must still fit them */
        for (int j = 0; j <= m; j++)
            a[j] = pass ? ldexp((double)G->C[j], -E[j]) : (double)G->real.c[G->deg[j]];
        if (!(fabs(a[0]) < 1.99 && a[0] > 0 && fabs(a[1]) < 0.99)) {
            snprintf(err, errlen, "order %d: c1 or c3 out of the kernel's range", G->order);
            return -1;
        }
        if (m >= 2)
            fx_partial_max(a + 2, m - 2, pm); /* pm[j - 2] bounds the tail's partial sum from c_j */
        int ok = 1;
        for (int j = m; j >= 2; j--) {
            /* |p_j| 2^E < 2^15 - 2: the product by s16 <= 2^16 stays below 2^31 */
            int e = (int)floor(log2(32766.0 / pm[j - 2]));
            if (j < m && e > E[j + 1] + 16)
                e = E[j + 1] + 16;
            if (e > 40)
                e = 40;
            if (pass == 0)
                E[j] = e;
            else
                ok = ok && e >= E[j];
        }
        if (m >= 2) {
            int e = (int)floor(log2(32766.0 / pm[0]));
            if (e > E[2] + 16)
                e = E[2] + 16;
            if (pass == 0)
                ey = e;
            else
                ok = ok && e >= ey;
            ok = ok && ey >= 15;
        }
        E[0] = 31;
        E[1] = 15;
        if (!ok) {
            snprintf(err, errlen, "order %d: no 32-bit-lane formats", G->order);
            return -1;
        }
        if (pass == 0) {
            int exps[FIT_MAX_ORDER + 1] = {0};
            int64_t stored[FIT_MAX_ORDER + 1];
            for (int j = 0; j <= m; j++)
                exps[G->deg[j]] = E[j];
            G->poly = G->real;
            if (fit_round_fixed(pb, exps, G->minimax ? fit_minimax : fit_lsq, &G->poly, stored, err, errlen) != 0)
                return -1;
            for (int j = 0; j <= m; j++)
                G->C[j] = stored[G->deg[j]];
            if (G->C[0] <= 0 || G->C[0] + 0x4000 >= ((int64_t)1 << 32) || G->C[1] <= -32768 || G->C[1] >= 32768) {
                snprintf(err, errlen, "order %d: c1 or c3 out of the kernel's range", G->order);
                return -1;
            }
        }
    }
    /* the error bound, absolute, in P's units (|v| <= 1, s <= 1) */
    double ds = 0x1p-17 + 0x1p-29; /* s16 against v^2: its rounding, and s's floor and dropped vl^2 */
    double dP = fabs(a[1]) * ds;   /* c3 s16: an exact product */
    if (m >= 2) {
        double dq = 0;             /* the tail's Horner, each step floored (< 1 lsb) */
        for (int j = m - 1; j >= 2; j--)
            dq += pm[j + 1 - 2] * ds + ldexp(1.0, -E[j]);
        double dy = dq + pm[0] * ds + (E[2] + 16 > ey ? ldexp(1.0, -ey) : 0);
        dP += pm[0] * ds + dy + (ey > 15 ? 0x1p-31 : 0); /* s y: |y| <= max |T| */
    }
    /* P16's rounding (1/2 of 2^-16, times |v| <= 1) and the floor of vl P16 2^-15 (2^-31) */
    G->arith = dP + 0x1p-17 + 0x1p-31;
    memcpy(G->E, E, sizeof E);
    G->trig.ey = ey;
    G->Ep = 16;
    G->pt = pf_type_fixed(0, 17, 16);
    G->root_sat = 0;
    G->dP = 0;
    fit_measure(pb, &G->poly);
    G->poly_err = G->poly.max_err;
    size_t o = (size_t)snprintf(G->alt_formats, sizeof G->alt_formats,
                                "|v| in 2^-30 units split as vh 2^-15 + vl 2^-30; s = v^2 to 2^-30, then s16 = s "
                                "rounded to 2^-16 (|error| <= %.3e); c1 ufixed<32,31>, c3 fixed<15,15>",
                                ds);
    for (int j = 2; j <= m && o < sizeof G->alt_formats; j++)
        o += (size_t)snprintf(G->alt_formats + o, sizeof G->alt_formats - o, ", c%d fixed<15,%d>", G->deg[j], E[j]);
    if (m >= 2 && o < sizeof G->alt_formats)
        o += (size_t)snprintf(G->alt_formats + o, sizeof G->alt_formats - o,
                              " (T's Horner in s16, each step floored to its coefficient's lsb); y = s T fixed<15,%d>",
                              ey);
    if (o < sizeof G->alt_formats)
        snprintf(G->alt_formats + o, sizeof G->alt_formats - o,
                 "; P = c1 + c3 s16 + s16 y summed at 2^-31 in a uint32_t, every product of two operands whose "
                 "bounds keep it below 2^31 (signed) or 2^32 (unsigned): no wrap; P16 = round(P 2^16) (its 2^-17 folded into c1); |v| P = vh P16 + "
                 "floor(vl P16 2^-15) at 2^-31 in a uint32_t; arithmetic error <= %.3e",
                 G->arith);
    return 0;
}

static int prep_sin(fx_gen *G, char *err, size_t n) { return prepare(G, err, n, 0); }
static int prep_cos(fx_gen *G, char *err, size_t n) { return prepare(G, err, n, 1); }

static int out_shift(const fx_gen *G) { return (G->W - 2) + G->Ep - G->out.exp; }

/* 16-bit lanes: v (2^-15) times P (2^-Ep) by the rounding multiply-high is
   at 2^-Ep: the output's lsb, or rounded again to a coarser one; a finer
   output takes the full 32-bit product */
static void budget16(fx_gen *G)
{
    int Eo = G->out.exp, Ep = G->Ep;
    G->R = 0;
    if (G->kind == 3) { /* absolute: the arithmetic, the phase, the fit */
        G->A = G->arith + M_PI / 2 * G->dred + G->poly_err;
        return;
    }
    if (Eo > Ep && 15 + Ep - Eo < 2) {
        G->A = INFINITY;
        return;
    }
    /* s = v^2 rounded (1/2 of 2^-15); Horner; phase; v held below 1 */
    G->A = G->arith + G->dP * 0x1p-16 + M_PI / 2 * G->dred + 5e-9;
    if (Eo < Ep)
        G->A += ldexp(0.5, -Ep); /* the product's rounding before the final one */
    if (G->errkind == FIT_REL)
        G->R = G->poly_err;
    else
        G->A += G->poly_err;
}

static void budget(fx_gen *G)
{
    if (G->W == 16) {
        budget16(G);
        return;
    }
    G->R = 0;
    if (out_shift(G) < 1 || out_shift(G) > 2 * G->W - 2) {
        G->A = INFINITY;
        return;
    }
    /* s = v^2: rounded (1/2 lsb) and saturated at v = +-1 (1 lsb) */
    double ds = 1.5 * ldexp(1.0, -(G->W - 1));
    G->A = G->arith + G->dP * ds + M_PI / 2 * G->dred;
    /* an absolute fit's error adds to A; a relative one's is R (of v P) */
    if (G->errkind == FIT_REL)
        G->R = G->poly_err;
    else
        G->A += G->poly_err;
}

/* 32-bit lane helpers of kind 3 (see kind3 above), written before the kernel */
static const char helpers3[] =
    "\n/* 32-bit lane helpers of the exact sin/cos kernel (gen/fixed/fixed_trig.c, kind 3).\n"
    "   GCC and Clang define >> of a negative int as arithmetic (floor); other\n"
    "   compilers get the same values from unsigned arithmetic. */\n"
    "\n"
    "/* floor(z / 2^d), 1 <= d <= 31 */\n"
    "PF_FX_INLINE int32_t pf_fx_sra32(int32_t z, int d)\n"
    "{\n"
    "#if defined(__GNUC__)\n"
    "    return z >> d;\n"
    "#else\n"
    "    return (int32_t)(((uint32_t)z + 0x80000000u) >> d) - (int32_t)(0x80000000u >> d);\n"
    "#endif\n"
    "}\n"
    "\n"
    "/* |u read as an int32_t| as a uint32_t (2^31 for 0x80000000): the smaller\n"
    "   of u and 2^32 - u, two vector instructions (vpsubd, vpminud) where the\n"
    "   signed forms cost a compare and a masked subtract, or abs(INT32_MIN) */\n"
    "PF_FX_INLINE uint32_t pf_fx_uabs32(uint32_t u)\n"
    "{\n"
    "    uint32_t m = 0u - u;\n"
    "    return u < m ? u : m;\n"
    "}\n";

static void emit16_3(fx_gen *G, pf_buf *body, int is_cos)
{
    int m = G->m, Eo = G->out.exp, ey = G->trig.ey;
    char what[96];
    pf_printf(body, "    /* phase: z = w - 2 = (u + %d) mod 4 - 2, u = x 2/pi in 2^-30 units (mod 2^32) */\n"
                    "    int32_t xi = x;\n",
              is_cos ? 2 : 1);
    const char *off = is_cos ? "" : " + 0xc0000000u";
    if (!G->trig.two)
        pf_printf(body, "    uint32_t z = (uint32_t)xi * %lluu%s;\n", (unsigned long long)G->trig.th, off);
    else if (G->in.is_signed)
        pf_printf(body, "    uint32_t z = (uint32_t)xi * %lluu + (uint32_t)pf_fx_sra32(xi * %lld, 16)%s; /* |x TL| < 2^31 */\n",
                  (unsigned long long)G->trig.th, (long long)G->trig.tl, off);
    else
        pf_printf(body, "    uint32_t z = (uint32_t)xi * %lluu + (((uint32_t)xi * %lluu) >> 16)%s; /* x TL < 2^32 */\n",
                  (unsigned long long)G->trig.th, (unsigned long long)G->trig.tl, off);
    pf_put(body, "    /* fold: v = 1 - |w - 2| in [-1, 1], 2^-30 units (mod 2^32); a = |v|, the sign of v kept in b */\n"
                 "    uint32_t b = 0x40000000u - pf_fx_uabs32(z);\n"
                 "    uint32_t a = pf_fx_uabs32(b); /* |v| in [0, 2^30] */\n"
                 "    /* s = v^2: a = vh 2^15 + vl, s = vh^2 + floor(vh vl 2^-14) in 2^-30 units (vl^2 dropped) */\n"
                 "    uint32_t vh = a >> 15, vl = a & 0x7fffu; /* vh <= 2^15, vl < 2^15 */\n"
                 "    uint32_t s = vh * vh + ((vh * vl) >> 14);\n"
                 "    int32_t s16 = (int32_t)((s + 0x2000u) >> 14); /* s rounded to 2^-16, <= 2^16 */\n");
    if (m >= 2) {
        pf_put(body, "    /* T(s) = c5 + c7 s + ...: Horner in s16, each step floored to its coefficient's lsb */\n");
        snprintf(what, sizeof what, "c%d = %.12g", G->deg[m], ldexp((double)G->C[m], -G->E[m]));
        pf_printf(body, "    int32_t q = %s; /* %s, 2^-%d units */\n", fx_k16(G, G->C[m], what), what, G->E[m]);
        for (int j = m - 1; j >= 2; j--) {
            snprintf(what, sizeof what, "c%d = %.12g", G->deg[j], ldexp((double)G->C[j], -G->E[j]));
            int sh = G->E[j + 1] + 16 - G->E[j];
            if (sh > 0)
                pf_printf(body, "    q = pf_fx_sra32(q * s16, %d) + %s; /* %s, 2^-%d units */\n", sh,
                          fx_k16(G, G->C[j], what), what, G->E[j]);
            else
                pf_printf(body, "    q = q * s16 + %s; /* %s, 2^-%d units */\n", fx_k16(G, G->C[j], what), what,
                          G->E[j]);
        }
        int sh = G->E[2] + 16 - ey;
        if (sh > 0)
            pf_printf(body, "    int32_t y = pf_fx_sra32(q * s16, %d); /* s T, 2^-%d units */\n", sh, ey);
        else
            pf_printf(body, "    int32_t y = q * s16; /* s T, 2^-%d units */\n", ey);
    }
    snprintf(what, sizeof what, "c3 = %.12g", ldexp((double)G->C[1], -G->E[1]));
    pf_printf(body, "    /* P = c1 + c3 s + s y at 2^-31, in [1, 2), plus 2^-17 (P16's rounding): modular uint32_t sums */\n"
                    "    uint32_t p = %lluu /* c1 = %.12g, + 0x4000 */ + (uint32_t)(%s * s16) /* %s */",
              (unsigned long long)G->C[0] + 0x4000u, ldexp((double)G->C[0], -31), fx_k16(G, G->C[1], what), what);
    if (m >= 2) {
        if (ey > 15)
            pf_printf(body, "\n               + (uint32_t)pf_fx_sra32(y * s16, %d)", ey - 15);
        else
            pf_put(body, "\n               + (uint32_t)(y * s16)");
    }
    pf_put(body, ";\n"
                 "    uint32_t p16 = p >> 15; /* P rounded to 2^-16, < 2^16.66 */\n"
                 "    /* |v| P at 2^-31, <= 2^31 (1 + its error): vh p16 and vl p16 < 2^15 2^16.66 */\n"
                 "    uint32_t r31 = vh * p16 + ((vl * p16) >> 15);\n");
    pf_printf(body, "    uint32_t r = (r31 + 0x%xu) >> %d; /* rounded once to the output's lsb */\n", 1u << (30 - Eo),
              31 - Eo);
    pf_put(body, "    int32_t rs = b >= 0x80000000u ? -(int32_t)r : (int32_t)r; /* the sign of v */\n");
    int64_t one = (int64_t)1 << Eo;
    fx_emit_return16(G, body, "rs", -one - 1, one + 1);
    snprintf(G->wide_text, sizeof G->wide_text,
             "every step in 32-bit lanes (16 per AVX-512 vector), each product a 32x32 -> 32-bit low half "
             "(vpmulld) that cannot wrap, no 64-bit lane: the exact bound needs about 20 fraction bits of the "
             "phase (16-bit lanes hold 14, whose rounding alone is a quarter lsb here) and about 33 bits for "
             "|v| P, so no step fits 16-bit words");
}

static void emit16(fx_gen *G, pf_buf *b, int is_cos)
{
    pf_buf body = {0}, horner = {0};
    int Eo = G->out.exp, Ep = G->Ep;
    if (G->kind == 3) {
        emit16_3(G, &body, is_cos);
        const char *kv[] = {"FUNC", is_cos ? "cos" : "sin", "PHASE", is_cos ? "2" : "1", "NAME", G->name, "IT", G->it,
                            "OT", G->ot, "BODY", body.s, "HELPERS", helpers3, "LANES", "in 32-bit lanes", "WORD",
                            "a uint32_t with 30 fraction bits", NULL};
        pf_subst(b, pf_template("fx_sincos16.c"), kv);
        free(body.s);
        return;
    }
    pf_printf(&body, "    /* phase w = (u + %d) mod 4, 2^-14 units */\n", is_cos ? 2 : 1);
    /* on |x|, so that sin is exactly odd and cos exactly even (the
       rounding multiply-high rounds ties up, which is not symmetric) */
    int full = G->in.storage_bits == 16 && G->in.is_signed; /* x can be -32768 */
    const char *ka = fx_k16(G, G->trig.a16 > 32767 ? G->trig.a16 - 65536 : G->trig.a16,
                            "A (as uint16_t): |x| 2^(15-Ei)/pi = |x| (A + B 2^-15)");
    const char *kb = fx_k16(G, G->trig.b16, "B");
    /* ax comes from pabsw, whose range GCC does not track: it needs no
       product by 1 to keep the multiply-high narrow */
    pf_printf(&body, "    uint16_t ax = pf_fx_abs16(x); /* |x| */\n");
    pf_printf(&body, "    uint16_t w = (uint16_t)((uint32_t)ax * (uint16_t)%s + (uint16_t)pf_fx_mulhrs((int16_t)ax, %s) + %s);\n",
              ka, kb, is_cos ? "0x8000u" : "0x4000u");
    if (full) /* |x| = 32768 went through the multiply-high as -32768: it gave -B for B
                 (a select: AVX-512 adds under a mask, one instruction fewer) */
        pf_printf(&body, "    w = (uint16_t)(ax == 32768u ? w + 2 * %s : w);\n", kb);
    /* the fold as one abs: with ws = w - 2 (the uint16_t's top bit flipped,
       read as an int16_t, in [-2, 2)), w - 1 = 1 + ws on [0, 2) and
       3 - w = 1 - ws on [2, 4) are both 1 - |ws|; |ws| <= 2 fits a
       uint16_t.  Clamping |ws| to [2^-14, 2 - 2^-14] holds v = +-1 at
       +-(1 - 2^-14), as a clamp of v would: the same values, 5 vector
       instructions instead of about 10 */
    pf_put(&body, "    /* fold: v = w - 1 on [0, 2), 3 - w on [2, 4), in [-1, 1] (2^-14), then 2^-15 units */\n"
                  "    uint16_t aw = pf_fx_abs16((int16_t)(w ^ 0x8000u)); /* |w - 2| in [0, 2] */\n"
                  "    aw = (uint16_t)(aw < 1u ? 1u : aw > 32767u ? 32767u : aw); /* +-1 held below */\n"
                  "    int16_t vc = (int16_t)(0x4000 - (int32_t)aw); /* 1 - |w - 2| = v */\n");
    pf_printf(&body, "    int16_t v = (int16_t)(vc * %s); /* 2^-15 units */\n", fx_k16(G, 2, "2 (see the array form)"));
    pf_put(&body, "    int16_t s = pf_fx_mulhrs(v, v); /* v^2 in [0, 1), 2^-15 units */\n");
    pf_put(&body, "    /* P(s) ~ sin(pi/2 t) / t with t^2 = s: Horner in 16-bit words, one rounding per step */\n");
    fx_emit_horner(G, &horner, "s", "    ");
    pf_put(&body, horner.s);
    if (Eo == Ep) {
        pf_put(&body, "    int16_t r = pf_fx_mulhrs(v, p); /* v P, rounded once to the output's lsb */\n");
    } else if (Eo < Ep) {
        pf_printf(&body, "    int16_t r = pf_fx_rsh16(pf_fx_mulhrs(v, p), %d); /* v P at 2^-%d, then the output's lsb */\n",
                  Ep - Eo, Ep);
    } else {
        pf_printf(&body, "    int32_t r = pf_fx_rsh32((int32_t)v * p, %d); /* v P: full 32-bit product, rounded once */\n",
                  15 + Ep - Eo);
        snprintf(G->wide_text, sizeof G->wide_text,
                 "the final product v P is a full 16x16 -> 32-bit product, rounded once: the output's lsb 2^-%d is "
                 "finer than P's 2^-%d", Eo, Ep);
    }
    if (!is_cos) {
        if (Eo > Ep)
            pf_put(&body, "    r = x < 0 ? -r : r; /* sin(-x) = -sin(x) */\n");
        else
            pf_put(&body, "    int16_t sg = pf_fx_sgn16(x); /* sin(-x) = -sin(x), through a mask */\n"
                          "    r = (int16_t)((r ^ sg) - sg);\n");
    }
    fx_emit_return16(G, &body, "r", Eo > Ep ? INT32_MIN : -32768, Eo > Ep ? INT32_MAX : 32767);
    const char *kv[] = {"FUNC", is_cos ? "cos" : "sin", "PHASE", is_cos ? "2" : "1", "NAME", G->name, "IT", G->it,
                        "OT", G->ot, "BODY", body.s, "HELPERS", "", "LANES", "in 16-bit lanes", "WORD",
                        "a uint16_t with 14 fraction bits", NULL};
    pf_subst(b, pf_template("fx_sincos16.c"), kv);
    free(body.s);
    free(horner.s);
}

static void emit(fx_gen *G, pf_buf *b, int is_cos)
{
    if (G->W == 16) {
        emit16(G, b, is_cos);
        return;
    }
    pf_buf phase = {0}, fold = {0}, sq = {0}, horner = {0}, out = {0};
    int W = G->W;
    if (G->kind == 0) {
        int sh = G->trig.sh;
        const char *off = is_cos ? "0x80000000u" : "0x40000000u";
        if (sh >= 1)
            pf_printf(&phase, "    uint32_t w = (uint32_t)pf_fx_rne((int64_t)x * %d, %d) + %s;", C31, sh, off);
        else if (sh == 0)
            pf_printf(&phase, "    uint32_t w = (uint32_t)((int64_t)x * %d) + %s;", C31, off);
        else
            pf_printf(&phase, "    uint32_t w = (uint32_t)((uint64_t)(int64_t)x * %du << %d) + %s;", C31, -sh, off);
        pf_put(&fold, "    int32_t v = w < 0x80000000u ? (int32_t)w - 0x40000000 : 0x40000000 - (int32_t)(w - 0x80000000u);");
    } else {
        pf_printf(&phase, "    uint64_t w = (uint64_t)(int64_t)x * UINT64_C(0x%016llx) + UINT64_C(%s);",
                  (unsigned long long)(uint64_t)G->trig.c64, is_cos ? "0x8000000000000000" : "0x4000000000000000");
        pf_printf(&fold,
                  "    int64_t v%s = w < UINT64_C(0x8000000000000000) ? (int64_t)w - INT64_C(0x4000000000000000)\n"
                  "                   : INT64_C(0x4000000000000000) - (int64_t)(w - UINT64_C(0x8000000000000000));",
                  W == 32 ? "62" : "");
        if (W == 32)
            pf_put(&fold, "\n    int32_t v = (int32_t)pf_fx_rne(v62, 32); /* v in [-1, 1], 2^-30 units */");
    }
    if (W == 32)
        pf_put(&sq, "    int64_t s0 = pf_fx_rne((int64_t)v * v, 29);\n"
                    "    int32_t s = (int32_t)(s0 < INT32_MAX ? s0 : INT32_MAX);");
    else
        pf_put(&sq, "    int64_t s = pf_fx_mul64(v, v, 61); /* saturates at INT64_MAX */");
    fx_emit_horner(G, &horner, "s", "    ");
    pf_chomp(&horner);
    int so = out_shift(G);
    int64_t mx = pf_type_max_stored(&G->out), mn = pf_type_min_stored(&G->out);
    if (W == 32)
        pf_printf(&out, "    int64_t r = pf_fx_rne((int64_t)v * p, %d);\n", so);
    else
        pf_printf(&out, "    int64_t r = pf_fx_mul64(v, p, %d);\n", so);
    pf_printf(&out, "    return (%s)(r > %lld ? %lld : r < %lld ? %lld : r);", G->ot, (long long)mx, (long long)mx,
              (long long)mn, (long long)mn);
    char wbits[8], wf[8], stype[64];
    snprintf(wbits, sizeof wbits, "%d", G->kind == 0 ? 32 : 64);
    snprintf(wf, sizeof wf, "%d", G->kind == 0 ? 30 : 62);
    pf_type_format(&G->xt, stype, sizeof stype);
    const char *kv[] = {"FUNC", is_cos ? "cos" : "sin", "PHASE", is_cos ? "2" : "1", "WBITS", wbits, "WF", wf,
                        "NAME", G->name, "IT", G->it, "OT", G->ot, "PHASE_CODE", phase.s, "FOLD_CODE", fold.s,
                        "S_TYPE", stype, "S_CODE", sq.s, "HORNER", horner.s, "OUT_TYPE", G->out_text, "OUT_CODE",
                        out.s, NULL};
    pf_subst(b, pf_template("fx_sincos.c"), kv);
    free(phase.s);
    free(fold.s);
    free(sq.s);
    free(horner.s);
    free(out.s);
}

static void emit_sin(fx_gen *G, pf_buf *b) { emit(G, b, 0); }
static void emit_cos(fx_gen *G, pf_buf *b) { emit(G, b, 1); }

const fx_func fx_func_sin = {
    .name = "sin", .ref = PF_SIN, .tmpl = "fx_sincos", .target_text = "sin(pi/2 t)", .g = g_sinpi2,
    .a = 0, .b = 1, .parity = FIT_PARITY_ODD, .errkind = FIT_ABS, .errkind_fast = FIT_REL, .con_zero = 0, .con_text = NULL,
    .prepare = prep_sin, .budget = budget, .emit = emit_sin, .fit16 = fit16,
};

const fx_func fx_func_cos = {
    .name = "cos", .ref = PF_COS, .tmpl = "fx_sincos", .target_text = "sin(pi/2 t)", .g = g_sinpi2,
    .a = 0, .b = 1, .parity = FIT_PARITY_ODD, .errkind = FIT_ABS, .errkind_fast = FIT_REL, .con_zero = 0, .con_text = NULL,
    .prepare = prep_cos, .budget = budget, .emit = emit_cos, .fit16 = fit16,
};
