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

#define KZ k[0]     /* round(ln2 2^Ez) or 2^Ez */
#define EMAX k[1]   /* max |e| */
#define EZ s[0]

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
    G->EMAX = elo < 0 ? -elo : elo;
    if ((ehi < 0 ? -ehi : ehi) > G->EMAX)
        G->EMAX = ehi < 0 ? -ehi : ehi;
    G->EZ = 62 - fx_bitlen((uint64_t)G->EMAX + 1) - 1;
    if (G->EZ <= Eo) {
        snprintf(err, errlen, "%s: output lsb 2^-%d is finer than the 64-bit sum can hold", fn, Eo);
        return -1;
    }
    if (base2) {
        G->KZ = (int64_t)1 << G->EZ;
    } else {
        mpfr_t l;
        mpfr_init2(l, 256);
        mpfr_const_log2(l, MPFR_RNDN);
        mpfr_mul_2si(l, l, G->EZ, MPFR_RNDN);
        mpfr_rint(l, l, MPFR_RNDN);
        mpz_t z;
        mpz_init(z);
        mpfr_get_z(z, l, MPFR_RNDN);
        G->KZ = (int64_t)mpz_get_si(z);
        mpz_clear(z);
        mpfr_clear(l);
    }
    G->fmax = 0;
    snprintf(G->sat_text, sizeof G->sat_text, "%s(x) for x <= 0 (undefined) gives %lld, the most negative output",
             fn, (long long)pf_type_min_stored(&G->out));
    G->dred = base2 ? 0 : (double)G->EMAX * ldexp(0.5, -G->EZ);
    snprintf(G->red_text, sizeof G->red_text,
             "x = 2^e (1 + t), e = n - %d with n = bitlen(x) - 1 (leading-zero count), t in [0, 1) the bits "
             "below the leading one (exact); %s(x) = e %s + P(t) summed in 64 bits at 2^-%d%s, rounded once; "
             "x <= 0 -> %lld (most negative)",
             Ei, fn, base2 ? "" : "ln2", (int)G->EZ,
             base2 ? "" : " (ln2 = KZ 2^-Ez, KZ from MPFR)", (long long)pf_type_min_stored(&G->out));
    return 0;
}

static int prep_log(fx_gen *G, char *err, size_t n) { return prepare(G, err, n, 0); }
static int prep_log2(fx_gen *G, char *err, size_t n) { return prepare(G, err, n, 1); }

static void budget(fx_gen *G)
{
    G->R = 0;
    int d = (int)G->EZ - G->Ep;
    G->A = G->poly_err + G->arith + G->dred + (d < 0 ? ldexp(0.5, -(int)G->EZ) : 0);
}

static void emit(fx_gen *G, fx_buf *b, int base2)
{
    fx_buf norm = {0}, horner = {0}, out = {0};
    int W = G->W, Ei = G->in.exp, Eo = G->out.exp;
    int64_t mx = pf_type_max_stored(&G->out), mn = pf_type_min_stored(&G->out);
    fx_put(&norm, "    uint32_t ux = x > 0 ? (uint32_t)x : 1u; /* x <= 0 is selected at the end */\n"
                  "    int n = pf_fx_bitlen(ux) - 1;\n");
    if (W == 32)
        fx_put(&norm, "    int32_t t = (int32_t)((ux << (31 - n)) - 0x80000000u); /* t in [0, 1), 2^-31 units */");
    else
        fx_put(&norm, "    int64_t t = (int64_t)(((uint64_t)ux << (63 - n)) - UINT64_C(0x8000000000000000)); /* 2^-63 units */");
    fx_emit_horner(G, &horner, "t", "    ");
    if (horner.n && horner.s[horner.n - 1] == '\n')
        horner.s[--horner.n] = 0;
    int d = (int)G->EZ - G->Ep;
    char pz[96];
    if (d > 0)
        snprintf(pz, sizeof pz, "(int64_t)p * INT64_C(%lld)", (long long)((int64_t)1 << d));
    else if (d == 0)
        snprintf(pz, sizeof pz, "(int64_t)p");
    else
        snprintf(pz, sizeof pz, "pf_fx_rne(p, %d)", -d);
    fx_printf(&out, "    /* e %s + P(t) at 2^-%d, exact; one rounding to the output */\n", base2 ? "" : "ln2", (int)G->EZ);
    if (base2 || G->KZ <= INT32_MAX)
        fx_printf(&out, "    int64_t z = (int64_t)(n - %d) * INT64_C(%lld) + %s;\n", Ei, (long long)G->KZ, pz);
    else /* e K from two 32x32-bit products, which vectorize (K = KH 2^31 + KL) */
        fx_printf(&out,
                  "    int64_t z = (int64_t)(n - %d) * %lld * INT64_C(2147483648) + (int64_t)(n - %d) * %lld + %s;\n",
                  Ei, (long long)(G->KZ >> 31), Ei, (long long)(G->KZ & 0x7fffffff), pz);
    fx_printf(&out, "    int64_t r = pf_fx_rne(z, %d);\n", (int)G->EZ - Eo);
    fx_printf(&out, "    r = r > %lld ? %lld : r < %lld ? %lld : r;\n", (long long)mx, (long long)mx, (long long)mn,
              (long long)mn);
    fx_printf(&out, "    return (%s)(x > 0 ? r : %lld);", G->ot, (long long)mn);
    char minout[32];
    snprintf(minout, sizeof minout, "%lld", (long long)mn);
    const char *kv[] = {"FUNC", base2 ? "log2" : "log", "KTEXT", base2 ? "" : "ln2", "PTEXT",
                        base2 ? "log2(1 + t)" : "log(1 + t)", "MINOUT", minout, "NAME", G->name, "IT", G->it, "OT",
                        G->ot, "NORM_CODE", norm.s, "HORNER", horner.s, "OUT_CODE", out.s, NULL};
    fx_subst(b, fx_template("fx_log.c"), kv);
    free(norm.s);
    free(horner.s);
    free(out.s);
}

static void emit_log(fx_gen *G, fx_buf *b) { emit(G, b, 0); }
static void emit_log2(fx_gen *G, fx_buf *b) { emit(G, b, 1); }

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
