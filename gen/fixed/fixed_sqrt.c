/* sqrt in fixed point (see gen/templates/fx_sqrt.c.in).
 *
 * x = X 2^-Ei, X > 0 = 2^n (1 + t) as for log; e = n - Ei, j = floor(e/2):
 * sqrt(x) = 2^j (sqrt 2 if e is odd) P(t), P(t) ~ sqrt(1 + t) in [1, sqrt 2).
 * y = P q with q = 1 or round(sqrt2 2^Eq) 2^-Eq is rounded to P's lsb, then
 * shifted by j and rounded to the output.  All of these errors are
 * relative (y >= 1).
 * The exact variant then corrects the result R to the correctly rounded one
 * (as pffixed.h's pf_fx_sqrt: to nearest, ties to even, saturated): with
 * 4N = X 2^G the exact square of 2 sqrt(x) 2^Eo, R is right when
 * (2R - 1)^2 < 4N < (2R + 1)^2; as the bound keeps R within one of it, a
 * step of +-1 decided by exact 64-bit squares suffices. */
#include "fixed_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void g_sqrt1p(mpfr_t y, const mpfr_t t, const void *ctx)
{
    (void)ctx;
    mpfr_t a;
    mpfr_init2(a, mpfr_get_prec(y) + 64);
    mpfr_add_ui(a, t, 1, MPFR_RNDN);
    mpfr_sqrt(y, a, MPFR_RNDN);
    mpfr_clear(a);
}


/* The own AVX-512 and AVX2 loops of the 16-bit sqrt (emit_f16_vec, f16_vec):
   for 16-bit storage in and out and G >= 16, where the exact correction runs
   in 16-bit lanes (N > R0 (R0 + 1) iff x > floor(R0 (R0 + 1) / 2^G), a
   vpmulhuw and a shift), and where the estimate's error bound is below 1/2
   (always, as N < 2^32) */
/* |S - sqrt(N)| for the loops' estimate from a reciprocal square root
   (relative error <= 1.5 2^-12, vrsqrtps; vrsqrt14ps: 2^-14) and one Newton
   step in float, N < 2^32 (see emit_f16_vec) */
static double f16_vec_err(const fx_gen *G)
{
    double d = 1.5 * 0x1p-12, u = 0x1p-24;
    double nmax = ldexp((double)pf_type_max_stored(&G->in), (int)G->sqrt.gsh);
    return (1.5 * d * d + d * d * d + 3 * u) * sqrt(nmax);
}

static int f16_vec(const fx_gen *G)
{
    return G->sqrt.gsh >= 16 && G->in.storage_bits == 16 && G->out.storage_bits == 16 && f16_vec_err(G) < 0.5;
}

/* 16-bit storage, N = x 2^G below 2^32 (G = 2 Eo - Ei >= 0): no polynomial
   but sqrtf and an exact correction (gen/templates/fx_sqrtf16.c.in), for the
   exact and the fast variant alike (the correction also keeps the fast one
   bit-identical under -ffast-math's approximate vectorized sqrtf) */
static int prepare_f16(fx_gen *G, int nb, int64_t omax)
{
    int g = 2 * G->out.exp - G->in.exp;
    if (g < 0 || nb + g > 32 || omax > 65535)
        return 0;
    G->nopoly = 1;
    G->sqrt.gsh = g;
    double inmax = ldexp((double)pf_type_max_stored(&G->in), -G->in.exp);
    G->fmax = fmin(fx_out_max(G), sqrt(inmax) * (1 + 1e-9));
    G->dred = 0;
    snprintf(G->sat_text, sizeof G->sat_text, "sqrt(x) for x < 0 (undefined) gives 0");
    G->bound_note[0] = 0;
    snprintf(G->red_text, sizeof G->red_text,
             "none: y = round(sqrt(N)) with N = x 2^%d (2 Eo - Ei) an integer below 2^32; s = sqrtf(N) "
             "(N exact in a float, IEEE sqrt correctly rounded on every x86-64 level), R0 = trunc(s), "
             "then R = R0 + 1 if N > R0 (R0 + 1), exact in 32 bits, else R0; x <= 0 -> 0",
             g);
    snprintf(G->alt_order, sizeof G->alt_order,
             "none (no polynomial): one IEEE single-precision square root and an exact integer correction");
    if (f16_vec(G)) {
        snprintf(G->wide_text, sizeof G->wide_text,
                 "x86-64-v4 and v3: loops of their own (intrinsics), the estimate s in 32-bit float lanes (half "
                 "the lanes vsqrtps, half vrsqrt14ps/vrsqrtps and one Newton step), the correction in 16-bit "
                 "lanes (vpmulhuw); other levels: 32-bit lanes (vsqrtps, 32-bit correction); 16-bit loads and stores");
        snprintf(G->alt_bound, sizeof G->alt_bound,
                 "correctly rounded, |result - f(x)| <= 0.5 LSB: |s - sqrt(N)| <= 2^-9 from sqrtf (half an ulp; "
                 "2^-7 for a 2-ulp one), <= %.3g from rsqrt and Newton (v4/v3 loops), < 1/2, so R0 = trunc(s) is "
                 "round(sqrt(N)) or one below, and one exact step reaches it (R0 + 1 when N > R0^2 + R0; no ties)",
                 f16_vec_err(G));
    } else {
        snprintf(G->wide_text, sizeof G->wide_text,
                 "32-bit lanes (float sqrt, vsqrtps; N and R0^2 need 32 bits); 16-bit loads and stores");
        snprintf(G->alt_bound, sizeof G->alt_bound,
                 "correctly rounded, |result - f(x)| <= 0.5 LSB: |s - sqrt(N)| <= 2^-9 (half a float ulp, s < 2^16; "
                 "2^-7 for a 2-ulp approximate sqrtf) <= 1/2, so R0 = trunc(s) is round(sqrt(N)) or one below, and one "
                 "exact step reaches it (R0 + 1 when sqrt(N) >= R0 + 1/2, i.e. N > R0^2 + R0 in integers; no ties)");
    }
    snprintf(G->alt_arith, sizeof G->alt_arith,
             "an int-to-float conversion and a multiply by 2^%d (both exact), IEEE sqrtf (correctly rounded), "
             "then 32-bit integers; the result does not depend on sqrtf's last bits, so it is bit-identical "
             "under any compiler flags (-ffast-math included) and on every x86-64 level",
             g);
    return 1;
}

static int prepare(fx_gen *G, char *err, size_t errlen)
{
    int Ei = G->in.exp, Eo = G->out.exp, W = G->W;
    G->nopoly = 0;
    G->alt_arith[0] = 0;
    if (Ei > 200 || Ei < -200 || Eo > 62 || Eo < -62) {
        snprintf(err, errlen, "sqrt: exponents out of the supported range");
        return -1;
    }
    int64_t imax = pf_type_max_stored(&G->in), omax = pf_type_max_stored(&G->out);
    int nb = fx_bitlen((uint64_t)imax);
    int64_t elo = -Ei, ehi = nb - 1 - Ei;
    G->sqrt.jlo = elo >= 0 ? elo / 2 : -((-elo + 1) / 2);
    G->sqrt.jhi = ehi >= 0 ? ehi / 2 : -((-ehi + 1) / 2);
    G->sqrt.j0 = G->sqrt.jlo < 0 ? -G->sqrt.jlo : 0;
    if (W == 16 && prepare_f16(G, nb, omax))
        return 0;
    if (W == 16) {
        /* 16-bit lanes: the fast variant only (the exact one's correction
           to the correctly rounded result needs exact 32-bit squares) */
        if (G->exact || Ei > 31 || Ei < -16) {
            snprintf(err, errlen, "16-bit lanes: exact sqrt is corrected in 32-bit words");
            return -2;
        }
    }
    G->sqrt.eq = W == 16 ? 15 : W - 2;
    mpfr_t a;
    mpz_t z;
    mpfr_init2(a, 256);
    mpz_init(z);
    mpfr_set_ui(a, 2, MPFR_RNDN);
    mpfr_sqrt(a, a, MPFR_RNDN);
    mpfr_mul_2si(a, a, G->sqrt.eq, MPFR_RNDN);
    mpfr_get_z(z, a, MPFR_RNDN);
    G->sqrt.qs = (int64_t)mpz_get_si(z);
    mpz_clear(z);
    mpfr_clear(a);
    double inmax = ldexp((double)imax, -Ei);
    G->fmax = fmin(fx_out_max(G), sqrt(inmax) * (1 + 1e-9));
    G->dred = 0;
    if (W == 16) {
        /* P / sqrt2 = round(P QS 2^-15): half P's lsb over P/sqrt2 >= 1/sqrt2, and QS's own error */
        mpfr_init2(a, 256);
        mpfr_set_ui(a, 2, MPFR_RNDN);
        mpfr_sqrt(a, a, MPFR_RNDN);
        mpfr_ui_div(a, 1, a, MPFR_RNDN);
        mpfr_mul_2si(a, a, 15, MPFR_RNDN);
        mpfr_t r;
        mpfr_init2(r, 256);
        mpfr_rint(r, a, MPFR_RNDN);
        G->sqrt.qs15 = (int64_t)mpfr_get_si(r, MPFR_RNDN);
        mpfr_sub(r, r, a, MPFR_RNDN);
        G->sqrt.dq16 = fabs(mpfr_get_d(r, MPFR_RNDN)) / mpfr_get_d(a, MPFR_RNDN);
        mpfr_clears(a, r, (mpfr_ptr)0);
    }
    snprintf(G->sat_text, sizeof G->sat_text, "sqrt(x) for x < 0 (undefined) gives 0");
    G->bound_note[0] = 0;
    /* the correction needs exact squares in 64 bits */
    int gs = 2 * Eo - Ei + 2, bo = fx_bitlen((uint64_t)omax);
    G->sqrt.gsh = gs;
    G->sqrt.corr = G->exact && bo <= 31 && (gs >= 0 ? nb + gs <= 64 : 2 * (bo + 1) - gs <= 64);
    if (G->sqrt.corr)
        snprintf(G->bound_note, sizeof G->bound_note,
                 "the +-1 correction then makes the result correctly rounded (at most 0.5 LSB)");
    if (W == 16) {
        snprintf(G->red_text, sizeof G->red_text,
                 "x = 2^e (1 + t), e = n - %d with n = bitlen(x) - 1 (a staged normalization: constant shifts and "
                 "selects), t in [0, 1) the 15 bits below the leading one (exact); sqrt(x) = 2^ceil(e/2) P(t) "
                 "(/ sqrt2 if e is odd: P round(2^15/sqrt2) 2^-15 = P %lld 2^-15 by the rounding multiply-high, "
                 "MPFR); x <= 0 -> 0",
                 Ei, (long long)G->sqrt.qs15);
        return 0;
    }
    snprintf(G->red_text, sizeof G->red_text,
             "x = 2^e (1 + t), e = n - %d with n = bitlen(x) - 1 (leading-zero count), t in [0, 1) exact; "
             "sqrt(x) = 2^floor(e/2) (sqrt2 if e is odd) P(t), sqrt2 = %lld 2^-%d (MPFR)%s; x <= 0 -> 0",
             Ei, (long long)G->sqrt.qs, (int)G->sqrt.eq,
             G->sqrt.corr ? "; then corrected by +-1 with exact squares to the correctly rounded result (ties to even)" : "");
    return 0;
}

static void budget16(fx_gen *G)
{
    /* P >= 1: its absolute Horner error is relative; for odd e, P/sqrt2
       is rounded to P's lsb (relative 2^-(Ep+1) sqrt2) with QS's error */
    G->A = 0;
    G->R = G->poly_err + G->arith + ldexp(0.5, -G->Ep) * M_SQRT2 + G->sqrt.dq16;
    int smin = G->Ep - G->out.exp - (int)((G->sqrt.jhi * 2 + 2) / 2);
    if (smin < -14)
        G->R = INFINITY;
}

static void budget(fx_gen *G)
{
    if (G->nopoly) { /* correctly rounded: no error but the final rounding */
        G->R = 0;
        G->A = 0;
        return;
    }
    if (G->W == 16) {
        budget16(G);
        return;
    }
    G->A = 0;
    G->R = G->poly_err + G->arith + ldexp(0.5, -(int)G->sqrt.eq) / M_SQRT2 + ldexp(0.5, -G->Ep);
    int base = G->Ep - G->out.exp;
    if (base - (int)G->sqrt.jhi < -(62 - (G->Ep + 2)))
        G->R = INFINITY;
}

/* ceil(e / 2) for e = 2 j0 + ..., as in prepare (floor for negative) */
static int ceil_half(int e) { return e >= 0 ? (e + 1) / 2 : -((-e) / 2); }

static void emit16(fx_gen *G, pf_buf *b)
{
    pf_buf body = {0}, horner = {0};
    int Ei = G->in.exp, Eo = G->out.exp, Ep = G->Ep;
    int nb = fx_bitlen((uint64_t)pf_type_max_stored(&G->in));
    int64_t omax = pf_type_max_stored(&G->out);
    int elo = -Ei, ehi = nb - 1 - Ei;
    int jlo = ceil_half(elo), jhi = ceil_half(ehi);
    int j0 = elo < 0 ? (-elo + 1) / 2 : 0; /* e + 2 j0 >= 0 */
    pf_put(&body, "    uint16_t ux = (uint16_t)(x > 0 ? x : 1); /* x <= 0 is selected at the end */\n");
    fx_emit_norm16(G, &body, nb);
    pf_put(&body, "\n");
    pf_printf(&body, "    uint16_t eb = (uint16_t)(n + %d); /* e + 2 j0 >= 0, e = n - %d, j0 = %d */\n", 2 * j0 - Ei, Ei, j0);
    pf_printf(&body, "    int16_t tq = %s; /* t (a product: see the array form) */\n", fx_opaque16(G, "t"));
    pf_put(&body, "    /* P(t) ~ sqrt(1 + t): Horner in 16-bit words, one rounding per step */\n");
    fx_emit_horner(G, &horner, "tq", "    ");
    pf_put(&body, horner.s);
    pf_printf(&body, "    int16_t pq = pf_fx_mulhrs(p, %s); /* P / sqrt2 (computed for every element: branch-free) */\n",
              fx_k16(G, G->sqrt.qs15, "round(2^15 / sqrt2)"));
    pf_put(&body, "    int16_t y = (eb & 1) ? pq : p; /* P, or P / sqrt2 for odd e: sqrt(x) = 2^ceil(e/2) y */\n");
    int smin = Ep - Eo - jhi, smax = Ep - Eo - jlo;
    char sexpr[64];
    snprintf(sexpr, sizeof sexpr, "%d - (int32_t)((eb + 1) >> 1)", Ep - Eo + j0);
    pf_printf(&body, "    /* y 2^ceil(e/2) rounded once to the output, s = %d - ceil(e/2) in [%d, %d] */\n", Ep - Eo, smin,
              smax);
    fx_emit_vshift16(G, &body, "(uint16_t)y", 32767, sexpr, smin, smax, omax);
    snprintf(G->wide_text, sizeof G->wide_text,
             G->bw16 ? "the scaling by 2^ceil(e/2) is a per-element shift: in 16-bit lanes where AVX-512BW has "
                       "one (vpsrlvw), else in 32-bit lanes (AVX2 has no 16-bit per-element shift); the same "
                       "values, the error model does not need the wider lanes"
                     : "the scaling by 2^ceil(e/2) is a per-element shift, done in 32-bit lanes (AVX2 has no "
                       "16-bit per-element shift; the error model does not need them)");
    pf_put(&body, "    uint16_t m = (uint16_t)(0u - (uint16_t)(x > 0)); /* x <= 0 gives 0, through a mask */\n");
    pf_printf(&body, "    return (%s)(r16 & m);", G->ot);
    const char *kv[] = {"NAME", G->name, "IT", G->it, "OT", G->ot, "BODY", body.s, NULL};
    pf_subst(b, pf_template("fx_sqrt16.c"), kv);
    free(body.s);
    free(horner.s);
}

/* The loops of their own for x86-64-v4 and v3 (G >= 16, 16-bit storage:
   f16_vec).  Per vector of 16-bit x: words 0-3 and 4-7 of each 128-bit lane
   widened to 32-bit lanes by unpacking with a constant high word, which
   makes each lane the float 2^(G+E) (1 + x 2^-23), E = 21 or 23, minus 2^(G+E)
   exactly x 2^(G-2) or x 2^G (no int-to-float conversion, no shift).  Words
   4-7: s = sqrtf(x 2^G) (vsqrtps, as the scalar form).  Words 0-3 (vsqrtps
   is the peer's throughput limit, the reciprocal square root is not): with
   Z = x 2^(G-2) = N/4, y = rsqrt(Z) (1 + d), |d| <= 1.5 2^-12, t = fl(Z y),
   s = fl(t fl(3 - t y)) (fused) = 2 sqrt(Z) (1 - 3/2 d^2 - d^3/2 + e), |e| <=
   3 2^-24 for the three roundings: |s - sqrt(N)| <= (3/2 d^2 + d^3 + 3 2^-24)
   sqrt(N) < 2^-5 for N < 2^32; y is capped at 1 (it is below 2^-7 for
   x > 0), so that x = 0 gives s = 0 rather than 0 inf (a NaN and an invalid
   flag).  R0 = trunc(s) (vcvttps2dq, vpackusdw: back in word order) is
   then round(sqrt(N)) or one below, as in the scalar form, and R = R0 + 1
   iff N > R0 (R0 + 1), i.e. (N = x 2^G, x an integer) x > floor(R0 (R0 + 1)
   / 2^G): the high half of a 16x16-bit
   product (vpmulhuw), shifted by G - 16, compared in 16-bit lanes.  R0 + 1
   saturates at 65535: R0 = 65535 only when R = 65535 (N < 2^32 <
   65535.5^2), and both choices then give it. */
static void emit_f16_vec(fx_gen *G, pf_buf *b)
{
    const char *N = G->name;
    int g = (int)G->sqrt.gsh, sx = !strcmp(G->it, "int16_t");
    int64_t omax = pf_type_max_stored(&G->out);
    double rmax = floor(sqrt(ldexp((double)pf_type_max_stored(&G->in), g)) + 0.5);
    int clamp = rmax > (double)omax;
    double err = f16_vec_err(G);
    G->bw16 = 3;
    const char *cond = "#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(__AVX2__)\n";
    pf_printf(b,
              "\n/* x86-64-v4 and v3: loops of their own, with intrinsics (the array form\n"
              "   dispatches to them at run time; the other levels run the scalar steps\n"
              "   above).  Per 16-bit x, N = x 2^%d: words 4-7 of each 128-bit lane get\n"
              "   s = sqrtf(N) (vsqrtps), words 0-3, as vsqrtps is the throughput limit,\n"
              "   s from a reciprocal square root (vrsqrt14ps, vrsqrtps: relative error\n"
              "   d <= 1.5 2^-12) and one Newton step in float: with Z = N/4, y = rsqrt(Z),\n"
              "   t = fl(Z y), s = fl(t fl(3 - t y)) = sqrt(N) (1 - 3/2 d^2 - d^3/2 + e),\n"
              "   |e| <= 3 2^-24 (three roundings), so |s - sqrt(N)| <= %.3g < 1/2 and\n"
              "   R0 = trunc(s) is the result or one below it, as in the scalar form.\n"
              "   Each float is made by unpacking x with a constant high word: the\n"
              "   lane's bits are 2^B (1 + x 2^-23), minus 2^B exactly x 2^(B-23).  y is\n"
              "   capped at 1 (Z >= 2^14 otherwise): for x = 0, rsqrt's inf would make\n"
              "   0 inf, a NaN and an invalid-operation flag; the cap gives s = 0.\n"
              "   vpackusdw puts R0 back in word order; then\n"
              "   R = R0 + 1 iff N > R0 (R0 + 1), i.e. x > floor(R0 (R0 + 1) / 2^%d), the\n"
              "   high half of a 16x16-bit product (vpmulhuw)%s, in 16-bit lanes.  R0 + 1\n"
              "   saturates at 65535: R0 = 65535 only when the result is 65535 (N < 2^32\n"
              "   < 65535.5^2), which both choices give.  The same values as the scalar\n"
              "   form for every x (the correction makes both correctly rounded). */\n"
              "%s#include <immintrin.h>\n"
              "extern %s %s(%s x); /* the scalar form, for the last n %% 32 */\n",
              g, err, g, g > 16 ? " shifted right" : "", cond, G->ot, N, G->it);
    for (int v4 = 1; v4 >= 0; v4--) {
        const char *V = v4 ? "__m512" : "__m256", *P = v4 ? "_mm512" : "_mm256";
        int L = v4 ? 32 : 16;
        pf_printf(b,
                  "__attribute__((target(\"arch=x86-64-v%d\"), noinline))\n"
                  "static void %s_array_%s(const %s *x, %s *y, size_t n)\n{\n"
                  "    const %si er = %s_set1_epi16(0x%x), es = %s_set1_epi16(0x%x), one = %s_set1_epi16(1);\n"
                  "    const %s br = %s_set1_ps(0x1p%df), bs = %s_set1_ps(0x1p%df), three = %s_set1_ps(3.0f);\n"
                  "    const %s one_f = %s_set1_ps(1.0f);\n",
                  v4 ? 4 : 3, N, v4 ? "bw" : "avx2", G->it, G->ot, V, P, (148 + g) << 7, P, (150 + g) << 7, P, V, P,
                  g + 21, P, g + 23, P, V, P);
        if (clamp)
            pf_printf(b, "    const %si omax = %s_set1_epi16(%lld);\n", V, P, (long long)omax);
        pf_printf(b, "    size_t i = 0;\n    for (; i + %d <= n; i += %d) {\n", L, L);
        if (v4)
            pf_put(b, "        __m512i xv = _mm512_loadu_si512(x + i);\n");
        else
            pf_put(b, "        __m256i xv = _mm256_loadu_si256((const __m256i *)(x + i));\n");
        if (sx)
            pf_printf(b, "        xv = %s_max_epi16(xv, %s_setzero_si%d()); /* x <= 0 gives 0 */\n", P, P, v4 ? 512 : 256);
        pf_printf(b,
                  "        /* words 0-3: Z = x 2^%d, s = t (3 - t y), y = rsqrt(Z), t = Z y */\n"
                  "        %s z = %s_sub_ps(%s_castsi%d_ps(%s_unpacklo_epi16(xv, er)), br);\n"
                  "        %s r = %s_min_ps(%s_rsqrt%s_ps(z), one_f); /* x = 0: 1, not inf (no 0 inf) */\n"
                  "        %s t = %s_mul_ps(z, r);\n"
                  "        %s s0 = %s_mul_ps(t, %s_fnmadd_ps(t, r, three));\n"
                  "        /* words 4-7: s = sqrtf(x 2^%d) */\n"
                  "        %s s1 = %s_sqrt_ps(%s_sub_ps(%s_castsi%d_ps(%s_unpackhi_epi16(xv, es)), bs));\n"
                  "        %si r0 = %s_packus_epi32(%s_cvttps_epi32(s0), %s_cvttps_epi32(s1)); /* R0, in word order */\n"
                  "        %si r1 = %s_adds_epu16(r0, one);\n",
                  g - 2, V, P, P, v4 ? 512 : 256, P, V, P, P, v4 ? "14" : "", V, P, V, P, P, g, V, P, P, P,
                  v4 ? 512 : 256, P, V, P, P, P, V, P);
        if (g > 16)
            pf_printf(b, "        %si ph = %s_srli_epi16(%s_mulhi_epu16(r0, r1), %d); /* floor(R0 (R0 + 1) / 2^%d) */\n",
                      V, P, P, g - 16, g);
        else
            pf_printf(b, "        %si ph = %s_mulhi_epu16(r0, r1); /* floor(R0 (R0 + 1) / 2^16) */\n", V, P);
        if (v4)
            pf_put(b, "        __m512i rr = _mm512_mask_mov_epi16(r0, _mm512_cmpgt_epu16_mask(xv, ph), r1);\n");
        else
            pf_put(b, "        __m256i rr = _mm256_adds_epu16(r0, _mm256_min_epu16(_mm256_subs_epu16(xv, ph), one)); /* + (x > ph) */\n");
        if (clamp)
            pf_printf(b, "        rr = %s_min_epu16(rr, omax);\n", P);
        if (v4)
            pf_put(b, "        _mm512_storeu_si512(y + i, rr);\n");
        else
            pf_put(b, "        _mm256_storeu_si256((__m256i *)(y + i), rr);\n");
        pf_printf(b, "    }\n    for (; i < n; i++)\n        y[i] = %s(x[i]);\n}\n", N);
    }
    pf_put(b, "#endif\n");
}

static void emit_f16(fx_gen *G, pf_buf *b)
{
    pf_buf body = {0};
    int g = (int)G->sqrt.gsh;
    int64_t omax = pf_type_max_stored(&G->out);
    char w[64];
    snprintf(w, sizeof w, "G = 2 Eo - Ei: N = x 2^%d", g);
    pf_printf(&body, "    uint32_t xx = (uint32_t)(x > 0 ? x : 0);\n");
    pf_printf(&body, "    uint32_t N = xx << %s; /* x 2^G < 2^32, exact */\n", fx_k16(G, g, w));
    if (g)
        pf_printf(&body, "    float s = sqrtf((float)(int32_t)xx * 0x1p%df); /* N in a float, exact; s within 2^-9 of sqrt(N) */\n", g);
    else
        pf_printf(&body, "    float s = sqrtf((float)(int32_t)xx); /* N in a float, exact; s within 2^-9 of sqrt(N) */\n");
    pf_put(&body, "    int32_t r0 = (int32_t)s; /* round(sqrt(N)) or one below, as |s - sqrt(N)| <= 1/2 */\n");
    pf_put(&body, "    /* r0 + 1 when sqrt(N) >= r0 + 1/2, i.e. N > r0^2 + r0 (integers), r0 (r0 + 1) < 2^32 */\n");
    pf_put(&body, "    int32_t r = r0 + (N > (uint32_t)r0 * ((uint32_t)r0 + 1u));\n");
    /* the largest result, round(sqrt(max N)): a clamp only when it exceeds the output's max */
    double rmax = floor(sqrt(ldexp((double)pf_type_max_stored(&G->in), g)) + 0.5);
    if (rmax > (double)omax)
        pf_printf(&body, "    r = r < %lld ? r : %lld;\n", (long long)omax, (long long)omax);
    pf_printf(&body, "    return (%s)r;", G->ot);
    const char *kv[] = {"NAME", G->name, "IT", G->it, "OT", G->ot, "BODY", body.s, NULL};
    pf_subst(b, pf_template("fx_sqrtf16.c"), kv);
    free(body.s);
    if (f16_vec(G))
        emit_f16_vec(G, b);
}

static void emit(fx_gen *G, pf_buf *b)
{
    if (G->nopoly) {
        emit_f16(G, b);
        return;
    }
    if (G->W == 16) {
        emit16(G, b);
        return;
    }
    pf_buf norm = {0}, horner = {0}, out = {0};
    int W = G->W, Ei = G->in.exp;
    int64_t omax = pf_type_max_stored(&G->out);
    fx_emit_norm(G, &norm);
    fx_emit_horner(G, &horner, "t", "    ");
    pf_chomp(&horner);
    char qs[64], q1[64];
    fx_lit(qs, sizeof qs, G->sqrt.qs, W == 64);
    fx_lit(q1, sizeof q1, (int64_t)1 << G->sqrt.eq, W == 64);
    pf_printf(&out, "    uint64_t eb = (uint64_t)(n + %lld); /* e + 2 J0 = n - %d + 2 J0 >= 0, J0 = %lld */\n",
              (long long)(2 * G->sqrt.j0 - Ei), Ei, (long long)G->sqrt.j0);
    pf_printf(&out, "    %s q = (eb & 1) ? %s : %s; /* sqrt2 or 1, 2^-%d units */\n", G->wt, qs, q1, (int)G->sqrt.eq);
    pf_printf(&out, "    int64_t y = %s(p, q, %d); /* P q, 2^-%d units */\n", G->mul, (int)G->sqrt.eq, G->Ep);
    int base = G->Ep - G->out.exp;
    int shmin = base - (int)G->sqrt.jhi, shmax = base - (int)G->sqrt.jlo;
    long long bj = (long long)base + (long long)G->sqrt.j0; /* sh = Ep - Eo - floor(e/2) = bj - (eb >> 1) */
    if (shmin >= 1) {
        pf_printf(&out, "    uint64_t sh = %lld - (eb >> 1);\n", bj);
        pf_printf(&out, "    uint64_t r = pf_fx_rne_u((uint64_t)y, %s);\n", shmax > 63 ? "sh < 63 ? sh : 63" : "sh");
    } else {
        pf_printf(&out, "    int64_t sh = %lld - (int64_t)(eb >> 1);\n", bj);
        if (shmax <= 0)
            pf_put(&out, "    uint64_t r = (uint64_t)y << -sh;\n");
        else
            pf_put(&out, "    uint64_t r = sh >= 1 ? pf_fx_rne_u((uint64_t)y, (uint64_t)(sh < 63 ? sh : 63))\n"
                         "                         : (uint64_t)y << (sh > -62 ? -sh : 62);\n");
    }
    pf_printf(&out, "    r = r < %lluu ? r : %lluu;\n", (unsigned long long)omax, (unsigned long long)omax);
    if (G->sqrt.corr) {
        int gs = (int)G->sqrt.gsh;
        pf_put(&out, "    /* correctly rounded: R is right when (2R-1)^2 < 4N < (2R+1)^2, 4N = x 2^G exactly */\n");
        /* 2R +- 1 < 2^32 (bo <= 31): squares from 32x32-bit products; when
           everything stays below 2^63 the compares are signed (AVX2 has no
           unsigned 64-bit compare) */
        int nb = fx_bitlen((uint64_t)pf_type_max_stored(&G->in)), bo = fx_bitlen((uint64_t)omax);
        int sgn = (gs >= 0 ? nb + gs <= 62 && 2 * (bo + 1) <= 62 : 2 * (bo + 1) - gs <= 62);
        const char *ct = sgn ? "int64_t" : "uint64_t";
        pf_put(&out, "    uint32_t a1 = (uint32_t)(2 * r + 1), a0 = (uint32_t)(2 * r - 1);\n");
        if (gs >= 0)
            pf_printf(&out, "    %s n4 = (%s)((uint64_t)ux << %d), hi2 = (%s)((uint64_t)a1 * a1), lo2 = (%s)((uint64_t)a0 * a0);\n",
                      ct, ct, gs, ct, ct);
        else
            pf_printf(&out, "    %s n4 = (%s)ux, hi2 = (%s)((uint64_t)a1 * a1 << %d), lo2 = (%s)((uint64_t)a0 * a0 << %d);\n",
                      ct, ct, ct, -gs, ct, -gs);
        pf_put(&out, "    r = r + (n4 > hi2 || (n4 == hi2 && (r & 1))) - (r > 0 && (n4 < lo2 || (n4 == lo2 && (r & 1))));\n");
        pf_printf(&out, "    r = r < %lluu ? r : %lluu;\n", (unsigned long long)omax, (unsigned long long)omax);
    }
    pf_printf(&out, "    return (%s)(x > 0 ? r : 0);", G->ot);
    const char *kv[] = {"NAME", G->name, "IT", G->it, "OT", G->ot, "NORM_CODE", norm.s, "HORNER", horner.s,
                        "OUT_CODE", out.s, NULL};
    pf_subst(b, pf_template("fx_sqrt.c"), kv);
    free(norm.s);
    free(horner.s);
    free(out.s);
}

const fx_func fx_func_sqrt = {
    .name = "sqrt", .ref = PF_SQRT, .tmpl = "fx_sqrt", .target_text = "sqrt(1+t)", .g = g_sqrt1p, .a = 0, .b = 1,
    .parity = FIT_PARITY_NONE, .errkind = FIT_REL, .errkind_fast = FIT_REL, .con_zero = 1, .con_text = "p(0) = 1 (exact at powers of 4)",
    .prepare = prepare, .budget = budget, .emit = emit,
};
