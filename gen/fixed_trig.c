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

#define K_C64 k[0]
#define K_SH s[0]

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
    if (G->W == 32 && G->in.storage_bits <= 16 && (du0 * M_PI / 2 <= budget || du0 <= du1)) {
        G->kind = 0;
        G->dred = du0;
        G->K_SH = Ei + 1;
        snprintf(G->red_text, sizeof G->red_text,
                 "u = x 2/pi with 2/pi = %d 2^-31, the product rounded to 2^-30; phase w = (u + %d) mod 4 "
                 "(uint32_t, 30 fraction bits); fold to v in [-1, 1] (v = w - 1 or 3 - w); error of v <= %.3e",
                 C31, is_cos ? 2 : 1, du0);
    } else {
        G->kind = 1;
        G->dred = du1;
        G->K_C64 = (int64_t)two_over_pi_bits(62 - Ei);
        snprintf(G->red_text, sizeof G->red_text,
                 "u = x 2/pi mod 4 = x C mod 2^64 in 2^-62 units, C = round(2/pi 2^%d) mod 2^64 (bits of 2/pi "
                 "that only add multiples of 4 dropped, from MPFR); phase w = (u + %d) mod 4; fold to v in "
                 "[-1, 1] (v = w - 1 or 3 - w)%s; error of v <= %.3e",
                 62 - Ei, is_cos ? 2 : 1, G->W == 32 ? ", rounded to 2^-30" : "", du1);
        if ((uint64_t)G->K_C64 == 0) {
            snprintf(err, errlen, "%s: input exponent %d too large for the reduction", fn, Ei);
            return -1;
        }
    }
    return 0;
}

static int prep_sin(fx_gen *G, char *err, size_t n) { return prepare(G, err, n, 0); }
static int prep_cos(fx_gen *G, char *err, size_t n) { return prepare(G, err, n, 1); }

static int out_shift(const fx_gen *G) { return (G->W - 2) + G->Ep - G->out.exp; }

static void budget(fx_gen *G)
{
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

static void emit(fx_gen *G, fx_buf *b, int is_cos)
{
    fx_buf phase = {0}, fold = {0}, sq = {0}, horner = {0}, out = {0};
    int W = G->W;
    if (G->kind == 0) {
        int sh = G->K_SH;
        const char *off = is_cos ? "0x80000000u" : "0x40000000u";
        if (sh >= 1)
            fx_printf(&phase, "    uint32_t w = (uint32_t)pf_fx_rne((int64_t)x * %d, %d) + %s;", C31, sh, off);
        else if (sh == 0)
            fx_printf(&phase, "    uint32_t w = (uint32_t)((int64_t)x * %d) + %s;", C31, off);
        else
            fx_printf(&phase, "    uint32_t w = (uint32_t)((uint64_t)(int64_t)x * %du << %d) + %s;", C31, -sh, off);
        fx_put(&fold, "    int32_t v = w < 0x80000000u ? (int32_t)w - 0x40000000 : 0x40000000 - (int32_t)(w - 0x80000000u);");
    } else {
        fx_printf(&phase, "    uint64_t w = (uint64_t)(int64_t)x * UINT64_C(0x%016llx) + UINT64_C(%s);",
                  (unsigned long long)(uint64_t)G->K_C64, is_cos ? "0x8000000000000000" : "0x4000000000000000");
        fx_printf(&fold,
                  "    int64_t v%s = w < UINT64_C(0x8000000000000000) ? (int64_t)w - INT64_C(0x4000000000000000)\n"
                  "                   : INT64_C(0x4000000000000000) - (int64_t)(w - UINT64_C(0x8000000000000000));",
                  W == 32 ? "62" : "");
        if (W == 32)
            fx_put(&fold, "\n    int32_t v = (int32_t)pf_fx_rne(v62, 32); /* v in [-1, 1], 2^-30 units */");
    }
    if (W == 32)
        fx_put(&sq, "    int64_t s0 = pf_fx_rne((int64_t)v * v, 29);\n"
                    "    int32_t s = (int32_t)(s0 < INT32_MAX ? s0 : INT32_MAX);");
    else
        fx_put(&sq, "    int64_t s = pf_fx_mul64(v, v, 61); /* saturates at INT64_MAX */");
    fx_emit_horner(G, &horner, "s", "    ");
    if (horner.n && horner.s[horner.n - 1] == '\n')
        horner.s[--horner.n] = 0;
    int so = out_shift(G);
    int64_t mx = pf_type_max_stored(&G->out), mn = pf_type_min_stored(&G->out);
    if (W == 32)
        fx_printf(&out, "    int64_t r = pf_fx_rne((int64_t)v * p, %d);\n", so);
    else
        fx_printf(&out, "    int64_t r = pf_fx_mul64(v, p, %d);\n", so);
    fx_printf(&out, "    return (%s)(r > %lld ? %lld : r < %lld ? %lld : r);", G->ot, (long long)mx, (long long)mx,
              (long long)mn, (long long)mn);
    char wbits[8], wf[8], stype[64];
    snprintf(wbits, sizeof wbits, "%d", G->kind == 0 ? 32 : 64);
    snprintf(wf, sizeof wf, "%d", G->kind == 0 ? 30 : 62);
    pf_type_format(&G->xt, stype, sizeof stype);
    const char *kv[] = {"FUNC", is_cos ? "cos" : "sin", "PHASE", is_cos ? "2" : "1", "WBITS", wbits, "WF", wf,
                        "NAME", G->name, "IT", G->it, "OT", G->ot, "PHASE_CODE", phase.s, "FOLD_CODE", fold.s,
                        "S_TYPE", stype, "S_CODE", sq.s, "HORNER", horner.s, "OUT_TYPE", G->out_text, "OUT_CODE",
                        out.s, NULL};
    fx_subst(b, fx_template("fx_sincos.c"), kv);
    free(phase.s);
    free(fold.s);
    free(sq.s);
    free(horner.s);
    free(out.s);
}

static void emit_sin(fx_gen *G, fx_buf *b) { emit(G, b, 0); }
static void emit_cos(fx_gen *G, fx_buf *b) { emit(G, b, 1); }

const fx_func fx_func_sin = {
    .name = "sin", .ref = PF_SIN, .tmpl = "fx_sincos", .target_text = "sin(pi/2 t)", .g = g_sinpi2,
    .a = 0, .b = 1, .parity = FIT_PARITY_ODD, .errkind = FIT_ABS, .errkind_fast = FIT_REL, .con_zero = 0, .con_text = NULL,
    .prepare = prep_sin, .budget = budget, .emit = emit_sin,
};

const fx_func fx_func_cos = {
    .name = "cos", .ref = PF_COS, .tmpl = "fx_sincos", .target_text = "sin(pi/2 t)", .g = g_sinpi2,
    .a = 0, .b = 1, .parity = FIT_PARITY_ODD, .errkind = FIT_ABS, .errkind_fast = FIT_REL, .con_zero = 0, .con_text = NULL,
    .prepare = prep_cos, .budget = budget, .emit = emit_cos,
};
