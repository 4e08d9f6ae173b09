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
    snprintf(G->wide_text, sizeof G->wide_text,
             "32-bit lanes (float sqrt, vsqrtps; N and R0^2 need 32 bits); 16-bit loads and stores");
    snprintf(G->alt_bound, sizeof G->alt_bound,
             "correctly rounded, |result - f(x)| <= 0.5 LSB: |s - sqrt(N)| <= 2^-9 (half a float ulp, s < 2^16; "
             "2^-7 for a 2-ulp approximate sqrtf) <= 1/2, so R0 = trunc(s) is round(sqrt(N)) or one below, and one "
             "exact step reaches it (R0 + 1 when sqrt(N) >= R0 + 1/2, i.e. N > R0^2 + R0 in integers; no ties)");
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
