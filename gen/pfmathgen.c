/* pfmathgen: fit, report and emit C for one function.  See --help. */
#include "cli.h"
#include "fixedgen.h"
#include "fixedtype.h"
#include "generate.h"
#include "plot.h"
#include "scene.h"

#include <math.h>

#include <ctype.h>
#include <errno.h>
#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

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
    "  --out-type T        output type (fixed point; default: the input type)\n"
    "  --method M          minimax (default for exact: least maximum error, nlopt) or\n"
    "                      lsq (default for fast: the seed's least squares)\n"
    "  --target T          smallest order whose emitted polynomial meets T: float\n"
    "                      (relative error below 2^-24, the seed's criterion) or a\n"
    "                      fixed type such as 'fixed<15,14>' or 'unsigned fixed<8,8>'\n"
    "                      (absolute error below half an LSB of the output)\n"
    "  --max-rel-err E     the same with a relative error bound (1e-4, 2^-12)\n"
    "  --max-abs-err E     the same with an absolute error bound\n"
    "  --name NAME         emitted function name (default pf_<func>f, pf_<func>f_fast)\n"
    "  -o, --output FILE   write the C source to FILE (nothing is written on error)\n"
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
    "                      and report.txt\n"
    "  -h, --help          this text\n"
    "Exit status: 0 ok, 2 bad usage or impossible request, 1 internal failure.\n";

/* The command line as a shell would re-run it (quoted where needed). */
int main(int argc, char **argv)
{
    static const struct option opts[] = {
        {"func", required_argument, 0, 'f'},    {"variant", required_argument, 0, 'v'},
        {"order", required_argument, 0, 'n'},   {"reduction", required_argument, 0, 'r'},
        {"type", required_argument, 0, 't'},    {"method", required_argument, 0, 'm'},
        {"name", required_argument, 0, 'N'},    {"output", required_argument, 0, 'o'},
        {"json", no_argument, 0, 'j'},          {"no-sweep", no_argument, 0, 'S'},
        {"help", no_argument, 0, 'h'},          {"target", required_argument, 0, 'T'},
        {"max-rel-err", required_argument, 0, 'R'}, {"max-abs-err", required_argument, 0, 'A'},
        {"plot", required_argument, 0, 'P'},
        {0, 0, 0, 0}};
    for (int i = 1; i < argc; i++)
        if (!strcmp(argv[i], "--scene")) {
            const char *scene = i + 1 < argc ? argv[i + 1] : NULL, *dir = NULL;
            for (int j = 1; j < argc; j++)
                if ((!strcmp(argv[j], "-o") || !strcmp(argv[j], "--output")) && j + 1 < argc)
                    dir = argv[j + 1];
            if (!scene || !dir || argc != 5)
                pf_cli_die2("usage: pfmathgen --scene FILE -o DIR%s%s", "", "");
            char *cmd = pf_cli_command_line(argc, argv);
            int rc = pfmathgen_scene_main(scene, dir, cmd);
            free(cmd);
            return rc;
        }
    if (pfmathgen_wants_fixed(argc, argv))
        return pfmathgen_fixed_main(argc, argv);
    pf_gen_req rq = {0};
    rq.variant = "exact";
    rq.method = NULL;
    char target_text[96] = "";
    rq.sweep = 1;
    const char *out = NULL, *plot = NULL;
    int json = 0;
    opterr = 0;
    int c;
    while ((c = getopt_long(argc, argv, ":ho:", opts, NULL)) != -1) {
        switch (c) {
        case 'f': rq.func = optarg; break;
        case 'v':
            if (strcmp(optarg, "exact") && strcmp(optarg, "fast") && strcmp(optarg, "both"))
                pf_cli_die2("unknown variant '%s' (use exact, fast, or both with --plot)%s", optarg, "");
            rq.variant = optarg;
            break;
        case 'n': {
            char *end;
            errno = 0;
            long v = strtol(optarg, &end, 10);
            if (errno || end == optarg || *end || v < 1 || v > 30)
                pf_cli_die2("bad order '%s': expected an integer 1..30%s", optarg, "");
            rq.order = (int)v;
            break;
        }
        case 'r': rq.reduction = optarg; break;
        case 't':
            if (strcmp(optarg, "float"))
                pf_cli_die2("unsupported type '%s': only float is available in this build%s", optarg, "");
            break;
        case 'm':
            if (strcmp(optarg, "lsq") && strcmp(optarg, "minimax"))
                pf_cli_die2("unknown method '%s' (available: minimax, lsq)%s", optarg, "");
            rq.method = optarg;
            break;
        case 'T': {
            if (rq.target > 0)
                pf_cli_die2("only one of --target, --max-rel-err, --max-abs-err%s%s", "", "");
            pf_type t;
            char e[200];
            if (pf_type_parse(optarg, &t, e, sizeof e) != 0)
                pf_cli_die2("bad --target: %s%s", e, "");
            pf_type_format(&t, target_text, sizeof target_text);
            if (t.is_float) {
                rq.target = 0x1p-24;
                rq.target_abs = 0;
            } else {
                rq.target = 0.5 * pf_type_lsb(&t);
                rq.target_abs = 1;
            }
            break;
        }
        case 'R':
        case 'A': {
            if (rq.target > 0)
                pf_cli_die2("only one of --target, --max-rel-err, --max-abs-err%s%s", "", "");
            char *end;
            double v;
            if (!strncmp(optarg, "2^", 2)) {
                double ex = strtod(optarg + 2, &end);
                v = end == optarg + 2 ? NAN : ldexp(1.0, (int)ex);
                if (ex != (int)ex)
                    v = NAN;
            } else {
                v = strtod(optarg, &end);
            }
            if (*end || !(v > 0 && v < 1))
                pf_cli_die2("bad error bound '%s': expected a number in (0, 1) such as 1e-4 or 2^-12%s", optarg, "");
            rq.target = v;
            rq.target_abs = c == 'A';
            snprintf(target_text, sizeof target_text, "%s %s", c == 'A' ? "--max-abs-err" : "--max-rel-err", optarg);
            break;
        }
        case 'N':
            if (!pf_cli_is_identifier(optarg))
                pf_cli_die2("bad --name '%s': not a C identifier%s", optarg, "");
            rq.name = optarg;
            break;
        case 'o': out = optarg; break;
        case 'P': plot = optarg; break;
        case 'j': json = 1; break;
        case 'S': rq.sweep = 0; break;
        case 'h': printf(usage, pf_spec_func_list()); return 0;
        case ':': pf_cli_die2("option '%s' needs an argument%s", argv[optind - 1], ""); break;
        default: pf_cli_die2("unknown option '%s' (see --help)%s", argv[optind - 1], ""); break;
        }
    }
    if (optind < argc)
        pf_cli_die2("unexpected argument '%s' (see --help)%s", argv[optind], "");
    if (!rq.func)
        pf_cli_die2("--func is required (see --help)%s%s", "", "");
    if (rq.reduction && !pf_spec_find(rq.func, rq.variant, rq.reduction) && pf_spec_func_known(rq.func))
        pf_cli_die2("unknown reduction '%s' for %s", rq.reduction, rq.func);
    if (target_text[0])
        rq.target_text = target_text;
    rq.command = pf_cli_command_line(argc, argv);
    pf_gen_result r;
    char err[512];
    if (!strcmp(rq.variant, "both")) {
        if (!plot || out || json)
            pf_cli_die2("--variant both is for --plot only (no -o, no --json)%s%s", "", "");
        pf_gen_result r2;
        rq.variant = "exact";
        if (pf_generate(&rq, &r, err, sizeof err) != 0)
            pf_cli_die2("%s%s", err, "");
        rq.variant = "fast";
        if (pf_generate(&rq, &r2, err, sizeof err) != 0)
            pf_cli_die2("%s%s", err, "");
        pf_report_text(stderr, &r);
        pf_report_text(stderr, &r2);
        const pf_gen_result *both[2] = {&r, &r2};
        if (pf_plot_error(plot, both, 2, err, sizeof err) != 0) {
            fprintf(stderr, "pfmathgen: %s\n", err);
            return 1;
        }
        return 0;
    }
    if (pf_generate(&rq, &r, err, sizeof err) != 0)
        pf_cli_die2("%s%s", err, "");
    if (plot) {
        const pf_gen_result *one[1] = {&r};
        if (pf_plot_error(plot, one, 1, err, sizeof err) != 0) {
            fprintf(stderr, "pfmathgen: %s\n", err);
            return 1;
        }
    }
    if (json)
        pf_report_json(stdout, &r);
    else
        pf_report_text(stderr, &r);
    if (out) {
        if (pf_cli_write_atomically(out, r.csrc, r.clen) != 0) {
            fprintf(stderr, "pfmathgen: cannot write %s\n", out);
            return 1;
        }
    } else if (!json) {
        fwrite(r.csrc, 1, r.clen, stdout);
    }
    pf_gen_free(&r);
    free((void *)rq.command);
    return 0;
}
