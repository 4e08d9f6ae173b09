/* The fixed-point generation pipeline, shared by every function:
 *   fit (minimax for exact, least squares for fast) -> Horner formats from
 *   the bit-width analysis -> coefficients rounded to the lsb of their
 *   Horner step by pin-and-refit -> measured polynomial error -> the
 *   function's error model -> smallest order within the variant's bound
 *   (32-bit words first, then 64) -> emit from the templates -> compile and
 *   sweep the emitted code -> emit again with the sweep in the provenance. */
#include "fixed_internal.h"

#include "compile.h"
#include "fixedgen.h"
#include "round_fixed.h"

#include <dlfcn.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- small helpers ---- */

double fx_lsb(const fx_gen *G) { return ldexp(1.0, -G->out.exp); }

double fx_out_max(const fx_gen *G) { return ldexp((double)pf_type_max_stored(&G->out), -G->out.exp); }

int fx_bitlen(uint64_t v)
{
    int n = 0;
    while (v) {
        n++;
        v >>= 1;
    }
    return n;
}

static uint64_t uabs64(int64_t v) { return v < 0 ? (uint64_t)0 - (uint64_t)v : (uint64_t)v; }

static int int_bits(const pf_type *t) { return t->size - t->exp; }

static void type_text(const pf_type *t, char *buf, size_t n) { pf_type_format(t, buf, n); }

/* ---- the polynomial: fit, formats, rounding ---- */

static pf_type coef_type(int64_t stored, int e)
{
    int b = fx_bitlen(uabs64(stored));
    return pf_type_fixed(1, b < 1 ? 1 : b, e);
}

static fit_refit_fn refit_of(const fx_gen *G) { return G->minimax ? fit_minimax : fit_lsq; }

/* Horner formats for P's exponent Ep from coefficient types ct; E[] gets
 * each coefficient's lsb exponent.  0, or -1 when something does not fit
 * the W-bit word (then the caller lowers Ep). */
static int formats(fx_gen *G, int Ep, const pf_type *ct, int *E, pf_bw_step *st)
{
    int m = G->m, W = G->W;
    pf_type dest = pf_type_fixed(1, Ep + 1, Ep);
    if (pf_bw_horner(ct, m, G->xt, dest, st) != 0)
        return -1;
    for (int j = 0; j < m; j++)
        E[j] = st[j].p.exp;
    /* the leading coefficient feeds a product whose lsb the analysis caps at
       E[m-1] + (integer bits of x) */
    E[m] = m ? E[m - 1] + int_bits(&G->xt) : Ep;
    for (int j = 0; j < m; j++)
        if (st[j].p.size > W - 2 || st[j].shift < 1 || st[j].shift > 2 * W - 2)
            return -1;
    return 0;
}

void fx_partial_max(const double *a, int m, double *pmax)
{
    /* P_k(x) = sum_{j >= k} a_j x^(j-k): the largest |P_k| on a grid of
       N + 1 points, plus L h / 2 with L = sum (j-k) |a_j| >= |P_k'| and h
       the spacing, plus a relative 2^-40 for the double arithmetic */
    enum { N = 4096 };
    for (int k = 0; k <= m; k++) {
        double L = 0, best = 0;
        for (int j = k + 1; j <= m; j++)
            L += (j - k) * fabs(a[j]);
        for (int i = 0; i <= N; i++) {
            double x = (double)i / N, p = a[m];
            for (int j = m - 1; j >= k; j--)
                p = p * x + a[j];
            if (fabs(p) > best)
                best = fabs(p);
        }
        pmax[k] = (best + L * 0.5 / N) * (1 + 0x1p-40);
    }
}

/* 16-bit lanes: formats from pf_bw_horner_word on the polynomial's partial
   sums; every coefficient rounded to its step's lsb (pin-and-refit), the
   bounds taken again on the rounded coefficients, which must give the same
   formats */
static int fit_at16(fx_gen *G, char *err, size_t errlen)
{
    fit_problem *pb = &G->pb;
    int m = G->m;
    G->xt = pf_type_fixed(0, 15, 15);
    for (int emax = 15; emax >= 2; emax--) {
        double a[FX_MAXC], pm[FX_MAXC], e;
        pf_bw_wstep ws[FX_MAXC], ws2[FX_MAXC];
        for (int j = 0; j <= m; j++)
            a[j] = (double)G->real.c[G->deg[j]];
        fx_partial_max(a, m, pm);
        if (pf_bw_horner_word(pm, m, 16, emax, ws, &e) != 0)
            continue;
        int exps[FIT_MAX_ORDER + 1] = {0};
        for (int j = 0; j <= m; j++)
            exps[G->deg[j]] = ws[j].exp;
        G->poly = G->real;
        int64_t stored[FIT_MAX_ORDER + 1];
        if (fit_round_fixed(pb, exps, refit_of(G), &G->poly, stored, err, errlen) != 0)
            return -1;
        int ok = 1;
        for (int j = 0; j <= m; j++) {
            G->C[j] = stored[G->deg[j]];
            a[j] = ldexp((double)G->C[j], -ws[j].exp);
            ok = ok && G->C[j] >= -32767 && G->C[j] <= 32767;
        }
        if (!ok)
            continue;
        fx_partial_max(a, m, pm);
        if (pf_bw_horner_word(pm, m, 16, emax, ws2, &e) != 0)
            continue;
        for (int j = 0; j <= m; j++)
            ok = ok && ws2[j].exp == ws[j].exp;
        if (!ok)
            continue;
        memcpy(G->ws, ws2, sizeof ws2);
        for (int j = 0; j <= m; j++)
            G->E[j] = ws2[j].exp;
        G->Ep = ws2[0].exp;
        G->pt = pf_type_fixed(1, 15, G->Ep);
        G->root_sat = 0;
        G->arith = e;
        G->dP = 0;
        for (int j = 1; j <= m; j++)
            G->dP += j * fabs(a[j]);
        fit_measure(pb, &G->poly);
        G->poly_err = G->poly.max_err;
        return 0;
    }
    snprintf(err, errlen, "order %d: no Horner formats fit 16-bit words", G->order);
    return -1;
}

static int fit_at(fx_gen *G, int order, char *err, size_t errlen)
{
    const fx_func *F = G->fn;
    fit_problem *pb = &G->pb;
    memset(pb, 0, sizeof *pb);
    pb->g = F->g;
    pb->a = F->a;
    pb->b = F->b;
    pb->order = order;
    pb->parity = F->parity;
    pb->errkind = G->errkind;
    if (F->con_zero) {
        pb->ncon = 1;
        pb->con[0].kind = FIT_CON_VALUE;
        pb->con[0].t = 0;
    }
    fit_refit_fn refit = refit_of(G);
    if (refit(pb, &G->real, err, errlen) != 0)
        return -1;
    fit_measure(pb, &G->real);
    int m = -1;
    for (int k = 0; k <= order; k++) {
        if ((F->parity == FIT_PARITY_ODD && k % 2 == 0) || (F->parity == FIT_PARITY_EVEN && k % 2 == 1))
            continue;
        G->deg[++m] = k;
    }
    G->m = m;
    G->order = order;
    if (G->W == 16 && F->fit16) {
        int rc = F->fit16(G, err, errlen);
        if (rc != 1)
            return rc;
    }
    if (G->W == 16)
        return fit_at16(G, err, errlen);
    G->xt = pf_type_fixed(0, G->W - 1, G->W - 1);
    for (int Ep = G->W - 2; Ep >= 8; Ep--) {
        pf_type ct[FX_MAXC];
        int E[FX_MAXC], E2[FX_MAXC];
        for (int j = 0; j <= m; j++) {
            fit_real v = G->real.c[G->deg[j]];
            fit_real s = v * (fit_real)ldexp(1.0, Ep + 8);
            if (!(s < (fit_real)0x1p62 && s > -(fit_real)0x1p62))
                goto lower;
            ct[j] = coef_type(fit_fixed_stored(v, Ep + 8), Ep + 8);
        }
        if (formats(G, Ep, ct, E, G->st) != 0)
            continue;
        int exps[FIT_MAX_ORDER + 1] = {0};
        for (int j = 0; j <= m; j++)
            exps[G->deg[j]] = E[j];
        G->poly = G->real;
        int64_t stored[FIT_MAX_ORDER + 1];
        if (fit_round_fixed(pb, exps, refit, &G->poly, stored, err, errlen) != 0)
            return -1;
        for (int j = 0; j <= m; j++) {
            G->C[j] = stored[G->deg[j]];
            ct[j] = coef_type(G->C[j], E[j]);
            if (ct[j].size > G->W - 2)
                goto lower;
        }
        /* the analysis again, on the rounded coefficients: same lsbs */
        if (formats(G, Ep, ct, E2, G->st) != 0)
            continue;
        for (int j = 0; j <= m; j++)
            if (E2[j] != E[j])
                goto lower;
        memcpy(G->E, E, sizeof E);
        G->Ep = m ? G->st[0].p.exp : E[0];
        G->pt = m ? G->st[0].p : ct[0];
        /* was p_0 trimmed below its bottom-up integer bits? then saturate it */
        {
            int ib = int_bits(&ct[m]);
            for (int j = m - 1; j >= 0; j--) {
                int a = ib + int_bits(&G->xt), c = int_bits(&ct[j]);
                ib = (a > c ? a : c) + 1;
            }
            G->root_sat = m > 0 && ib > int_bits(&G->pt);
        }
        G->arith = 0;
        G->dP = 0;
        for (int j = 0; j <= m; j++) {
            if (j < m)
                G->arith += 0.5 * ldexp(1.0, -E[j]);
            if (j > 0)
                G->dP += j * ldexp((double)uabs64(G->C[j]), -E[j]);
        }
        if (G->root_sat)
            G->arith += ldexp(1.0, -G->Ep);
        fit_measure(pb, &G->poly);
        G->poly_err = G->poly.max_err;
        return 0;
    lower:;
    }
    snprintf(err, errlen, "order %d: no Horner formats fit %d-bit words", order, G->W);
    return -1;
}

/* the variant's bound on the error model; fills bound_lsb */
int fx_within(const fx_gen *G, double R, double A)
{
    double L = fx_lsb(G);
    double tot = R * G->fmax + A;
    if (!(tot == tot))
        return 0;
    if (G->exact)
        return tot < 0.5 * L * (1 - 1e-9);
    /* fast: R|f| + A + L/2 <= max(2^-10 |f|, 4L) for every |f|: it is
       enough at |f| = 2^12 L (the kink) and at |f| = 0, as R <= 2^-10 */
    return R <= 0x1p-10 && R * 4096 * L + A + 0.5 * L <= 4 * L * (1 - 1e-9);
}

static int accept(fx_gen *G)
{
    G->bound_lsb = 0.5 + (G->R * G->fmax + G->A) / fx_lsb(G);
    return fx_within(G, G->R, G->A);
}

/* ---- provenance ---- */

void fx_formats_text(const fx_gen *G, char *buf, size_t n)
{
    char t[64];
    size_t o = 0;
    buf[0] = 0;
    if (G->alt_formats[0]) { /* a function's own scheme (fit16, exp's table kernel) */
        snprintf(buf, n, "%s", G->alt_formats);
        return;
    }
    if (G->W == 16) {
        /* 16-bit lanes: every step a signed 16-bit word */
        o += (size_t)snprintf(buf + o, n - o, "x unsigned fixed<15,15> in int16_t; ");
        for (int j = G->m; j >= 0 && o < n; j--) {
            pf_type p = pf_type_fixed(1, 15, G->E[j]);
            type_text(&p, t, sizeof t);
            o += (size_t)snprintf(buf + o, n - o, "p%d %s", j, t);
            if (j < G->m && G->ws[j].xdrop && o < n)
                o += (size_t)snprintf(buf + o, n - o, " (x rounded to 2^-%d)", 15 - G->ws[j].xdrop);
            if (j && o < n)
                o += (size_t)snprintf(buf + o, n - o, ", ");
        }
        if (G->m > 0 && o < n)
            snprintf(buf + o, n - o, "; steps p = pf_fx_mulhrs(p, x) + c, the rounding multiply-high round(p x 2^-15) "
                                     "(pmulhrsw), formats from pf_bw_horner_word (bound on each |p_k| plus the "
                                     "rounding errors before it); Horner rounding error <= %.3e",
                     G->arith);
        return;
    }
    type_text(&G->xt, t, sizeof t);
    o += (size_t)snprintf(buf + o, n - o, "x %s; ", t);
    for (int j = G->m; j >= 0 && o < n; j--) {
        pf_type p = j == G->m ? pf_type_fixed(1, fx_bitlen(uabs64(G->C[j])) ? fx_bitlen(uabs64(G->C[j])) : 1, G->E[j])
                              : G->st[j].p;
        type_text(&p, t, sizeof t);
        o += (size_t)snprintf(buf + o, n - o, "p%d %s%s", j, t, j ? ", " : "");
    }
    if (G->m > 0 && o < n)
        o += (size_t)snprintf(buf + o, n - o, "; product shifts %d", G->st[G->m - 1].shift);
    if (G->root_sat && o < n)
        snprintf(buf + o, n - o, "; p0 saturated to its format");
}

static void wrap_text(pf_buf *b, const char *label, const char *text) { pf_prov_wrap(b, label, text, 1); }

static const char *method_text(const fx_gen *G)
{
    static char buf[512];
    /* the exact sin/cos in 32-bit lanes (int32_t words in a 16-bit request,
       fixed_trig.c's kind 3) take their formats from that kernel's own rule */
    int own = G->W == 16 && G->wt && strcmp(G->wt, "int32_t") == 0;
    return pf_method_text(buf, sizeof buf, G->minimax, G->errkind == FIT_REL,
                          own ? "their formats, from the 32-bit-lane kernel's own rule (fixed_trig.c, fit16: "
                                "bounds of the partial sums of the real, then of the rounded, coefficients)"
                              : "the lsb of their Horner step (bit-width analysis)");
}

static void provenance(pf_buf *b, const fx_gen *G)
{
    const fx_func *F = G->fn;
    char tmp[2048], a[64], bb[64];
    snprintf(tmp, sizeof tmp, "%s: %s for %s -> %s (%s -> %s), %s variant", G->name, F->name, G->in_text,
             G->out_text, G->it, G->ot, G->exact ? "exact" : "fast");
    pf_prov_begin(b, tmp, PF_NOTICE_OWN_LINE, G->command);
    snprintf(a, sizeof a, "%.9g", ldexp((double)pf_type_min_stored(&G->in), -G->in.exp));
    snprintf(bb, sizeof bb, "%.9g", ldexp((double)pf_type_max_stored(&G->in), -G->in.exp));
    snprintf(tmp, sizeof tmp, "%s x, value x 2^%d in [%s, %s]", G->it, -G->in.exp, a, bb);
    wrap_text(b, "Input:", tmp);
    snprintf(a, sizeof a, "%.9g", ldexp((double)pf_type_min_stored(&G->out), -G->out.exp));
    snprintf(bb, sizeof bb, "%.9g", ldexp((double)pf_type_max_stored(&G->out), -G->out.exp));
    snprintf(tmp, sizeof tmp, "%s y, value y 2^%d in [%s, %s]", G->ot, -G->out.exp, a, bb);
    wrap_text(b, "Output:", tmp);
    wrap_text(b, "Reduction:", G->red_text);
    snprintf(tmp, sizeof tmp, "%s on t in [%g, %g]%s", F->target_text, F->a, F->b,
             F->parity == FIT_PARITY_ODD ? " (odd polynomial t P(t^2))" : "");
    if (!G->nopoly)
        wrap_text(b, "Domain:", G->alt_domain[0] ? G->alt_domain : tmp);
    if (G->alt_order[0])
        snprintf(tmp, sizeof tmp, "%s", G->alt_order);
    else if (G->W == 16)
        snprintf(tmp, sizeof tmp, "%d (%d fixed-point coefficients; %s)", G->order, G->m + 1,
                 G->order_text[0] ? G->order_text : "int16_t words: 16-bit lanes");
    else
        snprintf(tmp, sizeof tmp, "%d (%d fixed-point coefficients; %s words, %d-bit products)", G->order, G->m + 1,
                 G->wt, 2 * G->W);
    wrap_text(b, "Order:", tmp);
    if (G->W == 16)
        wrap_text(b, "Lanes:", G->wide_text[0] ? G->wide_text : "every step in 16-bit lanes");
    if (!G->nopoly) {
        wrap_text(b, "Method:", G->alt_method[0] ? G->alt_method : method_text(G));
        wrap_text(b, "Constraints:", G->alt_con[0] ? G->alt_con : F->con_zero ? F->con_text : "none");
        fx_formats_text(G, tmp, sizeof tmp);
        wrap_text(b, "Formats:", tmp);
        snprintf(tmp, sizeof tmp, "max %s error %.3e (2^%.2f) at t = %.9g", G->errkind == FIT_REL ? "relative" : "absolute",
                 G->poly_err, log2(G->poly_err), G->poly.max_err_at);
        wrap_text(b, "Polynomial:", G->alt_poly[0] ? G->alt_poly : tmp);
    }
    char abs_text[96];
    snprintf(abs_text, sizeof abs_text, " + %.4f LSB (arithmetic and reduction, absolute)", G->A / fx_lsb(G));
    if (G->R > 0)
        snprintf(tmp, sizeof tmp,
                 "|result - f(x)| <= 0.5 LSB (final rounding) + %.3e |f(x)| (polynomial %.3e, arithmetic and "
                 "reduction %.3e, relative)%s = %.4f LSB at most (|f| <= %.6g)",
                 G->R, G->poly_err, G->R - G->poly_err, G->A > 0 && G->W == 16 ? abs_text : "", G->bound_lsb, G->fmax);
    else
        snprintf(tmp, sizeof tmp,
                 "|result - f(x)| <= 0.5 LSB (final rounding) + %.4f LSB (polynomial %.4f, arithmetic and "
                 "reduction %.4f) = %.4f LSB",
                 G->A / fx_lsb(G), G->poly_err / fx_lsb(G), (G->A - G->poly_err) / fx_lsb(G), G->bound_lsb);
    if (G->bound_note[0]) {
        size_t o = strlen(tmp);
        snprintf(tmp + o, sizeof tmp - o, "; %s", G->bound_note);
    }
    if (G->nopoly)
        snprintf(tmp, sizeof tmp, "%s", G->alt_bound);
    wrap_text(b, "Error bound:", tmp);
    if (G->swept) {
        snprintf(tmp, sizeof tmp, "max %.4f LSB at x = %lld (%.9g), mean %.4f LSB; %s", G->sw.max_err,
                 (long long)G->sw.worst_x, ldexp((double)G->sw.worst_x, -G->in.exp), pf_fx_mean(&G->sw),
                 G->sweep_desc);
        wrap_text(b, "Sweep:", tmp);
    }
    {
        char st[512];
        snprintf(st, sizeof st, "%s%sresults beyond the output range give its max or min", G->sat_text,
                 G->sat_text[0] ? "; " : "");
        wrap_text(b, "Saturation:", st);
    }
    wrap_text(b, "Target:",
              G->exact ? "exact: below 1 LSB of the output for every input"
                       : "fast: within max(2^-10 |f(x)|, 4 LSB) for every input");
    wrap_text(b, "Arithmetic:",
              G->alt_arith[0] ? G->alt_arith :
              G->W == 16 ? "integers only (no floating point, no <math.h>); every rounding to nearest, ties up (the "
                           "rounding multiply-high's rule; the error bound needs only half an lsb per rounding); "
                           "bit-identical under any compiler flags"
                         : "integers only (no floating point, no <math.h>); every rounding to nearest, ties to even; "
                           "bit-identical under any compiler flags");
    pf_prov_end_int(b);
}

char *fx_emit(const fx_gen *G, size_t *len)
{
    pf_buf b = {0};
    fx_gen *g = (fx_gen *)G; /* emit() fills the 16-bit constant table */
    g->nk = 0;
    g->bw16 = 0;
    pf_buf body = {0};
    G->fn->emit(g, &body); /* first: it may note wider steps for the provenance */
    provenance(&b, G);
    pf_put(&b, pf_template("fx_common.h"));
    if (G->W == 16)
        pf_put(&b, pf_template("fx_common16.h"));
    pf_put(&b, body.s);
    free(body.s);
    if (G->W == 16) {
        pf_buf kl = {0};
        for (int i = 0; i < G->nk; i++)
            pf_printf(&kl, "\n    %lld,%*s/* k[%d]: %s */", (long long)G->kval[i], 7 - (int)snprintf(NULL, 0, "%lld", (long long)G->kval[i]), "", i, G->kwhat[i]);
        char nk[16];
        snprintf(nk, sizeof nk, "%d", G->nk);
        /* a kernel with an AVX-512BW form gets a loop of its own for CPUs
           that have it, chosen at run time, ahead of the clones */
        pf_buf bwa = {0}, bwc = {0};
        if (G->bw16) {
            const char *cond = "#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(__AVX2__)\n";
            if (G->bw16 == 1) /* 2: the function wrote its own */
            pf_printf(&bwa,
                      "/* AVX-512 has a 16-bit per-element shift (vpsrlvw) and a leading-zero count\n"
                      "   (vplzcntd), AVX2 neither: on a CPU with x86-64-v4 the array form runs this\n"
                      "   loop, whose kernel (bw = 1) uses them; the clones below keep the forms every\n"
                      "   level vectorizes (bw = 0), as the scalar form does.  The same values\n"
                      "   (pfmathgen sweeps the array form on its machine against the scalar one). */\n"
                      "%s__attribute__((target(\"arch=x86-64-v4\"), noinline))\n"
                      "static void %s_array_bw(const %s *x, %s *y, size_t n)\n"
                      "{\n"
                      "    const int16_t *k = %s_k;\n"
                      "    __asm__(\"\" : \"+r\"(k));\n"
                      "    int16_t kl[%d]; /* a local copy: see the array form below */\n"
                      "    for (int j = 0; j < %d; j++)\n"
                      "        kl[j] = k[j];\n"
                      "#pragma GCC ivdep\n"
                      "    for (size_t i = 0; i < n; i++)\n"
                      "        y[i] = %s_inline(x[i], kl, 1);\n"
                      "}\n"
                      "#endif\n\n",
                      cond, G->name, G->it, G->ot, G->name, G->nk, G->nk, G->name);
            if (G->bw16 == 3) /* 2, and an AVX2 loop of its own too (<name>_array_avx2) */
                pf_printf(&bwc,
                          "%s#if defined(PF_FX_TEST_AVX2) /* tests: the AVX2 loop on any x86-64-v3 CPU (it is built for v3: FMA, BMI2 too) */\n"
                          "    if (__builtin_cpu_supports(\"x86-64-v3\")) {\n"
                          "        %s_array_avx2(x, y, n);\n"
                          "        return;\n"
                          "    }\n"
                          "#endif\n"
                          "    if (__builtin_cpu_supports(\"x86-64-v4\")) {\n"
                          "        %s_array_bw(x, y, n);\n"
                          "        return;\n"
                          "    }\n"
                          "    if (__builtin_cpu_supports(\"x86-64-v3\")) {\n"
                          "        %s_array_avx2(x, y, n);\n"
                          "        return;\n"
                          "    }\n"
                          "#endif\n",
                          cond, G->name, G->name, G->name);
            else
            pf_printf(&bwc,
                      "%s    if (__builtin_cpu_supports(\"x86-64-v4\")) {\n"
                      "        %s_array_bw(x, y, n);\n"
                      "        return;\n"
                      "    }\n"
                      "#endif\n",
                      cond, G->name);
        }
        /* the tail's note on the array loop, true for the kernel at hand: the
           16-bit kernels' pmulhrsw rules, or the 32-bit lanes of the exact
           sin/cos (kind 3: int32_t words) and of sqrt from sqrtf (nopoly) */
        const char *note16 =
                   "Array form in 16-bit lanes.  The constants come through a pointer that an\n"
                   "   empty asm hides from GCC: GCC 12 rewrites a product by a known constant\n"
                   "   into shifts and adds before it looks for the rounding multiply-high, and\n"
                   "   it drops the narrowing to 16 bits (so finds no pmulhrsw either) when it\n"
                   "   can bound both operands and prove the product fits; the body therefore\n"
                   "   feeds pf_fx_mulhrs only loads, constants, its own results and values\n"
                   "   multiplied by a constant of k[] (a pmullw).  The values are the same, so\n"
                   "   the scalar and array forms compute the same bits.  Built for a baseline\n"
                   "   without AVX2, it gets one clone per x86-64 level and the widest the CPU\n"
                   "   has is picked at load time (x86-64-v4: 32 lanes, v3: 16, the default:\n"
                   "   8, with pmulhrsw emulated by SSE2 multiplies); integers only, so every\n"
                   "   clone computes the same bits.";
        const char *note32 =
                   "Array form in 32-bit lanes, 16-bit loads and stores:\n"
                   "   %s.  The constants come through a\n"
                   "   pointer that an empty asm hides from GCC, as in the 16-bit kernels.\n"
                   "   Built for a baseline without AVX2, it gets one clone per x86-64 level\n"
                   "   and the widest the CPU has is picked at load time (x86-64-v4: 16\n"
                   "   lanes, v3: 8, the default: 4); every clone computes the same bits.";
        char note[2048];
        if (G->nopoly && G->bw16)
            snprintf(note, sizeof note, note32, "on x86-64-v4 and v3 it runs the loops above\n"
                     "   (see the dispatch below); otherwise the float square root (vsqrtps)\n"
                     "   and its exact integer correction in 32 bits, for the other levels\n"
                     "   and compilers");
        else if (G->nopoly)
            snprintf(note, sizeof note, note32, "the float square root (vsqrtps) and its exact\n   integer correction need 32 bits");
        else if (strcmp(G->wt, "int16_t") != 0)
            snprintf(note, sizeof note, note32, "every step in int32_t words with 32x32 -> 32-bit\n   products (vpmulld)");
        else
            snprintf(note, sizeof note, "%s", note16);
        const char *kv[] = {"NAME", G->name, "IT", G->it, "OT", G->ot, "NK", nk, "KLIST", kl.s ? kl.s : "",
                            "BWARRAY", bwa.s ? bwa.s : "", "BWCALL", bwc.s ? bwc.s : "", "ARRAYNOTE", note, NULL};
        pf_subst(&b, pf_template("fx_tail16.c"), kv);
        free(kl.s);
        free(bwa.s);
        free(bwc.s);
    } else {
        const char *kv[] = {"NAME", G->name, "IT", G->it, "OT", G->ot, NULL};
        pf_subst(&b, pf_template("fx_tail.c"), kv);
    }
    *len = b.n;
    return b.s;
}

/* ---- the sweep of the compiled code ---- */

static int sweep_emitted(fx_gen *G, const char *src, size_t len, char *err, size_t errlen)
{
    void *h = pf_compile_load(src, len, err, errlen);
    if (!h)
        return -1;
    char an[160];
    snprintf(an, sizeof an, "%s_array", G->name);
    pf_fx_fn fn = {dlsym(h, G->name), dlsym(h, an), pf_type_to_fmt(&G->in), pf_type_to_fmt(&G->out)};
    if (!fn.scalar || !fn.array) {
        snprintf(err, errlen, "emitted code lacks %s or %s", G->name, an);
        dlclose(h);
        return -1;
    }
    pf_fx_stats_init(&G->sw);
    int64_t lo = pf_type_min_stored(&G->in), hi = pf_type_max_stored(&G->in);
    if (G->in.storage_bits <= 16) {
        pf_fx_sweep_range(&G->sw, G->fn->ref, &fn, lo, hi, 1, 0);
        G->exhaustive = 1;
        snprintf(G->sweep_desc, sizeof G->sweep_desc, "exhaustive: all %llu inputs",
                 (unsigned long long)(hi - lo + 1));
    } else {
        /* every input within 2^16 of 0, and 2^20 seeded random ones */
        int64_t a = lo > -65536 ? lo : -65536, z = hi < 65536 ? hi : 65536;
        pf_fx_sweep_range(&G->sw, G->fn->ref, &fn, a, z, 1, 0);
        pf_fx_sweep_random(&G->sw, G->fn->ref, &fn, 20260509, 1u << 20);
        G->exhaustive = 0;
        snprintf(G->sweep_desc, sizeof G->sweep_desc,
                 "sampled: every input in [%lld, %lld] and 2^20 seeded random ones (%llu; pfsweep --all "
                 "for all 2^%d)",
                 (long long)a, (long long)z, (unsigned long long)G->sw.count, G->in.storage_bits);
    }
    dlclose(h);
    G->swept = 1;
    return 0;
}

/* ---- the pipeline ---- */

int fx_generate(fx_gen *G, int sweep, char *err, size_t errlen)
{
    const fx_func *F = G->fn;
    char why[600] = "";
    G->below_err = -1;
    int method_req = G->minimax >= 0;
    G->minimax = G->minimax < 0 ? G->exact : G->minimax;
    G->errkind = G->exact ? F->errkind : F->errkind_fast;
    int found = 0;
    /* 16-bit lanes first when input and output are stored in at most 16
       bits: they hold twice the lanes of 32-bit ones */
    int W0 = G->in.storage_bits <= 16 && G->out.storage_bits <= 16 ? 16 : 32;
    for (int W = W0; W <= 64 && !found; W = W == 16 ? 32 : W + 32) {
        G->W = W;
        G->wt = W == 16 ? "int16_t" : W == 32 ? "int32_t" : "int64_t";
        G->mul = W == 16 ? "pf_fx_mulhrs" : W == 32 ? "pf_fx_mul32" : "pf_fx_mul64";
        G->wide_text[0] = 0;
        char e2[600] = "";
        int rc = F->prepare(G, e2, sizeof e2);
        if (rc == -1) {
            snprintf(err, errlen, "%s", e2);
            return -1;
        }
        if (rc == -2) {
            snprintf(why, sizeof why, "%s", e2);
            continue;
        }
        int lo = 1, hi = FX_MAX_SEARCH;
        if (G->order_req)
            lo = hi = G->order_req;
        double prev = -1, best = -1;
        int best_order = 0;
        for (int order = lo; order <= hi; order++) {
            if (F->parity == FIT_PARITY_ODD && order % 2 == 0 && !G->order_req)
                continue;
            /* a fast variant whose error may be absolute or relative (sin,
               cos) tries both fits: absolute suits coarse outputs, relative
               fine ones */
            int kinds[2] = {G->errkind, -1};
            if (!G->exact && F->errkind_fast != F->errkind)
                kinds[0] = F->errkind, kinds[1] = F->errkind_fast;
            int fitted = 0;
            for (int ki = 0; ki < 2 && kinds[ki] >= 0 && !found; ki++) {
                G->errkind = kinds[ki];
                if (fit_at(G, order, e2, sizeof e2) != 0) {
                    snprintf(why, sizeof why, "%s", e2);
                    continue;
                }
                fitted = 1;
                F->budget(G);
                if (accept(G)) {
                    found = 1;
                    G->below_err = G->order_req ? -1 : prev;
                }
            }
            if (found)
                break;
            if (!fitted)
                continue;
            if (best < 0 || G->bound_lsb < best) {
                best = G->bound_lsb;
                best_order = order;
            }
            prev = G->bound_lsb;
            /* the bound without any polynomial error: when the arithmetic
               and the reduction alone miss it, higher orders cannot help */
            double pe = G->poly_err;
            G->poly_err = 0;
            F->budget(G);
            int floor_ok = accept(G);
            G->poly_err = pe;
            F->budget(G);
            accept(G);
            if (!floor_ok)
                break;
        }
        if (found)
            break;
        if (G->order_req && best >= 0)
            snprintf(why, sizeof why, "order %d is bounded by %.4f LSB with %d-bit words", G->order_req, best, W);
        else if (best >= 0)
            snprintf(why, sizeof why, "the best order, %d, is bounded by %.4f LSB with %d-bit words", best_order,
                     best, W);
    }
    if (!found) {
        snprintf(err, errlen, "impossible: no %s %s for %s -> %s within %s (%s)", G->exact ? "exact" : "fast",
                 F->name, G->in_text, G->out_text, G->exact ? "1 LSB" : "max(2^-10 relative, 4 LSB)",
                 why[0] ? why : "no fit");
        return -1;
    }
    /* The table, segment and sqrtf kernels take no fitted order and choose
       their coefficients by their own search (their Order and Method lines
       say how): an --order or --method they would ignore is refused rather
       than dropped, before the sweep's cost.  (sin/cos with --order take the
       Horner kernel, which uses it.) */
    const char *unused = G->order_req && (G->nopoly || G->alt_order[0]) ? "--order"
                         : method_req && (G->nopoly || G->alt_method[0]) ? "--method"
                                                                         : NULL;
    if (unused) {
        snprintf(err, errlen,
                 "%s does not apply to %s %s for %s -> %s: its kernel (%s) picks its own order and "
                 "coefficients, which the Order and Method lines of a run without it show; leave %s out",
                 unused, G->exact ? "exact" : "fast", F->name, G->in_text, G->out_text,
                 G->nopoly ? "sqrtf and an integer correction" : "tables, segments or a searched polynomial",
                 unused);
        return -1;
    }
    if (sweep) {
        size_t len;
        char *src = fx_emit(G, &len);
        int rc = sweep_emitted(G, src, len, err, errlen);
        free(src);
        if (rc != 0)
            return -2;
    }
    return 0;
}

/* ---- reports ---- */

void fx_report_text(FILE *o, const fx_gen *G)
{
    const fx_func *F = G->fn;
    char tmp[2048];
    fprintf(o, "%s: %s, %s variant, %s -> %s\n", G->name, F->name, G->exact ? "exact" : "fast", G->in_text,
            G->out_text);
    fprintf(o, "  reduction    %s\n", G->red_text);
    /* a kernel without a Horner fit of its own (sqrt from sqrtf: nopoly; the
       exp/exp2 table kernel: alt_order) reports its own texts, as the
       provenance does, not the unused fit */
    int own = G->nopoly || G->alt_order[0];
    if (G->nopoly)
        ;
    else if (G->alt_domain[0])
        fprintf(o, "  domain       %s\n", G->alt_domain);
    else
        fprintf(o, "  domain       %s for t in [%g, %g]\n", F->target_text, F->a, F->b);
    if (own)
        fprintf(o, "  order        %s\n", G->nopoly && !G->alt_order[0] ? "none (no polynomial)" : G->alt_order);
    else if (G->W == 16)
        fprintf(o, "  order        %d%s, %s\n", G->order, G->below_err >= 0 ? " (smallest within the bound)" : "",
                G->order_text[0] ? G->order_text : "int16_t words: 16-bit lanes");
    else
        fprintf(o, "  order        %d%s, %s words, %d-bit products\n", G->order,
                G->below_err >= 0 ? " (smallest within the bound)" : "", G->wt, 2 * G->W);
    if (G->below_err >= 0)
        fprintf(o, "               the order below is bounded by %.4f LSB\n", G->below_err);
    if (!G->nopoly) {
        fprintf(o, "  method       %s\n", G->alt_method[0] ? G->alt_method : method_text(G));
        fprintf(o, "  constraints  %s\n", G->alt_con[0] ? G->alt_con : F->con_zero ? F->con_text : "none");
        if (G->alt_formats[0])
            snprintf(tmp, sizeof tmp, "%s", G->alt_formats);
        else
            fx_formats_text(G, tmp, sizeof tmp);
        fprintf(o, "  formats      %s\n", tmp);
    }
    if (!own) {
        fprintf(o, "  coefficients (stored, lsb, value):\n");
        for (int j = 0; j <= G->m; j++)
            fprintf(o, "    c%-2d %20lld  2^-%-3d %.12g\n", G->deg[j], (long long)G->C[j], G->E[j],
                    ldexp((double)G->C[j], -G->E[j]));
        fprintf(o, "  max %s error of the rounded polynomial: %.4e (2^%.2f) at t = %.9g\n",
                G->errkind == FIT_REL ? "rel" : "abs", G->poly_err, log2(G->poly_err), G->poly.max_err_at);
        fprintf(o, "    (real-coefficient fit: %.4e)\n", G->real.max_err);
    } else if (G->alt_poly[0])
        fprintf(o, "  polynomial   %s\n", G->alt_poly);
    if (G->nopoly && G->alt_bound[0])
        fprintf(o, "  error bound  %s\n", G->alt_bound);
    else
        fprintf(o, "  error bound  %.4f LSB (R = %.3e relative, A = %.3e absolute, |f| <= %.6g)\n", G->bound_lsb,
                G->R, G->A, G->fmax);
    if (G->swept) {
        snprintf(tmp, sizeof tmp, "  LSB sweep of the emitted function (%s)", G->sweep_desc);
        pf_fx_stats_print(o, tmp, F->ref, pf_type_to_fmt(&G->in), pf_type_to_fmt(&G->out), &G->sw, !G->exact);
    }
}

void fx_report_json(FILE *o, const fx_gen *G)
{
    const fx_func *F = G->fn;
    fprintf(o, "{\"func\": \"%s\", \"variant\": \"%s\", \"type\": \"%s\", \"out_type\": \"%s\", \"name\": \"%s\", ",
            F->name, G->exact ? "exact" : "fast", G->in_text, G->out_text, G->name);
    /* a kernel without a Horner fit of its own (sqrt from sqrtf: nopoly; the
       exp/exp2 table kernel: alt_order): its description (the provenance's
       Order line) instead of the unused fit */
    int own = G->nopoly || G->alt_order[0];
    if (own) {
        fprintf(o, "\"word_bits\": %d, \"kernel\": \"", G->W);
        for (const char *c = G->alt_order[0] ? G->alt_order : "none (no polynomial)"; *c; c++)
            fprintf(o, *c == '"' || *c == '\\' ? "\\%c" : "%c", *c);
        fprintf(o, "\", \"bound_lsb\": %.6f", G->bound_lsb);
    } else {
        fprintf(o, "\"order\": %d, \"word_bits\": %d, \"method\": \"%s\", \"coefficients\": [", G->order, G->W,
                G->minimax ? "minimax" : "lsq");
        for (int j = 0; j <= G->m; j++)
            fprintf(o, "%s{\"degree\": %d, \"stored\": %lld, \"exp\": %d}", j ? ", " : "", G->deg[j],
                    (long long)G->C[j], G->E[j]);
        fprintf(o, "], \"%s\": %.6e, \"bound_lsb\": %.6f", G->errkind == FIT_REL ? "max_rel_error" : "max_abs_error",
                G->poly_err, G->bound_lsb);
    }
    if (G->swept)
        fprintf(o, ", \"sweep\": {\"max_lsb\": %.6f, \"mean_lsb\": %.6f, \"worst_input\": %lld, \"count\": %llu, "
                   "\"exhaustive\": %s, \"over_fast\": %llu, \"mismatch\": %llu}",
                G->sw.max_err, pf_fx_mean(&G->sw), (long long)G->sw.worst_x, (unsigned long long)G->sw.count,
                G->exhaustive ? "true" : "false", (unsigned long long)G->sw.over_fast,
                (unsigned long long)G->sw.mismatch);
    fprintf(o, "}\n");
}

/* ---- the Horner block ---- */

static void coef_lit(const fx_gen *G, char *buf, size_t n, int64_t v, int add)
{
    char l[64];
    fx_lit(l, sizeof l, v < 0 && add ? -v : v, G->W == 64);
    if (add)
        snprintf(buf, n, "%s %s", v < 0 ? "-" : "+", l);
    else
        snprintf(buf, n, "%s", l);
}

const char *fx_k16(fx_gen *G, int64_t v, const char *what)
{
    static char names[64][16];
    if (G->nk >= 64) /* cannot happen: see nk in fixed_internal.h */
        abort();
    int i = G->nk++;
    G->kval[i] = v;
    snprintf(G->kwhat[i], sizeof G->kwhat[i], "%s", what);
    snprintf(names[i], sizeof names[i], "k[%d]", i);
    return names[i];
}

/* 16-bit Horner: p = mulhrs(p, x >> d) + c, formats from pf_bw_horner_word */
static void emit_horner16(fx_gen *G, pf_buf *b, const char *x, const char *ind)
{
    int m = G->m, done[16] = {0};
    for (int j = m - 1; j >= 0; j--) {
        int d = G->ws[j].xdrop;
        if (d && !done[d]) {
            char what[64];
            snprintf(what, sizeof what, "2^%d: %s rounded to %d fraction bits", 15 - d, x, 15 - d);
            pf_printf(b, "%sint16_t %s%d = pf_fx_mulhrs(%s, %s); /* %s rounded to 2^-%d */\n", ind, x, d, x,
                      fx_k16(G, (int64_t)1 << (15 - d), what), x, 15 - d);
            done[d] = 1;
        }
    }
    char what[64];
    snprintf(what, sizeof what, "c%d = %.12g", G->deg[m], ldexp((double)G->C[m], -G->E[m]));
    pf_printf(b, "%sint16_t p = %s; /* %s */\n", ind, fx_k16(G, G->C[m], what), what);
    for (int j = m - 1; j >= 0; j--) {
        char xv[32];
        if (G->ws[j].xdrop)
            snprintf(xv, sizeof xv, "%s%d", x, G->ws[j].xdrop);
        else
            snprintf(xv, sizeof xv, "%s", x);
        snprintf(what, sizeof what, "c%d = %.12g", G->deg[j], ldexp((double)G->C[j], -G->E[j]));
        if (G->C[j])
            pf_printf(b, "%sp = (int16_t)(pf_fx_mulhrs(p, %s) + %s); /* %s, 2^-%d units */\n", ind, xv,
                      fx_k16(G, G->C[j], what), what, G->E[j]);
        else
            pf_printf(b, "%sp = pf_fx_mulhrs(p, %s); /* %s, 2^-%d units */\n", ind, xv, what, G->E[j]);
    }
}

const char *fx_opaque16(fx_gen *G, const char *expr)
{
    static char buf[4][160];
    static int i;
    i = (i + 1) % 4;
    snprintf(buf[i], sizeof buf[i], "(int16_t)((%s) * %s)", expr, fx_k16(G, 1, "1 (see the array form)"));
    return buf[i];
}

void fx_emit_return16(const fx_gen *G, pf_buf *b, const char *r, int64_t lo, int64_t hi)
{
    /* r holds values in [lo, hi]: clamp only where the output is narrower
       (no comparison that is always false: -Wtype-limits) */
    int64_t mx = pf_type_max_stored(&G->out), mn = pf_type_min_stored(&G->out);
    pf_printf(b, "    return (%s)", G->ot);
    if (lo < mn)
        pf_printf(b, "(%s < %lld ? %lld : ", r, (long long)mn, (long long)mn);
    if (hi > mx)
        pf_printf(b, "(%s > %lld ? %lld : ", r, (long long)mx, (long long)mx);
    pf_put(b, r);
    if (hi > mx)
        pf_put(b, ")");
    if (lo < mn)
        pf_put(b, ")");
    pf_put(b, ";");
}

static void norm16_un(fx_gen *G, pf_buf *b, int nb);

void fx_emit_norm16(fx_gen *G, pf_buf *b, int nb)
{
    norm16_un(G, b, nb);
    pf_put(b, "    int16_t t = (int16_t)(u & 0x7fffu); /* the bits below the leading one: t in [0, 1), 2^-15 units, exact */");
}

void fx_emit_norm16_tq(fx_gen *G, pf_buf *b, int nb)
{
    norm16_un(G, b, nb);
    pf_printf(b, "    int16_t tq = (int16_t)(u & (uint16_t)%s); /* the bits below the leading one: t in [0, 1), 2^-15 "
                 "units, exact */",
              fx_k16(G, 0x7fff, "0x7fff: t's mask (from k[]: hides t's range from GCC)"));
}

static void norm16_un(fx_gen *G, pf_buf *b, int nb)
{
    /* bw = 0: u = ux 2^(16 - nb), then four (or fewer) stages shift the
       leading one up to bit 15: constant shifts and selects, 16-bit lanes.
       bw = 1 (AVX-512: vplzcntd, in 32-bit lanes): the leading-zero count
       of ux >= 1 as a uint32_t, less 16, is the whole shift; about half the
       vector instructions of the stages, and the same u and n */
    pf_put(b, "    uint16_t u;\n    int16_t n; /* bitlen(ux) - 1 */\n#if defined(__GNUC__)\n"
              "    if (bw) {\n"
              "        int lz = __builtin_clz((uint32_t)ux) - 16; /* ux >= 1: in [0, 15] */\n"
              "        u = (uint16_t)(ux << lz);\n"
              "        n = (int16_t)(15 - lz);\n"
              "    } else\n#endif\n    {\n");
    pf_printf(b, "        u = (uint16_t)(ux << %d);\n        n = %d;\n", 16 - nb, nb - 1);
    for (int sh = 8; sh >= 1; sh /= 2)
        if (sh < nb)
            pf_printf(b, "        n = (int16_t)(u < 0x%xu ? n - %d : n);\n        u = (uint16_t)(u < 0x%xu ? u << %d : u);\n",
                      1u << (16 - sh), sh, 1u << (16 - sh), sh);
    pf_put(b, "    }\n");
    G->bw16 = 1;
}

void fx_emit_norm(const fx_gen *G, pf_buf *b)
{
    /* x = 2^n (1 + t): n from the bit length, t the bits below the leading
       one, exact in W-bit words */
    pf_put(b, "    uint32_t ux = x > 0 ? (uint32_t)x : 1u; /* x <= 0 is selected at the end */\n"
              "    int n = pf_fx_bitlen(ux) - 1;\n");
    if (G->W == 32)
        pf_put(b, "    int32_t t = (int32_t)((ux << (31 - n)) - 0x80000000u); /* t in [0, 1), 2^-31 units */");
    else
        pf_put(b, "    int64_t t = (int64_t)(((uint64_t)ux << (63 - n)) - UINT64_C(0x8000000000000000)); /* 2^-63 units */");
}

void fx_emit_vshift16(fx_gen *G, pf_buf *b, const char *a, int64_t amax, const char *sexpr, int smin, int smax,
                      int64_t omax)
{
    /* bw = 0, 32-bit lanes: h = floor(a 2^(1 + L - s')) with s' = s + L >= 0
       (L lifts negative shifts), then r = (h + 1) >> 1 as (h >> 1) + (h & 1):
       round(a 2^-s), ties up; a 2^(1 + L) < 2^32.  AVX2 has no per-lane
       16-bit shift, so this is the form of its clone and the scalar one */
    int L = smin < 0 ? -smin : 0;
    int hi = smax + L;
    int bw = smin >= -1 && amax <= 32767;
    G->bw16 |= bw;
    pf_put(b, "    uint16_t r16;\n");
    if (bw) {
        /* bw = 1, 16-bit lanes (AVX-512BW's vpsrlvw): 2a < 2^16, so
           h = floor(2a 2^-s) for s in [0, 16] is a 16-bit shift (s = 16
           gives 0, as do vpsrlvw and C's shift of the promoted value; every
           s >= 16 is sent there: a 2^-s < 1/2 rounds to 0) and (h + 1) >> 1
           cannot overflow; s = -1 gives 2a = h exactly.  Every value as for
           bw = 0.  (The clamp at 16, not 15, spares GCC a select: 7 vector
           instructions fewer per loop.) */
        /* s ^ 0 (a constant of k[]): where GCC can bound s (exp2's comes
           straight from the clamped input) it widens the shift to 32-bit
           lanes; one xor hides the range */
        pf_printf(b, "    if (bw) { /* a = %s */\n        int16_t s = (int16_t)((%s) ^ %s);\n", a, sexpr,
                  fx_k16(G, 0, "0 (hides s's range from GCC, see the kernel)"));
        pf_printf(b, "        uint16_t sc = (uint16_t)(%s%s%s); /* s in [0, 16] */\n", smin < 0 ? "s < 0 ? 0 : " : "",
                  smax > 16 ? "s > 16 ? 16 : " : "", "s");
        pf_printf(b, "        uint16_t h = (uint16_t)((uint16_t)(%s << 1) >> sc); /* floor(a 2^(1 - s)) */\n", a);
        pf_put(b, "        r16 = (uint16_t)((uint16_t)(h + 1u) >> 1); /* round(a 2^-s), ties up */\n");
        if (smin < 0)
            pf_put(b, "        r16 = (uint16_t)(s < 0 ? h : r16); /* s = -1: 2a */\n");
        int64_t rmax = smin < 0 ? 2 * amax : amax;
        if (rmax > omax)
            pf_printf(b, "        r16 = (uint16_t)(r16 < %lluu ? r16 : %lluu);\n", (unsigned long long)omax,
                      (unsigned long long)omax);
        pf_put(b, "    } else {\n");
    } else {
        pf_put(b, "    { /* no 16-bit form: a 2 or s do not fit */\n");
    }
    pf_printf(b, "        uint32_t sv = (uint32_t)(%s + %d);\n", sexpr, L);
    if (hi > 31)
        pf_put(b, "        sv = sv < 31u ? sv : 31u;\n");
    pf_printf(b, "        uint32_t h = ((uint32_t)%s << %d) >> sv;\n", a, 1 + L);
    pf_put(b, "        uint32_t r = (h >> 1) + (h & 1u);\n");
    pf_printf(b, "        r16 = (uint16_t)(r < %lluu ? r : %lluu);\n    }\n", (unsigned long long)omax,
              (unsigned long long)omax);
}

void fx_emit_horner(fx_gen *G, pf_buf *b, const char *x, const char *ind)
{
    if (G->W == 16) {
        emit_horner16(G, b, x, ind);
        return;
    }
    char l[80];
    int m = G->m;
    /* x >= 0: with every coefficient >= 0 so is every p, and the 64-bit
       product needs no sign handling */
    int pos = 1;
    for (int j = 0; j <= m; j++)
        pos = pos && G->C[j] >= 0;
    coef_lit(G, l, sizeof l, G->C[m], 0);
    pf_printf(b, "%s%s p = %s; /* c%d = %.12g */\n", ind, G->wt, l, G->deg[m], ldexp((double)G->C[m], -G->E[m]));
    for (int j = m - 1; j >= 0; j--) {
        coef_lit(G, l, sizeof l, G->C[j], 1);
        if (!G->C[j])
            l[0] = 0;
        if (G->W == 32)
            pf_printf(b, "%sp = (int32_t)pf_fx_mul32(p, %s, %d)%s%s; /* c%d = %.12g */\n", ind, x, G->st[j].shift,
                      l[0] ? " " : "", l, G->deg[j], ldexp((double)G->C[j], -G->E[j]));
        else
            pf_printf(b, "%sp = pf_fx_mul64%s(p, %s, %d)%s%s; /* c%d = %.12g */\n", ind, pos ? "p" : "", x, G->st[j].shift, l[0] ? " " : "", l, G->deg[j],
                      ldexp((double)G->C[j], -G->E[j]));
    }
    if (G->root_sat) {
        char hi[64], lo[64], t[64];
        fx_lit(hi, sizeof hi, pf_type_max_stored(&G->pt), G->W == 64);
        fx_lit(lo, sizeof lo, pf_type_min_stored(&G->pt), G->W == 64);
        pf_type_format(&G->pt, t, sizeof t);
        pf_printf(b, "%sp = p > %s ? %s : p < %s ? %s : p; /* p0 saturated to %s */\n", ind, hi, hi, lo, lo, t);
    }
}

/* s with each line indented by 4 more spaces */
static void put_indented(pf_buf *b, const char *s)
{
    while (*s) {
        const char *e = strchr(s, '\n');
        size_t n = e ? (size_t)(e - s) + 1 : strlen(s);
        if (n > 1)
            pf_put(b, "    ");
        pf_putn(b, s, n);
        s += n;
    }
}

/* The vector loop over blocks of L words, software pipelined: one pass
   runs stage 1 (s1: x + i loaded, up to the variables cv[]) of block i and
   stage 2 (s2: from cv[] to r) of block i - L.  One block's steps are a
   chain of some 40 dependent instructions, longer than the scheduler can
   overlap over consecutive blocks (the loops measured latency-bound); two
   blocks' halves in one pass halve it.  Then the scalar form for the last
   n % L (and all of n < L).  s1 and s2 are written at the 8-space indent
   of a plain loop body. */
void fx_pipe_loop(pf_buf *kern, const char *vt, int L, const char *s1, const char *s2, const char *const *cv, int nc,
                      const char *store, const char *scalar)
{
    pf_printf(kern, "    size_t i = 0;\n    if (n >= %d) {\n        /* software pipelined: a pass runs the first steps of block i and the\n"
                    "           rest of block i - %d (one block's chain is longer than the CPU overlaps) */\n        %s",
              L, L, vt);
    for (int k = 0; k < nc; k++)
        pf_printf(kern, "%s p_%s", k ? "," : "", cv[k]);
    pf_put(kern, ";\n        {\n");
    put_indented(kern, s1);
    pf_put(kern, "            ");
    for (int k = 0; k < nc; k++)
        pf_printf(kern, "%sp_%s = %s", k ? ", " : "", cv[k], cv[k]);
    pf_printf(kern, ";\n        }\n        for (i = %d; i + %d <= n; i += %d) {\n            %s", L, L, L, vt);
    for (int k = 0; k < nc; k++)
        pf_printf(kern, "%s n_%s", k ? "," : "", cv[k]);
    pf_put(kern, ";\n            {\n");
    pf_buf t = {0};
    put_indented(&t, s1);
    put_indented(kern, t.s);
    free(t.s);
    pf_put(kern, "                ");
    for (int k = 0; k < nc; k++)
        pf_printf(kern, "%sn_%s = %s", k ? ", " : "", cv[k], cv[k]);
    for (int pass = 0; pass < 2; pass++) {
        const char *in = pass ? "        " : "            ";
        pf_printf(kern, pass ? "        {\n            %s" : ";\n            }\n            {\n                %s", vt);
        for (int k = 0; k < nc; k++)
            pf_printf(kern, "%s %s = p_%s", k ? "," : "", cv[k], cv[k]);
        pf_put(kern, ";\n");
        if (pass)
            put_indented(kern, s2);
        else {
            pf_buf u = {0};
            put_indented(&u, s2);
            put_indented(kern, u.s);
            free(u.s);
        }
        pf_printf(kern, "%s    %s\n%s}\n", in, store, in);
        if (!pass) {
            pf_put(kern, "            ");
            for (int k = 0; k < nc; k++)
                pf_printf(kern, "%sp_%s = n_%s", k ? ", " : "", cv[k], cv[k]);
            pf_put(kern, ";\n        }\n");
        }
    }
    pf_printf(kern, "    }\n    for (; i < n; i++)\n        y[i] = %s(x[i]);\n}\n#endif", scalar);
}
