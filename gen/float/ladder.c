/* The accuracy ladder's search (gen/float/ladder.h). */
#include "ladder.h"

#include "compile.h"
#include "float_model.h"

#include <dlfcn.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* pfsweep --all's pair set for atan2 (tests/pfsweep_pairs.c, linked into
   pfmathgen by mk/ladder.mk) */
int pfsweep_pairs(pf_sweep_stats *s, pf_func f, pf_fn2 fn, uint64_t seed, uint64_t n);

#define LADDER_MAX_ORDER 21   /* above the library's highest exact order (13) with room */
/* every order of up to 16 rows of one function (log2 has 7); candidates()
   stops the program rather than drop rows silently if a table outgrows it */
#define LADDER_MAX_CANDS (16 * LADDER_MAX_ORDER)
#define PAIRS_SEED 1          /* pfsweep --all's defaults */
#define PAIRS_N (1ull << 28)

typedef struct {
    const pf_spec *s;
    int order, cost;
    int costed;           /* cost includes the model's compensated steps */
} cand;

static int nterms(const pf_spec *s, int order)
{
    int k0 = s->parity == FIT_PARITY_ODD ? 1 : 0, dk = s->parity == FIT_PARITY_NONE ? 1 : 2, n = 0;
    for (int k = k0; k <= order; k += dk)
        n++;
    return n;
}

/* The static cost, in half fmaf steps per element: a float Horner step is 2;
   a double step 4 (double lanes are half as wide) plus 12 for the double
   reduction and conversions; a template other than the fast one (the exact
   atrig schemes' hi + lo steps, Fast2Sum) 8 more, about four fmaf.  A rough
   static figure: it only orders candidates of the same function, and it
   keeps the choice deterministic (a timed choice would change from run to
   run).  Ties go to the fast template, then the lower order.  A model that
   compensates steps (log's exact scheme: NCOMP double-float steps) adds 8
   a step, known only after the fit: such a candidate is then put back in
   its place by the corrected cost (COMP_COST). */
#define COMP_COST 8
static int cost_of(const pf_spec *s, const pf_spec *fast, int order)
{
    int n = nterms(s, order);
    if (s->ladder_cost > 0)
        return 2 * n + s->ladder_cost;
    if (!strcmp(s->variant, "fast"))
        return 2 * n;
    if (!strcmp(s->real, "double"))
        return 4 * n + 12;
    if (fast && strcmp(s->tmpl, fast->tmpl))
        return 2 * n + 8;
    return 2 * n;
}

static int cand_cmp(const void *pa, const void *pb)
{
    const cand *a = pa, *b = pb;
    if (a->cost != b->cost)
        return a->cost < b->cost ? -1 : 1;
    int fa = !strcmp(a->s->variant, "fast"), fb = !strcmp(b->s->variant, "fast");
    if (fa != fb)
        return fb - fa;
    return a->order - b->order;
}

/* the smallest order the spec's constraints and parity allow (as pf_generate) */
static int min_order(const pf_spec *s)
{
    int lo = 1;
    while (lo < FIT_MAX_ORDER && (s->parity == FIT_PARITY_NONE ? lo + 1 : (lo + 2) / 2) < s->ncon)
        lo++;
    return lo;
}

/* Every row of the function's table with this reduction is a candidate
   template: the fast and exact variants, and ladder-only rows (variant
   "mid": schemes between the two, which the library does not ship). */
static int candidates(const char *func, const char *reduction, cand *c)
{
    if (!reduction) {
        /* the function's default: its first row (gen/float/funcs.h) */
        const pf_spec *d = pf_spec_find(func, "exact", NULL);
        d = d ? d : pf_spec_find(func, "fast", NULL);
        if (!d)
            return 0;
        reduction = d->reduction;
    }
    const pf_spec *fast = pf_spec_find(func, "fast", reduction);
    int n = 0;
    for (int i = 0; i < pf_spec_count(); i++) {
        const pf_spec *sp = pf_spec_at(i);
        if (strcmp(sp->func, func) || strcmp(sp->reduction, reduction))
            continue;
        for (int o = min_order(sp); o <= LADDER_MAX_ORDER; o++) {
            if ((sp->parity == FIT_PARITY_ODD && o % 2 == 0) || (sp->parity == FIT_PARITY_EVEN && o % 2))
                continue;
            if (n == LADDER_MAX_CANDS) {
                fprintf(stderr, "pfmathgen: internal error: %s has more than %d ladder candidates "
                                "(gen/float/ladder.c: LADDER_MAX_CANDS)\n", func, LADDER_MAX_CANDS);
                abort();
            }
            c[n++] = (cand){sp, o, cost_of(sp, fast, o), 0};
        }
    }
    qsort(c, (size_t)n, sizeof *c, cand_cmp);
    return n;
}

/* the prediction of step 1 (ladder.h) */
static double predict(const pf_gen_result *r)
{
    if (r->has_scheme)
        return r->scheme.bound_ulp;
    const pf_spec *s = r->spec;
    pf_fm_bound fm = pf_fm_horner(&r->poly, r->order, s->parity, s->a, s->b, 0, 0);
    return 0.5 + (r->poly.max_err + fm.rel_max) * 0x1p24;
}

static float asfloat(uint32_t u)
{
    float f;
    memcpy(&f, &u, 4);
    return f;
}

/* step 2: the sample */
static void sweep_sample(pf_sweep_stats *st, pf_func f, pf_fn1 f1, pf_fn2 f2, uint64_t nrandom)
{
    pf_sweep_init(st);
    pf_sweep_directed(st, f, f1, f2);
    pf_sweep_random(st, f, f1, f2, 20261123, nrandom);
    if (f1) {
        uint32_t lo, hi;
        pf_sweep_reduced_range(f, &lo, &hi);
        for (uint64_t b = lo; b <= hi; b += 16)
            pf_sweep_one(st, f, f1, NULL, asfloat((uint32_t)b), 1.0f);
    }
    /* the trig reductions lose most next to multiples of pi/2, where a
       random sample almost never lands (fast sin at 128 ULP: 621.8 ULP at
       0x1.f9cbe2p+8, near 161 pi, passed a 2^22 sample): the float nearest
       k pi/2 and two on each side, both signs, for k pi/2 < 2^17 */
    if (f1 && (f == PF_SIN || f == PF_COS || f == PF_TAN))
        for (int k = 1; k * 1.5707963267948966 < 131072.0; k++) {
            float c = (float)(k * 1.5707963267948966);
            uint32_t u;
            memcpy(&u, &c, 4);
            for (uint32_t d = u - 2; d <= u + 2; d++) {
                pf_sweep_one(st, f, f1, NULL, asfloat(d), 1.0f);
                pf_sweep_one(st, f, f1, NULL, -asfloat(d), 1.0f);
            }
        }
}

/* step 3: every float, in chunks of 2^16 over the threads, stopping when a
   chunk exceeds the bound (the stats are then partial; the candidate fails).
   pf_sweep_merge breaks ties by bit pattern, so the result does not depend
   on the threads. */
static void sweep_every(pf_sweep_stats *st, pf_func f, pf_fn1 f1, double bound)
{
    const uint64_t chunk = 1u << 16, nch = (1ull << 32) / chunk;
    int stop = 0;
    pf_sweep_stats tot;
    pf_sweep_init(&tot);
#pragma omp parallel
    {
        pf_sweep_stats loc;
        pf_sweep_init(&loc);
#pragma omp for schedule(dynamic, 1)
        for (uint64_t c = 0; c < nch; c++) {
            int halt;
#pragma omp atomic read
            halt = stop;
            if (halt)
                continue;
            for (uint64_t b = c * chunk; b < (c + 1) * chunk; b++)
                pf_sweep_one(&loc, f, f1, NULL, asfloat((uint32_t)b), 1.0f);
            if (!(loc.max_ulp <= bound)) {
#pragma omp atomic write
                stop = 1;
            }
        }
#pragma omp critical(pf_ladder_merge)
        pf_sweep_merge(&tot, &loc);
    }
    *st = tot;
}

/* the provenance lines, after the "Regenerate:" line of the header comment */
static int add_provenance(pf_gen_result *r, const char *lines)
{
    const char *at = strstr(r->csrc, "\n * Reduction:");
    if (!at)
        return -1;
    size_t pre = (size_t)(at - r->csrc) + 1, add = strlen(lines);
    char *s = malloc(r->clen + add + 1);
    if (!s)
        return -1;
    memcpy(s, r->csrc, pre);
    memcpy(s + pre, lines, add);
    memcpy(s + pre + add, r->csrc + pre, r->clen - pre + 1);
    free(r->csrc);
    r->csrc = s;
    r->clen += add;
    return 0;
}

static void default_name(char *out, size_t n, const char *func, double u)
{
    char num[64];
    if (u == floor(u) && u < 1e9)
        snprintf(num, sizeof num, "%.0f", u);
    else /* the shortest that reads back as u: 1.0000001 is not 1's name */
        for (int p = 1; p <= 17; p++) {
            snprintf(num, sizeof num, "%.*g", p, u);
            if (strtod(num, NULL) == u)
                break;
        }
    char *w = num;
    for (char *p = num; *p; p++)
        if (*p == '.')
            *w++ = 'p';
        else if (*p != '+')
            *w++ = *p == '-' ? 'm' : *p;
    *w = 0;
    snprintf(out, n, "pf_%sf_u%s", func, num);
}

/* One candidate through steps 1-3: 1 accepted (*r kept), 0 rejected, -1
   failure, 2 deferred (its cost grew past next_cost once the model chose
   compensated steps). */
static int try_cand(const pf_gen_req *base, cand *c, int next_cost, double U, int sample, FILE *log,
                    pf_gen_result *r, double *predicted, char *why, size_t whylen)
{
    *predicted = INFINITY;
    pf_gen_req g = *base;
    g.variant = c->s->variant;
    g.reduction = c->s->reduction;
    g.order = c->order;
    g.target = 0;
    g.target_text = NULL;
    g.sweep = 0;
    char e[512];
    if (!base->method)
        g.method = "minimax";
    if (pf_generate(&g, r, e, sizeof e) != 0 && (base->method || (g.method = "lsq", pf_generate(&g, r, e, sizeof e) != 0))) {
        fprintf(log, "ladder: %-5s order %2d cost %3d: not generated (%s)\n", c->s->variant, c->order, c->cost, e);
        return 0;
    }
    if (!c->costed && r->has_scheme && r->scheme.ncomp > 0) {
        c->costed = 1;
        c->cost += COMP_COST * r->scheme.ncomp;
        if (c->cost > next_cost) {
            fprintf(log, "ladder: %-5s order %2d: %d compensated step(s), cost %d: deferred\n", c->s->variant,
                    c->order, r->scheme.ncomp, c->cost);
            pf_gen_free(r);
            return 2;
        }
    }
    double pred = *predicted = predict(r);
    fprintf(log, "ladder: %-5s order %2d cost %3d: predicted %.3g ULP", c->s->variant, c->order, c->cost, pred);
    if (!(pred <= U)) {
        fprintf(log, " > %g, skipped\n", U);
        pf_gen_free(r);
        return 0;
    }
    void *h = pf_compile_load(r->csrc, r->clen, e, sizeof e);
    if (!h) {
        snprintf(why, whylen, "emitted code did not load: %s", e);
        pf_gen_free(r);
        return -1;
    }
    void *sym = dlsym(h, r->name);
    pf_fn1 f1 = NULL;
    pf_fn2 f2 = NULL;
    if (c->s->arity == 2)
        *(void **)&f2 = sym;
    else
        *(void **)&f1 = sym;
    pf_func f = (pf_func)pfref_lookup(c->s->func);
    pf_sweep_stats st;
    sweep_sample(&st, f, f1, f2, sample ? 1u << 22 : 1u << 20);
    int ok = st.max_ulp <= U;
    fprintf(log, "; sample %.3f ULP at %a", st.max_ulp, (double)st.worst_x);
    if (ok && !sample) {
        if (f2)
            pfsweep_pairs(&st, f, f2, PAIRS_SEED, PAIRS_N);
        else
            sweep_every(&st, f, f1, U);
        ok = st.max_ulp <= U;
        fprintf(log, "; %s %.3f ULP at %a", f2 ? "pairs" : "every float", st.max_ulp, (double)st.worst_x);
    }
    dlclose(h);
    fprintf(log, "%s\n", ok ? ": accepted" : " > bound, rejected");
    if (!ok) {
        pf_gen_free(r);
        return 0;
    }
    r->sweep = st;
    r->swept = 1;
    if (sample)
        snprintf(r->sweep_desc, sizeof r->sweep_desc,
                 "sampled, not exhaustive (--confirm sample): directed list, 2^22 seeded random floats%s%s",
                 f1 ? ", every 16th float of the reduced range" : "",
                 f == PF_SIN || f == PF_COS || f == PF_TAN ? ", the 5 floats around k pi/2 below 2^17" : "");
    else if (f2)
        snprintf(r->sweep_desc, sizeof r->sweep_desc,
                 "pfsweep --all's pair set: 2^28 seeded pairs, every special pair, the directed list");
    else
        snprintf(r->sweep_desc, sizeof r->sweep_desc, "exhaustive: every one of the 2^32 floats");
    return 1;
}

static int search(const pf_gen_req *base, double U, int sample, FILE *log, pf_gen_result *res, char *err,
                  size_t errlen);

/* The search's log is kept until the end: shown with the report on success,
   dropped on failure (whose message is one line, as every pfmathgen error). */
int pf_ladder_generate(const pf_gen_req *base, double U, int sample, FILE *log, pf_gen_result *res, char *err,
                       size_t errlen)
{
    char *text = NULL;
    size_t len = 0;
    FILE *mem = open_memstream(&text, &len);
    if (!mem) {
        snprintf(err, errlen, "out of memory");
        return 1;
    }
    /* the candidates fit the same targets again (every template and order
       of one function): one cache scope shares g's MPFR values among them */
    fit_target_cache_begin();
    int rc = search(base, U, sample, mem, res, err, errlen);
    fit_target_cache_end();
    fclose(mem);
    if (rc == 0)
        fwrite(text, 1, len, log);
    free(text);
    return rc;
}

static int search(const pf_gen_req *base, double U, int sample, FILE *log, pf_gen_result *res, char *err,
                  size_t errlen)
{
    cand c[LADDER_MAX_CANDS];
    int n = candidates(base->func, base->reduction, c);
    char name[128];
    pf_gen_req g = *base;
    if (!g.name) {
        default_name(name, sizeof name, base->func, U);
        g.name = name;
    }
    fprintf(log, "ladder: %s within %g ULP: %d candidates, cheapest first\n", base->func, U, n);
    /* A spec whose prediction has not improved by 3% over its best for two
       orders in a row has reached its rounding floor: its higher orders are
       skipped (they would cost fits of up to a minute each for nothing). */
#define LADDER_MAX_SPECS 8
    const pf_spec *seen[LADDER_MAX_SPECS] = {NULL};
    double best[LADDER_MAX_SPECS];
    int stall[LADDER_MAX_SPECS] = {0};
    for (int k = 0; k < LADDER_MAX_SPECS; k++)
        best[k] = INFINITY;
    for (int i = 0; i < n; i++) {
        int k = 0;
        while (k < LADDER_MAX_SPECS - 1 && seen[k] && seen[k] != c[i].s)
            k++;
        seen[k] = c[i].s;
        if (stall[k] >= 2)
            continue;
        double pred;
        int rc = try_cand(&g, &c[i], i + 1 < n ? c[i + 1].cost : INT_MAX, U, sample, log, res, &pred, err, errlen);
        if (rc < 0)
            return 1;
        if (rc == 2) {
            /* back in its place by the corrected cost; c[i] is then the next one */
            cand d = c[i];
            int j = i;
            for (; j + 1 < n && cand_cmp(&c[j + 1], &d) <= 0; j++)
                c[j] = c[j + 1];
            c[j] = d;
            i--;
            continue;
        }
        if (isfinite(pred)) {
            stall[k] = pred > 0.97 * best[k] ? stall[k] + 1 : 0;
            best[k] = fmin(best[k], pred);
            if (stall[k] >= 2)
                fprintf(log, "ladder: %s template: no better prediction at higher orders, stops here\n",
                        c[i].s->variant);
        }
        if (rc == 0)
            continue;
        char lines[1024], hx[64];
        uint32_t wb;
        memcpy(&wb, &res->sweep.worst_x, 4);
        if (c[i].s->arity == 2)
            snprintf(hx, sizeof hx, "(y, x) = (%a, %a)", (double)res->sweep.worst_x, (double)res->sweep.worst_x2);
        else
            snprintf(hx, sizeof hx, "x = %a (0x%08x)", (double)res->sweep.worst_x, wb);
        snprintf(lines, sizeof lines,
                 " * Ladder:      --max-ulp %g: the cheapest of %d candidates (the function's templates,\n"
                 " *              orders up to %d) predicted and swept within %g ULP: %s template,\n"
                 " *              order %d, cost %d (gen/float/ladder.c); predicted %.3f ULP\n"
                 " * Confirmed:   max %.3f ULP at %s over %llu inputs;\n"
                 " *              %s\n",
                 U, n, LADDER_MAX_ORDER, U, res->spec->variant, res->order, c[i].cost, predict(res),
                 res->sweep.max_ulp, hx, (unsigned long long)res->sweep.count, res->sweep_desc);
        if (add_provenance(res, lines) != 0) {
            pf_gen_free(res);
            snprintf(err, errlen, "out of memory");
            return 1;
        }
        return 0;
    }
    snprintf(err, errlen, "impossible target: none of the %d candidates of %s (orders up to %d) is within %g ULP",
             n, base->func, LADDER_MAX_ORDER, U);
    return 2;
}
