/* pfmathgen: fit, report and emit C for one function.  See --help. */
#include "fixed_internal.h"
#include "generate.h"
#include "ladder.h"
#include "output.h"
#include "plot.h"
#include "request.h"
#include "scene.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char usage[] =
    "usage: pfmathgen --func NAME [options]\n"
    "Fits one polynomial over the function's reduced domain (least-squares relative\n"
    "error with value/slope constraints), rounds its coefficients to float, prints a\n"
    "report on stderr and writes self-contained C on stdout (or -o FILE).\n"
    "\n"
    "  --func NAME         function: %s\n"
    "  --variant V         exact (default: within 1 ULP) or fast (value and slope\n"
    "                      matched at both ends of the reduced domain)\n"
    "  --order N           polynomial degree, 1..30 (default: the library's; for fast,\n"
    "                      the smallest order reaching 2^-10 relative error)\n"
    "  --reduction R       argument reduction (log/log2: balanced (default), seed)\n"
    "  --type T            input type: float (default) or a fixed type such as\n"
    "                      'fixed<15,12>', 'unsigned fixed<16,8>', 'ufixed<16,8>'\n"
    "  --out-type T        output type (fixed point; default: the input type; needs --type)\n"
    "  --method M          minimax (default for exact: least maximum error, nlopt) or\n"
    "                      lsq (default for fast: the seed's least squares)\n"
    "  --target T          smallest order whose emitted polynomial meets T: float\n"
    "                      (relative error below 2^-24, the seed's criterion) or a\n"
    "                      fixed type such as 'fixed<15,14>' or 'unsigned fixed<8,8>'\n"
    "                      (absolute error below half an LSB of the output)\n"
    "  --max-rel-err E     the same with a relative error bound (1e-4, 2^-12)\n"
    "  --max-abs-err E     the same with an absolute error bound\n"
    "  --max-ulp U         the accuracy ladder: the cheapest template and order whose\n"
    "                      emitted code is within U ULP (a number >= 0.5, or 2^k) on\n"
    "                      every float, confirmed by an exhaustive sweep before the\n"
    "                      file is written (minutes); a relative level E is the ULP\n"
    "                      level E 2^23 (2^-16: --max-ulp 2^7); no --variant, --order,\n"
    "                      --target, --max-rel-err, --no-sweep; default name pf_<func>f_u<U>\n"
    "  --confirm sample    with --max-ulp: a sampled instead of the exhaustive sweep\n"
    "                      (for tests and quick ladders; the provenance says so)\n"
    "  --name NAME         emitted function name (default pf_<func>f, pf_<func>f_fast): a C\n"
    "                      identifier, not a keyword, at most 100 characters\n"
    "  -o, --output FILE   write the C source to FILE (nothing is written on error; see\n"
    "                      \"Output rules\" in the README)\n"
    "  --json              print the report as one JSON object on stdout instead of C\n"
    "  --plot FILE.svg     draw the error of the emitted polynomial over its domain;\n"
    "                      with --variant both, exact and fast side by side (then\n"
    "                      no C is written)\n"
    "  --no-sweep          do not compile and sweep the emitted code\n"
    "  --func noise1..noise4|noise --type T --out-type T2\n"
    "                      integer-only gradient noise for a fixed-point type pair,\n"
    "                      within 1 LSB of the exact noise (see --type T --help)\n"
    "  --scene FILE -o DIR generate exactly the functions a scene file lists (one\n"
    "                      'function exact|fast in-type out-type' a line, or\n"
    "                      'noiseN in-type out-type'), each at\n"
    "                      the smallest order meeting its output type, plus scene.h\n"
    "                      and report.txt; DIR may exist (files are replaced one by one)\n"
    "  --prefix P          with --scene: the functions are named P<func>f, P<func>_<types>\n"
    "                      (default: the scene file's name and '_', e.g. brick_)\n"
    "  -h, --help          this text\n"
    "Each option at most once.  Exit status: 0 ok, 2 bad usage or impossible request\n"
    "(one line on stderr, before any fitting where it can be known), 1 internal failure.\n";

/* Writes the C (and the plot) only when everything succeeded: both are
 * staged first, then renamed into place (output.h). */
static int write_outputs(const pf_request *rq, const char *src, size_t len, const char *svg, size_t svglen)
{
    char err[600];
    pf_out_staged st[2] = {{0}, {0}}; /* the C, the plot */
    int rc = 0;
    if (rq->output && pf_out_stage(rq->output, src, len, &st[0], err, sizeof err) != 0)
        rc = 1;
    if (!rc && svg && pf_out_stage(rq->plot, svg, svglen, &st[1], err, sizeof err) != 0)
        rc = 1;
    if (!rc && pf_out_commit_all(st, 2, err, sizeof err) != 0)
        rc = 1;
    pf_out_abort(&st[0]);
    pf_out_abort(&st[1]);
    if (rc)
        pf_say(err);
    return rc;
}

/* With --json and -o, the JSON goes out first: if standard output cannot
 * take it (a full disk, a closed pipe), the run fails before -o's file is
 * written, rather than failing with the file already in place. */
static int json_written(const pf_request *rq)
{
    if (!rq->json || (fflush(stdout) == 0 && !ferror(stdout)))
        return 1;
    pf_say(rq->output ? "cannot write the standard output (the JSON report); -o's file not written"
                      : "cannot write the standard output (the JSON report)");
    return 0;
}

static int run_float(pf_request *rq)
{
    pf_gen_req g = {0};
    g.func = rq->func;
    g.variant = rq->variant;
    g.reduction = rq->reduction;
    g.name = rq->name;
    g.method = rq->method;
    g.order = rq->order;
    g.target = rq->target;
    g.target_abs = rq->target_abs;
    g.target_text = rq->target_text[0] ? rq->target_text : NULL;
    g.sweep = rq->sweep;
    g.command = rq->command;
    char err[600];
    int both = !strcmp(rq->variant, "both");
    pf_gen_result r[2];
    for (int i = 0; i < 1 + both; i++) {
        if (both)
            g.variant = i ? "fast" : "exact";
        int grc = rq->max_ulp > 0 ? pf_ladder_generate(&g, rq->max_ulp, rq->confirm_sample, stderr, &r[i], err, sizeof err)
                                  : pf_generate(&g, &r[i], err, sizeof err) != 0 ? 2 : 0;
        if (grc) {
            pf_say(err);
            if (i)
                pf_gen_free(&r[0]);
            return grc;
        }
    }
    char *svg = NULL;
    size_t svglen = 0;
    if (rq->plot) {
        const pf_gen_result *rs[2] = {&r[0], &r[1]};
        if (pf_plot_svg(rs, 1 + both, &svg, &svglen, err, sizeof err) != 0) {
            pf_say(err);
            for (int i = 0; i < 1 + both; i++)
                pf_gen_free(&r[i]);
            return 1;
        }
    }
    if (rq->json)
        pf_report_json(stdout, &r[0]);
    else
        for (int i = 0; i < 1 + both; i++)
            pf_report_text(stderr, &r[i]);
    int rc = json_written(rq) ? write_outputs(rq, r[0].csrc, r[0].clen, svg, svglen) : 1;
    if (!rc && !both && !rq->output && !rq->json)
        fwrite(r[0].csrc, 1, r[0].clen, stdout);
    free(svg);
    for (int i = 0; i < 1 + both; i++)
        pf_gen_free(&r[i]);
    return rc;
}

/* fixed point and noise: the generator reports, this writes */
static int run_fixed(pf_request *rq)
{
    char err[800], *src;
    size_t len = 0;
    FILE *rep = rq->json ? stdout : stderr;
    int rc = rq->mode == PF_MODE_NOISE ? pf_run_noise(rq, rep, &src, &len, err, sizeof err)
                                       : pf_run_fixed(rq, rep, &src, &len, err, sizeof err);
    if (rc) {
        pf_say(err);
        return rc;
    }
    rc = json_written(rq) ? write_outputs(rq, src, len, NULL, 0) : 1;
    if (!rc && !rq->output && !rq->json)
        fwrite(src, 1, len, stdout);
    free(src);
    return rc;
}

int main(int argc, char **argv)
{
    pf_request rq;
    char err[800];
    if (pf_request_parse(argc, argv, &rq, err, sizeof err) != 0) {
        pf_say(err);
        return 2;
    }
    int rc = 0;
    if (rq.help) {
        pf_type t;
        int fixed = fx_noise_is(rq.func);
        if (rq.type_s && pf_type_parse(rq.type_s, &t, NULL, 0) == 0 && !t.is_float)
            fixed = 1;
        if (rq.out_type_s && pf_type_parse(rq.out_type_s, &t, NULL, 0) == 0 && !t.is_float)
            fixed = 1;
        /* no return here: the text, too, is checked as written below */
        if (fixed)
            fputs(fx_usage_text(), stdout);
        else
            printf(usage, pf_spec_func_list());
    } else {
        switch (rq.mode) {
        case PF_MODE_SCENE: rc = pf_scene_run(&rq); break;
        case PF_MODE_FLOAT: rc = run_float(&rq); break;
        default: rc = run_fixed(&rq); break;
        }
    }
    pf_request_free(&rq);
    /* C or JSON on a full disk or a closed pipe is a failure, not success */
    if ((fflush(stdout) != 0 || ferror(stdout)) && !rc) {
        pf_say("cannot write the standard output");
        rc = 1;
    }
    return rc;
}
