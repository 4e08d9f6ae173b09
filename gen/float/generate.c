#include "generate.h"

#include "compile.h"
#include "emit.h"

#include <dlfcn.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char *method_text(const pf_gen_result *r)
{
    static char buf[256];
    return pf_method_text(buf, sizeof buf, r->minimax, r->pb.errkind == FIT_REL, "float");
}

static void constraints_text(const pf_spec *s, char *buf, size_t n)
{
    buf[0] = 0;
    for (int i = 0; i < s->ncon; i++) {
        if (i)
            strncat(buf, ", ", n - strlen(buf) - 1);
        strncat(buf, s->con[i].text, n - strlen(buf) - 1);
    }
    if (!s->ncon)
        snprintf(buf, n, "none");
}

static void emit(pf_buf *b, const pf_gen_result *r, const char *command)
{
    const pf_spec *s = r->spec;
    char con[512], ha[64], hb[64], hw[64], title[256];
    constraints_text(s, con, sizeof con);
    pf_hexf(ha, sizeof ha, s->a);
    pf_hexf(hb, sizeof hb, s->b);
    pf_hexf(hw, sizeof hw, r->poly.max_err_at);
    snprintf(title, sizeof title, "%s: %s for float, %s variant", r->name, s->func, s->variant);
    pf_prov_begin(b, title, PF_NOTICE_SAME_LINE, command);
    pf_prov_line(b, "Reduction:", "%s", s->reduction_text);
    pf_prov_line(b, "Domain:", "%s on t in [%s, %s]  (%.9g .. %.9g)", s->target_text, ha, hb, s->a, s->b);
    pf_prov_line(b, "Order:", "%d (float coefficients, Horner in %s)", r->order,
                 !strcmp(s->real, "fma") ? "float with fmaf" : s->real);
    if (r->has_scheme) {
        pf_prov_line(b, "Evaluation:", "%s", r->scheme.text);
        pf_prov_line(b, "Error model:", "at most %.3f ULP (fit error and every rounding of the scheme)",
                     r->scheme.bound_ulp);
    }
    pf_prov_line(b, "Method:", "%s", method_text(r));
    pf_prov_line(b, "Constraints:", "%s", con);
    pf_printf(b, " * Max %s error of this polynomial on the domain: %.3e (2^%.2f) at t = %s\n",
              s->errkind == FIT_REL ? "relative" : "absolute", r->poly.max_err, log2(r->poly.max_err), hw);
    if (r->swept) {
        uint32_t wb;
        memcpy(&wb, &r->sweep.worst_x, 4);
        char hx[64];
        pf_hexf(hx, sizeof hx, r->sweep.worst_x);
        pf_prov_line(b, "Sweep:", "max %.3f ULP at x = %s (0x%08x), mean %.4f ULP, %.2f%% correctly", r->sweep.max_ulp,
                     hx, wb, pf_sweep_mean(&r->sweep), pf_sweep_cr_percent(&r->sweep));
        pf_prov_line(b, "", "rounded; %s", r->sweep_desc); /* continued */
    }
    pf_put(b, " */\n"
              "/* no FP-exception semantics are promised, and dropping them lets GCC\n"
              "   if-convert the special-case selects so the array loop vectorizes;\n"
              "   no FMA contraction, so every x86-64 level gives the same bits */\n"
              "#if defined(__GNUC__) && !defined(__clang__)\n#pragma GCC optimize(\"no-trapping-math\", \"fp-contract=off\")\n#endif\n"
              "#include <math.h>\n#include <stddef.h>\n#include <stdint.h>\n#include <string.h>\n\n");
    pf_put(b, pf_template("poly_float.h"));
    int k0 = s->parity == FIT_PARITY_ODD ? 1 : 0, dk = s->parity == FIT_PARITY_NONE ? 1 : 2;
    int nco = 0;
    for (int k = k0; k <= r->order; k += dk)
        nco++;
    pf_printf(b, "\n/* %s ~ sum C[k] t^%s, lowest degree first */\nstatic const float %s_C[%d] = {\n",
              s->target_text, s->parity == FIT_PARITY_ODD ? "(2k+1)" : s->parity == FIT_PARITY_EVEN ? "(2k)" : "k",
              r->name, nco);
    for (int k = k0; k <= r->order; k += dk) {
        char h[64];
        pf_hexf(h, sizeof h, (double)r->poly.c[k]);
        pf_printf(b, "    %sf,%s/* c%d = %.9g */\n", h, strlen(h) < 16 ? "    " : " ", k, (double)r->poly.c[k]);
    }
    pf_put(b, "};\n\n");
    if (s->extra) {
        char *xb = malloc(1 << 20);
        if (!xb)
            abort();
        int xn = s->extra(xb, 1 << 20);
        pf_putn(b, xb, (size_t)(xn > 0 ? xn : 0));
        free(xb);
    }
    char ncoef[16], ncomp[16];
    snprintf(ncoef, sizeof ncoef, "%d", nco);
    snprintf(ncomp, sizeof ncomp, "%d", r->has_scheme ? r->scheme.ncomp : 0);
    const char *horner = !strcmp(s->real, "double") ? "pf_horner_d"
                       : !strcmp(s->real, "fma")    ? "pf_horner_fma" : "pf_horner_f";
    const char *kv[] = {"NAME", r->name, "REAL", !strcmp(s->real, "fma") ? "float" : s->real,
                        "HORNER", horner, "NCOEF", ncoef, "NCOMP", ncomp,
                        "KSCALE", s->kscale ? s->kscale : "1", "PSCALE", s->pscale ? s->pscale : "1", NULL};
    char tname[128];
    snprintf(tname, sizeof tname, "%s.c", s->tmpl);
    if (s->head)
        pf_subst(b, pf_template(s->head), kv);
    pf_subst(b, pf_template(tname), kv);
    pf_subst(b, pf_template(s->tail ? s->tail : s->arity == 2 ? "tail_binary.c" : "tail_unary.c"), kv);
}

static int fit_order(const pf_spec *s, int order, int minimax, int errkind, fit_poly *real,
                     fit_poly *poly, fit_problem *pb, char *err, size_t errlen)
{
    pf_spec_problem(s, order, pb);
    pb->errkind = errkind;
    fit_refit_fn refit = minimax ? fit_minimax : fit_lsq;
    if (refit(pb, real, err, errlen) != 0)
        return -1;
    *poly = *real;
    fit_measure(pb, real);
    fit_coeffmt fmt = {FIT_COEF_FLOAT, 0};
    if (fit_round(pb, fmt, refit, poly, NULL, err, errlen) != 0)
        return -1;
    fit_measure(pb, poly);
    return 0;
}

static void sweep_emitted(pf_gen_result *r, void *h, char *err, size_t errlen)
{
    pf_func f = (pf_func)pfref_lookup(r->spec->func);
    void *sym = dlsym(h, r->name);
    if (!sym) {
        snprintf(err, errlen, "emitted code has no symbol %s", r->name);
        return;
    }
    pf_fn1 f1 = NULL;
    pf_fn2 f2 = NULL;
    if (r->spec->arity == 2)
        *(void **)&f2 = sym;
    else
        *(void **)&f1 = sym;
    pf_sweep_init(&r->sweep);
    uint32_t lo, hi;
    pf_sweep_reduced_range(f, &lo, &hi);
    /* every 16th float of the reduced range, a seeded full-range sample and the directed list */
    for (uint64_t b = lo; b <= hi; b += 16) {
        float x;
        uint32_t u = (uint32_t)b;
        memcpy(&x, &u, 4);
        pf_sweep_one(&r->sweep, f, f1, f2, x, 1.0f);
    }
    pf_sweep_random(&r->sweep, f, f1, f2, 20261121, 1u << 18);
    pf_sweep_directed(&r->sweep, f, f1, f2);
    float flo, fhi;
    memcpy(&flo, &lo, 4);
    memcpy(&fhi, &hi, 4);
    snprintf(r->sweep_desc, sizeof r->sweep_desc,
             "sampled sweep of %llu inputs (every 16th float in [%a, %a], 2^18 seeded random, directed list)",
             (unsigned long long)r->sweep.count, (double)flo, (double)fhi);
    r->swept = 1;
}

/* The fits of one function: the requested order, or the smallest that
   meets the target, and the least-squares fit of the same order beside a
   minimax one.  Every fit is of the same target, so pf_generate's one cache
   scope around this lets them share g's values (MPFR at 256 bits: most of
   the time of a run).  Returns the order, or -1 with err set. */
static int fit_all(const pf_gen_req *rq, const pf_spec *s, pf_gen_result *r, int errkind, double target,
                   char *err, size_t errlen)
{
    int order = rq->order ? rq->order : rq->target > 0 ? 0 : s->default_order;
    if (order) {
        if (fit_order(s, order, r->minimax, errkind, &r->real, &r->poly, &r->pb, err, errlen) != 0)
            return -1;
        if (rq->target > 0 && !(r->poly.max_err <= rq->target)) {
            snprintf(err, errlen, "order %d does not meet the target %s: max %s error %.3e > %.3e",
                     order, r->target_text, errkind == FIT_REL ? "relative" : "absolute",
                     r->poly.max_err, rq->target);
            return -1;
        }
    } else {
        /* the smallest order whose emitted polynomial meets the target */
        int lo = 1;
        while (lo < FIT_MAX_ORDER && (s->parity == FIT_PARITY_NONE ? lo + 1 : (lo + 2) / 2) < s->ncon)
            lo++;
        double prev = -1;
        for (order = lo; order <= FIT_MAX_ORDER; order++) {
            char e2[256];
            if (s->parity == FIT_PARITY_ODD && order % 2 == 0)
                continue; /* an odd fit of even order is the order below */
            if (s->parity == FIT_PARITY_EVEN && order % 2 == 1)
                continue;
            if (fit_order(s, order, r->minimax, errkind, &r->real, &r->poly, &r->pb, e2, sizeof e2) != 0)
                continue;
            if (r->poly.max_err <= target)
                break;
            prev = r->poly.max_err;
        }
        if (order > FIT_MAX_ORDER) {
            snprintf(err, errlen, "impossible target: no order up to %d reaches %s error %.3g (order %d: %.3g)",
                     FIT_MAX_ORDER, errkind == FIT_REL ? "relative" : "absolute", target, FIT_MAX_ORDER, prev);
            return -1;
        }
        r->below_err = prev;
        r->searched = 1;
    }
    if (r->minimax) {
        fit_poly tmp;
        fit_problem pb2;
        if (fit_order(s, order, 0, errkind, &tmp, &r->lsq_poly, &pb2, err, errlen) != 0)
            return -1;
    }
    return order;
}

int pf_generate(const pf_gen_req *rq, pf_gen_result *r, char *err, size_t errlen)
{
    memset(r, 0, sizeof *r);
    r->below_err = -1;
    if (!pf_spec_func_known(rq->func)) {
        snprintf(err, errlen, "unknown function '%s' (known: %s)", rq->func, pf_spec_func_list());
        return -1;
    }
    const pf_spec *s = pf_spec_find(rq->func, rq->variant, rq->reduction);
    if (!s) {
        snprintf(err, errlen, "no %s variant of %s%s%s", rq->variant, rq->func,
                 rq->reduction ? " with reduction " : "", rq->reduction ? rq->reduction : "");
        return -1;
    }
    r->spec = s;
    if (rq->name)
        snprintf(r->name, sizeof r->name, "%s", rq->name);
    else
        snprintf(r->name, sizeof r->name, "pf_%sf%s", s->func, !strcmp(s->variant, "fast") ? "_fast" : "");
    r->minimax = rq->method ? !strcmp(rq->method, "minimax") : !strcmp(s->variant, "exact");
    int errkind = rq->target > 0 && rq->target_abs ? FIT_ABS : s->errkind;
    double target = rq->target > 0 ? rq->target : s->fast_target;
    r->target = rq->target;
    r->target_abs = rq->target_abs;
    snprintf(r->target_text, sizeof r->target_text, "%s", rq->target_text ? rq->target_text : "");
    fit_target_cache_begin();
    int order = fit_all(rq, s, r, errkind, target, err, errlen);
    fit_target_cache_end();
    if (order < 0)
        return -1;
    r->order = order;
    if (s->model) {
        if (s->model(&r->poly, order, &r->scheme) != 0) {
            snprintf(err, errlen, "%s", r->scheme.text);
            return -1;
        }
        r->has_scheme = 1;
    }
    pf_buf b = {0};
    emit(&b, r, rq->command);
    if (rq->sweep) {
        char e2[512];
        void *h = pf_compile_load(b.s, b.n, e2, sizeof e2);
        if (!h) {
            snprintf(err, errlen, "emitted code did not load: %s", e2);
            free(b.s);
            return -1;
        }
        e2[0] = 0;
        sweep_emitted(r, h, e2, sizeof e2);
        dlclose(h);
        if (!r->swept) {
            snprintf(err, errlen, "%s", e2);
            free(b.s);
            return -1;
        }
        free(b.s);
        b = (pf_buf){0};
        emit(&b, r, rq->command);
    }
    r->csrc = b.s;
    r->clen = b.n;
    return 0;
}

void pf_gen_free(pf_gen_result *r)
{
    free(r->csrc);
    r->csrc = NULL;
}

void pf_report_text(FILE *o, const pf_gen_result *r)
{
    const pf_spec *s = r->spec;
    char con[512];
    constraints_text(s, con, sizeof con);
    fprintf(o, "%s: %s, %s variant, float\n", r->name, s->func, s->variant);
    fprintf(o, "  reduction    %s\n", s->reduction_text);
    fprintf(o, "  domain       %s for t in [%a, %a] = [%.9g, %.9g]\n", s->target_text, s->a, s->b, s->a, s->b);
    fprintf(o, "  order        %d%s\n", r->order, r->below_err >= 0 || r->searched ? " (smallest meeting the target)" : "");
    if (r->below_err >= 0 || r->target > 0)
        fprintf(o, "  target       %s%smax %s error <= %.3g; order %d reaches %.3e%s\n", r->target_text,
                r->target_text[0] ? ": " : "", r->pb.errkind == FIT_REL ? "relative" : "absolute",
                r->target > 0 ? r->target : s->fast_target, r->order, r->poly.max_err, "");
    if (r->below_err >= 0)
        fprintf(o, "               the order below reaches %.3e\n", r->below_err);
    fprintf(o, "  method       %s\n", method_text(r));
    fprintf(o, "  constraints  %s\n", con);
    fprintf(o, "  coefficients (hex-float, decimal):\n");
    for (int k = 0; k <= r->order; k++)
        fprintf(o, "    c%-2d %-18a %.9g\n", k, (double)r->poly.c[k], (double)r->poly.c[k]);
    fprintf(o, "  max %s error of the emitted polynomial: %.4e (2^%.2f) at t = %.9g\n",
            s->errkind == FIT_REL ? "rel" : "abs", r->poly.max_err, log2(r->poly.max_err), r->poly.max_err_at);
    fprintf(o, "    (real-coefficient fit before rounding: %.4e)\n", r->real.max_err);
    if (r->minimax)
        fprintf(o, "    (least-squares fit of the same order, rounded the same way: %.4e)\n", r->lsq_poly.max_err);
    if (r->swept) {
        pf_sweep_print(o, "  ULP sweep of the emitted function", (pf_func)pfref_lookup(s->func), &r->sweep);
        fprintf(o, "    (%s)\n", r->sweep_desc);
    }
    if (r->has_scheme)
        fprintf(o, "  evaluation   %s\n  error model  at most %.3f ULP\n", r->scheme.text, r->scheme.bound_ulp);
}

void pf_report_json(FILE *o, const pf_gen_result *r)
{
    const pf_spec *s = r->spec;
    char con[512];
    constraints_text(s, con, sizeof con);
    fprintf(o, "{\"func\": \"%s\", \"variant\": \"%s\", \"type\": \"float\", \"name\": \"%s\", "
               "\"reduction\": \"%s\", \"order\": %d, \"domain\": [\"%a\", \"%a\"], ",
            s->func, s->variant, r->name, s->reduction, r->order, s->a, s->b);
    fprintf(o, "\"method\": \"%s\", \"constraints\": \"%s\", \"coefficients\": [", r->minimax ? "minimax" : "lsq", con);
    for (int k = 0; k <= r->order; k++)
        fprintf(o, "%s\"%a\"", k ? ", " : "", (double)r->poly.c[k]);
    fprintf(o, "], \"%s\": %.6e, \"max_rel_error_at\": %.9g, \"max_rel_error_real_coefficients\": %.6e",
            r->pb.errkind == FIT_REL ? "max_rel_error" : "max_abs_error", r->poly.max_err, r->poly.max_err_at, r->real.max_err);
    if (r->minimax)
        fprintf(o, ", \"lsq_max_rel_error\": %.6e", r->lsq_poly.max_err);
    if (r->below_err >= 0)
        fprintf(o, ", \"order_below_error\": %.6e", r->below_err);
    if (r->swept) {
        fprintf(o, ", \"sweep\": {\"max_ulp\": %.6f, \"mean_ulp\": %.6f, \"cr_percent\": %.4f, "
                   "\"count\": %llu, \"worst_input\": \"%a\"}",
                r->sweep.max_ulp, pf_sweep_mean(&r->sweep), pf_sweep_cr_percent(&r->sweep),
                (unsigned long long)r->sweep.count, (double)r->sweep.worst_x);
    }
    fprintf(o, "}\n");
}
