/* log and log2 in fixed point (see gen/templates/fx_log.c.in).
 *
 * x = X 2^-Ei with X > 0 = 2^n (1 + t), n = bitlen(X) - 1, so t is X's bits
 * below the leading one: exact in 2^-(W-1) units for any 32-bit X.  With
 * e = n - Ei, f(x) = e K + P(t) (K = ln 2 for log, 1 for log2), formed in
 * 64 bits at exponent Ez (K rounded there: |e| 2^-(Ez+1) for log) and
 * rounded once to the output. */
#include "fixed_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void g_log1p(mpfr_t y, const mpfr_t t, const void *ctx)
{
    (void)ctx;
    mpfr_log1p(y, t, MPFR_RNDN);
}

static void g_log2_1p(mpfr_t y, const mpfr_t t, const void *ctx)
{
    (void)ctx;
    mpfr_t a, l;
    mpfr_inits2(mpfr_get_prec(y) + 64, a, l, (mpfr_ptr)0);
    mpfr_log1p(a, t, MPFR_RNDN);
    mpfr_const_log2(l, MPFR_RNDN);
    mpfr_div(y, a, l, MPFR_RNDN);
    mpfr_clears(a, l, (mpfr_ptr)0);
}


/* ---- 16-bit lanes: the table kernel (kind 1) ----
 *
 * An unsigned input of at most 16 bits is x = 2^(15 - lz) (1 + t) with
 * lz = 16 - bitlen(x) (16 for x = 0): u = x << lz has its leading one at
 * bit 15, j = t's top jb bits picks one of 2^jb segments of [0, 1) and f =
 * t's other 15 - jb bits (at 2^-16) the place in it, all exact: jb = 3
 * (8 segments) where the variant's target allows it (and S 2^4 fits a
 * word), else 4 (16), else 5 (32: one vpermw of 32 16-bit entries).  F(t) = log(1 + t) or log2(1 + t) is a
 * line per segment at 2^-Ef, V[j] + floor(S[j] f 2^-16), and e K (e = 15 -
 * lz - Ei) = TH[lz] 2^-Eo + TL[lz] 2^-Ef; the result is TH[lz] + round((V[j]
 * + floor(S[j] f 2^-16) + TL[lz]) 2^-(Ef - Eo)), every step a 16-bit word,
 * the lookups one vpermw each (AVX-512), or vpshufb on the tables' byte
 * planes (AVX2: two per plane for 32 entries, one for 16; TH and TL there
 * by multiplies where pfmathgen finds an exact form).  Where the output's
 * lsb allows (fast, log2), TL is left out: TH alone, rounded at 2^-Eo.
 * S[j] comes from the chord through MPFR's values at the segment's ends
 * (searched +-2 around it), V[j] centres the segment's error over its
 * 2^(15-jb) points (a discrete minimax of the integer step, the floor
 * included).  The bound is taken over every input by running these integer
 * steps (tab_y) against MPFR. */

static int64_t floordiv(int64_t a, int64_t b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

/* the emitted steps for one input; 0 if a word would overflow.  *pre is the
   value before the final rounding, in output lsb */
static int tab_y(const fx_log_red *L, uint32_t x, int32_t *y, double *pre)
{
    int lz = 16 - fx_bitlen(x);
    uint32_t u = (x << lz) & 0xffffu;
    int jb = L->tjb;
    unsigned j = (u >> (15 - jb)) & ((1u << jb) - 1);
    uint32_t f = (u << (jb + 1)) & 0xffffu;
    int32_t w = L->tv[j] + (int32_t)(((uint32_t)L->ts[j] * f) >> 16) + L->tl[lz];
    if (w < -32768 || w > 32767)
        return 0;
    int32_t r = (int32_t)floordiv((int64_t)floordiv((int64_t)w * (1 << (15 - L->td)), 1 << 14) + 1, 2);
    *y = L->th[lz] + r;
    *pre = (double)L->th[lz] + ldexp((double)w, -L->td);
    return *y >= -32768 && *y <= 32767;
}

/* F(t) 2^Ef at t = i 2^-15 for i in [0, 2^15], from MPFR */
/* g[i] = log(1 + i 2^-15) (log2: / ln2) 2^ef, i in [0, 2^15], MPFR at 128
   bits rounded to long double.  prep_tab asks for the same grid at several
   ef, each up to six times: the logarithms are computed once per base
   (kept; generation runs on one thread) and scaled by 2^ef, which is exact
   and commutes with the rounding (no value is subnormal or overflows), so
   g is what the per-call computation gave.  -1: out of memory. */
static int tab_grid(long double *g, int base2, int ef)
{
    static long double *base[2];
    if (!base[base2]) {
        long double *b = malloc(sizeof *b * 32769);
        if (!b)
            return -1;
        mpfr_t t, l;
        mpfr_inits2(128, t, l, (mpfr_ptr)0);
        mpfr_const_log2(l, MPFR_RNDN);
        for (int i = 0; i <= 32768; i++) {
            mpfr_set_si(t, i, MPFR_RNDN);
            mpfr_div_2ui(t, t, 15, MPFR_RNDN);
            mpfr_log1p(t, t, MPFR_RNDN);
            if (base2)
                mpfr_div(t, t, l, MPFR_RNDN);
            b[i] = mpfr_get_ld(t, MPFR_RNDN);
        }
        mpfr_clears(t, l, (mpfr_ptr)0);
        base[base2] = b;
    }
    for (int i = 0; i <= 32768; i++)
        g[i] = ldexpl(base[base2][i], ef);
    return 0;
}

/* log(x 2^-Ei) (log2: / ln2) 2^Eo for every stored x in [1, 65535] of an
   unsigned 16-bit input, MPFR at 128 bits rounded to double: what the table
   and Horner kernel searches measure each candidate against.  prep_tab
   tries up to 30 tables, each over every input, so the 65535 logarithms
   are computed once per (Ei, Eo, base2) and kept (generation runs on one
   thread); the values are those each search computed for itself before.
   NULL: out of memory. */
static const double *log_refs(int Ei, int Eo, int base2)
{
    static double *ref;
    static int kei, keo, kb;
    if (ref && kei == Ei && keo == Eo && kb == base2)
        return ref;
    double *r = ref ? ref : malloc(sizeof *r * 65536);
    ref = NULL;
    if (!r)
        return NULL;
    mpfr_t xr, lr;
    mpfr_inits2(128, xr, lr, (mpfr_ptr)0);
    mpfr_const_log2(lr, MPFR_RNDN);
    r[0] = -INFINITY;
    for (uint32_t x = 1; x < 65536; x++) {
        mpfr_set_ui(xr, x, MPFR_RNDN);
        mpfr_mul_2si(xr, xr, -Ei, MPFR_RNDN);
        mpfr_log(xr, xr, MPFR_RNDN);
        if (base2)
            mpfr_div(xr, xr, lr, MPFR_RNDN);
        mpfr_mul_2si(xr, xr, Eo, MPFR_RNDN);
        r[x] = mpfr_get_d(xr, MPFR_RNDN);
    }
    mpfr_clears(xr, lr, (mpfr_ptr)0);
    ref = r, kei = Ei, keo = Eo, kb = base2;
    return ref;
}

/* tables for Ef, TL or not; then the bound over every input.  0: ok */
static int tab_try(fx_gen *G, int base2, int ef, int tlo, int jb, const long double *g)
{
    fx_log_red *L = &G->log;
    int Ei = G->in.exp, Eo = G->out.exp;
    int64_t mn = pf_type_min_stored(&G->out), mx = pf_type_max_stored(&G->out);
    L->td = ef - Eo;
    L->tlo = tlo;
    L->tseg = 0;
    L->tjb = jb;
    int np = 1 << (15 - jb); /* points per segment */
    for (int j = 0; j < 1 << jb; j++) {
        const long double *gj = g + j * np;
        int64_t s0 = (int64_t)llroundl(gj[np] - gj[0]);
        double best = INFINITY;
        for (int64_t s = s0 - 2; s <= s0 + 2; s++) {
            if (s < 0 || s > 32767)
                continue;
            long double lo = INFINITY, hi = -INFINITY;
            for (int i = 0; i < np; i++) {
                long double r = (long double)(((uint64_t)s * ((uint64_t)i << (jb + 1))) >> 16) - gj[i];
                lo = r < lo ? r : lo;
                hi = r > hi ? r : hi;
            }
            int64_t v = (int64_t)llroundl(-(lo + hi) / 2);
            /* x = 0 reads V[0] alone (u = 0): without TL (whose TL[16] = -V[0]
               cancels it), V[0] must round to 0 at the output, |V[0]| < 2^(td-1) */
            int64_t vh = (int64_t)1 << (L->td - 1);
            if (j == 0 && !tlo)
                v = v < -vh ? -vh : v > vh - 1 ? vh - 1 : v;
            double e = (double)fmaxl(fabsl(v + lo), fabsl(v + hi));
            if (e < best && v >= -32768 && v <= 32767) {
                best = e;
                L->ts[j] = (int32_t)s;
                L->tv[j] = (int32_t)v;
            }
        }
        if (best == INFINITY)
            return -1;
        L->tseg = best > L->tseg ? best : L->tseg;
    }
    /* e K = TH 2^-Eo + TL 2^-Ef, from MPFR */
    mpfr_t a, b;
    mpfr_inits2(256, a, b, (mpfr_ptr)0);
    memset(L->th, 0, sizeof L->th);
    memset(L->tl, 0, sizeof L->tl);
    for (int lz = 0; lz < 16; lz++) {
        long e = 15 - lz - Ei;
        if (base2)
            mpfr_set_si(a, e, MPFR_RNDN);
        else {
            mpfr_const_log2(a, MPFR_RNDN);
            mpfr_mul_si(a, a, e, MPFR_RNDN);
        }
        mpfr_mul_2si(a, a, Eo, MPFR_RNDN);
        mpfr_rint(b, a, MPFR_RNDN);
        double th = mpfr_get_d(b, MPFR_RNDN);
        if (th < -32768 || th > 32767) {
            mpfr_clears(a, b, (mpfr_ptr)0);
            return -1;
        }
        L->th[lz] = (int32_t)th;
        if (tlo) {
            mpfr_sub(a, a, b, MPFR_RNDN);
            mpfr_mul_2si(a, a, L->td, MPFR_RNDN);
            mpfr_rint(a, a, MPFR_RNDN);
            L->tl[lz] = (int32_t)mpfr_get_si(a, MPFR_RNDN);
        }
    }
    mpfr_clears(a, b, (mpfr_ptr)0);
    /* x = 0: u = 0, j = 0, f = 0; the result must be the most negative */
    L->th[16] = (int32_t)mn;
    if (tlo)
        L->tl[16] = -L->tv[0];
    /* the bound: every input, against MPFR */
    const double *refs = log_refs(Ei, Eo, base2);
    if (!refs)
        return -1;
    double worst = 0;
    int ok = 1;
    int64_t imax = pf_type_max_stored(&G->in);
    for (int64_t x = 0; x <= imax && ok; x++) {
        int32_t y;
        double pre;
        if (!tab_y(L, (uint32_t)x, &y, &pre)) {
            ok = 0;
            break;
        }
        if (x == 0) {
            ok = y == mn;
            continue;
        }
        double ref = refs[x];
        if (ref < (double)mn || ref > (double)mx || y < mn || y > mx) {
            ok = 0;
            break;
        }
        double e = fabs(pre - ref);
        worst = e > worst ? e : worst;
    }
    if (!ok)
        return -1;
    L->terr = worst * (1 + 1e-12) + 1e-12; /* MPFR to 128 bits, rounded to double: far below */
    return fx_within(G, 0, L->terr * fx_lsb(G)) ? 0 : -1;
}

/* 1: every S[j] 2^(jb+1) fits an unsigned word, so the AVX-512 and AVX2
   loops take pmulhuw(S 2^(jb+1), u) (AVX2: S 2^jb and its u) without
   forming f (see emit_tab) */
static int tab_fs(const fx_log_red *L)
{
    int fs = 1;
    for (int j = 0; j < 1 << L->tjb; j++)
        fs &= L->ts[j] >= 0 && ((int64_t)L->ts[j] << (L->tjb + 1)) <= 65535;
    return fs;
}

/* 0: the table kernel is set up and bounded; -2: not for this type pair */
static int prep_tab(fx_gen *G, int base2)
{
    if (G->in.is_signed || G->in.storage_bits != 16 || G->out.storage_bits != 16 || !G->out.is_signed ||
        G->out.exp < 0 || G->out.exp > 14 || G->in.exp < -16 || G->in.exp > 31)
        return -2;
    long double *g = malloc(sizeof *g * 32769);
    if (!g)
        return -2;
    int rc = -2;
    /* 8 segments first (on AVX2 one vpshufb per table: its 16 bytes hold
       the 8 words' low and high bytes; only where S 2^4 fits a word, so
       that no f is formed), then 16 (one vpshufb per byte plane), then 32
       (two); TL only for log (log2's e is exact), and first without it
       (one lookup fewer) */
    for (int jb = 3; jb <= 5 && rc != 0; jb++)
        for (int tlo = 0; tlo <= !base2 && rc != 0; tlo++)
            for (int ef = 15; ef > G->out.exp && rc != 0; ef--) {
                if (tab_grid(g, base2, ef) == 0 && tab_try(G, base2, ef, tlo, jb, g) == 0 &&
                    (jb > 3 || tab_fs(&G->log)))
                    rc = 0;
            }
    free(g);
    return rc;
}

/* The AVX2 loop's plan: 0 if it cannot give the scalar form's values.
   There, x = 0 makes both TH and TL lookups 0 (their index has bit 7 set),
   so the result is TH' + round(w 2^-td) with TH' the stored -32768 and w =
   V[0] (no TL: tab_try has checked that it rounds to 0) or, with TL, 0: V
   is stored less V[0] and TL plus V[0], the same sums for x > 0.  That
   needs the most negative output -32768.
   *tharith: TH[lz] = (15 - lz - Ei) 2^Eo for every lz < 16 (log2) and the
   most negative output c 2^Eo with -127 - Ei <= c <= -Ei: TH = max(ex -
   127 - Ei, c) << Eo from the float's exponent ex (0 for x = 0), no lookup
   (e = ex - 127 - Ei >= -Ei for x > 0, -127 - Ei for x = 0).
   *tlbyte: every TL[lz] + V[0] fits a signed byte (one plane). */
static int tab_avx2(const fx_gen *G, int *tharith, int *tlbyte)
{
    const fx_log_red *L = &G->log;
    int Ei = G->in.exp, Eo = G->out.exp;
    int64_t mn = pf_type_min_stored(&G->out);
    *tharith = !L->tlo && mn % ((int64_t)1 << Eo) == 0;
    for (int lz = 0; lz < 16 && *tharith; lz++)
        *tharith = L->th[lz] == (int64_t)(15 - lz - Ei) * ((int64_t)1 << Eo) && mn / ((int64_t)1 << Eo) <= -Ei &&
                   mn / ((int64_t)1 << Eo) >= -127 - Ei;
    *tlbyte = 1;
    for (int lz = 0; lz < 16; lz++)
        *tlbyte &= L->tl[lz] + L->tv[0] >= -128 && L->tl[lz] + L->tv[0] <= 127;
    return *tharith || mn == -32768;
}

/* round(a b 2^-15), ties up: pmulhrsw */
static int32_t mulhrs16(int32_t a, int32_t b) { return (int32_t)floordiv(floordiv((int64_t)a * b, 1 << 14) + 1, 2); }
static int32_t wrap16(int64_t v) { return (int32_t)(int16_t)(uint16_t)((uint64_t)v & 0xffffu); }

/* The AVX2 loop's TH without a lookup where it is not e 2^Eo: TH[lz] =
   A e' + round(e' K 2^-15) - B (16-bit words, mod 2^16) for e' = e + s, e
   = 15 - lz - Ei, lz < 16: one vpmullw and one vpmulhrsw.  B >= 0 goes
   into the V planes as V - B 2^td (round((w - B 2^td) 2^-td) = round(w
   2^-td) - B, exact), so the final sum TH + round(w 2^-td) is unchanged;
   e' = max(ex - c0, c) with x = 0 clamped to c, whose A c + round(c K
   2^-15) - B is at most -32768, so a saturating add (vpaddsw) gives -32768
   there (w = V[0] rounds to 0 without TL, w = 0 with it).  Searched over A near the slope,
   K near the rest of it and the shift s (least |s| first); 0: none. */
/* the TL variant (exact log) too, where tab_tlq finds nothing: 1 (see the
   AVX2 loop's timings) */
#define THMUL_TL 1

/* With TL (exact log): TH[lz] 2^td + TL[lz] = q e for one integer q and
   every lz < 16 (e ln2 rounded at 2^-(Eo+td), exact multiples while |e| is
   small), so with q = a 2^td + b the result TH + round((w + TL) 2^-td) is
   a e' + round((w - q s + b e') 2^-td) for e' = e + s: two vpmullw, no
   lookup (V - q s stored).  x = 0: e' = max(ex - c0, c) = c, where the
   saturating add of a c and round((V[0] - q s + b c) 2^-td) (16-bit
   words) is at most -32768.  Searched over the shift s and c; 0: none. */
static int tab_tlq(const fx_gen *G, int *pa, int *pb, int *pq, int *ps, int *pc0, int *pc)
{
    const fx_log_red *L = &G->log;
    int Ei = G->in.exp, td = L->td, ns = 1 << L->tjb;
    if (!L->tlo || pf_type_min_stored(&G->out) != -32768)
        return 0;
    int64_t q = 0;
    int have = 0;
    for (int lz = 0; lz < 16; lz++) {
        int64_t e = 15 - lz - Ei, v = (int64_t)L->th[lz] * (1 << td) + L->tl[lz];
        if (e == 0) {
            if (v != 0)
                return 0;
            continue;
        }
        if (v % e)
            return 0;
        if (have && v / e != q)
            return 0;
        q = v / e;
        have = 1;
    }
    if (!have)
        return 0;
    int64_t a = floordiv(q, 1 << td), b = q - a * (1 << td);
    int64_t wlo = INT64_MAX, whi = INT64_MIN;
    for (int j = 0; j < ns; j++) {
        wlo = L->tv[j] < wlo ? L->tv[j] : wlo;
        int64_t h = L->tv[j] + (((int64_t)L->ts[j] * 65535) >> 16);
        whi = h > whi ? h : whi;
    }
    for (int sa = 0; sa <= 4; sa++)
        for (int sg = 0; sg < 2; sg++) {
            int sh = sg ? -sa : sa;
            if (sg && !sa)
                continue;
            int64_t elo = -Ei + sh, ehi = 15 - Ei + sh; /* e' over x > 0 */
            int64_t b1 = b * elo < b * ehi ? b * elo : b * ehi, b2 = b * elo < b * ehi ? b * ehi : b * elo;
            if (wlo - q * sh + b1 < -32768 || whi - q * sh + b2 > 32767 || a * elo < -32768 || a * ehi > 32767 ||
                a * elo > 32767 || a * ehi < -32768)
                continue;
            int c0 = 127 + Ei - sh;
            for (int c = -c0; c <= elo - 1; c++) {
                int32_t t0 = wrap16(a * c), m0 = mulhrs16(wrap16(L->tv[0] - q * sh + b * c), 1 << (15 - td));
                if (t0 + m0 <= -32768) {
                    *pa = (int)a;
                    *pb = (int)b;
                    *pq = (int)q;
                    *ps = sh;
                    *pc0 = c0;
                    *pc = c;
                    return 1;
                }
            }
        }
    return 0;
}

static int tab_thmul(const fx_gen *G, int *pa, int *pk, int *pc0, int *pc, int *pb)
{
    const fx_log_red *L = &G->log;
    int Ei = G->in.exp, td = L->td, ns = 1 << L->tjb;
    if (pf_type_min_stored(&G->out) != -32768)
        return 0;
    /* the range of w over every input (V, S, TL as the scalar form adds them) */
    int64_t wlo = INT64_MAX, whi = INT64_MIN, tlo = 0, thi = 0;
    for (int j = 0; j < ns; j++) {
        wlo = L->tv[j] < wlo ? L->tv[j] : wlo;
        int64_t h = L->tv[j] + (((int64_t)L->ts[j] * 65535) >> 16);
        whi = h > whi ? h : whi;
    }
    for (int lz = 0; L->tlo && lz < 16; lz++) {
        tlo = L->tl[lz] < tlo ? L->tl[lz] : tlo;
        thi = L->tl[lz] > thi ? L->tl[lz] : thi;
    }
    wlo += tlo;
    whi += thi;
    double slope = (double)(L->th[0] - L->th[15]) / 15;
    for (int sa = 0; sa <= 120; sa++)
        for (int sg = 0; sg < 2; sg++) {
            int s = sg ? -sa : sa;
            if (sg && !sa)
                continue;
            for (int a = (int)floor(slope) - 1; a <= (int)floor(slope) + 2; a++) {
                if (a < -32768 || a > 32767)
                    continue;
                int kc = (int)lround((slope - a) * 32768);
                for (int k = kc - 2500; k <= kc + 2500; k++) { /* the slope from the ends: +-1/15 */
                    if (k < -32768 || k > 32767)
                        continue;
                    int64_t bb = 0;
                    int ok = 1;
                    for (int lz = 0; lz < 16 && ok; lz++) {
                        int64_t e1 = 15 - lz - Ei + s;
                        if (e1 < -32768 || e1 > 32767) {
                            ok = 0;
                            break;
                        }
                        int64_t b = wrap16(wrap16(a * e1 + mulhrs16((int32_t)e1, k)) - (int64_t)L->th[lz]);
                        if (lz == 0)
                            bb = b;
                        ok = b == bb;
                    }
                    /* B >= 0, and w - B 2^td in an int16_t */
                    if (!ok || bb < 0 || wlo - (bb << td) < -32768 || whi - (bb << td) > 32767)
                        continue;
                    int c0 = 127 + Ei - s;
                    for (int c = -c0; c <= s - Ei - 1; c++) /* x = 0: ex - c0 = -c0 */
                        if (c >= -32768 && wrap16((int64_t)a * c + mulhrs16(c, k)) - bb <= -32768) {
                            *pa = a;
                            *pk = k;
                            *pc0 = c0;
                            *pc = c;
                            *pb = (int)bb;
                            return 1;
                        }
                }
            }
        }
    return 0;
}

static void tab_texts(fx_gen *G, int base2)
{
    const fx_log_red *L = &G->log;
    int Ei = G->in.exp, Eo = G->out.exp, Ef = Eo + L->td, jb = L->tjb, ns = 1 << jb;
    const char *fn = base2 ? "log2" : "log";
    int tha, tlb, avx2 = tab_avx2(G, &tha, &tlb), thm = 0, t6[6];
    int tlq = avx2 && tab_tlq(G, t6, t6 + 1, t6 + 2, t6 + 3, t6 + 4, t6 + 5);
    if (avx2 && !tha && !tlq && (THMUL_TL || !L->tlo))
        thm = tab_thmul(G, t6, t6 + 1, t6 + 2, t6 + 3, t6 + 4);
    snprintf(G->red_text, sizeof G->red_text,
             "x = 2^e (1 + t), e = 15 - lz - %d with lz = 16 - bitlen(x) (AVX-512: a leading-zero count of x 2^16 + "
             "2^15, vplzcntd;%s else branch-free stages), u = x << lz (vpsllvw), t in [0, 1) the 15 bits below u's "
             "leading one (exact): segment j = t's top %d bits, f = the other %d (2^-16); %s(x) = e%s + F(t), F(t) = "
             "%s; x = 0 -> lz = 16, u = 0, TH[16] = %lld (most negative)",
             Ei, avx2 ? " AVX2: the exponent and the fraction bits of x converted to float, exact;" : "", jb, 15 - jb,
             fn, base2 ? "" : " ln2", base2 ? "log2(1 + t)" : "log(1 + t)", (long long)pf_type_min_stored(&G->out));
    snprintf(G->alt_domain, sizeof G->alt_domain, "%s on t in [0, 1]: %d segments [j/%d, (j+1)/%d)",
             base2 ? "log2(1+t)" : "log(1+t)", ns, ns, ns);
    snprintf(G->alt_order, sizeof G->alt_order,
             "1 per segment (a line: V[j] + S[j] f), %d-entry tables V, S; TH%s by lz; int16_t words: 16-bit lanes",
             ns, L->tlo ? ", TL" : "");
    snprintf(G->alt_method, sizeof G->alt_method,
             "per segment: S[j] the chord's rise at 2^-%d through MPFR's F(j/%d), F((j+1)/%d) (128 bits), searched "
             "+-2 for the least error; V[j] centres the error of V[j] + floor(S[j] f 2^-16) - F(t) 2^%d over the "
             "segment's %d inputs (discrete minimax of the integer step, floor included); TH[lz] = round(e%s 2^%d)%s "
             "(MPFR, to nearest)",
             Ef, ns, ns, Ef, 1 << (15 - jb), base2 ? "" : " ln2", Eo,
             L->tlo ? ", TL[lz] = round((e ln2 2^Eo - TH[lz]) 2^d)" : "");
    snprintf(G->alt_con, sizeof G->alt_con, "none per segment (C0 only up to the tables' rounding); x = 0 gives the most negative output");
    snprintf(G->alt_formats, sizeof G->alt_formats,
             "V, S, TH%s int16_t; w = V[j] + pmulhuw(S[j], f)%s at 2^-%d (int16_t); result TH[lz] + round(w 2^-%d), "
             "the rounding multiply-high by 2^%d (pmulhrsw), ties up",
             L->tlo ? ", TL" : "", L->tlo ? " + TL[lz]" : "", Ef, L->td, 15 - L->td);
    snprintf(G->alt_poly, sizeof G->alt_poly,
             "segment lines within %.4f 2^-%d (%.4f LSB) of F(t) at every segment input (floor included)", L->tseg,
             Ef, ldexp(L->tseg, -L->td));
    if (avx2)
        snprintf(G->wide_text, sizeof G->wide_text,
                 "16-bit words throughout; x86-64-v4: lookups (vpermw), leading-zero count (vplzcntd on x 2^16 + "
                 "2^15, packed to words), per-element shift (vpsllvw) by AVX-512BW/CD intrinsics; x86-64-v3: "
                 "lookups by vpshufb on byte planes, lz and t from x's float (vcvtdq2ps on even and odd words)%s; "
                 "other clones, scalar form: plain C",
                 tha   ? ", TH = max(ex - c, lo) << Eo from its exponent"
                 : tlq ? ", TH and TL from its exponent by a vpmullw each (TH 2^td + TL = q e)"
                 : thm ? ", TH from its exponent by a vpmullw and a vpmulhrsw (searched)" : "");
    else
        snprintf(G->wide_text, sizeof G->wide_text,
                 "16-bit words throughout; lookups (vpermw), leading-zero count (vplzcntd on x 2^16 + 2^15, packed to "
                 "words) and the per-element shift (vpsllvw) by AVX-512BW/CD intrinsics (x86-64-v4); other clones, "
                 "scalar form: the same steps in plain C");
    snprintf(G->alt_arith, sizeof G->alt_arith,
             "integers only (%s no <math.h>); the segment product floors (pmulhuw: in the bound), "
             "the result is rounded once to nearest, ties up (pmulhrsw); bit-identical under any compiler flags",
             avx2 ? "no floating-point arithmetic: the AVX2 loop converts x to float, exact, and reads its bits;"
                  : "no floating point,");
    snprintf(G->bound_note, sizeof G->bound_note,
             "taken over every input from the emitted integer steps (the table kernel) against MPFR");
}

static void tab_table(pf_buf *b, const char *name, const char *suf, const int32_t *v, int n, const char *what)
{
    pf_printf(b, "/* %s */\nstatic const int32_t %s_%s[%d] = {", what, name, suf, n);
    for (int i = 0; i < n; i++)
        pf_printf(b, "%s%d,", i % 8 ? " " : "\n    ", (int)v[i]);
    pf_put(b, "\n};\n");
}

static void emit_tab(fx_gen *G, pf_buf *body, pf_buf *tabs, pf_buf *kern, int base2)
{
    const fx_log_red *L = &G->log;
    const char *N = G->name;
    int Ei = G->in.exp, Eo = G->out.exp, Ef = Eo + L->td, jb = L->tjb, ns = 1 << jb;
    char w[160];
    const char *fn = base2 ? "log2" : "log";
    snprintf(w, sizeof w, "V[j]: the segment line's value at its start, F = %s(1 + t) at 2^-%d", fn, Ef);
    tab_table(tabs, N, "tv", L->tv, ns, w);
    snprintf(w, sizeof w, "S[j]: the segment line's rise across the segment, at 2^-%d", Ef);
    tab_table(tabs, N, "ts", L->ts, ns, w);
    snprintf(w, sizeof w, "TH[lz] = round(e%s 2^%d), e = 15 - lz - %d (MPFR); TH[16] (x = 0): the most negative",
             base2 ? "" : " ln2", Eo, Ei);
    tab_table(tabs, N, "th", L->th, 32, w);
    if (L->tlo) {
        snprintf(w, sizeof w, "TL[lz] = round((e ln2 2^%d - TH[lz]) 2^%d) (MPFR); TL[16] = -V[0] (x = 0)", Eo, L->td);
        tab_table(tabs, N, "tl", L->tl, 32, w);
    }
    snprintf(w, sizeof w, "2^%d: round(w / 2^%d), a rounding multiply-high", 15 - L->td, L->td);
    const char *kr = fx_k16(G, (int64_t)1 << (15 - L->td), w);
    pf_put(body, "    /* x = 2^(15 - lz) (1 + t), lz = 16 - bitlen(x) (16 for x = 0) */\n"
                 "    int lz = 16 - pf_fx_bitlen(x);\n"
                 "    uint16_t u = (uint16_t)((uint32_t)x << lz); /* leading one at bit 15; 0 for x = 0 */\n");
    pf_printf(body, "    unsigned j = (u >> %d) & %du;               /* segment: t's top %d bits */\n"
                    "    uint16_t f = (uint16_t)(u << %d);            /* t's other %d bits: the place in it, 2^-16 */\n",
              15 - jb, ns - 1, jb, jb + 1, 15 - jb);
    pf_printf(body, "    /* F(t) on segment j, at 2^-%d: V[j] + floor(S[j] f 2^-16) (pmulhuw)%s */\n", Ef,
              L->tlo ? ", plus e ln2's low part" : "");
    pf_printf(body, "    int16_t w = (int16_t)(%s_tv[j] + (int32_t)(((uint32_t)%s_ts[j] * f) >> 16));\n", N, N);
    if (L->tlo)
        pf_printf(body, "    w = (int16_t)(w + %s_tl[lz]);\n", N);
    pf_printf(body, "    /* e%s at 2^-%d plus w rounded once to it */\n", base2 ? "" : " ln2", Eo);
    pf_printf(body, "    return (%s)(%s_th[lz] + pf_fx_mulhrs(w, %s));", G->ot, N, kr);
    const char *cond = "#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(__AVX2__)\n";
    pf_printf(kern,
              "\n\n/* AVX-512BW/CD: the same steps on 32 lanes, with intrinsics, as GCC does not\n"
              "   turn the table lookups into vpermw nor a 16-bit leading-zero count into\n"
              "   vplzcntd: the array form runs this loop on a CPU with x86-64-v4 (see its\n"
              "   dispatch), the rest of the array and the other clones use the scalar steps\n"
              "   above.  x 2^16 + 2^15 in 32-bit lanes has lz leading zeros (16 for x = 0);\n"
              "   unpack and pack keep the lanes' order.  The same values (pfmathgen sweeps\n"
              "   the array form on its machine against the scalar one). */\n%s#include <immintrin.h>\n"
              "extern %s %s(%s x); /* the scalar form, for the last n %% 32 (or 16) */\n"
              "/* 32 table entries as 16-bit words, for vpermw */\n"
              "__attribute__((target(\"arch=x86-64-v4\"))) static inline __m512i %s_w16(const int32_t *t)\n{\n"
              "    return _mm512_inserti64x4(_mm512_castsi256_si512(_mm512_cvtepi32_epi16(_mm512_loadu_si512(t))),\n"
              "                              _mm512_cvtepi32_epi16(_mm512_loadu_si512(t + 16)), 1);\n}\n",
              cond, G->ot, N, G->it, N);
    /* fs: no f.  pmulhuw(S 2^(jb+1), u) = S (2^jb + j) + floor(S f 2^-16)
       exactly (u = 2^15 + j 2^(15-jb) + f 2^-(jb+1), and S 2^(jb+1) fits
       an unsigned word), so V - S (2^jb + j) is stored and f is not formed
       (one shift fewer); the index u >> (15 - jb) is 2^jb + j. */
    int fs = tab_fs(L);
    if (jb == 4 && !fs)
        pf_printf(kern,
                  "/* 16 entries as 16-bit words, twice (vpermw reads 5 index bits: u >> 11 is 16 + j) */\n"
                  "__attribute__((target(\"arch=x86-64-v4\"))) static inline __m512i %s_w16x2(const int32_t *t)\n{\n"
                  "    return _mm512_broadcast_i64x4(_mm512_cvtepi32_epi16(_mm512_loadu_si512(t)));\n}\n",
                  N);
    pf_printf(kern,
              "__attribute__((target(\"arch=x86-64-v4\"), noinline))\n"
              "static void %s_array_bw(const %s *x, %s *y, size_t n)\n{\n",
              N, G->it, G->ot);
    if (fs) {
        pf_printf(kern,
                  "    /* pmulhuw(S 2^%d, u) = S (%d + j) + floor(S f 2^-16), exact: V - S (%d + j) is\n"
                  "       stored (words, mod 2^16), and f is not formed */\n"
                  "    int32_t v2[32], s2[32]%s;\n"
                  "    for (int k = 0; k < 32; k++) {\n"
                  "        v2[k] = %s_tv[k & %d] - %s_ts[k & %d] * (%d + (k & %d));\n"
                  "        s2[k] = %s_ts[k & %d] * %d;\n",
                  jb + 1, ns, ns, jb <= 4 ? "" : ", h2[32]", N, ns - 1, N, ns - 1, ns, ns - 1, N, ns - 1, 2 * ns);
        if (jb == 5)
            pf_printf(kern, "        h2[k] = %s_th[k];\n", N);
        pf_put(kern, "    }\n");
        if (jb <= 4)
            pf_printf(kern, "    v2[0] = %s_tv[0]; /* index 0 (u = 0): x = 0 alone */\n"
                            "    const __m512i tv = %s_w16(v2), ts = %s_w16(s2), th = %s_w16(%s_th);\n",
                      N, N, N, N, N);
        else {
            /* x = 0 (u = 0) reads index 0, segment 0's V - 2^jb S: TH[16]
               takes the difference of the two rounded w (mod 2^16), so the
               plain add gives the scalar form's value */
            int32_t kq = 1 << (15 - L->td), t16 = L->tlo ? L->tl[16] : 0;
            int32_t wo = wrap16((int64_t)L->tv[0] + t16), wn = wrap16((int64_t)wrap16((int64_t)L->tv[0] - (int64_t)L->ts[0] * ns) + t16);
            int32_t h16 = wrap16((int64_t)L->th[16] + mulhrs16(wo, kq) - mulhrs16(wn, kq));
            pf_printf(kern, "    h2[16] = %d; /* x = 0 reads index 0 (V[0] - %d S[0]): TH[16] + round(w 2^-%d) the same */\n"
                            "    const __m512i tv = %s_w16(v2), ts = %s_w16(s2), th = %s_w16(h2);\n",
                      (int)h16, ns, L->td, N, N, N);
        }
    } else {
        const char *wv = jb == 4 ? "w16x2" : "w16";
        pf_printf(kern, "    const __m512i tv = %s_%s(%s_tv), ts = %s_%s(%s_ts), th = %s_w16(%s_th);\n", N, wv, N, N, wv, N, N,
                  N);
    }
    if (L->tlo)
        pf_printf(kern, "    const __m512i tl = %s_w16(%s_tl);\n", N, N);
    pf_printf(kern, "    const __m512i c8 = _mm512_set1_epi16(-32768), kr = _mm512_set1_epi16(%d);\n", 1 << (15 - L->td));
    pf_buf s1 = {0}, s2 = {0};
    pf_put(&s1, "        __m512i xv = _mm512_loadu_si512(x + i);\n"
                "        __m512i lz = _mm512_packus_epi32(_mm512_lzcnt_epi32(_mm512_unpacklo_epi16(c8, xv)),\n"
                "                                         _mm512_lzcnt_epi32(_mm512_unpackhi_epi16(c8, xv)));\n"
                "        __m512i u = _mm512_sllv_epi16(xv, lz);\n");
    if (fs)
        pf_printf(&s1, "        __m512i j = _mm512_srli_epi16(u, %d); /* vpermw reads its low 5 bits */\n", 15 - jb);
    else
        pf_printf(&s1, "        __m512i j = _mm512_srli_epi16(u, %d), f = _mm512_slli_epi16(u, %d); /* vpermw reads j's low 5 bits */\n",
                  15 - jb, jb + 1);
    pf_printf(&s2, "        __m512i w = _mm512_add_epi16(_mm512_permutexvar_epi16(j, tv),\n"
                   "                                     _mm512_mulhi_epu16(_mm512_permutexvar_epi16(j, ts), %s));\n",
              fs ? "u" : "f");
    if (L->tlo)
        pf_put(&s2, "        w = _mm512_add_epi16(w, _mm512_permutexvar_epi16(lz, tl));\n");
    pf_put(&s2, "        __m512i r = _mm512_add_epi16(_mm512_permutexvar_epi16(lz, th), _mm512_mulhrs_epi16(w, kr));\n");
    /* pipelined as the AVX2 loop below: block i's leading-zero count and
       shift beside block i - 32's lookups and multiplies */
    const char *cv5[] = {"j", fs ? "u" : "f", "lz"};
    fx_pipe_loop(kern, "__m512i", 32, s1.s, s2.s, cv5, 3, "_mm512_storeu_si512(y + i - 32, r);", N);
    free(s1.s);
    free(s2.s);
    s1 = s2 = (pf_buf){0};
    kern->n -= strlen("#endif"); /* fx_pipe_loop closed the #if: the AVX2 loop (or the #endif) follows */
    kern->s[kern->n] = 0;
    int tha, tlb, thm = 0, ta = 0, tk = 0, tc0 = 0, tc = 0, tb = 0, tq = 0, ts = 0;
    if (!tab_avx2(G, &tha, &tlb)) {
        pf_put(kern, "#endif");
        G->bw16 = 2;
        return;
    }
    int tlq = tab_tlq(G, &ta, &tb, &tq, &ts, &tc0, &tc);
    if (!tha && !tlq && (THMUL_TL || !L->tlo))
        thm = tab_thmul(G, &ta, &tk, &tc0, &tc, &tb);
    /* AVX2: no vpermw, no 16-bit per-element shift, no leading-zero count.
       x converted to float (even and odd words apart, in 32-bit lanes) is
       exact: its fraction bits are t, its exponent field 126 + bitlen(x) (0
       for x = 0); two blends of shifted copies put them back in the words'
       order.  A table of 16 words is two vpshufb on its byte planes merged
       by vpblendvb, with the index in both bytes of the word; 32 entries are
       two tables of 16 per plane, the wrong one zeroed by bit 7 of its
       index.  An index with bit 7 set also zeroes the TH and TL lookups for
       x = 0 (TH' = TH ^ 0x8000 stored, the result's sign bit flipped back);
       tab_avx2 says when that gives the scalar form's values. */
    pf_printf(kern,
              "\n/* AVX2 (x86-64-v3): the same steps on 16 lanes.  lz and t from x converted\n"
              "   to float, exact (even and odd words apart, in 32-bit lanes): its fraction\n"
              "   bits are t, its exponent ex = 126 + bitlen(x), 0 for x = 0; two blends put\n"
              "   them back in the words' order.  No vpermw: a table of 16 words is two\n"
              "   vpshufb (its low and its high bytes), the index in both bytes of the word,\n"
              "   merged by vpblendvb%s.%s\n",
              jb == 5 ? "; 32 words are two such tables per plane: entries\n"
                        "   16-31 looked up by j (vpshufb reads its low 4 bits) plus the\n"
                        "   bytewise differences of entries 0-15 less 16-31 by j + 0x70 (bit 7\n"
                        "   set, a zero, for j >= 16), mod 2^8 per byte"
              : jb == 3 ? "; 8 words are one vpshufb: their low bytes at 0-7, their\n"
                          "   high bytes at 8-15, the index j in the word's low byte and j + 8 in\n"
                          "   its high byte"
                      : "",
              fs ? "\n   u = t 2^16 = j 2^(16 - jb) + f 2^-jb (jb segment bits), so pmulhuw(S 2^jb,\n"
                   "   u) = S j + floor(S f 2^-16), exact: V - S j and S 2^jb are stored, and f\n"
                   "   is not formed."
                 : "");
    if (tha)
        pf_printf(kern, "   TH = max(ex - %d, %lld) << %d from ex, no lookup: %lld for x = 0, whose w =\n"
                        "   V[0] rounds to 0 (the scalar form's check).  The same values. */\n",
                  127 + Ei, (long long)(pf_type_min_stored(&G->out) / ((int64_t)1 << Eo)), Eo,
                  (long long)pf_type_min_stored(&G->out));
    else if (tlq)
        pf_printf(kern, "   TH 2^%d + TL = %d e for every lz < 16, %d = %d 2^%d + %d: the result is\n"
                        "   %d e' + round((w - %d s + %d e') 2^-%d), e' = e + s = max(ex - %d, %d), s = %d:\n"
                        "   two vpmullw, no lookup (V - %d s is stored).  x = 0: e' = %d, and the\n"
                        "   saturating add gives -32768 (pfmathgen checked it).  The same values. */\n",
                  L->td, tq, tq, ta, L->td, tb, ta, tq, tb, L->td, tc0, tc, ts, tq, tc);
    else if (thm)
        pf_printf(kern, "   TH + B = A e' + round(e' K 2^-15) (mod 2^16), A = %d, K = %d, B = %d,\n"
                        "   e' = max(ex - %d, %d): no lookup (pfmathgen searched A, K, B and the\n"
                        "   shift of e' for every lz < 16); V%s - B 2^%d is stored, so the sum is\n"
                        "   the same.  x = 0: e' = %d, A e' + round(e' K 2^-15) - B = %d, and w =\n"
                        "   %s, so the saturating add gives -32768.  The same values. */\n",
                  ta, tk, tb, tc0, tc, L->tlo ? " - V[0]" : "", L->td, tc,
                  wrap16((int64_t)ta * tc + mulhrs16(tc, tk)) - tb,
                  L->tlo ? "-B 2^td (TL's lookup is 0)" : "V[0] - B 2^td rounds to -B");
    else
        pf_printf(kern, "   x = 0: the index ex - 127 of the TH%s lookups has bit 7 set, so they\n"
                        "   give 0: TH' = TH ^ 0x8000 is stored and the sign bit flipped back%s.\n"
                        "   The same values. */\n",
                  L->tlo ? " and TL" : "",
                  L->tlo ? ";\n   V - V[0] and TL + V[0] are stored, so w = 0 there" : " (w = V[0]\n   rounds to 0)");
    pf_printf(kern, "__attribute__((target(\"arch=x86-64-v3\"), noinline))\n"
                    "static void %s_array_avx2(const %s *x, %s *y, size_t n)\n{\n",
              N, G->it, G->ot);
    int nq = 0, qv = 0, qs = 0, qh = 0, ql = 0;
    /* byte planes: V (2 or 4), S (2 or 4), TH' (2, lookup only), TL (1 or 2) */
    qv = nq; nq += jb == 3 ? 1 : 2 * (ns / 16); /* 8 segments: low bytes at 0-7, high at 8-15 */
    qs = nq; nq += jb == 3 ? 1 : 2 * (ns / 16);
    if (!tha && !thm && !tlq) { qh = nq; nq += 2; }
    if (L->tlo && !tlq) { ql = nq; nq += tlb ? 1 : 2; }
    pf_printf(kern, "    uint8_t b[%d][16]; /* byte planes: ", nq);
    pf_printf(kern, "V%s%s low, high%s; S low, high%s", tlq ? " - q s" : L->tlo ? " - V[0]" : "", thm ? " - B 2^td" : "",
              jb == 5 ? " (entries 0-15, 16-31)" : jb == 3 ? " (bytes 0-7, 8-15 of one plane)" : "",
              jb == 5 ? " (0-15, 16-31)" : jb == 3 ? " (the same)" : "");
    if (!tha && !thm && !tlq)
        pf_put(kern, "; TH' by bitlen(x) - 1, low, high");
    if (L->tlo && !tlq)
        pf_printf(kern, "; TL + V[0] by bitlen(x) - 1%s", tlb ? " (one byte each)" : ", low, high");
    pf_put(kern, " */\n    for (int k = 0; k < 16; k++) {\n");
    for (int h = 0; h < (jb == 3 ? 1 : ns / 16); h++) {
        const char *o = jb == 3 ? " & 7" : h ? " + 16" : "";
        char vk[1024], vb[256] = "";
        if (fs) /* V - S j: pmulhuw(S 2^jb, u) = S j + floor(S f 2^-16) */
            snprintf(vb, sizeof vb, " - %s_ts[k%s] * (k%s)", N, o, o);
        if (thm)
            snprintf(vb + strlen(vb), sizeof vb - strlen(vb), " - %d", tb << L->td);
        if (tlq)
            snprintf(vk, sizeof vk, "(uint32_t)(%s_tv[k%s]%s - %lld)", N, o, vb, (long long)tq * ts);
        else if (L->tlo)
            snprintf(vk, sizeof vk, "(uint32_t)(%s_tv[k%s] - %s_tv[0]%s)", N, o, N, vb);
        else if (thm || fs)
            snprintf(vk, sizeof vk, "(uint32_t)(%s_tv[k%s]%s)", N, o, vb);
        else
            snprintf(vk, sizeof vk, "(uint32_t)%s_tv[k%s]", N, o);
        if (jb == 3) { /* one plane each: entry k & 7's low byte at k < 8, its high byte at k >= 8 (fs holds) */
            pf_printf(kern, "        b[%d][k] = (uint8_t)(%s >> (k & 8));\n", qv, vk);
            pf_printf(kern, "        b[%d][k] = (uint8_t)((uint32_t)(%s_ts[k%s] * %d) >> (k & 8));\n", qs, N, o, ns);
            continue;
        }
        pf_printf(kern, "        b[%d][k] = (uint8_t)%s;\n", qv + h, vk);
        pf_printf(kern, "        b[%d][k] = (uint8_t)(%s >> 8);\n", qv + ns / 16 + h, vk);
        if (fs) {
            pf_printf(kern, "        b[%d][k] = (uint8_t)(%s_ts[k%s] * %d);\n", qs + h, N, o, ns);
            pf_printf(kern, "        b[%d][k] = (uint8_t)((uint32_t)(%s_ts[k%s] * %d) >> 8);\n", qs + ns / 16 + h, N, o, ns);
        } else {
            pf_printf(kern, "        b[%d][k] = (uint8_t)%s_ts[k%s];\n", qs + h, N, o);
            pf_printf(kern, "        b[%d][k] = (uint8_t)((uint32_t)%s_ts[k%s] >> 8);\n", qs + ns / 16 + h, N, o);
        }
    }
    if (jb == 5) /* entries 0-15 as differences (the lookup by j + 0x70 adds them to 16-31's) */
        for (int q = 0; q < 4; q++) {
            int p = q < 2 ? qv + 2 * q : qs + 2 * (q - 2);
            pf_printf(kern, "        b[%d][k] = (uint8_t)(b[%d][k] - b[%d][k]);\n", p, p, p + 1);
        }
    if (!tha && !thm && !tlq) {
        pf_printf(kern, "        b[%d][k] = (uint8_t)((uint32_t)%s_th[15 - k] ^ 0x8000u);\n", qh, N);
        pf_printf(kern, "        b[%d][k] = (uint8_t)(((uint32_t)%s_th[15 - k] ^ 0x8000u) >> 8);\n", qh + 1, N);
    }
    if (L->tlo && !tlq) {
        pf_printf(kern, "        b[%d][k] = (uint8_t)(uint32_t)(%s_tl[15 - k] + %s_tv[0]);\n", ql, N, N);
        if (!tlb)
            pf_printf(kern, "        b[%d][k] = (uint8_t)((uint32_t)(%s_tl[15 - k] + %s_tv[0]) >> 8);\n", ql + 1, N, N);
    }
    pf_put(kern, "    }\n");
    for (int q = 0; q < nq; q++)
        pf_printf(kern, "    const __m256i q%d = _mm256_broadcastsi128_si256(_mm_loadu_si128((const __m128i *)b[%d]));\n", q, q);
    pf_printf(kern, "    __m256i dup = _mm256_set1_epi16(0x101); /* x 0x101: a byte in both bytes of its word */\n"
                    "    __asm__(\"\" : \"+x\"(dup));              /* (a vpmullw, not shifts and adds) */\n"
                    "%s"
                    "    const __m256i lo16 = _mm256_set1_epi32(0xffff)%s;\n"
                    "    const __m256i kr = _mm256_set1_epi16(%d);\n",
              jb == 3 ? "    const __m256i c800 = _mm256_set1_epi16(0x800); /* the high byte's index: j + 8 */\n"
              : jb == 4 && fs ? "    __m256i c16 = _mm256_set1_epi16(16);    /* u >> 12 as vpmulhuw */\n"
                              "    __asm__(\"\" : \"+x\"(c16));\n"
              : jb == 4 ? "    __m256i c16 = _mm256_set1_epi16(16);    /* u >> 12, u << 4 as vpmulhuw, vpmullw */\n"
                        "    __asm__(\"\" : \"+x\"(c16));\n"
                      : "",
              jb != 3 || (!tha && !thm && !tlq) || (L->tlo && !tlq && !tlb) ? ", hib = _mm256_set1_epi16(-256)" : "",
              1 << (15 - L->td));
    if (jb == 5)
        pf_put(kern, "    const __m256i c70 = _mm256_set1_epi8(0x70);\n");
    if (tha)
        pf_printf(kern, "    const __m256i ce = _mm256_set1_epi16(%d), lo = _mm256_set1_epi16(%lld);\n", 127 + Ei,
                  (long long)(pf_type_min_stored(&G->out) / ((int64_t)1 << Eo)));
    else if (tlq)
        pf_printf(kern, "    const __m256i ce = _mm256_set1_epi16(%d), lo = _mm256_set1_epi16(%d);\n"
                        "    __m256i ka = _mm256_set1_epi16(%d), kb = _mm256_set1_epi16(%d); /* a, b */\n"
                        "    __asm__(\"\" : \"+x\"(ka), \"+x\"(kb));\n",
                  tc0, tc, ta, tb);
    else if (thm)
        pf_printf(kern, "    const __m256i ce = _mm256_set1_epi16(%d), lo = _mm256_set1_epi16(%d);\n"
                        "    __m256i ka = _mm256_set1_epi16(%d), kb = _mm256_set1_epi16(%d); /* A, K */\n"
                        "    __asm__(\"\" : \"+x\"(ka), \"+x\"(kb));\n",
                  tc0, tc, ta, tk);
    if ((L->tlo && !tlq) || (!tha && !thm && !tlq))
        pf_printf(kern, "    const __m256i c127 = _mm256_set1_epi16(127)%s;\n", tha || thm ? "" : ", sgn = _mm256_set1_epi16(-32768)");
    pf_put(&s1, "        __m256i xv = _mm256_loadu_si256((const __m256i *)(x + i));\n"
                 "        __m256i fe = _mm256_castps_si256(_mm256_cvtepi32_ps(_mm256_and_si256(xv, lo16)));\n"
                 "        __m256i fo = _mm256_castps_si256(_mm256_cvtepi32_ps(_mm256_srli_epi32(xv, 16)));\n"
                 "        __m256i u = _mm256_blend_epi16(_mm256_srli_epi32(fe, 7), _mm256_slli_epi32(fo, 9), 0xaa); /* t 2^16 */\n"
                 "        __m256i ex = _mm256_blend_epi16(_mm256_srli_epi32(fe, 23), _mm256_srli_epi32(fo, 7), 0xaa);\n");
    if (jb == 3) /* j in the low byte, j + 8 in the high: one vpshufb gives the word */
        pf_put(&s1, "        __m256i jj = _mm256_add_epi16(_mm256_mullo_epi16(_mm256_srli_epi16(u, 13), dup), c800);\n");
    else if (jb == 4) /* j and f by multiplies: the shifts' ports are the busier (measured 2% faster; not so at 32) */
        pf_printf(&s1, "        __m256i jj = _mm256_mullo_epi16(_mm256_mulhi_epu16(u, c16), dup)%s;\n",
                  fs ? "" : ", f = _mm256_mullo_epi16(u, c16)");
    else if (fs)
        pf_printf(&s1, "        __m256i jj = _mm256_mullo_epi16(_mm256_srli_epi16(u, %d), dup);\n", 16 - jb);
    else
        pf_printf(&s1, "        __m256i jj = _mm256_mullo_epi16(_mm256_srli_epi16(u, %d), dup), f = _mm256_slli_epi16(u, %d);\n",
                  16 - jb, jb);
    if (jb == 3)
        pf_printf(&s2, "        __m256i v = _mm256_shuffle_epi8(q%d, jj), s = _mm256_shuffle_epi8(q%d, jj);\n", qv, qs);
    else if (jb == 4)
        pf_printf(&s2,
                  "        __m256i v = _mm256_blendv_epi8(_mm256_shuffle_epi8(q%d, jj), _mm256_shuffle_epi8(q%d, jj), hib);\n"
                  "        __m256i s = _mm256_blendv_epi8(_mm256_shuffle_epi8(q%d, jj), _mm256_shuffle_epi8(q%d, jj), hib);\n",
                  qv, qv + 1, qs, qs + 1);
    else
        pf_printf(&s2,
                  "        __m256i a0 = _mm256_add_epi8(jj, c70); /* bit 7 set (lookup 0) for j >= 16 */\n"
                  "        __m256i v = _mm256_blendv_epi8(_mm256_add_epi8(_mm256_shuffle_epi8(q%d, a0), _mm256_shuffle_epi8(q%d, jj)),\n"
                  "                                       _mm256_add_epi8(_mm256_shuffle_epi8(q%d, a0), _mm256_shuffle_epi8(q%d, jj)), hib);\n"
                  "        __m256i s = _mm256_blendv_epi8(_mm256_add_epi8(_mm256_shuffle_epi8(q%d, a0), _mm256_shuffle_epi8(q%d, jj)),\n"
                  "                                       _mm256_add_epi8(_mm256_shuffle_epi8(q%d, a0), _mm256_shuffle_epi8(q%d, jj)), hib);\n",
                  qv, qv + 1, qv + 2, qv + 3, qs, qs + 1, qs + 2, qs + 3);
    pf_printf(&s2, "        __m256i w = _mm256_add_epi16(v, _mm256_mulhi_epu16(s, %s));%s\n", fs ? "u" : "f",
              fs ? " /* S 2^jb u 2^-16 = S j + S f 2^-16 */" : "");
    if ((L->tlo && !tlq) || (!tha && !thm && !tlq))
        pf_put(&s2, "        __m256i kk = _mm256_mullo_epi16(_mm256_sub_epi16(ex, c127), dup); /* bitlen(x) - 1 */\n");
    if (L->tlo && !tlq) {
        if (tlb)
            pf_printf(&s2, "        w = _mm256_add_epi16(w, _mm256_srai_epi16(_mm256_shuffle_epi8(q%d, kk), 8));\n", ql);
        else
            pf_printf(&s2, "        w = _mm256_add_epi16(w, _mm256_blendv_epi8(_mm256_shuffle_epi8(q%d, kk), _mm256_shuffle_epi8(q%d, kk), hib));\n",
                      ql, ql + 1);
    }
    if (tha)
        pf_printf(&s2, "        __m256i th = _mm256_slli_epi16(_mm256_max_epi16(_mm256_sub_epi16(ex, ce), lo), %d);\n"
                        "        __m256i r = _mm256_add_epi16(th, _mm256_mulhrs_epi16(w, kr));\n",
                  Eo);
    else if (tlq)
        pf_put(&s2, "        __m256i e = _mm256_max_epi16(_mm256_sub_epi16(ex, ce), lo);\n"
                     "        w = _mm256_add_epi16(w, _mm256_mullo_epi16(e, kb));\n"
                     "        __m256i r = _mm256_adds_epi16(_mm256_mullo_epi16(e, ka), _mm256_mulhrs_epi16(w, kr));\n");
    else if (thm)
        pf_put(&s2, "        __m256i e = _mm256_max_epi16(_mm256_sub_epi16(ex, ce), lo);\n"
                     "        __m256i th = _mm256_add_epi16(_mm256_mullo_epi16(e, ka), _mm256_mulhrs_epi16(e, kb)); /* TH + B */\n"
                     "        __m256i r = _mm256_adds_epi16(th, _mm256_mulhrs_epi16(w, kr));\n");
    else
        pf_printf(&s2, "        __m256i th = _mm256_blendv_epi8(_mm256_shuffle_epi8(q%d, kk), _mm256_shuffle_epi8(q%d, kk), hib);\n"
                        "        __m256i r = _mm256_xor_si256(_mm256_add_epi16(th, _mm256_mulhrs_epi16(w, kr)), sgn);\n",
                  qh, qh + 1);
    /* one block's chain (float conversion, shifts, multiply, lookups, two
       multiplies) is longer than the CPU overlaps over blocks: pipelined,
       the lookups on block i - 16 beside block i's conversion */
    const char *cv[] = {"jj", fs ? "u" : "f", "ex"};
    fx_pipe_loop(kern, "__m256i", 16, s1.s, s2.s, cv, 3, "_mm256_storeu_si256((__m256i *)(y + i - 16), r);", N);
    free(s1.s);
    free(s2.s);
    G->bw16 = 3;
}

/* ---- 16-bit lanes: the cubic kernel (kind 2, fast log2) ----
 *
 * x = 2^e (1 + t), u = x << lz as for the table kernel; t is cut to its top
 * Eo bits (T = t's top Eo bits at 2^-16, the rest dropped), and log2(x) 2^Eo
 * = e 2^Eo + F(t) 2^Eo with F(t) = log2(1 + t) a cubic p(T) = T (c1 - T (c2
 * - c3 T)) (p(0) = 0: exact at powers of 2, and x = 0 gives TH[16] alone),
 * three pmulhuw, each a floor: a2 = D2 - floor(C3 T 2^-16), a4 = C1 -
 * floor(a2 T 2^-16), y = e 2^Eo + floor(a4 T 2^-16), every value an
 * unsigned word.  On AVX2 the reduction is x's float: its bits shifted
 * right by 23 - Eo are (127 + bitlen(x) - 1) 2^Eo + t's top Eo bits, so
 * less (127 + Ei) 2^Eo they are e 2^Eo + T 2^(Eo-16) = U, the packing
 * (vpackssdw) saturating x = 0 to -32768; T = U << (16 - Eo), and y = U +
 * floor((a4 - 2^Eo) T 2^-16) (a4 >= 2^Eo, checked): the same values
 * without e.  C1, D2, C3 start from the fitter's minimax cubic (p(0) = 0)
 * at 2^Eo, then a search around it takes the least max error over every
 * input, against MPFR, of these integer steps. */

/* e's part at 2^-Eo: e 2^Eo (log2), round(e 2^Eo K 2^-15) with K = round(ln2
   2^15) (log: one pmulhrsw) */
static int32_t poly_e(const fx_gen *G, int lz)
{
    int32_t e = (15 - lz - G->in.exp) * (1 << G->out.exp);
    return G->log.pbase2 ? e : mulhrs16(e, (int32_t)G->log.k15);
}

/* the emitted steps' value for one input (x > 0); 0 if a word overflows */
static int poly_y(const fx_gen *G, uint32_t x, int32_t *y)
{
    const fx_log_red *L = &G->log;
    int Eo = G->out.exp;
    int lz = 16 - fx_bitlen(x);
    uint32_t u = (x << lz) & 0xffffu;
    uint32_t t = (u << 1) & (0xffffu << (16 - Eo)) & 0xffffu;
    int32_t a2 = L->pd2 - (int32_t)(((uint32_t)L->pc3 * t) >> 16);
    if (a2 < 0 || a2 > 65535)
        return 0;
    int32_t a4 = L->pc1 - (int32_t)(((uint32_t)a2 * t) >> 16);
    if (a4 < (L->pbase2 ? 1 << Eo : 0) || a4 > 65535)
        return 0;
    *y = poly_e(G, lz) + (int32_t)(((uint32_t)a4 * t) >> 16);
    return 1;
}

/* max error (output lsb) of C3, D2, C1 over every T, from lo[T], hi[T]: the
   range of ref - e's part over the inputs with that T (lo > hi: none); a4
   >= amin */
static double poly_eval(int Eo, int32_t amin, int32_t c3, int32_t d2, int32_t c1, const double *lo, const double *hi)
{
    double w = 0;
    if (c3 < 0 || c3 > 65535 || d2 < 0 || d2 > 65535 || c1 < 0 || c1 > 65535)
        return INFINITY;
    for (uint32_t k = 0; k < 1u << Eo; k++) {
        if (lo[k] > hi[k])
            continue;
        uint32_t t = k << (16 - Eo);
        int32_t a2 = d2 - (int32_t)(((uint32_t)c3 * t) >> 16);
        if (a2 < 0)
            return INFINITY;
        int32_t a4 = c1 - (int32_t)(((uint32_t)a2 * t) >> 16);
        if (a4 < amin)
            return INFINITY;
        double p = (double)(((uint32_t)a4 * t) >> 16);
        double e = fmax(fabs(p - lo[k]), fabs(hi[k] - p));
        if (e > w)
            w = e;
    }
    return w;
}

/* 0: the cubic kernel is set up and bounded; -2: not for this type pair */
static int prep_poly(fx_gen *G, int base2)
{
    int Ei = G->in.exp, Eo = G->out.exp;
    int64_t mn = pf_type_min_stored(&G->out), mx = pf_type_max_stored(&G->out);
    if (G->exact || G->in.is_signed || G->in.storage_bits != 16 || pf_type_max_stored(&G->in) != 65535 ||
        G->out.storage_bits != 16 || !G->out.is_signed || mn != -32768 || Eo < 6 || Eo > 15 || Ei < -16 || Ei > 31)
        return -2;
    /* e 2^Eo + T: x = 1 above -32768, the largest below 2^15; the AVX2
       packing saturates x = 0 (0 - (127 + Ei) 2^Eo) to -32768 */
    if ((int64_t)-Ei * (1 << Eo) <= -32768 || (int64_t)(16 - Ei) * (1 << Eo) > 32767 ||
        (int64_t)(127 + Ei) * (1 << Eo) < 32768)
        return -2;
    fit_problem pb;
    memset(&pb, 0, sizeof pb);
    pb.g = base2 ? g_log2_1p : g_log1p;
    pb.a = 0;
    pb.b = 1;
    pb.order = 3;
    pb.parity = FIT_PARITY_NONE;
    pb.errkind = FIT_ABS;
    pb.ncon = 1;
    pb.con[0].kind = FIT_CON_VALUE;
    pb.con[0].t = 0;
    fit_poly fp;
    char err[200];
    if (fit_minimax(&pb, &fp, err, sizeof err) != 0)
        return -2;
    fit_measure(&pb, &fp);
    fx_log_red *L = &G->log;
    L->pfit = fp.max_err;
    L->pbase2 = base2;
    mpfr_t xr, lr;
    mpfr_inits2(128, xr, lr, (mpfr_ptr)0);
    mpfr_const_log2(lr, MPFR_RNDN);
    mpfr_mul_2si(xr, lr, 15, MPFR_RNDN);
    mpfr_rint(xr, xr, MPFR_RNDN);
    L->k15 = (int64_t)mpfr_get_si(xr, MPFR_RNDN); /* log: round(ln2 2^15) */
    int n = 1 << Eo;
    mpfr_clears(xr, lr, (mpfr_ptr)0);
    double *lo = malloc(sizeof *lo * (size_t)n), *hi = malloc(sizeof *hi * (size_t)n);
    const double *ref = log_refs(Ei, Eo, base2);
    if (!lo || !hi || !ref) {
        free(lo);
        free(hi);
        return -2;
    }
    for (int k = 0; k < n; k++)
        lo[k] = INFINITY, hi[k] = -INFINITY;
    for (uint32_t x = 1; x < 65536; x++) {
        int lz = 16 - fx_bitlen(x);
        uint32_t u = (x << lz) & 0xffffu;
        int k = (int)(((u << 1) & 0xffffu) >> (16 - Eo));
        double r = ref[x] - (double)poly_e(G, lz);
        lo[k] = r < lo[k] ? r : lo[k];
        hi[k] = r > hi[k] ? r : hi[k];
    }
    int32_t c3 = (int32_t)lround((double)fp.c[3] * n), d2 = (int32_t)lround(-(double)fp.c[2] * n),
            c1 = (int32_t)lround((double)fp.c[1] * n);
    /* the search: a box around the fit (the cut of t and the floors move the
       best integer coefficients off the real fit's), then +-1 steps */
    int r3 = n / 48 > 3 ? n / 48 : 3, r1 = n / 160 > 3 ? n / 160 : 3;
    int32_t amin = base2 ? 1 << Eo : 0; /* log2's AVX2 loop adds U, not e 2^Eo: a4 - 2^Eo >= 0 */
    double best = poly_eval(Eo, amin, c3, d2, c1, lo, hi);
    int32_t b3 = c3, b2 = d2, b1 = c1;
    for (int a = -r3; a <= r3; a++)
        for (int b = -r3; b <= r3; b++)
            for (int c = -r1; c <= r1; c++) {
                double e = poly_eval(Eo, amin, c3 + a, d2 + b, c1 + c, lo, hi);
                if (e < best)
                    best = e, b3 = c3 + a, b2 = d2 + b, b1 = c1 + c;
            }
    for (int more = 1; more;) {
        more = 0;
        int32_t s3 = b3, s2 = b2, s1 = b1;
        for (int a = -1; a <= 1; a++)
            for (int b = -1; b <= 1; b++)
                for (int c = -1; c <= 1; c++) {
                    double e = poly_eval(Eo, amin, s3 + a, s2 + b, s1 + c, lo, hi);
                    if (e < best)
                        best = e, b3 = s3 + a, b2 = s2 + b, b1 = s1 + c, more = 1;
                }
    }
    L->pc3 = b3, L->pd2 = b2, L->pc1 = b1;
    /* the bound: every input, the emitted steps against MPFR */
    double worst = 0;
    int ok = best < INFINITY;
    for (uint32_t x = 1; x < 65536 && ok; x++) {
        int32_t y;
        if (!poly_y(G, x, &y) || y <= mn || y > mx || ref[x] < (double)mn || ref[x] > (double)mx) {
            ok = 0;
            break;
        }
        double e = fabs((double)y - ref[x]);
        worst = e > worst ? e : worst;
    }
    free(lo);
    free(hi);
    if (!ok)
        return -2;
    L->terr = worst * (1 + 1e-12) + 1e-12; /* MPFR to 128 bits, rounded to double: far below */
    return fx_within(G, 0, L->terr * fx_lsb(G)) ? 0 : -2;
}

static void poly_texts(fx_gen *G)
{
    const fx_log_red *L = &G->log;
    int Ei = G->in.exp, Eo = G->out.exp, b2 = L->pbase2;
    const char *fn = b2 ? "log2" : "log", *F = b2 ? "log2(1 + t)" : "log(1 + t)";
    char ek[160];
    if (b2)
        snprintf(ek, sizeof ek, "e 2^%d", Eo);
    else
        snprintf(ek, sizeof ek, "round(e 2^%d K 2^-15), K = %d = round(ln2 2^15) (MPFR; pmulhrsw)", Eo, (int)L->k15);
    snprintf(G->red_text, sizeof G->red_text,
             "x = 2^e (1 + t), e = 15 - lz - %d with lz = 16 - bitlen(x) (AVX-512: a leading-zero count of x 2^16 + "
             "2^15, vplzcntd; AVX2: x converted to float, exact, whose bits >> %d less %d are e 2^%d + T 2^-%d, "
             "vpackssdw saturating x = 0; else branch-free stages), u = x << lz (vpsllvw), T = t's top %d bits at "
             "2^-16 (the rest dropped: in the bound); %s(x) = e%s + F(t), F(t) = %s; x = 0 -> -32768 "
             "(most negative)",
             Ei, 23 - Eo, (127 + Ei) * (1 << Eo), Eo, 16 - Eo, Eo, fn, b2 ? "" : " ln2", F);
    snprintf(G->alt_domain, sizeof G->alt_domain, "%s on t in [0, 1], at t's top %d bits", b2 ? "log2(1+t)" : "log(1+t)",
             Eo);
    snprintf(G->alt_order, sizeof G->alt_order,
             "3, p(T) = T (C1 - T (D2 - C3 T)) 2^-%d, three pmulhuw (unsigned words); int16_t words: 16-bit lanes", Eo);
    snprintf(G->alt_method, sizeof G->alt_method,
             "the fitter's minimax cubic for %s with p(0) = 0 (max error %.3e), its coefficients at 2^-%d, "
             "then C3 = %d, D2 = %d, C1 = %d from a search around them for the least max error of the integer steps "
             "over every input against MPFR (the cut of t and the floors included)",
             b2 ? "log2(1+t)" : "log(1+t)", L->pfit, Eo, (int)L->pc3, (int)L->pd2, (int)L->pc1);
    snprintf(G->alt_con, sizeof G->alt_con, "p(0) = 0 (%s; x = 0 gives the most negative output)",
             b2 ? "log2 of powers of 2 exact" : "log(1) = 0 exactly");
    snprintf(G->alt_formats, sizeof G->alt_formats,
             "T, C3, D2, C1, a2, a4 unsigned words (a2 = D2 - floor(C3 T 2^-16), a4 = C1 - floor(a2 T 2^-16) >= %d, "
             "checked over every T); result %s + floor(a4 T 2^-16), int16_t",
             b2 ? 1 << Eo : 0, ek);
    snprintf(G->alt_poly, sizeof G->alt_poly, "the fitter's cubic within %.4f LSB of %s on [0, 1]",
             ldexp(L->pfit, Eo), b2 ? "log2(1+t)" : "log(1+t)");
    snprintf(G->wide_text, sizeof G->wide_text,
             "16-bit words throughout, but x's float (32-bit lanes: vcvtdq2ps on the unpacked words, the shift "
             "and the bias, then vpackssdw) on x86-64-v3, two blocks a pass, software pipelined; x86-64-v4: "
             "leading-zero count (vplzcntd on x 2^16 + "
             "2^15, packed to words), per-element shift (vpsllvw), e%s 2^%d by vpermw; other clones, scalar form: "
             "plain C",
             b2 ? "" : " ln2", Eo);
    snprintf(G->alt_arith, sizeof G->alt_arith,
             "integers only (no floating-point arithmetic: the AVX2 loop converts x to float, exact, and reads its "
             "bits; no <math.h>); the three products floor (pmulhuw: in the bound)%s; bit-identical under any "
             "compiler flags",
             b2 ? "" : ", e ln2 rounds to nearest, ties up (pmulhrsw)");
    snprintf(G->bound_note, sizeof G->bound_note,
             "taken over every input from the emitted integer steps (the cubic kernel, floors included) against MPFR");
}

/* One step of the AVX2 loop below: @ is the block's number (0 or 1), $ its
   offset in x and y (+ 16 for block 1), at the indent in */
static void log_put_step(pf_buf *b, const char *t, int k, const char *in)
{
    pf_put(b, in);
    for (const char *c = t; *c; c++) {
        if (*c == '@')
            pf_printf(b, "%d", k);
        else if (*c == '$') {
            if (k)
                pf_put(b, " + 16");
        } else
            pf_printf(b, "%c", *c);
    }
    pf_put(b, "\n");
}

/* steps j0 .. j1 - 1 of st, each for blocks 0 .. nb - 1 in turn */
static void log_put_steps(pf_buf *b, const char (*st)[240], int j0, int j1, int nb, const char *in)
{
    for (int j = j0; j < j1; j++)
        for (int k = 0; k < nb; k++)
            log_put_step(b, st[j], k, in);
}

static void emit_poly(fx_gen *G, pf_buf *body, pf_buf *tabs, pf_buf *kern)
{
    const fx_log_red *L = &G->log;
    const char *N = G->name;
    int Ei = G->in.exp, Eo = G->out.exp;
    uint32_t tm = (0xffffu << (16 - Eo)) & 0xffffu;
    char w3[64], w2[64], w1[64], k3[16], k2[16], k1[16];
    snprintf(w3, sizeof w3, "C3 = %d (unsigned word)", (int)L->pc3);
    snprintf(w2, sizeof w2, "D2 = %d (unsigned word)", (int)L->pd2);
    snprintf(w1, sizeof w1, "C1 = %d (unsigned word)", (int)L->pc1);
    snprintf(k3, sizeof k3, "%s", fx_k16(G, (int16_t)(uint16_t)L->pc3, w3));
    snprintf(k2, sizeof k2, "%s", fx_k16(G, (int16_t)(uint16_t)L->pd2, w2));
    snprintf(k1, sizeof k1, "%s", fx_k16(G, (int16_t)(uint16_t)L->pc1, w1));
    char epart[200], wk[160];
    int b2 = L->pbase2;
    if (b2)
        snprintf(epart, sizeof epart, "(15 - lz - %d) * %d", Ei, 1 << Eo);
    else {
        /* e ln2 by lz: a table (the AVX-512 loop's vpermw), from the
           pmulhrsw the AVX2 loop runs */
        int32_t th[32] = {0};
        for (int lz = 0; lz < 16; lz++)
            th[lz] = poly_e(G, lz);
        th[16] = -32768;
        snprintf(wk, sizeof wk, "TH[lz] = round(e 2^%d K 2^-15), K = %d = round(ln2 2^15) (MPFR), e = 15 - lz - %d",
                 Eo, (int)L->k15, Ei);
        tab_table(tabs, N, "th", th, 32, wk);
        snprintf(epart, sizeof epart, "%s_th[lz]", N);
    }
    pf_printf(body,
              "    /* x = 2^(15 - lz) (1 + t), lz = 16 - bitlen(x) (16 for x = 0) */\n"
              "    int lz = 16 - pf_fx_bitlen(x);\n"
              "    uint16_t u = (uint16_t)((uint32_t)x << lz);           /* leading one at bit 15; 0 for x = 0 */\n"
              "    uint32_t t = ((uint32_t)u << 1) & 0x%xu;             /* T: t's top %d bits at 2^-16 */\n"
              "    /* p(T) = T (C1 - T (D2 - C3 T)) 2^-%d, three floors (pmulhuw) */\n"
              "    uint32_t a2 = (uint16_t)((uint16_t)%s - (((uint16_t)%s * t) >> 16));\n"
              "    uint32_t a4 = (uint16_t)((uint16_t)%s - ((a2 * t) >> 16));\n"
              "    int32_t e = %s%s%s; /* e%s 2^%d; x = 0: the most negative (p = 0) */\n"
              "    return (%s)(e + (int32_t)((a4 * t) >> 16));",
              (unsigned)tm, Eo, Eo, k2, k3, k1, b2 ? "lz < 16 ? " : "", epart, b2 ? " : -32768" : "", b2 ? "" : " ln2", Eo,
              G->ot);
    const char *cond = "#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(__AVX2__)\n";
    char epk[200];
    if (b2)
        snprintf(epk, sizeof epk, "(15 - k - %d) * %d", Ei, 1 << Eo);
    else
        snprintf(epk, sizeof epk, "%s_th[k]", N);
    pf_printf(kern,
              "\n\n/* AVX-512BW/CD: the same steps on 32 lanes, with intrinsics, as GCC does not\n"
              "   turn a 16-bit leading-zero count into vplzcntd nor e%s 2^%d into vpermw: the\n"
              "   array form runs this loop on a CPU with x86-64-v4 (see its dispatch), the\n"
              "   rest of the array and the other clones use the scalar steps above.  x 2^16\n"
              "   + 2^15 in 32-bit lanes has lz leading zeros (16 for x = 0); unpack and\n"
              "   pack keep the lanes' order; T = (2 x) << lz, cut (the add is off the\n"
              "   leading-zero count's path: measured as fast as three lookups).  The same\n"
              "   values (pfmathgen sweeps the array form on its machine against the scalar\n"
              "   one). */\n%s#include <immintrin.h>\n"
              "extern %s %s(%s x); /* the scalar form, for the last n %% 32 (or 16) */\n"
              "__attribute__((target(\"arch=x86-64-v4\"), noinline))\n"
              "static void %s_array_bw(const %s *x, %s *y, size_t n)\n{\n"
              "    int32_t e2[32]; /* e%s 2^%d by lz; x = 0 (lz = 16): the most negative */\n"
              "    for (int k = 0; k < 32; k++)\n"
              "        e2[k] = k < 16 ? %s : k == 16 ? -32768 : 0;\n"
              "    const __m512i th = _mm512_inserti64x4(_mm512_castsi256_si512(_mm512_cvtepi32_epi16(_mm512_loadu_si512(e2))),\n"
              "                                          _mm512_cvtepi32_epi16(_mm512_loadu_si512(e2 + 16)), 1);\n"
              "    const __m512i c8 = _mm512_set1_epi16(-32768), tm = _mm512_set1_epi16(%d);\n"
              "    const __m512i c3 = _mm512_set1_epi16(%d), d2 = _mm512_set1_epi16(%d), c1 = _mm512_set1_epi16(%d);\n",
              b2 ? "" : " ln2", Eo, cond, G->ot, N, G->it, N, G->it, G->ot, b2 ? "" : " ln2", Eo, epk, (int)(int16_t)tm, (int)(int16_t)L->pc3,
              (int)(int16_t)L->pd2, (int)(int16_t)L->pc1);
    pf_buf s1 = {0}, s2 = {0};
    pf_put(&s1, "        __m512i xv = _mm512_loadu_si512(x + i);\n"
                "        __m512i lz = _mm512_packus_epi32(_mm512_lzcnt_epi32(_mm512_unpacklo_epi16(c8, xv)),\n"
                "                                         _mm512_lzcnt_epi32(_mm512_unpackhi_epi16(c8, xv)));\n"
                "        __m512i t = _mm512_and_si512(_mm512_sllv_epi16(_mm512_add_epi16(xv, xv), lz), tm); /* u << 1, cut */\n");
    pf_put(&s2, "        __m512i a2 = _mm512_sub_epi16(d2, _mm512_mulhi_epu16(c3, t));\n"
                "        __m512i a4 = _mm512_sub_epi16(c1, _mm512_mulhi_epu16(a2, t));\n"
                "        __m512i r = _mm512_add_epi16(_mm512_permutexvar_epi16(lz, th), _mm512_mulhi_epu16(a4, t));\n");
    const char *cv5[] = {"t", "lz"};
    fx_pipe_loop(kern, "__m512i", 32, s1.s, s2.s, cv5, 2, "_mm512_storeu_si512(y + i - 32, r);", N);
    free(s1.s);
    free(s2.s);
    kern->n -= strlen("#endif"); /* fx_pipe_loop closed the #if: the AVX2 loop follows */
    kern->s[kern->n] = 0;
    /* the comment's shared head, then log's or log2's steps, then the
       function's head; the C1 stored differs (log2: C1 - 2^Eo, see below) */
    pf_printf(kern,
              "\n/* AVX2 (x86-64-v3): the same values on 16 lanes, without a leading-zero\n"
              "   count or a per-element shift: x converted to float (the words unpacked to\n"
              "   32-bit lanes, in each 128-bit lane's order, as vpackssdw packs them back)\n"
              "   is exact, and its bits >> %d are (127 + bitlen(x) - 1) 2^%d + t's top %d\n"
              "   bits, so less %d they are U = e 2^%d + T 2^-%d, in a word for x > 0;\n"
              "   x = 0 (bits 0) gives -%d, which the packing saturates to -32768.  T =\n",
              23 - Eo, Eo, Eo, (127 + Ei) * (1 << Eo), Eo, 16 - Eo, (127 + Ei) * (1 << Eo));
    if (!b2)
        pf_printf(kern,
                  "   U << %d, e 2^%d = U with its low %d bits cleared, and e ln2 2^%d =\n"
                  "   round(e 2^%d K 2^-15) (pmulhrsw, as the table).  x = 0 (U = -32768, the\n"
                  "   only such U): -32768 by a compare and a blend.  Two blocks a pass, step\n"
                  "   by step, software pipelined (measured on Zen 3, this loop alone: 6.4 ->\n"
                  "   5.8 core cycles per 16 lanes).  The same values. */\n",
                  16 - Eo, Eo, Eo, Eo, Eo);
    else
        pf_printf(kern,
                  "   U << %d, and floor((a4 - 2^%d) T 2^-16) = floor(a4 T 2^-16) - T 2^-%d\n"
                  "   (a4 >= 2^%d, checked), so y = U + floor((a4 - 2^%d) T 2^-16) without\n"
                  "   e: C1 - 2^%d is stored.  x = 0: T = 0, y = -32768.  Two blocks a pass,\n"
                  "   step by step, software pipelined (measured on Zen 3, this loop alone:\n"
                  "   5.5 -> 5.1 core cycles per 16 lanes).  The same values. */\n",
                  16 - Eo, Eo, 16 - Eo, Eo, Eo, Eo);
    pf_printf(kern,
              "__attribute__((target(\"arch=x86-64-v3\"), noinline))\n"
              "static void %s_array_avx2(const %s *x, %s *y, size_t n)\n{\n"
              "    const __m256i z = _mm256_setzero_si256(), cb = _mm256_set1_epi32(%d);\n"
              "    const __m256i c3 = _mm256_set1_epi16(%d), d2 = _mm256_set1_epi16(%d), c1 = _mm256_set1_epi16(%d);\n",
              N, G->it, G->ot, (127 + Ei) * (1 << Eo), (int)(int16_t)L->pc3, (int)(int16_t)L->pd2,
              b2 ? (int)(int16_t)(L->pc1 - (1 << Eo)) : (int)(int16_t)L->pc1);
    if (!b2)
        pf_printf(kern,
                  "    const __m256i em = _mm256_set1_epi16(%d), kl = _mm256_set1_epi16(%d), c8 = _mm256_set1_epi16(-32768);\n",
                  -(1 << Eo), (int)L->k15);
    /* one step a line, @ for the block's number, $ for its offset */
    char st[10][240];
    int ns = 0, split;
    snprintf(st[ns++], sizeof st[0], "__m256i xv@ = _mm256_loadu_si256((const __m256i *)(x + i$));");
    snprintf(st[ns++], sizeof st[0], "__m256i fl@ = _mm256_castps_si256(_mm256_cvtepi32_ps(_mm256_unpacklo_epi16(xv@, z)));");
    snprintf(st[ns++], sizeof st[0], "__m256i fh@ = _mm256_castps_si256(_mm256_cvtepi32_ps(_mm256_unpackhi_epi16(xv@, z)));");
    snprintf(st[ns++], sizeof st[0],
             "__m256i u@ = _mm256_packs_epi32(_mm256_sub_epi32(_mm256_srli_epi32(fl@, %d), cb), "
             "_mm256_sub_epi32(_mm256_srli_epi32(fh@, %d), cb)); /* e 2^%d + T 2^-%d */",
             23 - Eo, 23 - Eo, Eo, 16 - Eo);
    split = ns;
    snprintf(st[ns++], sizeof st[0], "__m256i t@ = _mm256_slli_epi16(u@, %d);", 16 - Eo);
    snprintf(st[ns++], sizeof st[0], "__m256i a2_@ = _mm256_sub_epi16(d2, _mm256_mulhi_epu16(c3, t@));");
    if (b2)
        snprintf(st[ns++], sizeof st[0], "__m256i a4_@ = _mm256_sub_epi16(c1, _mm256_mulhi_epu16(a2_@, t@)); /* a4 - 2^%d */",
                 Eo);
    else
        snprintf(st[ns++], sizeof st[0], "__m256i a4_@ = _mm256_sub_epi16(c1, _mm256_mulhi_epu16(a2_@, t@));");
    if (b2)
        snprintf(st[ns++], sizeof st[0], "__m256i r@ = _mm256_add_epi16(u@, _mm256_mulhi_epu16(a4_@, t@));");
    else {
        snprintf(st[ns++], sizeof st[0],
                 "__m256i r@ = _mm256_add_epi16(_mm256_mulhrs_epi16(_mm256_and_si256(u@, em), kl), "
                 "_mm256_mulhi_epu16(a4_@, t@));");
        snprintf(st[ns++], sizeof st[0], "r@ = _mm256_blendv_epi8(r@, c8, _mm256_cmpeq_epi16(u@, c8)); /* x = 0 */");
    }
    /* Two blocks a pass, step by step, software pipelined: a pass runs the
       reduction (to u) of blocks i and i + 16 and the polynomial of blocks
       i - 32 and i - 16.  Measured (2026-12-07, Zen 3, the AVX2 loop alone
       over the 2^16 inputs shuffled, best of 400 calls, core cycles per 16
       lanes): log2 5.5 (one block a pass, pipelined) -> 5.1, log 6.45 ->
       6.2; no faster: two or four blocks a pass not pipelined, three and four
       stages of one block, the words split by masked loads (vpand) instead
       of unpacked, vpmovzxwd loads, T by vpmullw instead of the shift */
    pf_put(kern, "    size_t i = 0;\n    if (n >= 32) {\n"
                 "        /* software pipelined over pairs of blocks: a pass runs the reduction of\n"
                 "           blocks i and i + 16 and the polynomial of blocks i - 32 and i - 16,\n"
                 "           step by step (one block's chain is longer than the CPU overlaps) */\n"
                 "        __m256i p_u0, p_u1;\n        {\n");
    log_put_steps(kern, st, 0, split, 2, "            ");
    pf_put(kern, "            p_u0 = u0, p_u1 = u1;\n        }\n"
                 "        for (i = 32; i + 32 <= n; i += 32) {\n            __m256i n_u0, n_u1;\n            {\n");
    log_put_steps(kern, st, 0, split, 2, "                ");
    pf_put(kern, "                n_u0 = u0, n_u1 = u1;\n            }\n"
                 "            {\n                __m256i u0 = p_u0, u1 = p_u1;\n");
    log_put_steps(kern, st, split, ns, 2, "                ");
    pf_put(kern, "                _mm256_storeu_si256((__m256i *)(y + i - 32), r0);\n"
                 "                _mm256_storeu_si256((__m256i *)(y + i - 16), r1);\n");
    pf_put(kern, "            }\n            p_u0 = n_u0, p_u1 = n_u1;\n        }\n"
                 "        {\n            __m256i u0 = p_u0, u1 = p_u1;\n");
    log_put_steps(kern, st, split, ns, 2, "            ");
    pf_put(kern, "            _mm256_storeu_si256((__m256i *)(y + i - 32), r0);\n"
                 "            _mm256_storeu_si256((__m256i *)(y + i - 16), r1);\n");
    pf_put(kern, "        }\n    }\n    for (; i + 16 <= n; i += 16) { /* one block left of a pair */\n");
    log_put_steps(kern, st, 0, ns, 1, "        ");
    pf_put(kern, "        _mm256_storeu_si256((__m256i *)(y + i), r0);\n");
    pf_printf(kern, "    }\n    for (; i < n; i++)\n        y[i] = %s(x[i]);\n}\n#endif", N);
    G->bw16 = 3;
}

/* 16-bit lanes (see fx_log16.c.in): z = e K + P at 2^-a in an int16_t,
   then rounded once to the output; a >= Eo, and |z| 2^a must fit */
static int prepare16(fx_gen *G, char *err, size_t errlen, int base2)
{
    int Ei = G->in.exp, Eo = G->out.exp;
    double K = base2 ? 1 : M_LN2, emax = (double)G->log.emax;
    int a = 15;
    while (a >= Eo && (emax * K + 1.01) * ldexp(1.0, a) > 32767)
        a--;
    if (!base2) /* e 2^a must be an int16_t: |e| 2^a <= 2^15 */
        while (a >= Eo && emax * ldexp(1.0, a) > 32768)
            a--;
    /* the wide sum: e K + P at 2^-Ez32 in an int32_t, K from MPFR */
    int ez = 30;
    while (ez > 15 && (emax * K + 2) * ldexp(1.0, ez) > 0x1p30)
        ez--;
    if (Eo < 0 || Eo >= ez || Ei > 15 + 16 || Ei < -16) {
        snprintf(err, errlen, "16-bit lanes: e %s + P does not fit at the output's lsb", base2 ? "" : "ln2");
        return -2;
    }
    G->log.ez32 = ez;
    if (base2)
        G->log.kz32 = (int64_t)1 << ez;
    else {
        mpfr_t l;
        mpfr_init2(l, 256);
        mpfr_const_log2(l, MPFR_RNDN);
        mpfr_mul_2si(l, l, ez, MPFR_RNDN);
        mpfr_rint(l, l, MPFR_RNDN);
        G->log.kz32 = (int64_t)mpfr_get_si(l, MPFR_RNDN);
        mpfr_clear(l);
    }
    /* log2: e 2^a is exact, so a finer a only adds P's rounding before the
       final one: a = Eo.  log: at a = Eo + 1 the roundings of e ln2 and of
       P cost as much as at a = Eo, where P's is the final one: a = Eo */
    if (a >= Eo && (base2 || a == Eo + 1))
        a = Eo;
    G->log.a16 = a < Eo ? -1 : a; /* -1: only the wide sum */
    G->log.dk16 = 0;
    if (!base2) {
        mpfr_t l;
        mpfr_init2(l, 256);
        mpfr_const_log2(l, MPFR_RNDN);
        mpfr_mul_2si(l, l, 15, MPFR_RNDN);
        mpfr_rint(l, l, MPFR_RNDN);
        G->log.k15 = (int64_t)mpfr_get_si(l, MPFR_RNDN);
        mpfr_const_log2(l, MPFR_RNDN);
        mpfr_mul_2si(l, l, 15, MPFR_RNDN);
        mpfr_sub_si(l, l, (long)G->log.k15, MPFR_RNDN);
        double kerr = fabs(mpfr_get_d(l, MPFR_RNDN));
        mpfr_clear(l);
        /* round(e 2^a K15 2^-15): half an lsb, and |e| 2^a |K15 - ln2 2^15| 2^-15 */
        G->log.dk16 = ldexp(0.5, -a) + emax * kerr * 0x1p-15;
    }
    return 0;
}

static int prepare(fx_gen *G, char *err, size_t errlen, int base2)
{
    const char *fn = base2 ? "log2" : "log";
    int Ei = G->in.exp, Eo = G->out.exp;
    if (!G->out.is_signed) {
        snprintf(err, errlen, "%s: output type %s is unsigned but %s takes negative values (and %s(0) saturates "
                              "to the most negative output); use a signed type",
                 fn, G->out_text, fn, fn);
        return -1;
    }
    if (Ei > 200 || Ei < -200) {
        snprintf(err, errlen, "%s: input exponent %d not supported", fn, Ei);
        return -1;
    }
    int64_t imax = pf_type_max_stored(&G->in);
    int nb = fx_bitlen((uint64_t)imax);
    int64_t elo = -Ei, ehi = nb - 1 - Ei;
    G->log.emax = elo < 0 ? -elo : elo;
    if ((ehi < 0 ? -ehi : ehi) > G->log.emax)
        G->log.emax = ehi < 0 ? -ehi : ehi;
    G->log.ez = 62 - fx_bitlen((uint64_t)G->log.emax + 1) - 1;
    if (G->log.ez <= Eo) {
        snprintf(err, errlen, "%s: output lsb 2^-%d is finer than the 64-bit sum can hold", fn, Eo);
        return -1;
    }
    if (base2) {
        G->log.kz = (int64_t)1 << G->log.ez;
    } else {
        mpfr_t l;
        mpfr_init2(l, 256);
        mpfr_const_log2(l, MPFR_RNDN);
        mpfr_mul_2si(l, l, G->log.ez, MPFR_RNDN);
        mpfr_rint(l, l, MPFR_RNDN);
        mpz_t z;
        mpz_init(z);
        mpfr_get_z(z, l, MPFR_RNDN);
        G->log.kz = (int64_t)mpz_get_si(z);
        mpz_clear(z);
        mpfr_clear(l);
    }
    G->fmax = 0;
    G->kind = 0;
    G->alt_domain[0] = G->alt_order[0] = G->alt_method[0] = G->alt_con[0] = G->alt_formats[0] = G->alt_poly[0] = 0;
    G->alt_arith[0] = 0;
    G->bound_note[0] = 0;
    snprintf(G->sat_text, sizeof G->sat_text, "%s(x) for x <= 0 (undefined) gives %lld, the most negative output",
             fn, (long long)pf_type_min_stored(&G->out));
    if (G->W == 16) {
        /* the table kernel where the type pair allows it, else the Horner form */
        if (prep_poly(G, base2) == 0) {
            G->kind = 2;
            poly_texts(G);
            return 0;
        }
        if (prep_tab(G, base2) == 0) {
            G->kind = 1;
            tab_texts(G, base2);
            return 0;
        }
        return prepare16(G, err, errlen, base2);
    }
    G->dred = base2 ? 0 : (double)G->log.emax * ldexp(0.5, -G->log.ez);
    snprintf(G->red_text, sizeof G->red_text,
             "x = 2^e (1 + t), e = n - %d with n = bitlen(x) - 1 (leading-zero count), t in [0, 1) the bits "
             "below the leading one (exact); %s(x) = e %s + P(t) summed in 64 bits at 2^-%d%s, rounded once; "
             "x <= 0 -> %lld (most negative)",
             Ei, fn, base2 ? "" : "ln2", (int)G->log.ez,
             base2 ? "" : " (ln2 = KZ 2^-Ez, KZ from MPFR)", (long long)pf_type_min_stored(&G->out));
    return 0;
}

static int prep_log(fx_gen *G, char *err, size_t n) { return prepare(G, err, n, 0); }
static int prep_log2(fx_gen *G, char *err, size_t n) { return prepare(G, err, n, 1); }

static void budget16(fx_gen *G)
{
    if (G->kind == 2) {
        /* the cubic kernel: the max error over every input, less the 1/2
           lsb the bound adds for a final rounding (its final step is a floor,
           in terr); the fitter's cubic error as the polynomial's share */
        G->R = 0;
        G->A = (G->log.terr > 0.5 ? G->log.terr - 0.5 : 0) * fx_lsb(G);
        G->poly_err = G->log.pfit < G->A ? G->log.pfit : G->A;
        return;
    }
    if (G->kind == 1) {
        /* the table kernel: no Horner polynomial (the fit the pipeline makes
           is not used); the pre-rounding error over every input, of which the
           segment lines' share is the polynomial's */
        G->R = 0;
        G->A = G->log.terr * fx_lsb(G);
        G->poly_err = ldexp(G->log.tseg, -(G->out.exp + G->log.td));
        return;
    }
    /* 16-bit sum: e K (rounded for log), P rounded to 2^-a when finer, then
       the final rounding (the 1/2 lsb).  Wide sum, when that misses the
       bound: e K exact but for K's rounding, P exact, one rounding */
    G->R = 0;
    double a16 = INFINITY;
    if (G->log.a16 >= 0 && G->Ep >= G->log.a16)
        /* P's rounding to 2^-a is the final one when a = Eo (z is the result) */
        a16 = G->poly_err + G->arith + G->log.dk16 +
              (G->Ep > G->log.a16 && G->log.a16 > G->out.exp ? ldexp(0.5, -(int)G->log.a16) : 0);
    /* log, split form (all in 16-bit words): e ln2 2^Ep = e H 2^d + e L
       + e (ln2 2^Ep - Kp), Kp = round(ln2 2^Ep) = H 2^d + L, d = Ep - Eo.
       e H is exact at the output's lsb, e L + P at P's lsb is rounded once
       to it (the final rounding); the only other error is e's share of
       Kp's rounding, |e| |ln2 2^Ep - Kp| 2^-Ep */
    double asplit = INFINITY;
    G->log.split = 0;
    int d = G->Ep - G->out.exp;
    if (G->fn->ref == PF_LOG && d >= 1 && d <= 14 && G->Ep <= 30) {
        mpfr_t l, r;
        mpfr_inits2(256, l, r, (mpfr_ptr)0);
        mpfr_const_log2(l, MPFR_RNDN);
        mpfr_mul_2si(r, l, G->out.exp, MPFR_RNDN);
        mpfr_rint(r, r, MPFR_RNDN);
        int64_t H = (int64_t)mpfr_get_si(r, MPFR_RNDN);
        mpfr_mul_2si(l, l, G->Ep, MPFR_RNDN);
        mpfr_rint(r, l, MPFR_RNDN);
        int64_t Kp = (int64_t)mpfr_get_si(r, MPFR_RNDN);
        mpfr_sub(r, l, r, MPFR_RNDN);
        double kerr = fabs(mpfr_get_d(r, MPFR_RNDN));
        mpfr_clears(l, r, (mpfr_ptr)0);
        int64_t L = Kp - (H << d), em = G->log.emax;
        /* |P| <= log(2) plus its errors, below 0.7 in P's units */
        double pmax = 0.7 * ldexp(1.0, G->Ep);
        if (em * (H < 0 ? -H : H) + (int64_t)ldexp(pmax + (double)(em * (L < 0 ? -L : L)), -d) + 2 <= 32767 &&
            pmax + (double)(em * (L < 0 ? -L : L)) <= 32767) {
            G->log.hs = H;
            G->log.ls = L;
            G->log.dsplit = (double)em * kerr * ldexp(1.0, -G->Ep);
            asplit = G->poly_err + G->arith + G->log.dsplit;
        }
    }
    int kexact = G->log.kz32 == (int64_t)1 << G->log.ez32; /* log2 */
    double a32 = G->poly_err + G->arith + (kexact ? 0 : (double)G->log.emax * ldexp(0.5, -(int)G->log.ez32));
    if (G->Ep > G->log.ez32)
        a32 = INFINITY;
    if (fx_within(G, 0, a16)) {
        G->log.wide = 0;
        G->A = a16;
    } else if (fx_within(G, 0, asplit)) {
        G->log.wide = 0;
        G->log.split = 1;
        G->A = asplit;
    } else {
        G->log.wide = 1;
        G->A = a32;
    }
}

static void budget(fx_gen *G)
{
    if (G->W == 16) {
        budget16(G);
        return;
    }
    G->R = 0;
    int d = (int)G->log.ez - G->Ep;
    G->A = G->poly_err + G->arith + G->dred + (d < 0 ? ldexp(0.5, -(int)G->log.ez) : 0);
}

/* round(v / 2^d), ties up, 1 <= d <= 15, as the rounding multiply-high by
   2^(15-d): floor(v 2^(15-d) 2^-15 + 1/2), pf_fx_rsh16's value in one
   pmulhrsw instead of two shifts, an and and an add */
static const char *rsh_mulhrs(fx_gen *G, char *buf, size_t n, const char *v, int d)
{
    char w[96];
    snprintf(w, sizeof w, "2^%d: round(z / 2^%d), a rounding multiply-high", 15 - d, d);
    snprintf(buf, n, "pf_fx_mulhrs(%s, %s)", v, fx_k16(G, (int64_t)1 << (15 - d), w));
    return buf;
}

static void emit16(fx_gen *G, pf_buf *b, int base2)
{
    if (G->kind == 2) {
        pf_buf tb = {0}, tt = {0}, tk = {0};
        emit_poly(G, &tb, &tt, &tk);
        const char *kv[] = {"FUNC", base2 ? "log2" : "log", "KTEXT", base2 ? "" : " ln2", "PTEXT",
                            base2 ? "log2(1 + t)" : "log(1 + t)", "NAME", G->name, "IT", G->it, "OT", G->ot,
                            "BODY", tb.s, "TABLES", tt.s ? tt.s : "", "KERNEL", tk.s, NULL};
        pf_subst(b, pf_template("fx_logpoly16.c"), kv);
        free(tb.s);
        free(tt.s);
        free(tk.s);
        return;
    }
    if (G->kind == 1) {
        pf_buf tb = {0}, tt = {0}, tk = {0};
        emit_tab(G, &tb, &tt, &tk, base2);
        char minout[32];
        snprintf(minout, sizeof minout, "%lld", (long long)pf_type_min_stored(&G->out));
        const char *kv[] = {"FUNC", base2 ? "log2" : "log", "KTEXT", base2 ? "" : " ln2", "PTEXT",
                            base2 ? "log2(1 + t)," : "log(1 + t),", "MINOUT", minout, "NAME", G->name, "IT", G->it,
                            "OT", G->ot, "BODY", tb.s, "TABLES", tt.s, "KERNEL", tk.s, NULL};
        pf_subst(b, pf_template("fx_logtab16.c"), kv);
        free(tb.s);
        free(tt.s);
        free(tk.s);
        return;
    }
    pf_buf body = {0}, horner = {0};
    int Ei = G->in.exp, Eo = G->out.exp, a = (int)G->log.a16, Ep = G->Ep;
    int nb = fx_bitlen((uint64_t)pf_type_max_stored(&G->in));
    int64_t mn = pf_type_min_stored(&G->out);
    char sumtxt[200];
    if (G->log.wide)
        snprintf(sumtxt, sizeof sumtxt, "in an int32_t at 2^-%d (%s)", (int)G->log.ez32,
                 base2 ? "e exact" : "ln2 = K 2^-Ez, K from MPFR");
    else if (G->log.split)
        snprintf(sumtxt, sizeof sumtxt,
                 "in 16-bit words with ln2 in two words: e H at 2^-%d exact (H = round(ln2 2^%d) = %lld) plus "
                 "e L + P at 2^-%d (L = round(ln2 2^%d) - H 2^%d = %lld; MPFR) rounded to 2^-%d",
                 Eo, Eo, (long long)G->log.hs, Ep, Ep, Ep - Eo, (long long)G->log.ls, Eo);
    else
        snprintf(sumtxt, sizeof sumtxt, "in an int16_t at 2^-%d%s", a,
                 base2 ? "" : " (e ln2 = round(e 2^a K 2^-15), K = round(ln2 2^15) from MPFR, the rounding "
                              "multiply-high)");
    pf_put(&body, "    uint16_t ux = (uint16_t)(x > 0 ? x : 1); /* x <= 0 is selected at the end */\n");
    fx_emit_norm16_tq(G, &body, nb);
    pf_put(&body, "\n");
    pf_put(&body, "    /* P(t) ~ ");
    pf_put(&body, base2 ? "log2(1 + t)" : "log(1 + t)");
    pf_put(&body, ": Horner in 16-bit words, one rounding per step */\n");
    fx_emit_horner(G, &horner, "tq", "    ");
    pf_put(&body, horner.s);
    int64_t mx = pf_type_max_stored(&G->out);
    char rc[200];
    if (G->log.wide) {
        int ez = (int)G->log.ez32;
        pf_printf(&body, "    /* e%s + P at 2^-%d in 32-bit lanes (see Lanes above), rounded once */\n",
                  base2 ? "" : " ln2", ez);
        pf_printf(&body, "    int32_t z = (int32_t)(n - %d) * %lld + (int32_t)p * %lld;\n", Ei, (long long)G->log.kz32,
                  (long long)1 << (ez - Ep));
        pf_printf(&body, "    int32_t r = pf_fx_rsh32(z, %d);\n", ez - Eo);
        snprintf(rc, sizeof rc, "(int16_t)(r < %lld ? %lld : r > %lld ? %lld : r)", (long long)mn, (long long)mn,
                 (long long)mx, (long long)mx);
        snprintf(G->wide_text, sizeof G->wide_text,
                 "the sum e%s + P and its rounding are in 32-bit lanes: at the 16-bit sum's lsb 2^-%d, the "
                 "roundings of e%s and of P would leave the %s bound",
                 base2 ? "" : " ln2", a < 0 ? Eo : a, base2 ? "" : " ln2", G->exact ? "exact (1 LSB)" : "fast");
    } else if (G->log.split) {
        int d = Ep - Eo;
        char w[96];
        snprintf(w, sizeof w, "H = round(ln2 2^%d): e ln2 at 2^-%d, high word", Eo, Eo);
        pf_printf(&body, "    int16_t eh = (int16_t)((n - %d) * %s); /* e H, exact */\n", Ei, fx_k16(G, G->log.hs, w));
        snprintf(w, sizeof w, "L = round(ln2 2^%d) - H 2^%d: low word at 2^-%d", Ep, d, Ep);
        pf_printf(&body, "    int16_t el = (int16_t)((n - %d) * %s); /* e L, exact */\n", Ei, fx_k16(G, G->log.ls, w));
        pf_printf(&body, "    /* e ln2 + P = e H 2^-%d + (e L + P) 2^-%d (but for e's share of round(ln2 2^%d)), "
                         "rounded once */\n", Eo, Ep, Ep);
        char rs[96];
        pf_printf(&body, "    int16_t r = (int16_t)(eh + %s);\n", rsh_mulhrs(G, rs, sizeof rs, "(int16_t)(el + p)", d));
    } else {
        char pa[96];
        if (Ep > a)
            rsh_mulhrs(G, pa, sizeof pa, "p", Ep - a);
        else
            snprintf(pa, sizeof pa, "p");
        char w[64];
        snprintf(w, sizeof w, "2^%d: e at 2^-%d", a, a);
        pf_printf(&body, "    int16_t ea = (int16_t)((n - %d) * %s); /* e 2^%d */\n", Ei, fx_k16(G, (int64_t)1 << a, w), a);
        if (base2)
            pf_printf(&body, "    int16_t z = (int16_t)(ea + %s); /* e + P at 2^-%d */\n", pa, a);
        else
            pf_printf(&body, "    int16_t z = (int16_t)(pf_fx_mulhrs(ea, %s) + %s); /* e ln2 + P at 2^-%d */\n",
                      fx_k16(G, G->log.k15, "round(ln2 2^15)"), pa, a);
        if (a > Eo) {
            char rs[96];
            pf_printf(&body, "    int16_t r = %s; /* rounded once to the output */\n", rsh_mulhrs(G, rs, sizeof rs, "z", a - Eo));
        } else {
            pf_put(&body, "    int16_t r = z;\n");
        }
    }
    if (!G->log.wide) { /* both 16-bit sums end in r: its clamp to the output's range */
        pf_put(&body, "    int16_t rc = (int16_t)");
        rc[0] = 0;
        if (mn > -32768)
            snprintf(rc + strlen(rc), sizeof rc - strlen(rc), "(r < %lld ? %lld : ", (long long)mn, (long long)mn);
        if (mx < 32767)
            snprintf(rc + strlen(rc), sizeof rc - strlen(rc), "(r > %lld ? %lld : ", (long long)mx, (long long)mx);
        snprintf(rc + strlen(rc), sizeof rc - strlen(rc), "r%s%s", mx < 32767 ? ")" : "", mn > -32768 ? ")" : "");
        pf_put(&body, rc);
        pf_put(&body, ";\n");
        snprintf(rc, sizeof rc, "rc");
    }
    /* x <= 0: with the sum in 32-bit lanes through a mask (a select on x
       makes GCC widen the loop); in 16-bit lanes as a select, which the
       AVX-512 loop does in one masked move (the mask took four
       instructions; the AVX2 clone's loop is the same either way) */
    if (G->log.wide) {
        pf_put(&body, "    uint16_t m = (uint16_t)(0u - (uint16_t)(x <= 0)); /* all ones for x <= 0 */\n");
        pf_printf(&body, "    int16_t rc = %s;\n", rc);
        pf_printf(&body, "    return (%s)(int16_t)(((uint16_t)rc & ~m) | ((uint16_t)%lld & m));", G->ot, (long long)mn);
    } else {
        pf_printf(&body, "    return (%s)(x <= 0 ? %lld : rc);", G->ot, (long long)mn);
    }
    snprintf(G->red_text, sizeof G->red_text,
             "x = 2^e (1 + t), e = n - %d with n = bitlen(x) - 1 (a staged normalization: constant shifts and "
             "selects; on AVX-512 CPUs a leading-zero count, the same n), t in [0, 1) the 15 bits below the leading one (exact); %s(x) = e%s + P(t) summed %s, "
             "rounded once; x <= 0 -> %lld (most negative)",
             Ei, base2 ? "log2" : "log", base2 ? "" : " ln2", sumtxt, (long long)mn);
    char minout[32];
    snprintf(minout, sizeof minout, "%lld", (long long)mn);
    const char *kv[] = {"FUNC", base2 ? "log2" : "log", "KTEXT", base2 ? "" : "ln2", "PTEXT",
                        base2 ? "log2(1 + t)" : "log(1 + t)", "MINOUT", minout, "NAME", G->name, "IT", G->it, "OT",
                        G->ot, "BODY", body.s, NULL};
    pf_subst(b, pf_template("fx_log16.c"), kv);
    free(body.s);
    free(horner.s);
}

static void emit(fx_gen *G, pf_buf *b, int base2)
{
    if (G->W == 16) {
        emit16(G, b, base2);
        return;
    }
    pf_buf norm = {0}, horner = {0}, out = {0};
    int Ei = G->in.exp, Eo = G->out.exp;
    int64_t mx = pf_type_max_stored(&G->out), mn = pf_type_min_stored(&G->out);
    fx_emit_norm(G, &norm);
    fx_emit_horner(G, &horner, "t", "    ");
    pf_chomp(&horner);
    int d = (int)G->log.ez - G->Ep;
    char pz[96];
    if (d > 0)
        snprintf(pz, sizeof pz, "(int64_t)p * INT64_C(%lld)", (long long)((int64_t)1 << d));
    else if (d == 0)
        snprintf(pz, sizeof pz, "(int64_t)p");
    else
        snprintf(pz, sizeof pz, "pf_fx_rne(p, %d)", -d);
    pf_printf(&out, "    /* e %s + P(t) at 2^-%d, exact; one rounding to the output */\n", base2 ? "" : "ln2", (int)G->log.ez);
    if (base2 || G->log.kz <= INT32_MAX)
        pf_printf(&out, "    int64_t z = (int64_t)(n - %d) * INT64_C(%lld) + %s;\n", Ei, (long long)G->log.kz, pz);
    else /* e K from two 32x32-bit products, which vectorize (K = KH 2^31 + KL) */
        pf_printf(&out,
                  "    int64_t z = (int64_t)(n - %d) * %lld * INT64_C(2147483648) + (int64_t)(n - %d) * %lld + %s;\n",
                  Ei, (long long)(G->log.kz >> 31), Ei, (long long)(G->log.kz & 0x7fffffff), pz);
    pf_printf(&out, "    int64_t r = pf_fx_rne(z, %d);\n", (int)G->log.ez - Eo);
    pf_printf(&out, "    r = r > %lld ? %lld : r < %lld ? %lld : r;\n", (long long)mx, (long long)mx, (long long)mn,
              (long long)mn);
    pf_printf(&out, "    return (%s)(x > 0 ? r : %lld);", G->ot, (long long)mn);
    char minout[32];
    snprintf(minout, sizeof minout, "%lld", (long long)mn);
    const char *kv[] = {"FUNC", base2 ? "log2" : "log", "KTEXT", base2 ? "" : "ln2", "PTEXT",
                        base2 ? "log2(1 + t)" : "log(1 + t)", "MINOUT", minout, "NAME", G->name, "IT", G->it, "OT",
                        G->ot, "NORM_CODE", norm.s, "HORNER", horner.s, "OUT_CODE", out.s, NULL};
    pf_subst(b, pf_template("fx_log.c"), kv);
    free(norm.s);
    free(horner.s);
    free(out.s);
}

static void emit_log(fx_gen *G, pf_buf *b) { emit(G, b, 0); }
static void emit_log2(fx_gen *G, pf_buf *b) { emit(G, b, 1); }

const fx_func fx_func_log = {
    .name = "log", .ref = PF_LOG, .tmpl = "fx_log", .target_text = "log(1+t)", .g = g_log1p, .a = 0, .b = 1,
    .parity = FIT_PARITY_NONE, .errkind = FIT_ABS, .errkind_fast = FIT_ABS, .con_zero = 1, .con_text = "p(0) = 0 (log(1) = 0 exactly)",
    .prepare = prep_log, .budget = budget, .emit = emit_log,
};

const fx_func fx_func_log2 = {
    .name = "log2", .ref = PF_LOG2, .tmpl = "fx_log", .target_text = "log2(1+t)", .g = g_log2_1p, .a = 0, .b = 1,
    .parity = FIT_PARITY_NONE, .errkind = FIT_ABS, .errkind_fast = FIT_ABS, .con_zero = 1,
    .con_text = "p(0) = 0 (log2 of powers of 2 exact)", .prepare = prep_log2, .budget = budget, .emit = emit_log2,
};
