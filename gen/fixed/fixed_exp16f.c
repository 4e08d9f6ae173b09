/* exp and exp2, fast variant, 16-bit lanes: the segment-table kernel
 * (kind 2).
 *
 * x is clamped from above to D (D = XSAT where the output saturates), and
 * u = D - x (a uint16_t: D - min(x) < 2^16) is taken, so that
 * w = t(D) - t >= 0 needs no bias and grows to the underflow side:
 * exp2: W = u (w 2^Ei, exact); exp: W = floor(u L 2^-16) with
 * L = round(log2(e) 2^15), w at 2^-(Ei - 1).  With W = c 2^fb + g 2^fb,
 * f(x) 2^Eo = 2^(t(D) + Eo - g) 2^-c: T(g) = 2^(t(D) + Eo - g) in
 * [2^15, 2^16) (t(D) + Eo ~ 16 at XSAT) comes from 16 segments on g, each
 * a chord (C0 at the seams: value V[j] = T(j/16 + d), drop S[j] =
 * V[j] - T((j+1)/16 + d), from MPFR, rounded to nearest; d, a quarter
 * step of W's lsb, centres the floors' error), and the result is T >> c
 * (truncated; c >= 16 gives 0: below 1 lsb).  At x >= D: W = 0, the result
 * V[0] = the output's max (saturation, as the exact variant).
 *
 * Per 32 lanes on AVX-512BW: vpminsw, vpsubw, (exp: vpmulhuw), vpsrlw,
 * two vpermw (16 entries repeated in a 32-entry table: the index needs no
 * mask), vpsllw, vpmulhuw, vpsubw, vpsrlw, vpsrlvw: 10 or 11 instructions
 * where the degree-3 Horner took ~20.  AVX2 (16 lanes): 16 entries are
 * what one vpshufb reaches, so the same table serves both (bit-identical
 * clones); 20 or 21 instructions per 16 lanes (exp2, exp), j carried by
 * the chord (see fx_exp16f_emit).  Measured on Zen 3 (min of 2000 calls
 * on 2^16 inputs, TSC ticks per 16 lanes): exp 5.35 -> 4.86, exp2 4.95 ->
 * 4.67 against the 22/21-instruction loop with j copied to both bytes;
 * the float fast arrays take 7.9 and 8.1 there.  No analytic chain: the bound is
 * taken by running the emitted integer steps (ft_eval, the same C) on every
 * one of the 2^16 inputs against 2^t in long double, and the kernel is used
 * only when that is within the fast bound max(2^-10 relative, 4 lsb) with
 * margin, else the Horner form stays. */
#include "fixed_exp16f.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define FT_J 4 /* 16 segments: one vpermw (or, later, a vpshufb pair) per table */

static long double t_of(int base2, int Ei, int64_t x)
{
    long double t = ldexpl((long double)x, -Ei);
    return base2 ? t : t * 1.4426950408889634073599246810018921L;
}

/* the emitted steps for one stored input (as fx_exp16f_emit writes them) */
static unsigned ft_eval(const fx_exp_red *X, int base2, int64_t x)
{
    int fb = X->ffb, rb = fb - FT_J;
    int64_t xc = x < X->fd ? x : X->fd;
    uint16_t u = (uint16_t)(X->fd - xc);
    uint16_t w = base2 ? u : (uint16_t)((uint32_t)u * (uint32_t)X->fl >> 16);
    unsigned j = (unsigned)(w >> rb) & 15u;
    uint16_t rr = (uint16_t)((uint32_t)w << (16 - rb));
    uint16_t v = (uint16_t)(X->fv[j] - ((uint32_t)X->fs[j] * rr >> 16));
    unsigned c = (unsigned)(w >> fb);
    return c < 16 ? (unsigned)(v >> c) : 0u;
}

/* T(g) = 2^(tD + Eo - g) 2^-d at g = j/16 (MPFR, 256 bits), rounded to
   nearest, capped at omax */
static int64_t tval(const mpfr_t tde, int j, int q, int fb, int64_t omax)
{
    mpfr_t a;
    mpfr_init2(a, 256);
    mpfr_set_si(a, -j, MPFR_RNDN);
    mpfr_div_2ui(a, a, FT_J, MPFR_RNDN);              /* -j/16, exact */
    mpfr_t d;
    mpfr_init2(d, 256);
    mpfr_set_si(d, q, MPFR_RNDN);
    mpfr_div_2ui(d, d, (unsigned long)(fb + 2), MPFR_RNDN); /* q/4 of 2^-fb, exact */
    mpfr_sub(a, a, d, MPFR_RNDN);
    mpfr_add(a, a, tde, MPFR_RNDN);
    mpfr_exp2(a, a, MPFR_RNDN);
    mpfr_rint(a, a, MPFR_RNDN);
    double v = mpfr_get_d(a, MPFR_RNDN);
    mpfr_clear(a);
    mpfr_clear(d);
    return v > (double)omax ? omax : (int64_t)v;
}

/* max of |y - f| / max(2^-10 f, 4) over every input (f capped at the
   output's max as the sweep does), and R = max (|y - f| - 1) / f */
static double ft_score(const fx_exp_red *X, int base2, const long double *f, int64_t imin, int64_t imax,
                       double omax, double *R)
{
    double worst = 0, r = 0;
    for (int64_t x = imin; x <= imax; x++) {
        long double fv = f[x - imin];
        if (fv > omax)
            fv = omax;
        double e = (double)fabsl((long double)ft_eval(X, base2, x) - fv);
        double a = 0x1p-10 * (double)fv;
        a = a > 4 ? a : 4;
        worst = e / a > worst ? e / a : worst;
        if (fv > 0 && e > 1 && (e - 1) / (double)fv > r)
            r = (e - 1) / (double)fv;
    }
    *R = r;
    return worst;
}

int fx_exp16f_prep(fx_gen *G, int base2)
{
    fx_exp_red *X = &G->exp;
    int Ei = G->in.exp, Eo = G->out.exp;
    if (G->exact || G->in.storage_bits != 16 || !G->in.is_signed || G->out.storage_bits != 16)
        return -2;
    int fb = base2 ? Ei : Ei - 1;
    if (fb < FT_J + 1 || Ei > 15)
        return -2;
    int64_t imin = pf_type_min_stored(&G->in), imax = pf_type_max_stored(&G->in);
    int64_t omax = pf_type_max_stored(&G->out);
    if (imax - imin != 65535)
        return -2;
    long double *f = malloc(65536 * sizeof *f);
    if (!f)
        return -2;
    for (int64_t x = imin; x <= imax; x++)
        f[x - imin] = exp2l(t_of(base2, Ei, x) + Eo);
    mpfr_t l2e, tde;
    mpfr_init2(l2e, 256);
    mpfr_init2(tde, 256);
    mpfr_set_ui(l2e, 1, MPFR_RNDN);
    mpfr_exp(l2e, l2e, MPFR_RNDN);
    mpfr_log2(l2e, l2e, MPFR_RNDN);
    int64_t lc[2] = {0, 0};
    if (!base2) {
        mpfr_t a;
        mpfr_init2(a, 256);
        mpfr_mul_2ui(a, l2e, 15, MPFR_RNDN);
        mpfr_floor(a, a);
        lc[0] = (int64_t)mpfr_get_d(a, MPFR_RNDN);
        lc[1] = lc[0] + 1;
        mpfr_clear(a);
    }
    /* candidates: D = XSAT or the one below (the output's max at W = 0),
       or the top input when nothing saturates; L either rounding; d in
       quarters of W's lsb.  The best worst-case ratio is kept (ties: the
       first, so generation is deterministic) */
    int64_t dc[2] = {X->sat ? X->xsat : imax, X->sat ? X->xsat - 1 : imax};
    fx_exp_red best = *X;
    double bscore = INFINITY, bR = 0;
    for (int di = 0; di < 2; di++) {
        int64_t D = dc[di];
        if (D > imax || D - imin > 65535 || (di && dc[1] == dc[0]))
            continue;
        mpfr_set_si(tde, (long)D, MPFR_RNDN);
        mpfr_div_2si(tde, tde, Ei, MPFR_RNDN);
        if (!base2)
            mpfr_mul(tde, tde, l2e, MPFR_RNDN);
        mpfr_add_si(tde, tde, Eo, MPFR_RNDN);     /* t(D) + Eo */
        if (mpfr_cmp_d(tde, 16.01) > 0 || mpfr_cmp_d(tde, 14.5) < 0)
            continue; /* T would overflow 16 bits, or waste them */
        for (int li = 0; li < (base2 ? 1 : 2); li++)
            for (int qf = 0; qf < 8; qf++) {
                int q = qf & 3, force = qf >> 2; /* force: V[0] = the max (saturation) */
                X->fd = D;
                X->fl = lc[li];
                X->ffb = fb;
                X->fq = qf;
                int64_t v[17];
                for (int j = 0; j <= 16; j++)
                    v[j] = tval(tde, j, q, fb, omax);
                if (force) {
                    if (v[0] == omax)
                        continue;
                    v[0] = omax;
                }
                for (int j = 0; j < 16; j++) {
                    X->fv[j] = (uint16_t)v[j];
                    X->fs[j] = (uint16_t)(v[j] - v[j + 1]);
                }
                /* saturation as the exact variant's: the max from XSAT up */
                if (X->sat && ft_eval(X, base2, imax) != (unsigned)omax)
                    continue;
                double R, s = ft_score(X, base2, f, imin, imax, (double)omax, &R);
                if (s < bscore) {
                    bscore = s;
                    bR = R;
                    best = *X;
                }
            }
    }
    mpfr_clear(l2e);
    mpfr_clear(tde);
    free(f);
    *X = best;
    /* a margin for the long double reference (its error is ~2^-63) and the
       sweep's own MPFR: 0.9 of the bound */
    if (!(bscore <= 0.9))
        return -2;
    X->fratio = bscore;
    X->fr = bR;
    G->kind = 2;
    fx_exp16f_budget(G);
    if (!fx_within(G, G->R, G->A)) {
        G->kind = 0;
        return -2;
    }
    return 0;
}

void fx_exp16f_budget(fx_gen *G)
{
    /* |y - f| <= R |f| + 1 lsb for every input (measured, above): A is the
       1/2 lsb beyond the model's final rounding, as the truncating Horner
       form counts it */
    G->R = G->exp.fr;
    G->A = 0.5 * fx_lsb(G);
    G->poly_err = 0;
}

/* The AVX2 loop carries j in the chord when every 16 S[j] fits a 16-bit
   word; else it takes the older loop with j in both index bytes.  The
   provenance text and the emitter ask the same question here. */
static int avx2_chord_fits(const fx_exp_red *X)
{
    for (int k = 0; k < 16; k++)
        if (X->fs[k] >= 4096)
            return 0;
    return 1;
}

void fx_exp16f_texts(fx_gen *G, int base2)
{
    const fx_exp_red *X = &G->exp;
    int Ei = G->in.exp, fb = X->ffb;
    if (base2)
        snprintf(G->red_text, sizeof G->red_text,
                 "t = x; W = (t(D) - t) 2^%d = u = D - min(x, D), D = %lld (stored; exact, a uint16_t); "
                 "c = W >> %d, g = (W mod 2^%d) 2^-%d in [0, 1): f(x) = 2^(t(D) - g) 2^-c",
                 Ei, (long long)X->fd, fb, fb, fb);
    else
        snprintf(G->red_text, sizeof G->red_text,
                 "t = x log2(e); W = floor(u L 2^-16) ~ (t(D) - t) 2^%d with u = D - min(x, D), D = %lld (stored; "
                 "a uint16_t) and L = %lld ~ log2(e) 2^15 (MPFR, the rounding the sweep below picked); c = W >> %d, "
                 "g = (W mod 2^%d) 2^-%d in [0, 1): f(x) = 2^(t(D) - g) 2^-c",
                 fb, (long long)X->fd, (long long)X->fl, fb, fb, fb);
    (void)Ei;
    snprintf(G->alt_domain, sizeof G->alt_domain,
             "T(g) = 2^(t(D) + Eo - g - d) on g in [0, 1), d = %d/4 2^-%d (centres the floors), 16 segments%s",
             X->fq & 3, fb, X->fq >> 2 ? "; V[0] raised to the output's max (saturation at XSAT)" : "");
    snprintf(G->alt_order, sizeof G->alt_order,
             "1 per segment: 16 chords of T (value and drop, two 16-entry tables); uint16_t words: 16-bit lanes");
    snprintf(G->alt_method, sizeof G->alt_method,
             "chords through T(j/16) (C0 at the seams): V[j] = round(T(j/16)), S[j] = V[j] - round(T((j+1)/16)), "
             "T from MPFR (256 bits), capped at the output's max (or V[0] set to it); D, L, d and V[0]'s choice taken over the candidates by the "
             "smallest worst case over every input");
    snprintf(G->alt_con, sizeof G->alt_con, "T(0) at D: the output's max at and above XSAT (the saturation)");
    snprintf(G->alt_formats, sizeof G->alt_formats,
             "W uint16_t at 2^-%d; j = (W >> %d) & 15, r = W mod 2^%d as rr = W << %d (r 2^-%d at 2^-16); "
             "T ~ V[j] - pmulhuw(S[j], rr) (floor); result T >> c (vpsrlvw; floor, 0 for c >= 16)",
             fb, fb - FT_J, fb - FT_J, 16 - (fb - FT_J), fb - FT_J);
    snprintf(G->alt_poly, sizeof G->alt_poly,
             "worst case over every input %.4f of the fast bound max(2^-10 |f|, 4 lsb); |y - f| <= %.3e |f| + 1 lsb",
             X->fratio, X->fr);
    int s16ok = avx2_chord_fits(X);
    if (s16ok)
        snprintf(G->wide_text, sizeof G->wide_text,
                 "16-bit words throughout; AVX-512BW (x86-64-v4): lookups vpermw, the shift vpsrlvw; AVX2 "
                 "(x86-64-v3): a lookup two vpshufb (by j, j << 8) and %s, tables V[j] + j S[j] and 16 S[j] times "
                 "W << %d (j S[j] cancels: no shift for r), the shift in 32-bit lanes (vpsrlvd) on even and odd "
                 "words; the default clone, scalar form: the same steps in plain C",
                 X->fv[0] % 257 == 0 ? "vpaddw (V) or vpblendvb (S)" : "vpblendvb", 16 - fb);
    else
        snprintf(G->wide_text, sizeof G->wide_text,
                 "16-bit words throughout; the lookups (vpermw) and the per-element shift (vpsrlvw) in 16-bit lanes by "
                 "AVX-512BW intrinsics (x86-64-v4); AVX2 intrinsics (x86-64-v3): each lookup two vpshufb and a "
                 "vpblendvb, the shift in 32-bit lanes (vpsrlvd) on the even and odd words; the default clone, scalar "
                 "form: the same steps in plain C");
    snprintf(G->alt_arith, sizeof G->alt_arith,
             "integers only (no floating point, no <math.h>); floors (multiply-highs, shifts), all in the bound; "
             "bit-identical under any compiler flags");
    snprintf(G->bound_note, sizeof G->bound_note,
             "taken over every input from the emitted integer steps against 2^t in long double (the segment table "
             "kernel)");
}

/* 16 entries as uint32_t (GCC vectorizes plain-C lookups of 32-bit
   entries), for the AVX-512 loop narrowed and repeated to 32 words */
static void ft_table(pf_buf *b, const char *name, const char *suf, const uint16_t *v, const char *what)
{
    pf_printf(b, "/* %s */\nstatic const uint32_t %s_%s[16] = {", what, name, suf);
    for (int i = 0; i < 16; i++)
        pf_printf(b, "%s%u,", i % 8 ? " " : "\n    ", v[i]);
    pf_put(b, "\n};\n");
}

static long long s16(int64_t v) { return (long long)(int16_t)(uint16_t)v; }

void fx_exp16f_emit(fx_gen *G, pf_buf *body, pf_buf *tabs, pf_buf *kern, int base2)
{
    const fx_exp_red *X = &G->exp;
    const char *N = G->name;
    int fb = X->ffb, rb = fb - FT_J;
    char w[64];
    snprintf(w, sizeof w, "D = %lld: the clamp, W = (t(D) - t) 2^%d from D - x", (long long)X->fd, fb);
    const char *kd = fx_k16(G, X->fd, w);
    ft_table(tabs, N, "fv", X->fv, "V[j] = round(T(j/16)), T(g) = 2^(t(D) + Eo - g - d) (MPFR), capped at the max");
    ft_table(tabs, N, "fs", X->fs, "S[j] = V[j] - round(T((j+1)/16)): the chord's drop over the segment (MPFR)");
    pf_printf(body, "    int16_t xc = (int16_t)(x > %s ? %s : x); /* %lld */\n", kd, kd, (long long)X->fd);
    pf_printf(body, "    uint16_t u = (uint16_t)((uint16_t)%s - (uint16_t)xc); /* D - x >= 0 */\n", kd);
    if (base2)
        pf_printf(body, "    uint16_t w = u; /* (t(D) - t) 2^%d */\n", fb);
    else
        pf_printf(body, "    uint16_t w = (uint16_t)((uint32_t)u * %lldu >> 16); /* ~(t(D) - t) 2^%d: pmulhuw */\n",
                  (long long)X->fl, fb);
    pf_printf(body, "    /* T(g) on segment j: the chord V[j] - S[j] r, r = (w mod 2^%d) 2^-%d */\n"
                    "    unsigned j = (unsigned)(w >> %d) & 15u;\n"
                    "    uint16_t rr = (uint16_t)((uint32_t)w << %d);\n"
                    "    uint16_t v = (uint16_t)(%s_fv[j] - ((uint32_t)%s_fs[j] * rr >> 16));\n",
              rb, rb, rb, 16 - rb, N, N);
    pf_printf(body, "    /* 2^-c, c = floor(t(D) - t), truncated; c >= 16: below 1 lsb, 0 (vpsrlvw's) */\n"
                    "    unsigned c = (unsigned)(w >> %d);\n"
                    "    return (%s)(c < 16u ? v >> c : 0);",
              fb, G->ot);
    const char *cond = "#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(__AVX2__)\n";
    pf_printf(kern,
              "\n\n/* AVX-512BW: the same steps on 32 lanes, with intrinsics, as GCC does not turn\n"
              "   the table lookups into vpermw: the array form runs this loop on a CPU\n"
              "   with x86-64-v4 (see its dispatch), the rest of the array and the other\n"
              "   clones use the scalar steps above.  The same values (pfmathgen sweeps the\n"
              "   array form on its machine against the scalar one). */\n%s#include <immintrin.h>\n"
              "extern %s %s(%s x); /* the scalar form, for the last n %% 32 */\n"
              "/* the 16 entries as 16-bit words, twice (vpermw reads 5 index bits) */\n"
              "__attribute__((target(\"arch=x86-64-v4\"))) static inline __m512i %s_w16(const uint32_t *t)\n{\n"
              "    return _mm512_broadcast_i64x4(_mm512_cvtepi32_epi16(_mm512_loadu_si512(t)));\n}\n"
              "__attribute__((target(\"arch=x86-64-v4\"), noinline))\n"
              "static void %s_array_bw(const %s *x, %s *y, size_t n)\n{\n",
              cond, G->ot, N, G->it, N, N, G->it, G->ot);
    pf_printf(kern, "    const __m512i tv = %s_w16(%s_fv), ts = %s_w16(%s_fs);\n"
                    "    const __m512i d = _mm512_set1_epi16(%lld);\n",
              N, N, N, N, s16(X->fd));
    if (!base2)
        pf_printf(kern, "    const __m512i l = _mm512_set1_epi16(%lld);\n", s16(X->fl));
    pf_buf s1 = {0}, s2 = {0};
    static const char *const cv[] = {"w"};
    pf_put(&s1, "        __m512i w = _mm512_sub_epi16(d, _mm512_min_epi16(_mm512_loadu_si512(x + i), d));\n");
    if (!base2)
        pf_put(&s1, "        w = _mm512_mulhi_epu16(w, l);\n");
    pf_printf(&s2, "        __m512i j = _mm512_srli_epi16(w, %d), rr = _mm512_slli_epi16(w, %d);\n"
                   "        __m512i v = _mm512_sub_epi16(_mm512_permutexvar_epi16(j, tv),\n"
                   "                                     _mm512_mulhi_epu16(_mm512_permutexvar_epi16(j, ts), rr));\n"
                   "        __m512i r = _mm512_srlv_epi16(v, _mm512_srli_epi16(w, %d));\n",
              rb, 16 - rb, fb);
    fx_pipe_loop(kern, "__m512i", 32, s1.s, s2.s, cv, 1, "_mm512_storeu_si512(y + i - 32, r);", N);
    free(s1.s);
    free(s2.s);
    s1 = s2 = (pf_buf){0};
    /* AVX2: no vpermw and no 16-bit per-element shift.  A 16-entry table of
       words is two vpshufb, one reading the low bytes with j in the low
       byte of its index word (jl = j), one the high bytes with j in the
       high byte (jh = j << 8); the other byte of each index is 0, so it
       reads entry 0.  Segment j enters the chord with the row: xs = W << (16
       - fb) keeps j and r only (j on top), and pmulhuw(16 S[j], xs) =
       j S[j] + floor(S[j] r 2^-rb) exactly (16 S[j] < 2^16, j S[j] an
       integer), so the tables hold V'[j] = V[j] + j S[j] (mod 2^16) and 16
       S[j], and v = V'[j] - pmulhuw(16 S[j], xs) is the same word with no
       shift for rr.  When V[0] = 257 a (the output's max, 65535 = 257 255),
       V' is the sum (vpaddw) of the two lookups with a in entry 0 of the low
       bytes and the high bytes less a (entry 0 read by both); else a
       vpblendvb merges them, as it does for 16 S.  v >> c is done in 32-bit
       lanes (vpsrlvd) on the even and the odd words apart, without
       unpacking.  Measured on Zen 3 (AVX2): the shuffles and shifts share
       two pipes, the multiplies two others, so the index steps are
       multiplies where that balances them; the same values (all 2^16
       inputs, test_fixed_hash's AVX2 row) */
    int s16ok = avx2_chord_fits(X);
    int vadd = X->fv[0] % 257 == 0;
    if (s16ok) {
        pf_printf(kern,
                  "\n\n/* AVX2 (x86-64-v3): the same steps on 16 lanes.  No vpermw: a table of 16\n"
                  "   words is two vpshufb, on its low bytes (j in the index's low byte) and\n"
                  "   its high bytes (j in the high byte); the chord takes j along: with xs =\n"
                  "   W << %d (j and r only), pmulhuw(16 S[j], xs) = j S[j] + floor(S[j] r 2^-%d),\n"
                  "   so the tables hold V[j] + j S[j] and 16 S[j].  No 16-bit per-element\n"
                  "   shift: v >> c in 32-bit lanes (vpsrlvd) on the even and the odd words\n"
                  "   apart.  The same values. */\n%s"
                  "__attribute__((target(\"arch=x86-64-v3\"), noinline))\n"
                  "static void %s_array_avx2(const %s *x, %s *y, size_t n)\n{\n"
                  "    uint8_t b[4][16]; /* V + j S: low, high bytes%s; 16 S: low, high bytes */\n"
                  "    for (int k = 0; k < 16; k++) {\n"
                  "        uint16_t vp = (uint16_t)(%s_fv[k] + (uint32_t)k * %s_fs[k]), sp = (uint16_t)(16u * %s_fs[k]);\n"
                  "        b[0][k] = (uint8_t)vp;\n"
                  "        b[1][k] = (uint8_t)((vp >> 8) - %du);\n"
                  "        b[2][k] = (uint8_t)sp;\n"
                  "        b[3][k] = (uint8_t)(sp >> 8);\n"
                  "    }\n"
                  "    const __m256i vl = _mm256_broadcastsi128_si256(_mm_loadu_si128((const __m128i *)b[0]));\n"
                  "    const __m256i vh = _mm256_broadcastsi128_si256(_mm_loadu_si128((const __m128i *)b[1]));\n"
                  "    const __m256i sl = _mm256_broadcastsi128_si256(_mm_loadu_si128((const __m128i *)b[2]));\n"
                  "    const __m256i sh = _mm256_broadcastsi128_si256(_mm_loadu_si128((const __m128i *)b[3]));\n"
                  "    const __m256i d = _mm256_set1_epi16(%lld), kx = _mm256_set1_epi16(%d), k256 = _mm256_set1_epi16(256);\n"
                  "    const __m256i hib = _mm256_set1_epi16(-256), lo16 = _mm256_set1_epi32(0xffff);\n",
                  16 - fb, rb, cond, N, G->it, G->ot,
                  vadd ? " less a = V[0] / 257 (the index's other byte reads entry 0: a and 0, so the sum is V[j] + j S[j])" : "",
                  N, N, N, vadd ? (int)(X->fv[0] / 257) : 0, s16(X->fd), 1 << (16 - fb));
        if (!base2)
            pf_printf(kern, "    const __m256i l = _mm256_set1_epi16(%lld);\n", s16(X->fl));
        pf_put(&s1, "        __m256i w = _mm256_sub_epi16(d, _mm256_min_epi16(_mm256_loadu_si256((const __m256i *)(x + i)), d));\n");
        if (!base2)
            pf_put(&s1, "        w = _mm256_mulhi_epu16(w, l);\n");
        pf_put(&s1, "        __m256i xs = _mm256_mullo_epi16(w, kx); /* j, r: W << (16 - fb) (a multiply: the shift pipes are the busy ones) */\n");
        pf_printf(&s2, "        __m256i jl = _mm256_srli_epi16(xs, 12), jh = _mm256_mullo_epi16(jl, k256); /* j, j << 8 */\n"
                       "        __m256i v = %s(_mm256_shuffle_epi8(vl, jl), _mm256_shuffle_epi8(vh, jh)%s);\n"
                       "        __m256i s = _mm256_blendv_epi8(_mm256_shuffle_epi8(sl, jl), _mm256_shuffle_epi8(sh, jh), hib);\n"
                       "        v = _mm256_sub_epi16(v, _mm256_mulhi_epu16(s, xs)); /* V[j] - floor(S[j] r 2^-%d) */\n"
                       "        __m256i ev = _mm256_srlv_epi32(_mm256_and_si256(v, lo16), _mm256_and_si256(_mm256_srli_epi16(w, %d), lo16));\n"
                       "        __m256i od = _mm256_srlv_epi32(v, _mm256_srli_epi32(w, %d)); /* its high word, by the high word's c */\n"
                       "        __m256i r = _mm256_blend_epi16(ev, od, 0xaa);\n",
                  vadd ? "_mm256_add_epi16" : "_mm256_blendv_epi8", vadd ? "" : ", hib", rb, fb, 16 + fb);
        static const char *const cv2[] = {"w", "xs"};
        fx_pipe_loop(kern, "__m256i", 16, s1.s, s2.s, cv2, 2, "_mm256_storeu_si256((__m256i *)(y + i - 16), r);", N);
        free(s1.s);
        free(s2.s);
        G->bw16 = 3;
        return;
    }
    /* 16 S[j] would not fit 16 bits: j in both bytes of the index (a
       vpshufb copies its low byte up), the lookups merged by vpblendvb, and
       r apart as rr */
    /* AVX2: no vpermw and no 16-bit per-element shift.  A 16-entry table of
       words is two vpshufb (its low and its high bytes, 16 per 128-bit
       lane) indexed by j in both bytes of the word (its low byte copied up
       by a vpshufb: a shuffle, where a pmullw would load the multipliers),
       merged by vpblendvb;
       v >> c is done in 32-bit lanes (vpsrlvd) on the even and the odd
       words apart, without unpacking: the same values */
    pf_printf(kern,
              "\n\n/* AVX2 (x86-64-v3): the same steps on 16 lanes.  No vpermw: a table of 16\n"
              "   words is two vpshufb (its low and its high bytes) merged by vpblendvb;\n"
              "   no 16-bit per-element shift: v >> c in 32-bit lanes (vpsrlvd) on the even\n"
              "   and the odd words apart.  The same values. */\n%s"
              "__attribute__((target(\"arch=x86-64-v3\"), noinline))\n"
              "static void %s_array_avx2(const %s *x, %s *y, size_t n)\n{\n"
              "    uint8_t b[4][16]; /* V's low, high bytes, S's low, high bytes */\n"
              "    for (int k = 0; k < 16; k++) {\n"
              "        b[0][k] = (uint8_t)%s_fv[k];\n"
              "        b[1][k] = (uint8_t)(%s_fv[k] >> 8);\n"
              "        b[2][k] = (uint8_t)%s_fs[k];\n"
              "        b[3][k] = (uint8_t)(%s_fs[k] >> 8);\n"
              "    }\n"
              "    const __m256i vl = _mm256_broadcastsi128_si256(_mm_loadu_si128((const __m128i *)b[0]));\n"
              "    const __m256i vh = _mm256_broadcastsi128_si256(_mm_loadu_si128((const __m128i *)b[1]));\n"
              "    const __m256i sl = _mm256_broadcastsi128_si256(_mm_loadu_si128((const __m128i *)b[2]));\n"
              "    const __m256i sh = _mm256_broadcastsi128_si256(_mm_loadu_si128((const __m128i *)b[3]));\n"
              "    const __m256i d = _mm256_set1_epi16(%lld), m15 = _mm256_set1_epi16(15);\n"
              "    const __m256i hib = _mm256_set1_epi16(-256), lo16 = _mm256_set1_epi32(0xffff);\n"
              "    const __m256i dup = _mm256_setr_epi8(0, 0, 2, 2, 4, 4, 6, 6, 8, 8, 10, 10, 12, 12, 14, 14,\n"
              "                                         0, 0, 2, 2, 4, 4, 6, 6, 8, 8, 10, 10, 12, 12, 14, 14);\n",
              cond, N, G->it, G->ot, N, N, N, N, s16(X->fd));
    if (!base2)
        pf_printf(kern, "    const __m256i l = _mm256_set1_epi16(%lld);\n", s16(X->fl));
    pf_put(&s1, "        __m256i w = _mm256_sub_epi16(d, _mm256_min_epi16(_mm256_loadu_si256((const __m256i *)(x + i)), d));\n");
    if (!base2)
        pf_put(&s1, "        w = _mm256_mulhi_epu16(w, l);\n");
    pf_printf(&s1, "        __m256i j = _mm256_shuffle_epi8(_mm256_and_si256(_mm256_srli_epi16(w, %d), m15), dup); /* j in both bytes */\n",
              rb);
    pf_printf(&s2, "        __m256i v = _mm256_blendv_epi8(_mm256_shuffle_epi8(vl, j), _mm256_shuffle_epi8(vh, j), hib);\n"
                   "        __m256i s = _mm256_blendv_epi8(_mm256_shuffle_epi8(sl, j), _mm256_shuffle_epi8(sh, j), hib);\n"
                   "        v = _mm256_sub_epi16(v, _mm256_mulhi_epu16(s, _mm256_slli_epi16(w, %d)));\n"
                   "        __m256i c = _mm256_srli_epi16(w, %d);\n"
                   "        __m256i ev = _mm256_srlv_epi32(_mm256_and_si256(v, lo16), _mm256_and_si256(c, lo16));\n"
                   "        __m256i od = _mm256_srlv_epi32(v, _mm256_srli_epi32(c, 16)); /* its high word */\n"
                   "        __m256i r = _mm256_blend_epi16(ev, od, 0xaa);\n",
              16 - rb, fb);
    static const char *const cv2[] = {"w", "j"};
    fx_pipe_loop(kern, "__m256i", 16, s1.s, s2.s, cv2, 2, "_mm256_storeu_si256((__m256i *)(y + i - 16), r);", N);
    free(s1.s);
    free(s2.s);
    G->bw16 = 3;
}
