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

#include <ctype.h>
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

/* ---- 16-bit lanes, the register-table kernel (kind 4) ----
 *
 * For int16_t inputs and int16_t outputs with 1..14 fraction bits, the
 * exact variant (the fast one: kind 6, or Horner).  u = |x| 2/pi in
 * quarter turns is U = |x| K mod 2^32 at 2^-30, K = round(2/pi 2^(30-Ei))
 * = KH 2^16 + KL: lo = |x| KL mod 2^16
 * (pmullw) and hi = floor(|x| KL 2^-16) + |x| KH + HOFF (pmulhuw, pmullw),
 * both exact, the only error |x| |K - 2/pi 2^(30-Ei)| 2^-30.  hi's top bit
 * is the half turn (sin(pi/2 (u + 2)) = -sin(pi/2 u)), its next five the
 * segment j of [0, 2) (16 of width 1/8: its next four bits; or 32 of
 * width 1/16: five), and the 15 bits of U below it the position in it
 * (tau = t 2^-15 in [0, 1), the rest of u truncated: < 2^-18 or 2^-19).
 * Per segment a cubic P_j(tau) = C0 + tau (C1 + tau (C2 + tau C3)) (16
 * segments) or a quadratic (32) in 2^-16 units, offset by 1/2 (P + 2^15 =
 * sin 2^16, so [0, 1) fits an int16_t): rounding multiply-highs
 * (pmulhrsw), the coefficients from tables of 16 or 32 entries, one zmm
 * register each (vpermw); on AVX2 the low and high bytes of 16 entries per
 * register, a lookup two vpshufb merged by vpor (four, and three vpor, for
 * 32 entries; see emit16_4).  The cubics are taken where their bound is
 * below 1 lsb (every default pair; on AVX2 they take 0.23 ns/elem, the
 * quadratics 0.32), else the quadratics.  Result round((P + 2^15)
 * 2^(Eo-16)) = pmulhrsw(P, 2^(Eo-1)) + 2^(Eo-1), then the sign: the half
 * turn's, and for sin x's.
 * Coefficients: Chebyshev interpolation of sin(pi/2 (j + tau) 2/ns) at
 * ord + 1 nodes, rounded, then the integers within a few units of it whose emitted
 * steps give the smallest largest error over the segment's inputs (every
 * 16-bit input falls in one segment: the search sees them all) against
 * sinl/cosl (long double, error far below 2^-40); no step may leave int16_t.
 * The bound is that largest pre-rounding error plus the final 1/2 lsb,
 * over all 2^16 inputs of the emitted integer steps (tr4_eval, the same
 * steps as the emitted C). */

static int kind4_ok(const fx_gen *G)
{
    int Ei = G->in.exp, Eo = G->out.exp;
    /* the output must hold +-1 (the kernels do not saturate); --order asks
       for one polynomial of that order: the Horner kernels */
    return G->W == 16 && !G->order_req && G->in.storage_bits == 16 && G->in.is_signed && G->out.storage_bits == 16 &&
           G->out.is_signed && Eo >= 1 && Eo <= 14 && Ei >= 2 && Ei <= 14 &&
           pf_type_max_stored(&G->out) >= ((int64_t)1 << Eo) && pf_type_min_stored(&G->out) <= -((int64_t)1 << Eo);
}

static int16_t tr4_mulhrs(int32_t a, int32_t b) { return (int16_t)((((a * b) >> 14) + 1) >> 1); }

typedef struct {
    int j, s;      /* segment, result negated */
    int32_t t;     /* tau 2^15 */
} tr4_ph;

static void tr4_phase(const fx_gen *G, int64_t x, int is_cos, tr4_ph *p)
{
    const fx_trig_red *T = &G->trig;
    uint32_t ax = (uint32_t)(x < 0 ? -x : x);
    uint32_t pl = ax * (uint32_t)T->kl;
    uint32_t lo = pl & 0xffffu;
    uint32_t hi = ((pl >> 16) + ax * (uint32_t)T->kh + (uint32_t)T->hoff) & 0xffffu;
    if (T->tns == 16) {
        p->j = (int)((hi >> 11) & 15u);
        p->t = (int32_t)(((hi << 4) | (lo >> 12)) & 0x7fffu);
    } else {
        p->j = (int)((hi >> 10) & 31u);
        p->t = (int32_t)(((hi << 5) | (lo >> 11)) & 0x7fffu);
    }
    p->s = (int)(hi >> 15) ^ (!is_cos && x < 0);
}

/* P for segment coefficients c[ord + 1] at t; 0 when a step leaves int16_t */
static int tr4_p(int ord, const int32_t *c, int32_t t, int32_t *p)
{
    int32_t q = ord == 3 ? tr4_mulhrs(t, c[3]) + c[2] : c[2];
    if (q < -32768 || q > 32767)
        return 0;
    q = tr4_mulhrs(t, q) + c[1];
    if (q < -32768 || q > 32767)
        return 0;
    *p = tr4_mulhrs(t, q) + c[0];
    return *p >= -32768 && *p <= 32767;
}

/* f(x) 2^Eo, signed as the kernel folds it (>= 0 up to the phase error) */
static long double tr4_target(const fx_gen *G, int64_t x, int is_cos, int s)
{
    long double a = ldexpl((long double)x, -G->in.exp);
    long double f = is_cos ? cosl(a) : sinl(a);
    return ldexpl(s ? -f : f, G->out.exp);
}

/* the fit of kind 4 on ns segments with polynomials of degree ord (16
   and 3, or 32 and 2); its largest pre-rounding error in T->terr */
static int prepare4_n(fx_gen *G, int is_cos, int ns, int ord, char *err, size_t errlen)
{
    fx_trig_red *T = &G->trig;
    int Eo = G->out.exp;
    T->tns = ns;
    T->tord = ord;
    /* the inputs of each segment */
    static int32_t ts[32][65536];
    static long double ys[32][65536];
    int cnt[32] = {0};
    for (int64_t x = -32768; x <= 32767; x++) {
        tr4_ph p;
        tr4_phase(G, x, is_cos, &p);
        ts[p.j][cnt[p.j]] = p.t;
        /* the pre-rounding target of (P + 2^15) 2^(Eo-16) */
        ys[p.j][cnt[p.j]] = tr4_target(G, x, is_cos, p.s);
        cnt[p.j]++;
    }
    long double sc = ldexpl(1, Eo - 16);
    double worst = 0;
    int w3 = ord == 3 ? 2 : 0, w2 = 3, w1 = ord == 3 ? 3 : 4, w0 = ord == 3 ? 3 : 4; /* the search's half-widths */
    for (int j = 0; j < ns; j++) {
        /* Chebyshev nodes of [0, 1]: the polynomial through them (Newton's
           divided differences, then the monomial form) */
        long double tn[4], yn[4], dd[4], a[4] = {0, 0, 0, 0};
        for (int k = 0; k <= ord; k++) {
            tn[k] = 0.5L + 0.5L * cosl((2 * k + 1) * 3.14159265358979323846264338327950288L / (2 * (ord + 1)));
            yn[k] = sinl(1.57079632679489661923132169163975144L * (j + tn[k]) * 2 / ns) * 65536 - 32768;
            dd[k] = yn[k];
        }
        for (int l = 1; l <= ord; l++)
            for (int k = ord; k >= l; k--)
                dd[k] = (dd[k] - dd[k - 1]) / (tn[k] - tn[k - l]);
        for (int k = ord; k >= 0; k--) { /* a(t) = a(t) (t - tn[k]) + dd[k] */
            for (int l = ord; l >= 1; l--)
                a[l] = a[l - 1] - tn[k] * a[l];
            a[0] = dd[k] - tn[k] * a[0];
        }
        int32_t b0 = (int32_t)llroundl(a[0]), b1 = (int32_t)llroundl(a[1]), b2 = (int32_t)llroundl(a[2]);
        int32_t b3 = (int32_t)llroundl(a[3]);
        double best = INFINITY;
        int32_t bc[4] = {0, 0, 0, 0};
        for (int32_t d3 = -w3; d3 <= w3; d3++)
        for (int32_t d2 = -w2; d2 <= w2; d2++)
            for (int32_t d1 = -w1; d1 <= w1; d1++)
                for (int32_t d0 = -w0; d0 <= w0; d0++) {
                    int32_t c[4] = {b0 + d0, b1 + d1, b2 + d2, b3 + d3};
                    if (c[0] < -32768 || c[0] > 32767 || c[1] < -32768 || c[1] > 32767 || c[2] < -32768 ||
                        c[2] > 32767 || c[3] < -32768 || c[3] > 32767)
                        continue;
                    double e = 0;
                    for (int i = 0; i < cnt[j] && e < best; i++) {
                        int32_t p;
                        if (!tr4_p(ord, c, ts[j][i], &p)) {
                            e = INFINITY;
                            break;
                        }
                        double d = (double)fabsl((long double)(p + 32768) * sc - ys[j][i]);
                        e = d > e ? d : e;
                    }
                    if (e < best) {
                        best = e;
                        bc[0] = c[0], bc[1] = c[1], bc[2] = c[2], bc[3] = c[3];
                    }
                }
        if (!(best < INFINITY)) {
            snprintf(err, errlen, "16-bit table kernel: segment %d has no coefficients within int16_t", j);
            return -2;
        }
        T->tc0[j] = (int16_t)bc[0];
        T->tc1[j] = (int16_t)bc[1];
        T->tc2[j] = (int16_t)bc[2];
        T->tc3[j] = (int16_t)bc[3];
        worst = best > worst ? best : worst;
    }
    T->terr = worst * (1 + 1e-9) + 1e-9; /* long double's own error: far below */
    return 0;
}

/* kinds 4 and 6's phase: K = round(2/pi 2^(30-Ei)) as two 16-bit words
   kh:kl, the offset hoff and the phase's error from K's rounding; 0 when K
   does not fit (the 16-bit kinds then do not apply) */
static uint64_t tr_phase(fx_trig_red *T, int Ei, int hoff)
{
    uint64_t K = two_over_pi_bits(30 - Ei);
    if (K >= ((uint64_t)1 << 32) || K < ((uint64_t)1 << 15))
        return 0;
    T->kh = (int64_t)(K >> 16);
    T->kl = (int64_t)(K & 0xffffu);
    T->hoff = hoff;
    T->tred = 32768.0 * two_over_pi_frac(30 - Ei) * 0x1p-30;
    return K;
}

static int prepare4(fx_gen *G, int is_cos, char *err, size_t errlen)
{
    fx_trig_red *T = &G->trig;
    int Ei = G->in.exp, Eo = G->out.exp;
    uint64_t K = tr_phase(T, Ei, is_cos ? 0x4000 : 0);
    if (!K)
        return -2;
    /* cubics on 16 segments where they are within 1 lsb (on AVX2 a 16-entry
       lookup is two vpshufb, a 32-entry one four), else quadratics on 32 */
    int rc = prepare4_n(G, is_cos, 16, 3, err, errlen);
    if (rc != 0 || !(T->terr + 0.5 < 1 - 1e-6))
        rc = prepare4_n(G, is_cos, 32, 2, err, errlen);
    if (rc != 0)
        return rc;
    int ns = T->tns, ord = T->tord, nb = ns == 16 ? 4 : 5;
    G->kind = 4;
    G->dred = T->tred;
    G->fmax = 1;
    snprintf(G->red_text, sizeof G->red_text,
             "on |x| (sin(-x) = -sin(x), cos(-x) = cos(x), exactly); u = |x| 2/pi in quarter turns, U = u 2^30 mod "
             "2^32 = |x| K%s, K = round(2/pi 2^%d) = %lld = %lld 2^16 + %lld (MPFR), as two 16-bit words: lo = |x| "
             "%lld mod 2^16 (pmullw), hi = floor(|x| %lld 2^-16) + |x| %lld%s (pmulhuw, pmullw), exact; |error of u| "
             "<= %.3e; half turn h = bit 31 of U, segment j = bits 30..%d (u mod 2 in [j, j + 1) 2^-%d), tau = "
             "bits %d..%d 2^-15 in [0, 1) (the rest truncated, < 2^-%d quarter turns)",
             is_cos ? " + 2^30 (cos(x) = sin(pi/2 (u + 1)))" : "", 30 - Ei, (long long)K, (long long)T->kh,
             (long long)T->kl, (long long)T->kl, (long long)T->kl, (long long)T->kh, is_cos ? " + 2^14" : "",
             T->tred, 31 - nb, nb - 1, 30 - nb, 16 - nb, 14 + nb);
    snprintf(G->alt_domain, sizeof G->alt_domain,
             "sin(pi/2 (j + tau) 2^-%d) on tau in [0, 1) for each of %d segments j of the half turn [0, 2) quarter "
             "turns (the other half by the sign)",
             nb - 1, ns);
    if (ord == 3)
        snprintf(G->alt_order, sizeof G->alt_order,
                 "3 per segment (P_j(tau) = C0 + tau (C1 + tau (C2 + tau C3))), four %d-entry tables of int16_t; "
                 "int16_t words: 16-bit lanes",
                 ns);
    else
        snprintf(G->alt_order, sizeof G->alt_order,
                 "2 per segment (P_j(tau) = C0 + tau (C1 + tau C2)), three %d-entry tables of int16_t; int16_t "
                 "words: 16-bit lanes",
                 ns);
    snprintf(G->alt_method, sizeof G->alt_method,
             "per segment: the %s through the %s Chebyshev nodes of [0, 1] (long double), rounded to 2^-16, then "
             "the integers within %s of it with the smallest largest error of the emitted steps over the segment's "
             "inputs (every 16-bit input, against sinl/cosl), no step leaving int16_t%s",
             ord == 3 ? "cubic" : "quadratic", ord == 3 ? "four" : "three",
             ord == 3 ? "(+-3, +-3, +-3, +-2)" : "(+-4, +-4, +-3)",
             ord == 3 ? "; cubics on 16 segments where their bound is below 1 lsb, else quadratics on 32" : "");
    snprintf(G->alt_con, sizeof G->alt_con, "none (the sign fold makes sin exactly odd and cos exactly even)");
    if (ord == 3)
        snprintf(G->alt_formats, sizeof G->alt_formats,
                 "tau int16_t at 2^-15 in [0, 2^15); C0..C3, q3 = C2 + pmulhrsw(tau, C3) and q = C1 + "
                 "pmulhrsw(tau, q3) int16_t at 2^-16; P = C0 + pmulhrsw(tau, q) int16_t at 2^-16 offset by 1/2 "
                 "(sin = (P + 2^15) 2^-16); result pmulhrsw(P, 2^%d) + 2^%d = round(sin 2^%d), ties up, then "
                 "negated when h (xor x < 0, for sin)",
                 Eo - 1, Eo - 1, Eo);
    else
        snprintf(G->alt_formats, sizeof G->alt_formats,
                 "tau int16_t at 2^-15 in [0, 2^15); C0, C1, C2 and q = C1 + pmulhrsw(tau, C2) int16_t at 2^-16; P = "
                 "C0 + pmulhrsw(tau, q) int16_t at 2^-16 offset by 1/2 (sin = (P + 2^15) 2^-16); result "
                 "pmulhrsw(P, 2^%d) + 2^%d = round(sin 2^%d), ties up, then negated when h (xor x < 0, for sin)",
                 Eo - 1, Eo - 1, Eo);
    snprintf(G->alt_poly, sizeof G->alt_poly,
             "largest pre-rounding error of the emitted steps %.4f lsb (all 2^16 inputs, against sinl/cosl: "
             "segment fit, coefficient and multiply-high roundings, phase)",
             T->terr);
    snprintf(G->alt_arith, sizeof G->alt_arith,
             "integers only (no floating point, no <math.h>); the phase exact but for K's rounding, tau truncated, "
             "the multiply-highs and the result rounded to nearest, ties up; bit-identical under any compiler "
             "flags");
    snprintf(G->bound_note, sizeof G->bound_note,
             "taken over every input from the emitted integer steps (the register-table kernel)");
    snprintf(G->order_text, sizeof G->order_text, "int16_t words: 16-bit lanes, %s %d-entry tables",
             ord == 3 ? "four" : "three", ns);
    return 0;
}

/* ---- 16-bit lanes, fast: one quintic on the folded quarter turn (kind 6) ----
 *
 * No tables: hi = floor(|x| K 2^-16) mod 2^16, kind 4's U >> 16 (u to
 * 2^-14 quarter turns, a full turn in 16 bits), then a fold to t in [-1, 1]
 * quarter turns and sin(pi/2 t) = t P(t^2), P a quadratic in s = t^2.
 * sin: z = hi << 1 (t = z 2^-15 = u mod 2 taken in [-1, 1)); sin(pi/2 u)
 * = sin(pi/2 t) when bits 15 and 14 of hi agree, -sin(pi/2 t) when not
 * (sin(pi/2 (t + 2)) = -sin(pi/2 t)); that sign, xor x's, the result's.
 * cos: v = 1 - |hi| (hi as an int16_t, 2^-14 units: cos(pi/2 u) =
 * sin(pi/2 (1 - |u|)) on u in [-2, 2)), z = 2 v saturated (t = 1 held as
 * 1 - 2^-15: sin is flat there).  Then s = pmulhrsw(z, z) read as
 * unsigned (z = -2^15 gives 2^15 = 1, which no signed word holds), and,
 * as P's coefficients alternate in sign, two unsigned multiply-highs
 * (pmulhuw): q = C3 - floor(s C5 2^-16), p = C1 - floor(s q 2^-16), the
 * result pmulhrsw(z, p): five multiplies, 13 (cos) or 14 (sin) vector
 * instructions per vector.  It replaced kind 5 (fast sin: quadratics on 16
 * segments of the half turn, three 16-entry tables: 17 instructions per
 * vector on AVX-512, three vpermw; 24 on AVX2, nine of them for the
 * lookups), which git history keeps.  |x| first: sin exactly odd, cos
 * exactly even.
 * Coefficients: value 1 and slope 0 at the quarter turn (the fast
 * variant's seam rule; prepare6 says how that leaves one integer free), then
 * the free integer with the smallest largest (pre-rounding error + 1/2 lsb)
 * / max(2^-10 |f|, 4 lsb) over every input (the emitted integer steps
 * against sinl/cosl); no step may leave its word.  The bound R |f| + A + 1/2 lsb: R and A the smallest (R 2^12 + A
 * in lsb) that cover the pre-rounding error of every input, R on a grid of
 * 2^-16. */

/* the emitted steps for x: 0 when a step leaves its word, else the result
   in *res and the value before its last rounding (signed as the result) in *pre */
static int tr6_eval(const fx_gen *G, const int32_t *c, int64_t x, int is_cos, long double *pre, int32_t *res)
{
    const fx_trig_red *T = &G->trig;
    uint32_t ax = (uint32_t)(x < 0 ? -x : x);
    uint32_t hi = (((ax * (uint32_t)T->kl) >> 16) + ax * (uint32_t)T->kh) & 0xffffu;
    int32_t z;
    if (is_cos) {
        int32_t h = (int32_t)(int16_t)(uint16_t)hi;
        int32_t v2 = 2 * (0x4000 - (h < 0 ? -h : h)); /* [-2^15, 2^15] */
        z = v2 > 32767 ? 32767 : v2;
    } else
        z = (int32_t)(int16_t)(uint16_t)(hi << 1);
    int32_t s = (z * z + 0x4000) >> 15; /* [0, 2^15]: pmulhrsw read as unsigned */
    int32_t q = c[1] - (int32_t)(((uint32_t)s * (uint32_t)c[2]) >> 16);
    if (q < 0 || q > 65535)
        return 0;
    int32_t p = c[0] - (int32_t)(((uint32_t)s * (uint32_t)q) >> 16);
    if (p < -32767 || p > 32767)
        return 0;
    int32_t r = tr4_mulhrs(z, p);
    long double e = (long double)z * p / 32768;
    int neg = !is_cos && ((hi ^ (uint32_t)(uint16_t)z ^ (uint32_t)(uint16_t)x) & 0x8000u);
    *res = neg ? -r : r;
    *pre = neg ? -e : e;
    return 1;
}

static int prepare6(fx_gen *G, int is_cos)
{
    fx_trig_red *T = &G->trig;
    int Ei = G->in.exp, Eo = G->out.exp;
    if (!tr_phase(T, Ei, 0))
        return -2;
    T->tred += 0x1p-14; /* the floor to 2^-14 quarter turns */
    static long double ys[65536];
    for (int64_t x = -32768; x <= 32767; x++)
        ys[x + 32768] = tr4_target(G, x, is_cos, 0);
    /* The fast variant's seam rule: sin(pi/2 t) = t P(t^2) takes value 1 and
       slope 0 at t = 1, the quarter turn, where the fold puts two mirrored
       pieces side by side (t -> -t beyond it, and |x| at cos's 0), so they
       join with a matched slope.  With p(t) 2^-Eo = P, p = C1 - t^2 C3/2 +
       t^4 C5/4 (the multiply-highs' scales), value and slope at t = 1 are
       4 C1 - 2 C3 + C5 = 4 2^Eo and 4 C1 - 6 C3 + 5 C5 = 0: C5 = 4m,
       C3 = 4m + 2^Eo, C1 = m + 3 2^(Eo-1), one integer m left.  Starting
       point: P's linear term pi/2 (m0 = 2^Eo (pi/2 - 3/2)); the search takes
       the m with the smallest largest error over every input.  (Unconstrained,
       the slope at the seam was 0.005 per quarter turn, 0.3% of the
       steepest; the constrained quintic uses about 0.32 of the bound before
       the arithmetic's roundings.) */
    if (Eo < 1 || Eo > 14)
        return -2;
    const int64_t one = (int64_t)1 << Eo;
    int64_t m0 = llroundl(ldexpl(1.57079632679489661923132169163975144L - 1.5L, Eo));
    double best = INFINITY;
    int32_t bc[3] = {0, 0, 0};
    const int64_t wm = 64; /* the search's half-width in m */
    for (int64_t m = m0 - wm; m <= m0 + wm; m++) {
        int64_t c1 = m + 3 * one / 2, c3 = 4 * m + one, c5 = 4 * m;
        if (m < 0 || c1 > 32767 || c3 > 65535 || c5 > 65535)
            continue;
        int32_t c[3] = {(int32_t)c1, (int32_t)c3, (int32_t)c5};
        double e = 0;
        /* the inputs from the largest |x| down: the worst ones come early */
        for (int64_t i = 0; i < 65536 && e < best; i++) {
            int64_t x = (i & 1) ? 32767 - (i >> 1) : -32768 + (i >> 1);
            long double pre;
            int32_t r;
            if (!tr6_eval(G, c, x, is_cos, &pre, &r)) {
                e = INFINITY;
                break;
            }
            long double y = ys[x + 32768];
            double d = (double)((fabsl(pre - y) + 0.5L) / fmaxl(fabsl(y) * 0x1p-10L, 4.0L));
            e = d > e ? d : e;
        }
        if (e < best) {
            best = e;
            bc[0] = c[0], bc[1] = c[1], bc[2] = c[2];
        }
    }
    if (!(best <= 1))
        return -2;
    T->pc1 = bc[0];
    T->pc3 = bc[1];
    T->pc5 = bc[2];
    T->fworst = best;
    /* R and A over every input's pre-rounding error */
    double bestRA = INFINITY;
    for (int k = 0; k < 64; k++) {
        double rho = k * 0x1p-16, A = 0;
        for (int64_t x = -32768; x <= 32767; x++) {
            long double pre;
            int32_t r;
            if (!tr6_eval(G, bc, x, is_cos, &pre, &r))
                return -2; /* not reached: the search kept only coefficients in range */
            long double y = ys[x + 32768];
            double d = (double)(fabsl(pre - y) - rho * fabsl(y));
            A = d > A ? d : A;
        }
        A = A * (1 + 1e-9) + 1e-9;
        if (rho * 4096 + A < bestRA) {
            bestRA = rho * 4096 + A;
            T->fR = rho;
            T->fA = A;
        }
    }
    if (!(bestRA + 0.5 <= 4 * (1 - 1e-9)))
        return -2;
    G->kind = 6;
    G->dred = T->tred;
    G->fmax = 1;
    snprintf(G->red_text, sizeof G->red_text,
             "on |x| (sin(-x) = -sin(x), cos(-x) = cos(x), exactly); u = |x| 2/pi in quarter turns, hi = "
             "floor(u 2^14) mod 2^16 = floor(|x| %lld 2^-16) + |x| %lld (pmulhuw, pmullw; K = round(2/pi 2^%d) "
             "= %lld 2^16 + %lld, MPFR); |error of u| <= %.3e (K's rounding and the floor); %s",
             (long long)T->kl, (long long)T->kh, 30 - Ei, (long long)T->kh, (long long)T->kl, T->tred,
             is_cos ? "fold: v = 1 - |hi| (hi as int16_t, 2^-14 units; cos(pi/2 u) = sin(pi/2 (1 - |u|)) on u in "
                      "[-2, 2)), z = 2 v saturated to int16_t (t = 1 held as 1 - 2^-15), t = z 2^-15 in [-1, 1)"
                    : "fold: z = hi << 1 as int16_t, t = z 2^-15 = u mod 2 in [-1, 1); sin(pi/2 u) = sin(pi/2 t) "
                      "when bits 15 and 14 of hi agree, else -sin(pi/2 t); negated again when x < 0");
    snprintf(G->alt_domain, sizeof G->alt_domain,
             "sin(pi/2 t) = t P(t^2) on t in [-1, 1] quarter turns (odd polynomial, one for the whole turn)");
    snprintf(G->alt_order, sizeof G->alt_order,
             "5 (P(s) = C1 - s (C3 - s C5), s = t^2: three fixed-point coefficients, no tables); int16_t "
             "words: 16-bit lanes");
    snprintf(G->alt_method, sizeof G->alt_method,
             "the one-parameter family that meets the constraints (C5 = 4m, C3 = 4m + 2^%d, C1 = m + 3 2^%d), m "
             "within 64 of P's linear term pi/2, the m with the smallest largest (pre-rounding error + 1/2 lsb) / "
             "max(2^-10 |f|, 4 lsb) over every 16-bit input (the emitted steps against sinl/cosl): %.4f of the "
             "bound at most",
             Eo, Eo - 1,
             T->fworst);
    snprintf(G->alt_con, sizeof G->alt_con,
             "value 1, slope 0 at t = 1 where folded pieces meet (4 C1 - 2 C3 + C5 = 2^%d, 4 C1 - 6 C3 + 5 C5 = 0); "
             "|x| first: sin odd, cos even", Eo + 2);
    snprintf(G->alt_formats, sizeof G->alt_formats,
             "z = t 2^15 int16_t; s = pmulhrsw(z, z) = t^2 2^15 read as uint16_t in [0, 2^15]; C5 = %d, C3 = %d "
             "and q = C3 - pmulhuw(s, C5) uint16_t (q = -(c3 + c5 t^2) 2^%d); C1 = %d and p = C1 - pmulhuw(s, q) "
             "int16_t at the output's lsb 2^-%d (p = P(t^2) 2^%d); r = pmulhrsw(z, p) (the result's rounding)%s",
             T->pc5, T->pc3, Eo + 1, T->pc1, Eo, Eo, is_cos ? "" : ", then negated as the fold says");
    snprintf(G->alt_poly, sizeof G->alt_poly,
             "pre-rounding error of the emitted steps <= %.3e |f| + %.4f lsb for every input (all 2^16, against "
             "sinl/cosl: the fit, the coefficients' and multiply-highs' roundings, the phase)",
             T->fR, T->fA);
    snprintf(G->alt_arith, sizeof G->alt_arith,
             "integers only (no floating point, no <math.h>); the phase floored to 2^-14 quarter turns, the "
             "unsigned multiply-highs floored, the rounding multiply-highs to nearest, ties up; bit-identical "
             "under any compiler flags");
    snprintf(G->bound_note, sizeof G->bound_note,
             "R and A taken over every input from the emitted integer steps (the one-polynomial kernel)");
    snprintf(G->order_text, sizeof G->order_text, "int16_t words: 16-bit lanes, no tables");
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
    G->alt_domain[0] = G->alt_order[0] = G->alt_method[0] = G->alt_con[0] = G->alt_poly[0] = G->bound_note[0] = 0;
    /* fast sin and cos: one quintic, no tables (kind 6; 2026-11-26,
       fixed<15,12> -> fixed<15,14>, bench_fixed: sin 0.08 ns/elem on
       AVX-512 and 0.09 on AVX2, cos 0.07 and 0.09, against 0.08-0.09 and
       0.14 for the 16-entry quadratic tables that fast sin had (kind 5,
       removed: kind 6 meets the bound for every pair kind4_ok takes) and
       0.11 and 0.14 for cos's Horner kernel, which stays the fallback) */
    if (G->W == 16 && kind4_ok(G) && !G->exact && prepare6(G, is_cos) == 0)
        return 0;
    if (G->W == 16 && kind4_ok(G) && G->exact) {
        int rc = prepare4(G, is_cos, err, errlen);
        if (rc != -2)
            return rc;
    }
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
    if (G->kind == 4 || G->kind == 6) { /* the register-table and one-polynomial kernels fit their own */
        G->poly = G->real;
        G->poly_err = 0;
        G->Ep = 16;
        G->arith = 0;
        G->dP = 0;
        G->root_sat = 0;
        return 0;
    }
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
    if (G->kind == 6) { /* the fast one-polynomial kernel: R and A over every input */
        G->R = G->trig.fR;
        G->A = G->trig.fA * fx_lsb(G);
        G->poly_err = 0;
        return;
    }
    if (G->kind == 4) { /* the register-table kernel: its error over every input */
        G->A = G->trig.terr * fx_lsb(G);
        G->poly_err = 0;
        return;
    }
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

/* kind 4 (see above): the plain-C steps (scalar form, other clones), the
   AVX-512BW loop with the tables in registers (vpermw) and the AVX2 loop
   (vpshufb on the tables' byte planes) */
static void tr4_table(pf_buf *b, const char *name, const char *suf, const int16_t *v, int n, const char *what)
{
    /* 32-bit entries: the plain-C lookups vectorize as 32-bit gathers; the
       AVX-512 loop narrows them once to one register */
    pf_printf(b, "/* %s */\nstatic const int32_t %s_%s[%d] = {", what, name, suf, n);
    for (int i = 0; i < n; i++)
        pf_printf(b, "%s%d,", i % 8 ? " " : "\n    ", v[i]);
    pf_put(b, "\n};\n");
}

static void emit16_4(fx_gen *G, pf_buf *out, int is_cos)
{
    const fx_trig_red *T = &G->trig;
    const char *N = G->name;
    int Eo = G->out.exp, ns = T->tns, ord = T->tord, nb = ns == 16 ? 4 : 5, nt = ord + 1;
    pf_buf body = {0}, tabs = {0}, kern = {0};
    tr4_table(&tabs, N, "c0", T->tc0, ns, "C0[j]: P_j(0) - 1/2, 2^-16 units (fitted, see the provenance)");
    tr4_table(&tabs, N, "c1", T->tc1, ns, "C1[j], 2^-16 units");
    tr4_table(&tabs, N, "c2", T->tc2, ns, "C2[j], 2^-16 units");
    if (ord == 3)
        tr4_table(&tabs, N, "c3", T->tc3, ns, "C3[j], 2^-16 units");
    const char *kl = fx_k16(G, (int16_t)(uint16_t)T->kl, "KL (as uint16_t): K = KH 2^16 + KL");
    const char *kh = fx_k16(G, T->kh, "KH");
    char w[64];
    snprintf(w, sizeof w, "2^%d: the result's rounding multiply-high", Eo - 1);
    const char *kr = fx_k16(G, (int64_t)1 << (Eo - 1), w);
    pf_printf(&body, "    /* U = |x| K mod 2^32 (u 2^30, u = |x| 2/pi) as hi 2^16 + lo, exact */\n"
                     "    uint16_t ax = pf_fx_abs16(x); /* |x| */\n"
                     "    uint32_t pl = (uint32_t)ax * (uint16_t)%s;\n"
                     "    uint16_t lo = (uint16_t)pl;\n"
                     "    uint16_t hi = (uint16_t)((pl >> 16) + (uint32_t)ax * (uint16_t)%s%s);\n",
              kl, kh, is_cos ? " + 0x4000u" : "");
    pf_printf(&body, "    /* segment j = bits 30..%d, tau = bits %d..%d (2^-15) */\n"
                     "    unsigned j = (unsigned)(hi >> %d) & %du;\n"
                     "    int16_t t = (int16_t)((((uint32_t)hi << %d) | ((uint32_t)lo >> %d)) & 0x7fffu);\n",
              31 - nb, 30 - nb, 16 - nb, 15 - nb, ns - 1, nb, 16 - nb);
    if (ord == 3)
        pf_printf(&body, "    /* P = C0 + tau (C1 + tau (C2 + tau C3)), 2^-16 units offset by 1/2 */\n"
                         "    int16_t q = (int16_t)(pf_fx_mulhrs(t, (int16_t)%s_c3[j]) + %s_c2[j]);\n"
                         "    q = (int16_t)(pf_fx_mulhrs(t, q) + %s_c1[j]);\n",
                  N, N, N);
    else
        pf_printf(&body, "    /* P = C0 + tau (C1 + tau C2), 2^-16 units offset by 1/2 */\n"
                         "    int16_t q = (int16_t)(pf_fx_mulhrs(t, (int16_t)%s_c2[j]) + %s_c1[j]);\n",
                  N, N);
    pf_printf(&body, "    int16_t p = (int16_t)(pf_fx_mulhrs(t, q) + %s_c0[j]);\n"
                     "    int16_t r = (int16_t)(pf_fx_mulhrs(p, %s) + %d); /* round((P + 2^15) 2^%d) */\n",
              N, kr, 1 << (Eo - 1), Eo - 16);
    if (is_cos)
        pf_put(&body, "    int16_t sg = pf_fx_sgn16((int16_t)hi); /* the half turn */\n");
    else
        pf_put(&body, "    int16_t sg = pf_fx_sgn16((int16_t)(hi ^ (uint16_t)x)); /* the half turn, and x < 0 */\n");
    pf_printf(&body, "    return (%s)((r ^ sg) - sg);", G->ot);
    const char *cond = "#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(__AVX2__)\n";
    pf_printf(&kern,
              "\n\n/* AVX-512BW: the same steps on 32 lanes, with intrinsics, as GCC does not turn\n"
              "   the table lookups into vpermw: the array form runs this loop on a CPU\n"
              "   with x86-64-v4 (see its dispatch), the rest of the array and the other\n"
              "   clones use the scalar steps above.  The same values (pfmathgen sweeps the\n"
              "   array form on its machine against the scalar one). */\n%s#include <immintrin.h>\n"
              "extern %s %s(%s x); /* the scalar form, for the last n %% 32 */\n",
              cond, G->ot, N, G->it);
    if (ns == 16)
        pf_printf(&kern, "/* the 16 entries as 16-bit words, twice (vpermw reads 5 index bits) */\n"
                         "__attribute__((target(\"arch=x86-64-v4\"))) static inline __m512i %s_w16(const int32_t *t)\n{\n"
                         "    return _mm512_broadcast_i64x4(_mm512_cvtepi32_epi16(_mm512_loadu_si512(t)));\n}\n",
                  N);
    else
        pf_printf(&kern, "/* 32 table entries as 16-bit words, for vpermw */\n"
                         "__attribute__((target(\"arch=x86-64-v4\"))) static inline __m512i %s_w16(const int32_t *t)\n{\n"
                         "    return _mm512_inserti64x4(_mm512_castsi256_si512(_mm512_cvtepi32_epi16(_mm512_loadu_si512(t))),\n"
                         "                              _mm512_cvtepi32_epi16(_mm512_loadu_si512(t + 16)), 1);\n}\n",
                  N);
    pf_printf(&kern, "__attribute__((target(\"arch=x86-64-v4\"), noinline))\n"
                     "static void %s_array_bw(const %s *x, %s *y, size_t n)\n{\n"
                     "    const __m512i c0 = %s_w16(%s_c0), c1 = %s_w16(%s_c1), c2 = %s_w16(%s_c2);\n",
              N, G->it, G->ot, N, N, N, N, N, N);
    if (ord == 3)
        pf_printf(&kern, "    const __m512i c3 = %s_w16(%s_c3);\n", N, N);
    pf_printf(&kern, "    const __m512i kl = _mm512_set1_epi16(%d), kh = _mm512_set1_epi16(%d), kr = _mm512_set1_epi16(%d);\n"
                     "    const __m512i ho = _mm512_set1_epi16(%d), m15 = _mm512_set1_epi16(0x7fff);\n",
              (int)(int16_t)(uint16_t)T->kl, (int)T->kh, 1 << (Eo - 1), is_cos ? 0x4000 : 0);
    pf_printf(&kern, "    const __m512i half = _mm512_set1_epi16(%d), zero = _mm512_setzero_si512();\n", 1 << (Eo - 1));
    pf_buf s1 = {0}, s2 = {0};
    pf_put(&s1, "        __m512i xv = _mm512_loadu_si512(x + i);\n"
                  "        __m512i ax = _mm512_abs_epi16(xv);\n"
                  "        __m512i lo = _mm512_mullo_epi16(ax, kl);\n"
                  "        __m512i hi = _mm512_add_epi16(_mm512_mulhi_epu16(ax, kl), _mm512_mullo_epi16(ax, kh));\n");
    if (is_cos)
        pf_put(&s1, "        hi = _mm512_add_epi16(hi, ho);\n");
    else
        pf_put(&s1, "        (void)ho;\n");
    pf_printf(&s1, "        __m512i j = _mm512_srli_epi16(hi, %d); /* vpermw reads the low 5 bits */\n"
                     "        /* (hi << %d | lo >> %d) & 0x7fff: one vpternlog */\n"
                     "        __m512i t = _mm512_ternarylogic_epi64(_mm512_slli_epi16(hi, %d), _mm512_srli_epi16(lo, %d), m15, 0xa8);\n",
              15 - nb, nb, 16 - nb, nb, 16 - nb);
    if (ord == 3)
        pf_put(&s2, "        __m512i q = _mm512_add_epi16(_mm512_mulhrs_epi16(t, _mm512_permutexvar_epi16(j, c3)),\n"
                      "                                     _mm512_permutexvar_epi16(j, c2));\n"
                      "        q = _mm512_add_epi16(_mm512_mulhrs_epi16(t, q), _mm512_permutexvar_epi16(j, c1));\n");
    else
        pf_put(&s2, "        __m512i q = _mm512_add_epi16(_mm512_mulhrs_epi16(t, _mm512_permutexvar_epi16(j, c2)),\n"
                      "                                     _mm512_permutexvar_epi16(j, c1));\n");
    pf_put(&s2, "        __m512i p = _mm512_add_epi16(_mm512_mulhrs_epi16(t, q), _mm512_permutexvar_epi16(j, c0));\n"
                  "        __m512i r = _mm512_add_epi16(_mm512_mulhrs_epi16(p, kr), half);\n");
    if (is_cos)
        pf_put(&s2, "        __mmask32 neg = _mm512_movepi16_mask(hi);\n");
    else
        pf_put(&s2, "        __mmask32 neg = _mm512_movepi16_mask(_mm512_xor_si512(hi, xv));\n");
    pf_put(&s2, "        r = _mm512_mask_sub_epi16(r, neg, zero, r);\n");
    /* software pipelined (fx_pipe_loop): block i's reduction beside block
       i - 32's lookups and polynomial */
    static const char *const cv4[] = {"j", "t", "hi", "xv"};
    fx_pipe_loop(&kern, "__m512i", 32, s1.s, s2.s, cv4, is_cos ? 3 : 4, "_mm512_storeu_si512(y + i - 32, r);", N);
    free(s1.s);
    free(s2.s);
    s1 = s2 = (pf_buf){0};
    /* AVX2 (16 lanes): no vpermw.  Each table is held as byte planes, its
       low and its high bytes, 16 entries per register (vpshufb reads 4
       index bits per 128-bit lane and zeroes a byte whose index has bit 7
       set): a lookup is two vpshufb (16 entries) or four (32), whose
       indices zero all but the right plane and half, merged by vpor */
    pf_printf(&kern,
              "\n\n/* AVX2 (x86-64-v3): the same steps on 16 lanes.  No vpermw: each table is\n"
              "   its low and its high bytes (byte planes) in %s registers; a lookup is %s\n"
              "   vpshufb whose indices have bit 7 set (the byte zeroed) where the plane%s\n"
              "   is not theirs, merged by vpor.  The sign by vpsignw.  The same values. */\n%s",
              ns == 16 ? "two" : "four (j < 16, j >= 16)", ns == 16 ? "two" : "four",
              ns == 16 ? "" : " or the half", cond);
    if (ns == 16)
        pf_printf(&kern, "__attribute__((target(\"arch=x86-64-v3\"))) static inline __m256i %s_lk(const __m256i *p, __m256i ia,\n"
                         "                                                                    __m256i ib)\n{\n"
                         "    return _mm256_or_si256(_mm256_shuffle_epi8(p[0], ia), _mm256_shuffle_epi8(p[1], ib));\n}\n",
                  N);
    else
        pf_printf(&kern, "__attribute__((target(\"arch=x86-64-v3\"))) static inline __m256i %s_lk(const __m256i *p, __m256i ia,\n"
                         "                                                                    __m256i ib, __m256i ja, __m256i jb)\n{\n"
                         "    return _mm256_or_si256(_mm256_or_si256(_mm256_shuffle_epi8(p[0], ia), _mm256_shuffle_epi8(p[1], ib)),\n"
                         "                           _mm256_or_si256(_mm256_shuffle_epi8(p[2], ja), _mm256_shuffle_epi8(p[3], jb)));\n}\n",
                  N);
    pf_printf(&kern,
              "__attribute__((target(\"arch=x86-64-v3\"), noinline))\n"
              "static void %s_array_avx2(const %s *x, %s *y, size_t n)\n{\n"
              "    const int32_t *tab[%d] = {%s_c0, %s_c1, %s_c2%s%s%s};\n",
              N, G->it, G->ot, nt, N, N, N, ord == 3 ? ", " : "", ord == 3 ? N : "", ord == 3 ? "_c3" : "");
    if (ns == 16)
        pf_printf(&kern, "    uint8_t b[%d][2][16]; /* per table: the low bytes, the high bytes */\n"
                         "    for (int a = 0; a < %d; a++)\n"
                         "        for (int k = 0; k < 16; k++) {\n"
                         "            b[a][0][k] = (uint8_t)(uint32_t)tab[a][k];\n"
                         "            b[a][1][k] = (uint8_t)((uint32_t)tab[a][k] >> 8);\n"
                         "        }\n"
                         "    __m256i c[%d][2];\n"
                         "    for (int a = 0; a < %d; a++)\n"
                         "        for (int p = 0; p < 2; p++)\n"
                         "            c[a][p] = _mm256_broadcastsi128_si256(_mm_loadu_si128((const __m128i *)b[a][p]));\n",
                  nt, nt, nt, nt);
    else
        pf_printf(&kern, "    uint8_t b[%d][4][16]; /* per table: low bytes of 0..15, 16..31, high bytes of 0..15, 16..31 */\n"
                         "    for (int a = 0; a < %d; a++)\n"
                         "        for (int k = 0; k < 32; k++) {\n"
                         "            b[a][k >> 4][k & 15] = (uint8_t)(uint32_t)tab[a][k];\n"
                         "            b[a][2 + (k >> 4)][k & 15] = (uint8_t)((uint32_t)tab[a][k] >> 8);\n"
                         "        }\n"
                         "    __m256i c[%d][4];\n"
                         "    for (int a = 0; a < %d; a++)\n"
                         "        for (int p = 0; p < 4; p++)\n"
                         "            c[a][p] = _mm256_broadcastsi128_si256(_mm_loadu_si128((const __m128i *)b[a][p]));\n",
                  nt, nt, nt, nt);
    pf_printf(&kern, "    const __m256i kl = _mm256_set1_epi16(%d), kh = _mm256_set1_epi16(%d), kr = _mm256_set1_epi16(%d);\n"
                     "    const __m256i ho = _mm256_set1_epi16(%d), m15 = _mm256_set1_epi16(0x7fff);\n"
                     "    const __m256i half = _mm256_set1_epi16(%d), one = _mm256_set1_epi16(1);\n",
              (int)(int16_t)(uint16_t)T->kl, (int)T->kh, 1 << (Eo - 1), is_cos ? 0x4000 : 0, 1 << (Eo - 1));
    if (ns == 16)
        pf_put(&kern, "    const __m256i ka = _mm256_set1_epi16((short)0x8000), kb = _mm256_set1_epi16(0x0080);\n");
    else
        pf_put(&kern, "    const __m256i m31 = _mm256_set1_epi16(31), ka = _mm256_set1_epi16((short)0x8070);\n"
                      "    const __m256i kb = _mm256_set1_epi16(0x0080), kc = _mm256_set1_epi16(0x7080), kd = _mm256_set1_epi16((short)0x8000);\n");
    pf_put(&s1, "        __m256i xv = _mm256_loadu_si256((const __m256i *)(x + i));\n"
                  "        __m256i ax = _mm256_abs_epi16(xv);\n"
                  "        __m256i lo = _mm256_mullo_epi16(ax, kl);\n"
                  "        __m256i hi = _mm256_add_epi16(_mm256_mulhi_epu16(ax, kl), _mm256_mullo_epi16(ax, kh));\n");
    pf_put(&s1, is_cos ? "        hi = _mm256_add_epi16(hi, ho);\n" : "        (void)ho;\n");
    const char *ix;
    if (ns == 16) {
        pf_put(&s1, "        /* hi >> 11 = h 16 + j in the low byte (vpshufb reads bits 3..0, bit 7 clear),\n"
                      "           0x80 in the high byte; ib: hi >> 3, the same in the high byte, 0x80 in the\n"
                      "           low one */\n"
                      "        __m256i ia = _mm256_or_si256(_mm256_srli_epi16(hi, 11), ka);\n"
                      "        __m256i ib = _mm256_or_si256(_mm256_srli_epi16(hi, 3), kb);\n");
        ix = "ia, ib";
    } else {
        pf_put(&s1, "        /* j in the low byte: + 0x70 keeps bit 7 clear for j < 16 (0x8070: the high\n"
                      "           byte's bit 7 set), xor 0x80 flips that for j >= 16; the same in the\n"
                      "           high byte for the high bytes' planes */\n"
                      "        __m256i jl = _mm256_and_si256(_mm256_srli_epi16(hi, 10), m31);\n"
                      "        __m256i ia = _mm256_add_epi16(jl, ka), ib = _mm256_xor_si256(ia, kb);\n"
                      "        __m256i ja = _mm256_add_epi16(_mm256_slli_epi16(jl, 8), kc), jb = _mm256_xor_si256(ja, kd);\n");
        ix = "ia, ib, ja, jb";
    }
    pf_printf(&s1, "        __m256i t = _mm256_and_si256(_mm256_or_si256(_mm256_slli_epi16(hi, %d), _mm256_srli_epi16(lo, %d)), m15);\n",
              nb, 16 - nb);
    if (ord == 3)
        pf_printf(&s2, "        __m256i q = _mm256_add_epi16(_mm256_mulhrs_epi16(t, %s_lk(c[3], %s)), %s_lk(c[2], %s));\n"
                         "        q = _mm256_add_epi16(_mm256_mulhrs_epi16(t, q), %s_lk(c[1], %s));\n",
                  N, ix, N, ix, N, ix);
    else
        pf_printf(&s2, "        __m256i q = _mm256_add_epi16(_mm256_mulhrs_epi16(t, %s_lk(c[2], %s)), %s_lk(c[1], %s));\n",
                  N, ix, N, ix);
    pf_printf(&s2, "        __m256i p = _mm256_add_epi16(_mm256_mulhrs_epi16(t, q), %s_lk(c[0], %s));\n"
                     "        __m256i r = _mm256_add_epi16(_mm256_mulhrs_epi16(p, kr), half);\n",
              N, ix);
    pf_put(&s2, is_cos ? "        r = _mm256_sign_epi16(r, _mm256_or_si256(hi, one)); /* negated when h */\n"
                         : "        r = _mm256_sign_epi16(r, _mm256_or_si256(_mm256_xor_si256(hi, xv), one)); /* negated when h xor x < 0 */\n");
    /* pipelined as the AVX-512 loop */
    const char *cv16[7];
    int nc16 = 0;
    cv16[nc16++] = "t";
    cv16[nc16++] = "hi";
    if (!is_cos)
        cv16[nc16++] = "xv";
    cv16[nc16++] = "ia";
    cv16[nc16++] = "ib";
    if (ns != 16) {
        cv16[nc16++] = "ja";
        cv16[nc16++] = "jb";
    }
    fx_pipe_loop(&kern, "__m256i", 16, s1.s, s2.s, cv16, nc16, "_mm256_storeu_si256((__m256i *)(y + i - 16), r);", N);
    free(s1.s);
    free(s2.s);
    G->bw16 = 3;
    snprintf(G->wide_text, sizeof G->wide_text,
             "every step in 16-bit lanes; the lookups (vpermw, %s registers of %s) in the AVX-512BW "
             "loop by intrinsics (x86-64-v4); AVX2 intrinsics (x86-64-v3): each lookup %s vpshufb on byte "
             "planes merged by vpor; the default clone, scalar form: the same steps in plain C (32-bit table "
             "loads)",
             ord == 3 ? "four" : "three", ns == 16 ? "16 entries twice" : "32 entries", ns == 16 ? "two" : "four");
    const char *kv[] = {"FUNC", is_cos ? "cos" : "sin", "NAME", N, "IT", G->it, "OT", G->ot, "BODY", body.s,
                        "TABLES", tabs.s, "KERNEL", kern.s, NULL};
    pf_subst(out, pf_template("fx_sincos16t.c"), kv);
    free(body.s);
    free(tabs.s);
    free(kern.s);
}

/* The vector loops of kind 6 (sin and cos, AVX-512 and AVX2).  Four
   blocks of L lanes a pass, then single blocks, then the scalar form.
   Each line of st[] is one step, written with @ for the block's number and
   $ for its offset in x and y.  The AVX2 loops emit the reductions and
   squares of the four blocks, then their polynomials (and signs).  The
   AVX-512 loops are software pipelined over groups of four blocks: a pass
   runs the first half (up to q) of group i and the second half of group
   i - 4L, four lines (one step of the four blocks) of one half, then four
   of the other.  |x| is an unsigned min(x, -x) in the AVX-512 cos loop
   (vpabsw shares the multipliers' pipes on Zen 4), vpabsw elsewhere: on Zen
   3 (2026-12-07, the AVX2 loop alone over the 2^16 inputs shuffled, best of
   400 calls, core cycles per 16 lanes) sin 4.71 -> 4.52 and cos 4.43 ->
   4.30 with vpabsw (one instruction for two; 1, 2 and 3 blocks a pass
   slower there: sin 4.93, 4.77, 4.58, cos -, 4.51, 4.36).  Those were
   the fastest measured (2026-11-26, Zen 4, an A/B harness: best of 40
   rounds of 20 passes over the 2^16 inputs shuffled, 3 runs, ns/elem: sin
   on AVX-512 0.0771 (one block a pass) -> 0.0722 (four, interleaved step by
   step, not pipelined) -> 0.0694 (this), on AVX2 0.0844 -> 0.0768; cos on
   AVX-512 0.0680 (fx_pipe_loop, one block) -> 0.0644, on AVX2 0.0808 ->
   0.0741.  Slower, or no faster, on one ISA or both: 2, 3, 5, 6 and 8
   blocks, the other orders, the halves split after s or after p, vpabsw or
   min(x, -x) the other way round, pipelining the AVX2 loops (16 registers:
   spills)).  The same steps and values as one block a pass. */
static void tr6_put_step(pf_buf *b, const char *t, int k, int L)
{
    pf_put(b, "        ");
    for (const char *c = t; *c; c++) {
        if (*c == '@')
            pf_printf(b, "%d", k);
        else if (*c == '$') {
            if (k)
                pf_printf(b, " + %d", k * L);
        } else
            pf_printf(b, "%c", *c);
    }
    pf_put(b, "\n");
}

static void tr6_loop(pf_buf *kern, int avx2, int is_cos, int64_t kh, const char *N)
{
    const char *P = avx2 ? "_mm256" : "_mm512", *R = avx2 ? "__m256i" : "__m512i";
    const int L = avx2 ? 16 : 32, U = 4;
    char st[12][200];
    int ns = 0, split = 0;
    if (avx2)
        snprintf(st[ns++], sizeof st[0], "%s xv@ = _mm256_loadu_si256((const __m256i *)(x + i$));", R);
    else
        snprintf(st[ns++], sizeof st[0], "%s xv@ = _mm512_loadu_si512(x + i$);", R);
    if (!avx2 && is_cos)
        snprintf(st[ns++], sizeof st[0], "%s ax@ = %s_min_epu16(xv@, %s_sub_epi16(zero, xv@)); /* |x| */", R, P, P);
    else if (avx2) /* vpabsw(-32768) = 0x8000: 32768 read unsigned, as pf_fx_abs16 */
        snprintf(st[ns++], sizeof st[0], "%s ax@ = %s_abs_epi16(xv@); /* |x| as uint16_t */", R, P);
    else
        snprintf(st[ns++], sizeof st[0], "%s ax@ = %s_abs_epi16(xv@);", R, P);
    if (kh == 1)
        snprintf(st[ns++], sizeof st[0], "%s hi@ = %s_add_epi16(%s_mulhi_epu16(ax@, kl), ax@);", R, P, P);
    else if (kh == 2)
        snprintf(st[ns++], sizeof st[0], "%s hi@ = %s_add_epi16(%s_mulhi_epu16(ax@, kl), %s_add_epi16(ax@, ax@));", R, P,
                 P, P);
    else
        snprintf(st[ns++], sizeof st[0], "%s hi@ = %s_add_epi16(%s_mulhi_epu16(ax@, kl), %s_mullo_epi16(ax@, kh));", R, P,
                 P, P);
    if (is_cos) {
        snprintf(st[ns++], sizeof st[0], "%s v@ = %s_sub_epi16(one, %s_abs_epi16(hi@));", R, P, P);
        snprintf(st[ns++], sizeof st[0], "%s z@ = %s_adds_epi16(v@, v@);", R, P);
    } else
        snprintf(st[ns++], sizeof st[0], "%s z@ = %s_add_epi16(hi@, hi@);", R, P);
    snprintf(st[ns++], sizeof st[0], "%s s@ = %s_mulhrs_epi16(z@, z@);", R, P);
    split = ns;
    snprintf(st[ns++], sizeof st[0], "%s q@ = %s_sub_epi16(c3, %s_mulhi_epu16(s@, c5));", R, P, P);
    snprintf(st[ns++], sizeof st[0], "%s p@ = %s_sub_epi16(c1, %s_mulhi_epu16(s@, q@));", R, P, P);
    snprintf(st[ns++], sizeof st[0], "%s r@ = %s_mulhrs_epi16(z@, p@);", R, P);
    if (is_cos)
        ;
    else if (avx2) /* vpsignw zeroes where its sign operand is 0: hi = 0 or x = 0, where r = 0.
                      x is read again for the sign, not kept: four blocks' values fill the 16
                      ymm registers, and GCC would spill xv (measured: 3.42 -> 3.70 TSC ticks per
                      16 lanes on Zen 3).  With y == x (in place) only the blocks before this
                      one have been stored, so the read still sees x. */
        snprintf(st[ns++], sizeof st[0],
                 "r@ = _mm256_sign_epi16(_mm256_sign_epi16(r@, _mm256_xor_si256(hi@, z@)), "
                 "_mm256_loadu_si256((const __m256i *)(x + i$)));");
    else
        snprintf(st[ns++], sizeof st[0],
                 "r@ = _mm512_mask_sub_epi16(r@, _mm512_movepi16_mask(_mm512_ternarylogic_epi32(hi@, z@, xv@, 0x96)), "
                 "zero, r@);");
    if (avx2)
        snprintf(st[ns++], sizeof st[0], "_mm256_storeu_si256((__m256i *)(y + i$), r@);");
    else
        snprintf(st[ns++], sizeof st[0], "_mm512_storeu_si512(y + i$, r@);");
    if (!avx2) {
        /* AVX-512: software pipelined over groups of four blocks, a pass
           running the reduction, square and q of group i (steps 0..split)
           beside p, r, (the sign) and the store of group i - 4L (whose
           values that the second half reads are carried as c*), four lines
           of one and four of the other in turn */
        static const char *const cand[] = {"xv", "ax", "hi", "v", "z", "s", "q"};
        const char *cv[7];
        int nc = 0;
        const int sp = split + 1; /* q joins the first half */
        char bst[6][200];
        int nb = 0;
        for (int v = 0; v < 7; v++) { /* the first half's values the second reads */
            char pat[8];
            snprintf(pat, sizeof pat, "%s@", cand[v]);
            int used = 0;
            for (int j = sp; j < ns && !used; j++)
                for (const char *c = strstr(st[j], pat); c && !used; c = strstr(c + 1, pat))
                    used = c == st[j] || !(isalnum((unsigned char)c[-1]) || c[-1] == '_');
            if (used)
                cv[nc++] = cand[v];
        }
        for (int j = sp; j < ns; j++) { /* the second half on the carried values */
            char *o = bst[nb++];
            const char *c = st[j];
            size_t w = 0;
            while (*c && w + 8 < sizeof bst[0]) {
                int hit = 0;
                for (int v = 0; v < nc && !hit; v++) {
                    size_t l = strlen(cv[v]);
                    int start = c == st[j] || !(isalnum((unsigned char)c[-1]) || c[-1] == '_');
                    if (start && !strncmp(c, cv[v], l) && c[l] == '@') {
                        w += (size_t)snprintf(o + w, sizeof bst[0] - w, "c%s", cv[v]);
                        c += l;
                        hit = 1;
                    }
                }
                if (!hit) {
                    if (!strncmp(c, "i$", 2)) {
                        w += (size_t)snprintf(o + w, sizeof bst[0] - w, "i - %d$", U * L);
                        c += 2;
                    } else
                        o[w++] = *c++;
                }
            }
            o[w] = 0;
        }
        pf_printf(kern, "    size_t i = 0;\n    if (n >= %d) {\n", U * L);
        for (int k = 0; k < U; k++) {
            pf_printf(kern, "        %s", R);
            for (int v = 0; v < nc; v++)
                pf_printf(kern, "%s c%s%d", v ? "," : "", cv[v], k);
            pf_put(kern, ";\n");
        }
        pf_put(kern, "        {\n");
        for (int j = 0; j < sp; j++)
            for (int k = 0; k < U; k++) {
                pf_put(kern, "    ");
                tr6_put_step(kern, st[j], k, L);
            }
        for (int k = 0; k < U; k++)
            for (int v = 0; v < nc; v++)
                pf_printf(kern, "            c%s%d = %s%d;\n", cv[v], k, cv[v], k);
        pf_printf(kern, "        }\n        for (i = %d; i + %d <= n; i += %d) { /* group i's first half, group i - %d's "
                        "second */\n", U * L, U * L, U * L, U * L);
        for (int j = 0; j < sp || j < nb; j++) {
            for (int k = 0; k < U && j < sp; k++) {
                pf_put(kern, "    ");
                tr6_put_step(kern, st[j], k, L);
            }
            for (int k = 0; k < U && j < nb; k++) {
                pf_put(kern, "    ");
                tr6_put_step(kern, bst[j], k, L);
            }
        }
        for (int k = 0; k < U; k++)
            for (int v = 0; v < nc; v++)
                pf_printf(kern, "            c%s%d = %s%d;\n", cv[v], k, cv[v], k);
        pf_put(kern, "        }\n        {\n");
        for (int j = 0; j < nb; j++)
            for (int k = 0; k < U; k++) {
                pf_put(kern, "    ");
                tr6_put_step(kern, bst[j], k, L);
            }
        pf_put(kern, "        }\n    }\n");
        pf_printf(kern, "    for (; i + %d <= n; i += %d) {\n", L, L);
        for (int j = 0; j < ns; j++)
            tr6_put_step(kern, st[j], 0, L);
        pf_printf(kern, "    }\n    for (; i < n; i++)\n        y[i] = %s(x[i]);\n}\n#endif", N);
        return;
    }
    pf_printf(kern, "    size_t i = 0;\n    for (; i + %d <= n; i += %d) { /* %d blocks a pass, %s */\n", U * L, U * L, U,
              avx2 ? "the reductions, then the polynomials" : "step by step");
    if (avx2) {
        for (int k = 0; k < U; k++)
            for (int j = 0; j < split; j++)
                tr6_put_step(kern, st[j], k, L);
        for (int k = 0; k < U; k++)
            for (int j = split; j < ns; j++)
                tr6_put_step(kern, st[j], k, L);
    } else
        for (int j = 0; j < ns; j++)
            for (int k = 0; k < U; k++)
                tr6_put_step(kern, st[j], k, L);
    pf_printf(kern, "    }\n    for (; i + %d <= n; i += %d) {\n", L, L);
    for (int j = 0; j < ns; j++)
        tr6_put_step(kern, st[j], 0, L);
    pf_printf(kern, "    }\n    for (; i < n; i++)\n        y[i] = %s(x[i]);\n}\n#endif", N);
}

/* kind 6 (fast, see above): plain-C steps, the AVX-512BW loop and the AVX2
   loop (the same instructions on 32 and 16 lanes; AVX2 has vpsignw,
   AVX-512 a masked subtract) */
static void emit16_6(fx_gen *G, pf_buf *out, int is_cos)
{
    const fx_trig_red *T = &G->trig;
    const char *N = G->name;
    pf_buf body = {0}, kern = {0};
    const char *kl = fx_k16(G, (int16_t)(uint16_t)T->kl, "KL (as uint16_t): K = KH 2^16 + KL");
    const char *kh = fx_k16(G, T->kh, "KH");
    const char *c1 = fx_k16(G, T->pc1, "C1 = P(0) 2^Eo: p = C1 - s q 2^-16");
    const char *c3 = fx_k16(G, (int16_t)(uint16_t)T->pc3, "C3 (as uint16_t): q = C3 - s C5 2^-16");
    const char *c5 = fx_k16(G, (int16_t)(uint16_t)T->pc5, "C5 (as uint16_t)");
    pf_printf(&body, "    /* hi = floor(u 2^14) mod 2^16, u = |x| 2/pi in quarter turns */\n"
                     "    uint16_t ax = pf_fx_abs16(x); /* |x| */\n"
                     "    uint16_t hi = (uint16_t)(((uint32_t)ax * (uint16_t)%s >> 16) + (uint32_t)ax * (uint16_t)%s);\n",
              kl, kh);
    if (is_cos)
        pf_put(&body, "    /* v = 1 - |hi| (2^-14 units): cos(pi/2 u) = sin(pi/2 v); z = 2 v, t = 1 held below\n"
                      "       (vpaddsw) */\n"
                      "    int16_t v = (int16_t)(uint16_t)(0x4000u - pf_fx_abs16((int16_t)hi));\n"
                      "    int16_t z = (int16_t)(uint16_t)((uint32_t)(uint16_t)v * 2u - (uint32_t)(v == 0x4000));\n");
    else
        pf_put(&body, "    /* t = u mod 2 in [-1, 1): z = t 2^15 */\n"
                      "    int16_t z = (int16_t)(uint16_t)((uint32_t)hi << 1);\n");
    pf_printf(&body, "    /* s = t^2 2^15 in [0, 2^15] (pmulhrsw read as unsigned); p = P(s) at the output's lsb */\n"
                     "    uint16_t s = (uint16_t)(((((int32_t)z * z) >> 14) + 1) >> 1); /* z z >= 0 */\n"
                     "    uint16_t q = (uint16_t)((uint16_t)%s - (uint16_t)(((uint32_t)s * (uint16_t)%s) >> 16));\n"
                     "    int16_t p = (int16_t)(uint16_t)((uint16_t)%s - (uint16_t)(((uint32_t)s * q) >> 16));\n"
                     "    int16_t r = pf_fx_mulhrs(z, p); /* t P(t^2), rounded once */\n",
              c3, c5, c1);
    if (is_cos)
        pf_printf(&body, "    return (%s)r;", G->ot);
    else
        pf_printf(&body, "    /* negated when bits 15 and 14 of hi differ, and again when x < 0 */\n"
                         "    int16_t sg = pf_fx_sgn16((int16_t)(hi ^ (uint16_t)z ^ (uint16_t)x));\n"
                         "    return (%s)((r ^ sg) - sg);",
                  G->ot);
    const char *cond = "#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(__AVX2__)\n";
    for (int v = 0; v < 2; v++) {
        const char *P = v ? "_mm256" : "_mm512", *R = v ? "__m256i" : "__m512i";
        if (v)
            pf_printf(&kern, "\n\n/* AVX2 (x86-64-v3): the same steps on 16 lanes%s; |x| by vpabsw\n"
                             "   (measured on Zen 3, this loop alone: %s core cycles per 16 lanes, %s\n"
                             "   with min(x, -x)).  The same values. */\n%s",
                      is_cos ? "" : ", the sign by vpsignw (it zeroes where its\n   sign operand is 0: hi = 0 or x = 0, where r = 0)",
                      is_cos ? "4.30" : "4.52", is_cos ? "4.43" : "4.71", cond);
        else
            pf_printf(&kern,
                      "\n\n/* AVX-512BW: the same steps on 32 lanes, with intrinsics, so that the\n"
                      "   instructions are these whatever GCC would make of the plain C%s\n"
                      "   array form runs this loop on a CPU with x86-64-v4 (see its dispatch), the\n"
                      "   AVX2 one below on x86-64-v3; the rest of the array and the other clones use\n"
                      "   the scalar steps above.  The same values (pfmathgen sweeps the array form on\n"
                      "   its machine against the scalar one). */\n%s#include <immintrin.h>\n"
                      "extern %s %s(%s x); /* the scalar form, for the last n %% 32 */\n",
                      is_cos ? ": the" : " (the sign\n   by a masked subtract): the", cond, G->ot, N, G->it);
        pf_printf(&kern, "__attribute__((target(\"arch=x86-64-%s\"), noinline))\n"
                         "static void %s_array_%s(const %s *x, %s *y, size_t n)\n{\n",
                  v ? "v3" : "v4", N, v ? "avx2" : "bw", G->it, G->ot);
        pf_printf(&kern, "    const %s kl = %s_set1_epi16(%d), kh = %s_set1_epi16(%d);\n"
                         "    const %s c1 = %s_set1_epi16(%d), c3 = %s_set1_epi16(%d), c5 = %s_set1_epi16(%d);\n",
                  R, P, (int)(int16_t)(uint16_t)T->kl, P, (int)T->kh, R, P, T->pc1, P, (int)(int16_t)(uint16_t)T->pc3,
                  P, (int)(int16_t)(uint16_t)T->pc5);
        if (is_cos)
            pf_printf(&kern, "    const %s one = %s_set1_epi16(0x4000);\n", R, P);
        if (!v) /* min(x, -x) and the AVX-512 sin's masked subtract; AVX2 takes vpabsw */
            pf_printf(&kern, "    const %s zero = %s_setzero_si512();\n", R, P);
        if (T->kh == 1 || T->kh == 2)
            pf_put(&kern, "    (void)kh;\n");
        /* the chain of one block (some 20 cycles of multiplies) is longer than
           the CPU overlaps over blocks: four blocks a pass, software pipelined
           on AVX-512 (tr6_loop) */
        tr6_loop(&kern, v, is_cos, T->kh, N);
    }
    G->bw16 = 3;
    snprintf(G->wide_text, sizeof G->wide_text,
             "every step in 16-bit lanes; the AVX-512BW (x86-64-v4) and AVX2 (x86-64-v3) loops by intrinsics "
             "(pmulhuw, pmulhrsw), %s vector instructions per vector%s; the default clone, scalar form: the same "
             "steps in plain C",
             is_cos ? "13 (AVX-512: 14, |x| as min(x, -x) unsigned, as vpabsw shares the multipliers' pipes on Zen 4)"
                    : "14 (the sign: AVX2 two vpsignw, AVX-512 a masked subtract)",
             ", four vectors a pass (AVX-512: software pipelined over groups of four)");
    const char *kv[] = {"FUNC", is_cos ? "cos" : "sin", "NAME", N, "IT", G->it, "OT", G->ot, "BODY", body.s,
                        "KERNEL", kern.s, NULL};
    pf_subst(out, pf_template("fx_sincos16p.c"), kv);
    free(body.s);
    free(kern.s);
}

static void emit16(fx_gen *G, pf_buf *b, int is_cos)
{
    if (G->kind == 6) {
        emit16_6(G, b, is_cos);
        return;
    }
    if (G->kind == 4) {
        emit16_4(G, b, is_cos);
        return;
    }
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
