/* pfmathgen for fixed-point types: the function list, the --help text and
 * pf_run_fixed, which runs one request checked by gen/front/request.c (a bad
 * type or pair never gets here).  The pipeline itself is gen/fixed/fixed_core.c. */
#include "fixedgen.h"
#include "request.h"

#include "fixed_internal.h"
#include "fixedtype.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static const fx_func *const funcs[] = {&fx_func_sin, &fx_func_cos,  &fx_func_exp, &fx_func_exp2,
                                       &fx_func_log, &fx_func_log2, &fx_func_sqrt};
#define NFUNCS ((int)(sizeof funcs / sizeof funcs[0]))

const fx_func *fx_func_find(const char *name)
{
    for (int i = 0; i < NFUNCS; i++)
        if (!strcmp(funcs[i]->name, name))
            return funcs[i];
    return NULL;
}

const char *fx_func_list(void)
{
    return "sin, cos, exp, exp2, log, log2, sqrt, noise1, noise2, noise3, noise4, noise";
}

static const char usage[] =
    "usage: pfmathgen --func NAME --type T [--out-type T2] [options]\n"
    "Fixed-point generation: integer-only C taking and returning the stored integers.\n"
    "  --func NAME         sin, cos, exp, exp2, log, log2, sqrt, or gradient noise:\n"
    "                      noise1, noise2, noise3, noise4 (one dimension) or noise (all four)\n"
    "  --type T            input type, e.g. 'fixed<15,12>', 'unsigned fixed<16,8>', 'ufixed<16,8>'\n"
    "                      (storage up to 32 bits)\n"
    "  --out-type T        output type (default: the input type; needs --type)\n"
    "  --variant V         exact (default: below 1 LSB of the output for every input) or\n"
    "                      fast (within max(2^-10 relative, 4 LSB))\n"
    "  --order N           polynomial degree 1..24 (default: the smallest within the variant's bound)\n"
    "  --method M          minimax (default for exact) or lsq (default for fast)\n"
    "  --name NAME         function name (default pf_<func>_<in>_<out>[_fast], see docs/fixed.md)\n"
    "  -o, --output FILE   write the C source to FILE (nothing is written on error)\n"
    "  --json              print the report as one JSON object on stdout instead of C\n"
    "  --no-sweep          do not compile and sweep the emitted code\n"
    "  --seed N            noise only: lattice from pf_noise_table_seed(N) (default: Perlin's\n"
    "                      permutation, the library's default table); noise takes exact only,\n"
    "                      no --order/--method, an input exp >= 1; --name S with --func noise\n"
    "                      names the four functions S1 .. S4\n"
    "  -h, --help          this text\n"
    "Exit status: 0 ok, 2 bad usage, bad type or pair, impossible request, 1 internal failure.\n";

const char *fx_usage_text(void) { return usage; }

/* The fixed-point generator for one checked request (request.h). */
int pf_run_fixed(const pf_request *rq, FILE *rep, char **src, size_t *len, char *err, size_t errlen)
{
    *src = NULL;
    const fx_func *F = fx_func_find(rq->func);
    if (!F) {
        snprintf(err, errlen, "no fixed-point %s (available: %s)", rq->func, fx_func_list());
        return 2;
    }
    fx_gen *G = calloc(1, sizeof *G);
    if (!G) {
        snprintf(err, errlen, "out of memory");
        return 1;
    }
    G->fn = F;
    G->exact = !strcmp(rq->variant, "exact");
    G->in = rq->in;
    G->out = rq->out;
    pf_type_format(&G->in, G->in_text, sizeof G->in_text);
    pf_type_format(&G->out, G->out_text, sizeof G->out_text);
    G->it = pf_type_ctype(&G->in);
    G->ot = pf_type_ctype(&G->out);
    G->order_req = rq->order;
    G->minimax = rq->method ? !strcmp(rq->method, "minimax") : -1;
    if (rq->name)
        snprintf(G->name, sizeof G->name, "%s", rq->name);
    else
        pf_fixed_default_name(F->name, &G->in, &G->out, !G->exact, G->name, sizeof G->name);
    G->command = rq->command;
    int rc = fx_generate(G, rq->sweep, err, errlen);
    if (rc != 0) {
        free(G);
        return rc == -1 ? 2 : 1;
    }
    if (G->swept) {
        /* the sweep checks the error model: a violation is a bug, not a result */
        const char *why = NULL;
        if (G->sw.mismatch)
            why = "the scalar and array forms differ";
        else if (G->exact && !(G->sw.max_err < 1))
            why = "the exact variant reaches 1 LSB";
        else if (!G->exact && G->sw.over_fast)
            why = "the fast variant exceeds max(2^-10 relative, 4 LSB)";
        else if (G->sw.max_err > G->bound_lsb + 1e-6)
            why = "the sweep exceeds the error bound";
        if (why) {
            fx_report_text(rep, G);
            snprintf(err, errlen, "internal failure: %s (max %.4f LSB at x = %lld, bound %.4f LSB)", why,
                     G->sw.max_err, (long long)G->sw.worst_x, G->bound_lsb);
            free(G);
            return 1;
        }
    }
    *src = fx_emit(G, len);
    if (rq->json)
        fx_report_json(rep, G);
    else
        fx_report_text(rep, G);
    free(G);
    return 0;
}
