/* pfmathgen --func noise1|noise2|noise3|noise4|noise --type IN --out-type OUT:
 * the gradient noise of libpfmath/pfnoise.h (same lattice, hashing,
 * gradients and fade) as self-contained integer-only C for any pair of
 * fixed-point types of at most 32 bits, within 1 LSB of the exact noise.
 *
 * The kernel, per dimension N (the library's pfnoise_fixed.c generalised):
 *   cell = floor(x 2^-F) mod 256 and t = x 2^-F − floor(x 2^-F) from the
 *   stored bits as unsigned integers (F = the input's exp, 1..62);
 *   corner offsets d = t − c and the gradient dot products g·d in D
 *   fraction bits (exact when F <= D; 1D holds d in D − 2 bits so that
 *   g·d/4 is exact too); the fade f(t) = 6t⁵ − 15t⁴ + 10t³ by Horner with
 *   the step formats pf_bw_horner assigns (coefficients fixed<4,0>, t as
 *   ufixed<T,T>, result fixed<fb,fb>); each lerp a + RNE(f (b − a) 2^-Ef),
 *   Ef the fade result's lsb; 4D's ·2/3 as RNE(v c 2^-S), c = RNE(2/3 2^S);
 *   the result RNE to the output's lsb and saturated to the output type.
 *   W-bit words (int32_t, or int64_t when the budget needs more bits) with
 *   64-bit products; no product exceeds 2^62.
 *
 * Why the result is within 1 LSB (the emitted file repeats this with its
 * numbers).  Let ε_f bound |f̃ − f(t)|: each Horner step that rounds
 * (shift > 0) adds at most half its lsb 2^-(E_k+1), carried to the result
 * times t^k <= 1; rounding t to T < F bits adds max|f'|·2^-(T+1), max|f'| =
 * 15/8.  Corner values are exact, or within e_0 = G 2^-(Dd+1) when F > Dd
 * (G = max Σ|g_i| in value units: 2, 2, 2, 3).  A lerp of values with
 * errors <= e, whose exact values differ by at most Δ = 2M (M = max |g·d|:
 * 2, 2, 2, 3), computes
 *   ã + f̃(b̃ − ã) − (a + f(b − a)) = (1 − f̃)(ã − a) + f̃(b̃ − b) + (f̃ − f)(b − a),
 * so with the product's rounding e' <= (1 + 2ε_f) e + Δ ε_f + 2^-(D+1)
 * (f̃ ∈ [−ε_f, 1 + ε_f]).  N levels of lerps, then for 4D
 * e'' <= 2/3 e + (3 + e) 2^-(S+1) + 2^-(D+1).  The generator takes the
 * smallest fade format (and 32-bit words before 64-bit ones) for which that
 * bound is below half an LSB of the output, 2^-(Eo+1); the final RNE then
 * adds at most 1/2 LSB, so |result − n| < 1 LSB, and saturation (1-Lipschitz)
 * keeps that against the exact noise clamped to the output range.  No
 * format's limit is reached: |p_k| <= 15 for the Horner steps (6, 6t − 15,
 * …, all far inside the formats), f̃ <= 1 + ε_f needs Ef + 1 bits, values
 * stay below (M + e) 2^D and differences below 2(M + e) 2^D < 2^(W−1)
 * (D <= W − 4), products below 2^62 (checked per step below).
 *
 * Then the emitted code is compiled, loaded and compared with the exact
 * noise (ref/pfref_noise.c, MPFR): every input for 1D with <= 16-bit
 * inputs, else lattice points, cell edges ± 1 lsb, the period wrap, the
 * type's extremes and seeded random points; the scalar and array forms
 * must agree bit for bit and every error must be < 1 LSB (and within the
 * bound), else pfmathgen fails (status 1). */
#include "compile.h"
#include "request.h"
#include "fixed_internal.h"
#include "fixedgen.h"
#include "fixedtype.h"

#include "bitwidth.h"
#include "pfnoise.h"
#include "pfref_noise.h"

#include <dlfcn.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    int n;                  /* dimension */
    char name[136];
    int W;                  /* word bits: 32 or 64 */
    const char *vt;         /* "int32_t" / "int64_t" */
    int T;                  /* fade input bits */
    int fb;                 /* fade destination exp */
    int Ef;                 /* exp of the fade's result (p0) */
    int D, Dd;              /* value and offset fraction bits */
    int S;                  /* 4D: 2/3 as c 2^-S */
    int64_t c23;
    pf_bw_step st[6];
    int64_t C[6];
    double eps_t, eps_h, eps_f, e0, err; /* the bound, value units */
    /* measurement */
    double max_err, sum_err;
    int64_t worst[4];
    uint64_t count, mismatch, over;
    int exhaustive;
} nz_dim;

typedef struct {
    pf_type in, out;
    char in_text[64], out_text[64];
    const char *it, *ot;
    int F, Eo;
    int64_t omin, omax;
    pf_noise_table tab;
    int seeded;
    unsigned long long seed;
    int nd;
    nz_dim d[4];
    const char *command;
    int swept;
} nz_gen;

static const int nz_M[5] = {0, 2, 2, 2, 3}; /* max |g·d| (before 4D's 2/3) */
static const int nz_G[5] = {0, 2, 2, 2, 3}; /* max Σ|g_i| in value units */

/* ---- precision plan ---- */

/* Fade formats for t ufixed<T,T> into fixed<fb,fb>: 0 when every step fits
 * W-bit words and 2^62-bounded products. */
static int fade_formats(nz_dim *d, int T, int fb, int W)
{
    static const int coef[6] = {0, 0, 0, 10, -15, 6};
    pf_type c[6];
    for (int k = 0; k < 6; k++)
        c[k] = pf_type_fixed(1, 4, 0);
    if (pf_bw_horner(c, 5, pf_type_fixed(0, T, T), pf_type_fixed(1, fb, fb), d->st) != 0)
        return -1;
    for (int k = 0; k < 5; k++) {
        if (d->st[k].shift < 0 || d->st[k].shift > 62 || d->st[k].p.exp < 0 || d->st[k].p.exp > 62)
            return -1;
        /* each step's format fits the word (p0: f <= 1 + eps needs Ef + 1
           bits); the product p_{k+1} t: |p_{k+1}| <= 15.01 2^E_{k+1} (6,
           6t - 15, ... on [0, 1]) and t <= 1, so below 2^(E_{k+1} + 4 + T) */
        if (k >= 1 && d->st[k].p.size > W - 1)
            return -1;
        if (d->st[k + 1].p.exp + 4 + T > 62)
            return -1;
    }
    if (d->st[0].p.exp > W - 2)
        return -1;
    for (int k = 0; k < 6; k++)
        d->C[k] = (int64_t)coef[k] * ((int64_t)1 << d->st[k].p.exp);
    d->T = T;
    d->fb = fb;
    d->Ef = d->st[0].p.exp;
    return 0;
}

/* the error bound (value units) before the final rounding, for d's formats */
static double bound(nz_dim *d, int F)
{
    int n = d->n;
    d->eps_h = 0;
    for (int k = 0; k < 5; k++)
        if (d->st[k].shift > 0)
            d->eps_h += ldexp(1.0, -(d->st[k].p.exp + 1));
    d->eps_t = d->T < F ? 1.875 * ldexp(1.0, -(d->T + 1)) : 0;
    d->eps_f = d->eps_h + d->eps_t;
    d->e0 = F > d->Dd ? nz_G[n] * ldexp(1.0, -(d->Dd + 1)) : 0;
    double e = d->e0, D2 = ldexp(1.0, -(d->D + 1));
    for (int k = 0; k < n; k++)
        e = (1 + 2 * d->eps_f) * e + 2 * nz_M[n] * d->eps_f + D2;
    if (n == 4)
        e = 2.0 / 3 * e + (3 + e) * ldexp(1.0, -(d->S + 1)) + D2;
    /* a little upward slack for the double arithmetic itself */
    return e * (1 + 1e-12);
}

/* smallest fade format (32-bit words first) meeting half an LSB; 0, or -1
 * with the best bound found in *best (LSB) */
static int plan_dim(const nz_gen *G, nz_dim *d, double *best)
{
    double half = ldexp(1.0, -(G->Eo + 1));
    *best = INFINITY;
    for (int W = 32; W <= 64; W += 32) {
        for (int fb = 1; fb <= W - 2; fb++) {
            nz_dim t = *d;
            t.W = W;
            t.vt = W == 32 ? "int32_t" : "int64_t";
            t.D = W == 32 ? W - 4 : (59 - fb < 60 ? 59 - fb : 60);
            t.Dd = d->n == 1 ? t.D - 2 : t.D;
            if (t.Dd < 1)
                continue;
            int Tmax = W == 32 ? 30 : 61, ok = -1;
            for (int T = G->F < Tmax ? G->F : Tmax; T >= 1 && ok; T--)
                ok = fade_formats(&t, T, fb, W);
            if (ok)
                continue;
            if (t.Ef + t.D > 59)
                continue;
            if (d->n == 4) {
                t.S = 60 - t.D < 62 ? 60 - t.D : 62;
                if (t.S < 1)
                    continue;
                t.c23 = (int64_t)((((uint64_t)1 << (t.S + 1)) + 1) / 3); /* RNE(2^(S+1)/3) */
            }
            t.err = bound(&t, G->F);
            /* values and differences within the word: (M + e) 2^D, 2(M + e) 2^D */
            if (2 * (nz_M[d->n] + t.err) > 8 * (1 - 1e-9))
                continue;
            if (t.err / (2 * half) < *best)
                *best = t.err / (2 * half);
            if (t.err < half) {
                *d = t;
                return 0;
            }
        }
    }
    return -1;
}

/* ---- emission ---- */

/* INT64_C only where a 64-bit word's value needs it */
static void lit(char *buf, size_t n, int64_t v, int w64)
{
    pf_int_lit(buf, n, v, w64 ? PF_LIT_INT64_WIDE : PF_LIT_PLAIN);
}

static void type_fmt(const pf_type *t, char *buf, size_t n) { pf_type_format(t, buf, n); }

static void formats_text(const nz_dim *d, char *buf, size_t n)
{
    char a[64];
    size_t o = 0;
    type_fmt(&(pf_type){0, 0, d->T, d->T, 0}, a, sizeof a);
    o += (size_t)snprintf(buf + o, n - o, "fade: t %s; Horner steps (pf_bw_horner) p5 fixed<4,0>", a);
    for (int k = 4; k >= 0 && o < n; k--) {
        type_fmt(&d->st[k].p, a, sizeof a);
        o += (size_t)snprintf(buf + o, n - o, ", p%d %s (shift %d)", k, a, d->st[k].shift);
    }
    if (o < n)
        o += (size_t)snprintf(buf + o, n - o,
                              "; values: corner offsets fixed<%d,%d>, dot products and lerps fixed<%d,%d> "
                              "in %s words, lerp a + RNE(f (b - a) 2^-%d) with 64-bit products",
                              d->Dd + 1, d->Dd, d->W - 1, d->D, d->vt, d->Ef);
    if (d->n == 4 && o < n)
        snprintf(buf + o, n - o, "; 2/3 as %lld 2^-%d", (long long)d->c23, d->S);
}

/* provenance lines without trailing blanks */
static void wrap(pf_buf *b, const char *label, const char *text) { pf_prov_wrap(b, label, text, 0); }

static const char *coord[4] = {"x", "y", "z", "w"};

static void args_text(const nz_gen *G, int n, char *buf, size_t len, int decl_array)
{
    size_t o = 0;
    buf[0] = 0;
    for (int i = 0; i < n; i++)
        o += (size_t)snprintf(buf + o, len - o, decl_array ? "%sconst %s *restrict %s" : "%s%s %s", i ? ", " : "",
                              G->it, coord[i]);
}

static void measured_text(const nz_gen *G, const nz_dim *d, char *buf, size_t n)
{
    size_t o = (size_t)snprintf(buf, n, "max %.4f LSB at (", d->max_err);
    for (int i = 0; i < d->n; i++)
        o += (size_t)snprintf(buf + o, n - o, "%s%lld", i ? ", " : "", (long long)d->worst[i]);
    o += (size_t)snprintf(buf + o, n - o, ") = (");
    for (int i = 0; i < d->n; i++)
        o += (size_t)snprintf(buf + o, n - o, "%s%.10g", i ? ", " : "", ldexp((double)d->worst[i], -G->F));
    snprintf(buf + o, n - o,
             "), mean %.4f LSB, against the exact noise (MPFR, ref/pfref_noise.c) over %llu points: %s; "
             "scalar and array forms identical",
             d->count ? d->sum_err / (double)d->count : 0, (unsigned long long)d->count,
             d->exhaustive ? "every input"
                           : "lattice points, cell edges +-1 lsb, period wrap, type extremes and seeded random "
                             "points");
}

static void provenance(pf_buf *b, const nz_gen *G)
{
    char tmp[2048], a[64], c[64];
    if (G->nd == 1)
        snprintf(tmp, sizeof tmp, "%s: gradient noise, %dD, for %s -> %s (%s -> %s)", G->d[0].name, G->d[0].n,
                 G->in_text, G->out_text, G->it, G->ot);
    else
        snprintf(tmp, sizeof tmp, "%s, %s, %s, %s: gradient noise, 1D to 4D, for %s -> %s (%s -> %s)",
                 G->d[0].name, G->d[1].name, G->d[2].name, G->d[3].name, G->in_text, G->out_text, G->it, G->ot);
    pf_prov_begin(b, tmp, PF_NOTICE_OWN_LINE, G->command);
    if (G->seeded)
        snprintf(c, sizeof c, "pf_noise_table_seed(%llu)", G->seed);
    else
        snprintf(c, sizeof c, "Perlin's permutation (pf_noise_table default)");
    snprintf(tmp, sizeof tmp,
             "gradient noise as libpfmath/pfnoise.h (pf_noiseNf): hashed lattice gradients, quintic fade "
             "6t^5 - 15t^4 + 10t^3, 0 at every lattice point, period 256; lattice from %s, tables below "
             "dumped from the library's pf_noise_table",
             c);
    wrap(b, "Function:", tmp);
    snprintf(a, sizeof a, "%.10g", ldexp((double)pf_type_min_stored(&G->in), -G->F));
    snprintf(c, sizeof c, "%.10g", ldexp((double)pf_type_max_stored(&G->in), -G->F));
    snprintf(tmp, sizeof tmp, "%s coordinates, value x 2^-%d in [%s, %s]", G->it, G->F, a, c);
    wrap(b, "Input:", tmp);
    snprintf(a, sizeof a, "%.10g", ldexp((double)G->omin, -G->Eo));
    snprintf(c, sizeof c, "%.10g", ldexp((double)G->omax, -G->Eo));
    snprintf(tmp, sizeof tmp,
             "%s, value y 2^%d in [%s, %s]: round(n 2^%d) to nearest even, saturated to the type", G->ot, -G->Eo,
             a, c, G->Eo);
    wrap(b, "Output:", tmp);
    snprintf(tmp, sizeof tmp,
             "every input of the type: cell = floor(x 2^-%d) mod 256 and t = the %d fraction bits, taken from "
             "the stored bits as unsigned integers",
             G->F, G->F);
    wrap(b, "Domain:", tmp);
    for (int i = 0; i < G->nd; i++) {
        const nz_dim *d = &G->d[i];
        double L = ldexp(1.0, -G->Eo);
        pf_printf(b, " *\n * %s (%dD):\n", d->name, d->n);
        formats_text(d, tmp, sizeof tmp);
        snprintf(tmp + strlen(tmp), sizeof tmp - strlen(tmp), "; result RNE to 2^-%d, saturated", G->Eo);
        wrap(b, "Method:", tmp);
        snprintf(tmp, sizeof tmp,
                 "fade |f~ - f| <= eps_f = %.3e (Horner %.3e + t rounding %.3e); corner values e0 = %.3e; each "
                 "lerp e' <= (1 + 2 eps_f) e + %d eps_f + 2^-%d (|b - a| <= %d)%s; total %.4e = %.4f LSB < 1/2 "
                 "LSB before the final rounding, so every result is within 1 LSB of the exact noise",
                 d->eps_f, d->eps_h, d->eps_t, d->e0, 2 * nz_M[d->n], d->D + 1, 2 * nz_M[d->n],
                 d->n == 4 ? ", then 2/3: e'' <= 2/3 e + (3 + e) 2^-(S+1) + 2^-(D+1)" : "", d->err, d->err / L);
        wrap(b, "Error bound:", tmp);
        if (G->swept) {
            measured_text(G, d, tmp, sizeof tmp);
            wrap(b, "Measured:", tmp);
        }
    }
    pf_put(b, " *\n");
    wrap(b, "Arithmetic:",
         "integers only (no floating point, no <math.h>); every rounding to nearest, ties to even; right "
         "shifts only of unsigned values; bit-identical under any compiler flags");
    pf_prov_end_int(b);
}

static void table(pf_buf *b, const char *name, const uint32_t *v, int n)
{
    pf_printf(b, "static const uint32_t %s[%d] = {", name, n);
    for (int i = 0; i < n; i++)
        pf_printf(b, "%s0x%08x,", i % 6 ? " " : "\n    ", (unsigned)v[i]);
    pf_put(b, "\n};\n\n");
}

/* the shared integer helpers (pf_fx_i64, pf_fx_rne, ...) of every emitted
   fixed-point function, then what only the noise loops need */
static const char vectorize[] = "#if defined(__GNUC__) && !defined(__clang__)\n"
                                "#pragma GCC optimize(\"tree-vectorize\")\n"
                                "#endif\n\n";

static void emit_dim(pf_buf *b, const nz_gen *G, const nz_dim *d)
{
    const char *N = d->name, *V = d->vt, *IT = G->it;
    int w64 = d->W == 64, F = G->F;
    char l[64], l2[64];
    int uw64 = F > 24;
    const char *UW = uw64 ? "uint64_t" : "uint32_t", *SW = uw64 ? "int64_t" : "int32_t";
    const char *TT = F <= 29 ? "int32_t" : "int64_t";
    pf_printf(b, "/* ---- %s: %dD, %s words ---- */\n\n", N, d->n, V);
    /* fade */
    pf_printf(b,
              "/* f(t) = 6t^5 - 15t^4 + 10t^3, t in ufixed<%d,%d>: Horner with the step formats of the\n"
              "   bit-width analysis; f in fixed<%d,%d> (error <= %.3e) */\n",
              d->T, d->T, d->Ef + 1, d->Ef, d->eps_h);
    pf_printf(b, "PF_FX_INLINE %s %s_fade(%s t)\n{\n    %s p = %lld;\n", V, N, V, V, (long long)d->C[5]);
    for (int k = 4; k >= 0; k--) {
        char add[80] = "";
        if (d->C[k]) {
            lit(l, sizeof l, d->C[k] < 0 ? -d->C[k] : d->C[k], w64);
            snprintf(add, sizeof add, " %s %s", d->C[k] < 0 ? "-" : "+", l);
        }
        if (d->st[k].shift == 0)
            pf_printf(b, "    p = p * t%s;\n", add);
        else
            pf_printf(b, "    p = (%s)pf_fx_rne((int64_t)p * t, %d)%s;\n", V, d->st[k].shift, add);
    }
    pf_put(b, "    return p;\n}\n\n");
    /* split */
    pf_printf(b,
              "/* cell floor(x 2^-%d) mod 256; offsets d0 = t, d1 = t - 1 in %d fraction bits; fade f(t) */\n"
              "PF_FX_INLINE uint32_t %s_split(%s x, %s *d0, %s *d1, %s *f)\n{\n",
              F, d->Dd, N, IT, V, V, V);
    if (G->in.is_signed)
        pf_printf(b, "    %s u = (%s)(%s)x;\n", UW, UW, SW);
    else
        pf_printf(b, "    %s u = (%s)x;\n", UW, UW);
    if (uw64)
        pf_printf(b, "    %s t = (%s)(u & UINT64_C(0x%llx));\n", TT, TT, (unsigned long long)(((uint64_t)1 << F) - 1));
    else
        pf_printf(b, "    %s t = (%s)(u & 0x%lxu);\n", TT, TT, (unsigned long)(((uint32_t)1 << F) - 1));
    lit(l2, sizeof l2, (int64_t)1 << F, 1);
    if (d->Dd >= F) {
        lit(l, sizeof l, (int64_t)1 << (d->Dd - F), w64);
        pf_printf(b, "    *d0 = (%s)t * %s;\n    *d1 = ((%s)t - %s) * %s;\n", V, l, V, l2, l);
    } else {
        pf_printf(b, "    *d0 = (%s)pf_fx_rne((int64_t)t, %d);\n", V, F - d->Dd);
        pf_printf(b, "    *d1 = (%s)pf_fx_rne((int64_t)t - %s, %d);\n", V, l2, F - d->Dd);
    }
    if (d->T == F)
        pf_printf(b, "    *f = %s_fade((%s)t);\n", N, V);
    else
        pf_printf(b, "    *f = %s_fade((%s)pf_fx_rne((int64_t)t, %d));\n", N, V, F - d->T);
    pf_printf(b, "    return (uint32_t)(u >> %d) & 255u;\n}\n\n", F);
    /* lerp and gradient */
    pf_printf(b,
              "/* a + f (b - a), one rounding: f has %d fraction bits */\n"
              "PF_FX_INLINE %s %s_lerp(%s f, %s a, %s b)\n{\n"
              "    return a + (%s)pf_fx_rne((int64_t)f * (b - a), %d);\n}\n\n",
              d->Ef, V, N, V, V, V, V, d->Ef);
    if (d->n > 1)
        pf_printf(b,
                  "/* (k - 1) d for the 2-bit gradient field k of code c at bit s */\n"
                  "PF_FX_INLINE %s %s_gd(uint32_t c, int s, %s d)\n{\n"
                  "    return ((%s)((c >> s) & 3u) - 1) * d;\n}\n\n",
                  V, N, V, V);
    /* core */
    char targs[200];
    args_text(G, d->n, targs, sizeof targs, 0);
    pf_printf(b, "PF_FX_INLINE %s %s_core(%s)\n{\n", V, N, targs);
    const char *g = d->n == 1 ? "pf_nz_g1" : d->n == 2 ? "pf_nz_g2" : d->n == 3 ? "pf_nz_g3" : "pf_nz_g4";
    switch (d->n) {
    case 1:
        pf_printf(b,
                  "    %s d0, d1, f;\n"
                  "    uint32_t c = %s[%s_split(x, &d0, &d1, &f)];\n"
                  "    /* (k - 8) d with d in %d fraction bits: g d / 4 in %d, %s */\n"
                  "    %s n0 = ((%s)(c & 31u) - 8) * d0;\n"
                  "    %s n1 = ((%s)((c >> 16) & 31u) - 8) * d1;\n"
                  "    return %s_lerp(f, n0, n1);\n}\n\n",
                  V, g, N, d->Dd, d->D, d->Dd >= F ? "exact" : "d rounded once (in the bound)", V, V, V, V, N);
        break;
    case 2:
        pf_printf(b,
                  "    %s x0, x1, u, y0, y1, v;\n"
                  "    uint32_t X = %s_split(x, &x0, &x1, &u), Y = %s_split(y, &y0, &y1, &v);\n"
                  "    uint32_t P = pf_nz_hash[X];\n"
                  "    uint32_t cA = %s[(P & 0xffffu) + Y], cB = %s[(P >> 16) + Y];\n"
                  "    %s n00 = %s_gd(cA, 0, x0) + %s_gd(cA, 2, y0), n01 = %s_gd(cA, 16, x0) + %s_gd(cA, 18, y1);\n"
                  "    %s n10 = %s_gd(cB, 0, x1) + %s_gd(cB, 2, y0), n11 = %s_gd(cB, 16, x1) + %s_gd(cB, 18, y1);\n"
                  "    return %s_lerp(v, %s_lerp(u, n00, n10), %s_lerp(u, n01, n11));\n}\n\n",
                  V, N, N, g, g, V, N, N, N, N, V, N, N, N, N, N, N, N);
        break;
    case 3:
        pf_printf(b,
                  "    %s x0, x1, u, y0, y1, v, z0, z1, w;\n"
                  "    uint32_t X = %s_split(x, &x0, &x1, &u), Y = %s_split(y, &y0, &y1, &v);\n"
                  "    uint32_t Z = %s_split(z, &z0, &z1, &w);\n"
                  "    uint32_t P = pf_nz_hash[X];\n"
                  "    uint32_t A = (P & 0xffffu) + Y, B = (P >> 16) + Y;\n"
                  "    uint32_t PA = pf_nz_hash[A], PB = pf_nz_hash[B];\n"
                  "    uint32_t c00 = %s[(PA & 0xffffu) + Z], c01 = %s[(PA >> 16) + Z];\n"
                  "    uint32_t c10 = %s[(PB & 0xffffu) + Z], c11 = %s[(PB >> 16) + Z];\n",
                  V, N, N, N, g, g, g, g);
        pf_printf(b,
                  "#define LO(c, xx, yy) (%s_gd(c, 0, xx) + %s_gd(c, 2, yy) + %s_gd(c, 4, z0))\n"
                  "#define HI(c, xx, yy) (%s_gd(c, 16, xx) + %s_gd(c, 18, yy) + %s_gd(c, 20, z1))\n",
                  N, N, N, N, N, N);
        pf_printf(b,
                  "    %s n000 = LO(c00, x0, y0), n001 = HI(c00, x0, y0);\n"
                  "    %s n010 = LO(c01, x0, y1), n011 = HI(c01, x0, y1);\n"
                  "    %s n100 = LO(c10, x1, y0), n101 = HI(c10, x1, y0);\n"
                  "    %s n110 = LO(c11, x1, y1), n111 = HI(c11, x1, y1);\n"
                  "#undef LO\n#undef HI\n"
                  "    %s a00 = %s_lerp(u, n000, n100), a01 = %s_lerp(u, n001, n101);\n"
                  "    %s a10 = %s_lerp(u, n010, n110), a11 = %s_lerp(u, n011, n111);\n"
                  "    return %s_lerp(w, %s_lerp(v, a00, a10), %s_lerp(v, a01, a11));\n}\n\n",
                  V, V, V, V, V, N, N, V, N, N, N, N, N);
        break;
    default:
        pf_printf(b,
                  "    %s dx[2], dy[2], dz[2], dw[2], fx, fy, fz, fw;\n"
                  "    uint32_t X = %s_split(x, &dx[0], &dx[1], &fx), Y = %s_split(y, &dy[0], &dy[1], &fy);\n"
                  "    uint32_t Z = %s_split(z, &dz[0], &dz[1], &fz), W = %s_split(w, &dw[0], &dw[1], &fw);\n"
                  "    uint32_t P = pf_nz_hash[X];\n"
                  "    uint32_t A = (P & 0xffffu) + Y, B = (P >> 16) + Y;\n"
                  "    uint32_t PA = pf_nz_hash[A], PB = pf_nz_hash[B];\n"
                  "    uint32_t PP[4] = {pf_nz_hash[(PA & 0xffffu) + Z], pf_nz_hash[(PA >> 16) + Z],\n"
                  "                      pf_nz_hash[(PB & 0xffffu) + Z], pf_nz_hash[(PB >> 16) + Z]};\n"
                  "    %s n[2][2][2][2], b[2][2][2], c2[2][2], e[2];\n"
                  "    for (int ij = 0; ij < 4; ij++) {\n"
                  "        int i = ij >> 1, j = ij & 1;\n"
                  "        for (int k = 0; k < 2; k++) {\n"
                  "            uint32_t c = %s[(k ? PP[ij] >> 16 : PP[ij] & 0xffffu) + W];\n"
                  "            for (int l = 0; l < 2; l++)\n"
                  "                n[i][j][k][l] = %s_gd(c, 16 * l, dx[i]) + %s_gd(c, 16 * l + 2, dy[j]) +\n"
                  "                                %s_gd(c, 16 * l + 4, dz[k]) + %s_gd(c, 16 * l + 6, dw[l]);\n"
                  "        }\n"
                  "    }\n"
                  "    for (int j = 0; j < 2; j++)\n"
                  "        for (int k = 0; k < 2; k++)\n"
                  "            for (int l = 0; l < 2; l++)\n"
                  "                b[j][k][l] = %s_lerp(fx, n[0][j][k][l], n[1][j][k][l]);\n"
                  "    for (int k = 0; k < 2; k++)\n"
                  "        for (int l = 0; l < 2; l++)\n"
                  "            c2[k][l] = %s_lerp(fy, b[0][k][l], b[1][k][l]);\n"
                  "    for (int l = 0; l < 2; l++)\n"
                  "        e[l] = %s_lerp(fz, c2[0][l], c2[1][l]);\n",
                  V, N, N, N, N, V, g, N, N, N, N, N, N, N);
        lit(l, sizeof l, d->c23, w64);
        pf_printf(b,
                  "    /* 2/3 as in the float version: %s = RNE(2/3 2^%d) */\n"
                  "    return (%s)pf_fx_rne((int64_t)%s_lerp(fw, e[0], e[1]) * %s, %d);\n}\n\n",
                  l, d->S, V, N, l, d->S);
        break;
    }
    /* output */
    int sh = d->D - G->Eo;
    if (sh > 62)
        sh = 62; /* |v| < 2^(D+2) <= 2^61: RNE(v 2^-sh) is 0 for every sh >= 62 */
    /* |result| <= 2.01 2^Eo + 1: clamp only where the type is narrower */
    int64_t R = G->Eo >= 0 ? (int64_t)ceil(2.01 * ldexp(1.0, G->Eo)) + 1 : 2;
    pf_printf(b, "PF_FX_INLINE %s %s_out(%s v)\n{\n    int64_t r = pf_fx_rne((int64_t)v, %d);\n", G->ot, N, V, sh);
    if (G->omax < R) {
        lit(l, sizeof l, G->omax, 1);
        pf_printf(b, "    r = r > %s ? %s : r;\n", l, l);
    }
    if (G->omin > -R) {
        lit(l, sizeof l, G->omin, 1);
        pf_printf(b, "    r = r < %s ? %s : r;\n", l, l);
    }
    pf_printf(b, "    return (%s)r;\n}\n\n", G->ot);
    char cargs[100] = "";
    size_t o = 0;
    for (int i = 0; i < d->n; i++)
        o += (size_t)snprintf(cargs + o, sizeof cargs - o, "%s%s", i ? ", " : "", coord[i]);
    pf_printf(b, "%s %s(%s)\n{\n    return %s_out(%s_core(%s));\n}\n\n", G->ot, N, targs, N, N, cargs);
    char aargs[300];
    args_text(G, d->n, aargs, sizeof aargs, 1);
    o = 0;
    char iargs[100] = "";
    for (int i = 0; i < d->n; i++)
        o += (size_t)snprintf(iargs + o, sizeof iargs - o, "%s%s[i]", i ? ", " : "", coord[i]);
    pf_printf(b,
              "/* Array form: branch-free integer code with table loads (gathers), so the loop vectorizes;\n"
              "   one clone per x86-64 level when the baseline lacks AVX2.  Every clone computes the\n"
              "   same bits. */\n"
              "#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(__AVX2__)\n"
              "__attribute__((target_clones(\"arch=x86-64-v4\", \"arch=x86-64-v3\", \"default\")))\n"
              "#endif\n"
              "void %s_array(%s, %s *restrict out, size_t n)\n{\n"
              "#if defined(__GNUC__) && !defined(__clang__)\n#pragma GCC ivdep\n#endif\n"
              "    for (size_t i = 0; i < n; i++)\n"
              "        out[i] = %s_out(%s_core(%s));\n}\n",
              N, aargs, G->ot, N, N, iargs);
}

static char *emit(const nz_gen *G, size_t *len)
{
    pf_buf b = {0};
    provenance(&b, G);
    pf_put(&b, pf_template("fx_common.h"));
    pf_put(&b, vectorize);
    int need[5] = {0};
    for (int i = 0; i < G->nd; i++)
        need[G->d[i].n] = 1;
    if (need[2] || need[3] || need[4])
        table(&b, "pf_nz_hash", G->tab.hash, 512);
    if (need[1])
        table(&b, "pf_nz_g1", G->tab.g1, 256);
    if (need[2])
        table(&b, "pf_nz_g2", G->tab.g2, 512);
    if (need[3])
        table(&b, "pf_nz_g3", G->tab.g3, 512);
    if (need[4])
        table(&b, "pf_nz_g4", G->tab.g4, 512);
    for (int i = 0; i < G->nd; i++) {
        emit_dim(&b, G, &G->d[i]);
        if (i + 1 < G->nd)
            pf_put(&b, "\n");
    }
    *len = b.n;
    return b.s;
}

/* ---- calling the compiled code ---- */

/* storage kind: 0..5 = int8, uint8, int16, uint16, int32, uint32 */
static int kind(const pf_type *t) { return (t->storage_bits == 8 ? 0 : t->storage_bits == 16 ? 2 : 4) + !t->is_signed; }

#define NZ_CALLS(TI, TO)                                                                                  \
    do {                                                                                                  \
        TI *a[4];                                                                                         \
        TO *o = malloc(K * sizeof(TO));                                                                   \
        for (int k = 0; k < n; k++) {                                                                     \
            a[k] = malloc(K * sizeof(TI));                                                                \
            for (size_t i = 0; i < K; i++)                                                                \
                a[k][i] = (TI)q[4 * i + (size_t)k];                                                       \
        }                                                                                                 \
        for (size_t i = 0; i < K; i++) {                                                                  \
            const int64_t *p = q + 4 * i;                                                                 \
            switch (n) {                                                                                  \
            case 1: sc[i] = ((TO(*)(TI))fs)((TI)p[0]); break;                                             \
            case 2: sc[i] = ((TO(*)(TI, TI))fs)((TI)p[0], (TI)p[1]); break;                               \
            case 3: sc[i] = ((TO(*)(TI, TI, TI))fs)((TI)p[0], (TI)p[1], (TI)p[2]); break;                 \
            default: sc[i] = ((TO(*)(TI, TI, TI, TI))fs)((TI)p[0], (TI)p[1], (TI)p[2], (TI)p[3]); break; \
            }                                                                                             \
        }                                                                                                 \
        switch (n) {                                                                                      \
        case 1: ((void (*)(const TI *, TO *, size_t))fa)(a[0], o, K); break;                              \
        case 2: ((void (*)(const TI *, const TI *, TO *, size_t))fa)(a[0], a[1], o, K); break;            \
        case 3: ((void (*)(const TI *, const TI *, const TI *, TO *, size_t))fa)(a[0], a[1], a[2], o, K); \
            break;                                                                                        \
        default:                                                                                          \
            ((void (*)(const TI *, const TI *, const TI *, const TI *, TO *, size_t))fa)(a[0], a[1], a[2], \
                                                                                          a[3], o, K);    \
            break;                                                                                        \
        }                                                                                                 \
        for (size_t i = 0; i < K; i++)                                                                    \
            ar[i] = (int64_t)o[i];                                                                        \
        for (int k = 0; k < n; k++)                                                                       \
            free(a[k]);                                                                                   \
        free(o);                                                                                          \
    } while (0)

#define NZ_OUTS(TI)                                                                                       \
    switch (ko) {                                                                                         \
    case 0: NZ_CALLS(TI, int8_t); break;                                                                  \
    case 1: NZ_CALLS(TI, uint8_t); break;                                                                 \
    case 2: NZ_CALLS(TI, int16_t); break;                                                                 \
    case 3: NZ_CALLS(TI, uint16_t); break;                                                                \
    case 4: NZ_CALLS(TI, int32_t); break;                                                                 \
    default: NZ_CALLS(TI, uint32_t); break;                                                               \
    }

/* scalar and array results for K points q[4 i + k] */
static void run_batch(const nz_gen *G, int n, void *fs, void *fa, const int64_t *q, size_t K, int64_t *sc,
                      int64_t *ar)
{
    int ki = kind(&G->in), ko = kind(&G->out);
    switch (ki) {
    case 0: NZ_OUTS(int8_t); break;
    case 1: NZ_OUTS(uint8_t); break;
    case 2: NZ_OUTS(int16_t); break;
    case 3: NZ_OUTS(uint16_t); break;
    case 4: NZ_OUTS(int32_t); break;
    default: NZ_OUTS(uint32_t); break;
    }
}

/* ---- measurement ---- */

static uint64_t sm_next(uint64_t *s)
{
    uint64_t z = (*s += 0x9E3779B97F4A7C15u);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9u;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBu;
    return z ^ (z >> 31);
}

/* special coordinates: lattice points and their neighbours, cell middles,
 * the period wrap, the type's extremes */
static int specials(const nz_gen *G, int64_t *v, int cap)
{
    int64_t lo = pf_type_min_stored(&G->in), hi = pf_type_max_stored(&G->in);
    int m = 0;
    static const int cells[] = {-257, -256, -255, -129, -2, -1, 0, 1, 2, 127, 255, 256, 257};
    const int64_t off[] = {-1, 0, 1, 2};
    for (size_t c = 0; c < sizeof cells / sizeof cells[0]; c++) {
        for (size_t j = 0; j < 5; j++) {
            /* cell · 2^F + offset, when it is in range (no overflow: |cell| < 2^9, F <= 62 checked) */
            double approx = ldexp((double)cells[c], G->F);
            if (approx > 9e18 || approx < -9e18)
                continue;
            int64_t base = cells[c] * ((int64_t)1 << G->F);
            int64_t x = j < 4 ? base + off[j] : base + ((int64_t)1 << (G->F - 1));
            if (x >= lo && x <= hi && m < cap)
                v[m++] = x;
        }
    }
    const int64_t ends[] = {lo, lo + 1, hi - 1, hi};
    for (int j = 0; j < 4 && m < cap; j++)
        v[m++] = ends[j];
    return m;
}

static int measure(nz_gen *G, char *err, size_t errlen)
{
    size_t len;
    char *src = emit(G, &len);
    void *h = pf_compile_load(src, len, err, errlen);
    free(src);
    if (!h)
        return -1;
    int rc = 0;
    int64_t lo = pf_type_min_stored(&G->in), hi = pf_type_max_stored(&G->in);
    uint64_t range = (uint64_t)(hi - lo) + 1;
    for (int di = 0; di < G->nd && !rc; di++) {
        nz_dim *d = &G->d[di];
        int n = d->n;
        char an[160];
        snprintf(an, sizeof an, "%s_array", d->name);
        void *fs = dlsym(h, d->name), *fa = dlsym(h, an);
        if (!fs || !fa) {
            snprintf(err, errlen, "emitted code lacks %s or %s", d->name, an);
            rc = -1;
            break;
        }
        /* the point list */
        int64_t sp[128];
        int ns = specials(G, sp, 128);
        size_t cap = 1 << 16, K = 0;
        int64_t *q = calloc(4 * cap, sizeof *q);
        d->exhaustive = n == 1 && G->in.storage_bits <= 16;
        uint64_t s = 0x6e6f697365ull + (uint64_t)n;
        if (d->exhaustive) {
            for (int64_t x = lo; x <= hi; x++)
                q[4 * K++] = x;
        } else {
            for (int i = 0; i < ns; i++) /* every special on each axis, the others random */
                for (int k = 0; k < n; k++) {
                    for (int j = 0; j < n; j++)
                        q[4 * K + (size_t)j] = lo + (int64_t)(sm_next(&s) % range);
                    q[4 * K + (size_t)k] = sp[i];
                    K++;
                }
            for (int i = 0; i < ns; i++) /* all on the same special */
                for (int j = 0; j < n; j++)
                    q[4 * K + (size_t)j] = sp[(i + j) % ns], K += j == n - 1;
            for (int i = 0; i < 2048; i++, K++) /* mixed specials */
                for (int j = 0; j < n; j++)
                    q[4 * K + (size_t)j] = sp[sm_next(&s) % (uint64_t)ns];
            size_t nr = n <= 2 ? 12288 : n == 3 ? 8192 : 4096;
            for (size_t i = 0; i < nr; i++, K++) /* random over the whole type */
                for (int j = 0; j < n; j++)
                    q[4 * K + (size_t)j] = lo + (int64_t)(sm_next(&s) % range);
        }
        int64_t *sc = malloc(K * sizeof *sc), *ar = malloc(K * sizeof *ar);
        run_batch(G, n, fs, fa, q, K, sc, ar);
        d->max_err = -1;
        d->sum_err = 0;
        d->count = K;
        for (size_t i = 0; i < K; i++) {
            if (sc[i] != ar[i])
                d->mismatch++;
            double e = pfref_noise_err_lsb(n, &G->tab, q + 4 * i, G->F, sc[i], G->Eo, G->omin, G->omax);
            d->sum_err += e;
            if (e > d->max_err) {
                d->max_err = e;
                memcpy(d->worst, q + 4 * i, sizeof d->worst);
            }
            if (!(e < 1) || e > 0.5 + d->err * ldexp(1.0, G->Eo) + 1e-9)
                d->over++;
        }
        free(sc);
        free(ar);
        free(q);
    }
    dlclose(h);
    G->swept = 1;
    return rc;
}

/* ---- report ---- */

static void report(FILE *o, const nz_gen *G)
{
    char tmp[2048];
    for (int i = 0; i < G->nd; i++) {
        const nz_dim *d = &G->d[i];
        fprintf(o, "%s: gradient noise %dD, %s -> %s, lattice %s\n", d->name, d->n, G->in_text, G->out_text,
                G->seeded ? "seeded" : "Perlin's permutation");
        formats_text(d, tmp, sizeof tmp);
        fprintf(o, "  formats      %s\n", tmp);
        fprintf(o, "  error bound  %.4e = %.4f LSB before the final rounding (fade %.3e, corners %.3e)\n", d->err,
                d->err * ldexp(1.0, G->Eo), d->eps_f, d->e0);
        if (G->swept) {
            measured_text(G, d, tmp, sizeof tmp);
            fprintf(o, "  measured     %s\n", tmp);
        }
    }
}

/* ---- command line ---- */

int fx_noise_is(const char *func)
{
    return func && (!strcmp(func, "noise") || ((!strncmp(func, "noise", 5) && func[5] >= '1' && func[5] <= '4' &&
                                                !func[6])));
}

/* The noise generator for one request checked by gen/front/request.c (types,
 * variant, exp range, name length). */
int pf_run_noise(const pf_request *rq, FILE *rep, char **src, size_t *len, char *err, size_t errlen)
{
    *src = NULL;
    /* one generation's state is large: static, and reset for every request
       (a scene runs several in one process) */
    static nz_gen Gs;
    nz_gen *G = &Gs;
    memset(G, 0, sizeof *G);
    const char *func = rq->func;
    G->in = rq->in;
    G->out = rq->out;
    G->seeded = rq->seeded;
    G->seed = rq->seed;
    pf_type_format(&G->in, G->in_text, sizeof G->in_text);
    pf_type_format(&G->out, G->out_text, sizeof G->out_text);
    G->F = G->in.exp;
    G->Eo = G->out.exp;
    G->omin = pf_type_min_stored(&G->out);
    G->omax = pf_type_max_stored(&G->out);
    G->it = pf_type_ctype(&G->in);
    G->ot = pf_type_ctype(&G->out);
    if (G->seeded)
        pf_noise_table_seed(&G->tab, G->seed);
    else
        G->tab = *pf_noise_default_table();
    int all = !strcmp(func, "noise");
    G->nd = all ? 4 : 1;
    for (int i = 0; i < G->nd; i++) {
        nz_dim *d = &G->d[i];
        d->n = all ? i + 1 : func[5] - '0';
        char fn[16];
        snprintf(fn, sizeof fn, "noise%d", d->n);
        if (rq->name && all)
            snprintf(d->name, sizeof d->name, "%s%d", rq->name, d->n);
        else if (rq->name)
            snprintf(d->name, sizeof d->name, "%s", rq->name);
        else
            pf_fixed_default_name(fn, &G->in, &G->out, 0, d->name, sizeof d->name);
        double best;
        if (plan_dim(G, d, &best) != 0) {
            snprintf(err, errlen,
                     "impossible: %s %s -> %s needs an error below 1/2 LSB = 2^-%d before the final rounding; with "
                     "64-bit words and products the best bound is %.3g LSB",
                     fn, G->in_text, G->out_text, G->Eo + 1, best);
            return 2;
        }
    }
    G->command = rq->command;
    if (rq->sweep && measure(G, err, errlen) != 0)
        return 1;
    for (int i = 0; i < G->nd && G->swept; i++) {
        const nz_dim *d = &G->d[i];
        if (d->mismatch || d->over) {
            report(rep, G);
            snprintf(err, errlen, "internal failure: %s: %s (max %.4f LSB)", d->name,
                     d->mismatch ? "the scalar and array forms differ" : "an error reaches 1 LSB or exceeds the bound",
                     d->max_err);
            return 1;
        }
    }
    *src = emit(G, len);
    report(rep, G);
    return 0;
}
